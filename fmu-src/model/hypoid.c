/* The HypoidGearPair model object: see hypoid.h. */
#include "model/hypoid.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "io/constants.h"
#include "model/friction_table_policy.h"
#include "model/model_object.h"
#include "model/outputs.h"
#include "model/stepping.h"
#include "model/table_store.h"

#define MAX_EVENTS_PER_STEP 100000
#define MAX_SOLVER_STEPS 500000 /* per call of the integrator */

void hg_model_start_values(hg_vars *v)
{
    int r;
    memset(v, 0, sizeof *v);
    for (r = 0; r < HG_NUM_VARS; r++) {
        const hg_var_info *info = &hg_var_table[r];
        void *p = hg_var_ptr(v, info);
        if (info->type == HG_REAL)
            *(double *)p = info->start;
        else if (info->type == HG_STRING)
            *(const char **)p = info->start_string;
        else
            *(int *)p = (int)info->start;
    }
}

hg_model *hg_model_new(const char *resource_dir, hg_log_fn log, void *log_ctx)
{
    hg_model *m = calloc(1, sizeof *m);
    if (!m) return NULL;
    m->resource_dir = malloc(strlen(resource_dir ? resource_dir : "") + 1);
    if (!m->resource_dir) {
        free(m);
        return NULL;
    }
    hg_store_attach(); /* the process's shared tables live while an instance does */
    strcpy(m->resource_dir, resource_dir ? resource_dir : "");
    m->log.fn = log;
    m->log.ctx = log_ctx;
    return m;
}

void hg_model_free(hg_model *m)
{
    if (!m) return;
    hg_solver_free(m->solver);
    hg_setup_free(&m->s);
    hg_ftp_free(&m->tables);
    free(m->resource_dir);
    free(m);
    hg_store_detach();
}

double hg_model_time(const hg_model *m) { return m->rt.t; }

#define HALF_SHAFT_STEP_PERIODS 0.4 /* of the half-shaft mode: the range the coupling matrix and
                                       the one-step map cover (docs/integration.md) */

double hg_model_comm_step_limit(const hg_model *m)
{
    const hg_dyn_params *p = &m->s.p;
    double J = p->I_w + p->I_g + (p->I_s + p->I_p) * p->ratio * p->ratio; /* [kg m^2] */
    if (!p->half_shaft || !(p->k_hs > 0.0)) return 0.0;
    return HALF_SHAFT_STEP_PERIODS * HG_TWO_PI / sqrt(p->k_hs / J);
}

/* ------------------------------------------------------------------ the integrator */

/* The integrator holds the first n_active states (the half-shaft's two only under load_mode =
 * half_shaft); the model's arrays are HG_NY long, the others 0. */
static int rhs(double t, const double *y_in, double *ydot_out, void *user)
{
    hg_model *m = user;
    hg_inputs u;
    hg_dyn_eval ev;
    int n = m->s.n_active;
    double y_all[HG_NY], ydot_all[HG_NY];
    const double *y = y_in;
    double *ydot = n == HG_Y_TWIST_HS ? ydot_all : ydot_out; /* n: HG_NY or HG_Y_TWIST_HS */
    if (n == HG_Y_TWIST_HS) { /* without the half-shaft: copies of a constant size, inlined */
        memcpy(y_all, y_in, HG_Y_TWIST_HS * sizeof *y_all);
        memset(y_all + HG_Y_TWIST_HS, 0, (HG_NY - HG_Y_TWIST_HS) * sizeof *y_all);
        y = y_all;
    }
    hg_stepping_inputs_at(&m->rt, t, &u);
    hg_dyn_evaluate(&m->s.p, &u, m->rt.mode, y, 0, m->rt.T_c_warm, &ev);
    hg_dyn_derivatives(&m->s.p, &u, y, &ev, ydot);
    if (n == HG_Y_TWIST_HS) memcpy(ydot_out, ydot_all, HG_Y_TWIST_HS * sizeof *ydot_out);
    return 0;
}

static int roots(double t, const double *y, double *g, void *user)
{
    hg_model *m = user;
    (void)t;
    hg_stepping_roots(&m->rt, &m->s, y, g);
    return 0;
}

/* (Re)creates the integrator on the model's right-hand side and roots. */
static int make_solver(hg_model *m, char *err, size_t errlen)
{
    hg_solver_options opt;
    int solver = m->s.solver;
    opt.method = solver == HG_SOLVER_CVODE_ADAMS ? HG_METHOD_ADAMS
                 : solver == HG_SOLVER_NEWMARK    ? HG_METHOD_NEWMARK
                 : solver == HG_SOLVER_ARKODE_ERK ? HG_METHOD_ERK
                                                  : HG_METHOD_BDF;
    opt.rtol = m->s.rtol;
    opt.atol = m->s.atol;
    opt.max_steps = MAX_SOLVER_STEPS;
    opt.max_order = m->s.max_order;
    opt.jac_every = m->s.jac_every;
    hg_solver_free(m->solver);
    m->solver = hg_solver_new(m->s.n_active, HG_STEPPING_N_ROOTS, rhs, roots, m, &opt, err,
                              errlen);
    return m->solver ? 0 : -1;
}

/* ------------------------------------------------------------------ outputs */

static void write_outputs(hg_model *m, hg_vars *v, int set)
{
    long steps = 0, evals = 0;
    if (set == HG_OUTSET_PAIRS) {
        hg_model_outputs(m, v, HG_OUTSET_MAIN); /* the split of P_loss applies to it */
        hg_outputs_pairs(&m->s, &m->rt, v);
    } else {
        if (m->solver) hg_solver_stats(m->solver, &steps, &evals);
        /* the same unless restored or failed: a restart */
        m->s.p.tables = hg_ftp_of_state(m->tables, &m->rt, &m->s, &m->log);
        if (set == HG_OUTSET_STATES)
            hg_outputs_states(&m->rt, v);
        else if (set == HG_OUTSET_DERIVATIVES)
            hg_outputs_derivatives(&m->s, &m->rt, v);
        else
            hg_outputs_main(&m->s, &m->rt, steps, evals, v);
    }
    m->outputs_current[set] = 1;
}

static void write_all_outputs(hg_model *m, hg_vars *v)
{
    int set;
    for (set = 0; set < HG_NUM_OUTSETS; set++) write_outputs(m, v, set);
}

void hg_model_outputs_stale(hg_model *m)
{
    memset(m->outputs_current, 0, sizeof m->outputs_current);
}

int hg_model_outputs_current(const hg_model *m, int set) { return m->outputs_current[set]; }

void hg_model_outputs(hg_model *m, hg_vars *v, int set)
{
    if (!m->outputs_current[set]) write_outputs(m, v, set);
}

/* ------------------------------------------------------------------ set-up */

int hg_model_setup(hg_model *m, hg_vars *v, double t0, char *err, size_t errlen)
{
    const hg_setup *s = &m->s;
    if (hg_setup_load(&m->s, m->resource_dir, &m->log, v, err, errlen) ||
        hg_ftp_setup(&m->tables, &m->s, m->resource_dir, v, err, errlen))
        return -1;
    hg_stepping_start(&m->rt, &m->s, v, t0);
    if (make_solver(m, err, errlen)) return -1;
    hg_logf(&m->log, "logEvents",
            "set-up: %s, i = %.4f, k_m0 = %.4g N/m, R_p0 = %.3f mm, modes %.1f / %.1f / %.1f Hz, "
            "dampers c_t1 = %.4g, c = %.4g, c_t2 = %.4g; eta_cycle holds 1 until the first window "
            "of %d mesh cycles completes",
            s->gear.name, s->p.ratio, s->p.k_m0, 1e3 * s->p.R_p0, v->f_2, v->f_3, v->f_4,
            s->p.c_t1, s->p.c_m, s->p.c_t2, v->n_avg_cycles);
    write_all_outputs(m, v);
    return 0;
}

/* ------------------------------------------------------------------ stepping */

/* The right-hand side at the current state with the inputs u, the thermal warm starts left as
 * they are. */
static void rhs_now(hg_model *m, const hg_inputs *u, double *ydot)
{
    hg_dyn_eval ev;
    double warm[HG_MAX_PAIRS];
    memcpy(warm, m->rt.T_c_warm, sizeof warm);
    hg_dyn_evaluate(&m->s.p, u, m->rt.mode, m->rt.y, 0, warm, &ev);
    hg_dyn_derivatives(&m->s.p, u, m->rt.y, &ev, ydot);
}

/* The inputs of a step and whether the integrator restarts for them (docs/model.md, "Steps
 * without restarts"): a change of their derivatives alone keeps the right-hand side continuous
 * and does not; a jump of their values or a new friction table does; anything does when the
 * integrator has already stepped past the step's start on the old right-hand side. The explicit
 * method, whose history is its step size alone, keeps it through a jump small against its
 * tolerances (hg_stepping_jump_small); *h0 is then its first step, else 0. */
static void begin_inputs(hg_model *m, const hg_vars *v, const hg_inputs *du, double *h0)
{
    hg_runtime *rt = &m->rt;
    hg_inputs u, du_in = *du;
    hg_input_change change;
    double f_old[HG_NY], f_new[HG_NY];
    int rebuild, keep;
    hg_vars_inputs(v, &u);
    hg_stepping_wheel_correct(rt, &m->s, &u);
    hg_stepping_wheel_input(rt, &m->s, &u, &du_in);
    du = &du_in;
    change = hg_stepping_change(rt, &u, du);
    rebuild = hg_ftp_stale(m->tables, rt, &m->s.p, &u);
    keep = m->s.explicit_rk && !rt->restart && (change == HG_INPUTS_JUMP || rebuild);
    if (change == HG_INPUTS_JUMP || rebuild || (rt->ahead && change != HG_INPUTS_SAME))
        rt->restart = 1;
    if (keep) rhs_now(m, &rt->u_end, f_old);
    hg_stepping_begin(rt, &m->s, &u, du, change);
    /* after the old right-hand side's last use: to or from the direct solve is a full restart */
    if (hg_ftp_begin(m->tables, rt, &m->s, rebuild, &m->log)) {
        rt->restart = 1;
        keep = 0;
    }
    if (keep) rhs_now(m, &u, f_new);
    *h0 = keep && hg_stepping_jump_small(rt, &m->s, f_old, f_new) ? rt->h_int : 0.0;
}

static int begin_step(hg_model *m, const hg_vars *v, const hg_inputs *du, double h,
                      char *err, size_t errlen)
{
    hg_runtime *rt = &m->rt;
    double h0;
    if (m->s.p.ledger.sump
            ? hg_setup_oil_in_range(&m->s, "T_oil", rt->y[HG_Y_T_OIL], err, errlen)
            : hg_setup_oil_in_range(&m->s, "T_bath", v->T_bath, err, errlen))
        return -1;
    begin_inputs(m, v, du, &h0);
    if (hg_solver_set_max_step(m->solver, hg_stepping_step_limit(rt, &m->s, h), err, errlen))
        return -1;
    if (rt->restart && hg_solver_restart(m->solver, rt->t, rt->y, h0, err, errlen)) return -1;
    rt->restart = 0;
    return 0;
}

/* The first state that is not finite (its index), or -1. */
static int nonfinite_state(const double *y)
{
    int k;
    for (k = 0; k < HG_NY; k++)
        if (!isfinite(y[k])) return k;
    return -1;
}

static int advance(hg_model *m, const hg_vars *v, const hg_inputs *du, double h, char *err,
                   size_t errlen)
{
    hg_runtime *rt = &m->rt;
    double t_end = rt->t + h;
    long steps0 = 0, steps1 = 0, evals = 0;
    int events = 0, dir[HG_STEPPING_N_ROOTS], pass;
    if (begin_step(m, v, du, h, err, errlen)) return -1;
    pass = hg_stepping_may_pass(rt);
    hg_solver_stats(m->solver, &steps0, &evals);
    while (rt->t < t_end) {
        hg_advance_result r =
            hg_solver_advance(m->solver, t_end, pass, &rt->t, rt->y, dir, err, errlen);
        if (r == HG_ADVANCE_FAILED) return -1;
        if (r == HG_ADVANCE_REACHED) break;
        if (++events > MAX_EVENTS_PER_STEP) {
            hg_errorf(err, errlen, "more than %d contact events in one step at t = %.9g s "
                      "(chattering); reduce the step or use a smaller rtol", MAX_EVENTS_PER_STEP,
                      rt->t);
            return -1;
        }
        if (dir[2] || dir[3]) hg_stepping_window_event(rt, &m->log);
        /* a contact change alters the right-hand side: restart; a window end changes nothing
         * the integrator sees but its root function, which it re-evaluates at the root */
        if ((dir[0] || dir[1]) &&
            (hg_stepping_contact_event(rt, &m->s, dir, &m->log),
             hg_solver_restart(m->solver, rt->t, rt->y, 0.0, err, errlen)))
            return -1;
    }
    hg_solver_stats(m->solver, &steps1, &evals);
    rt->h_int = h / (double)(steps1 > steps0 ? steps1 - steps0 : 1);
    rt->ahead = pass;
    hg_stepping_end(rt, &m->s, t_end, h, &m->log);
    return 0;
}

int hg_model_step(hg_model *m, hg_vars *v, const hg_inputs *du, double h, char *err,
                  size_t errlen)
{
    hg_runtime start = m->rt;
    int bad = -1;
    hg_model_outputs_stale(m);
    if (!advance(m, v, du, h, err, errlen) && (bad = nonfinite_state(m->rt.y)) < 0) return 0;
    if (bad >= 0)
        hg_errorf(err, errlen, "state %d of the integrator became %g at t = %.9g s", bad,
                  m->rt.y[bad], m->rt.t);
    m->rt = start; /* the last good state, whose outputs stay readable */
    m->rt.restart = 1;
    return -1;
}

/* ------------------------------------------------------------------ snapshots */

void hg_model_save(hg_model *m, hg_runtime *out)
{
    m->rt.restart = 1;
    *out = m->rt;
}

int hg_model_restore(hg_model *m, hg_vars *v, const hg_runtime *in, char *err, size_t errlen)
{
    if (!m->solver) {
        hg_errorf(err, errlen, "cannot restore a state into a model that is not set up");
        return -1;
    }
    m->rt = *in;
    m->rt.restart = 1;
    write_all_outputs(m, v);
    return 0;
}
