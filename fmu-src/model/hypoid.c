/* The HypoidGearPair model object: see hypoid.h. */
#include "model/hypoid_internal.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define N_ROOTS 4             /* x - b, x + b, window end forwards, window end backwards */
#define WRAP_PERIODS 1024     /* wrap the pinion angle after this many load-share periods */
#define MAX_EVENTS_PER_STEP 100000
#define MAX_AUTO_STEP 1e-3    /* [s] */
#define STEPS_PER_MODE 8      /* fixed steps per period of the highest natural mode, at least */

void hg_model_log(hg_model *m, const char *category, const char *fmt, ...)
{
    char msg[HG_ERRLEN];
    va_list ap;
    if (!m->log) return;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    m->log(m->log_ctx, category, msg);
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
    strcpy(m->resource_dir, resource_dir ? resource_dir : "");
    m->log = log;
    m->log_ctx = log_ctx;
    return m;
}

void hg_model_free(hg_model *m)
{
    if (!m) return;
    hg_solver_free(m->solver);
    hg_effmap_free(&m->map);
    free(m->resource_dir);
    free(m);
}

double hg_model_time(const hg_model *m) { return m->rt.t; }

/* ------------------------------------------------------------------ right-hand side, roots */

static void inputs_at(const hg_runtime *rt, double t, hg_dyn_inputs *u)
{
    double dt = t - rt->t_u0;
    u->T_s = rt->u0.T_s + rt->du.T_s * dt;
    u->T_w = rt->u0.T_w + rt->du.T_w * dt;
    u->T_bath = rt->u0.T_bath + rt->du.T_bath * dt;
    u->w_set = rt->u0.w_set + rt->du.w_set * dt;
}

static int rhs(double t, const double *y, double *ydot, void *user)
{
    hg_model *m = user;
    hg_dyn_inputs u;
    hg_dyn_eval ev;
    inputs_at(&m->rt, t, &u);
    hg_dyn_evaluate(&m->p, &u, m->rt.mode, y, 0, m->rt.T_c_warm, &ev);
    hg_dyn_derivatives(&m->p, &u, y, &ev, ydot);
    return 0;
}

/* Contact changes are events only for the exact dead zone of the varying mesh. */
static int exact_backlash(const hg_dyn_params *p)
{
    return p->mesh == HG_MESH_MODEL_VARYING && p->backlash.eps == 0.0;
}

static int roots(double t, const double *y, double *g, void *user)
{
    hg_model *m = user;
    (void)t;
    int events = exact_backlash(&m->p);
    g[0] = events ? y[HG_Y_X] - m->p.backlash.b : 1.0;
    g[1] = events ? y[HG_Y_X] + m->p.backlash.b : 1.0;
    g[2] = y[HG_Y_PHI_P] - (m->rt.win_phi0 + m->window_angle);
    g[3] = y[HG_Y_PHI_P] - (m->rt.win_phi0 - m->window_angle);
    return 0;
}

int hg_model_make_solver(hg_model *m, const hg_vars *v, char *err, size_t errlen)
{
    hg_solver_options opt;
    opt.method = v->solver == HG_SOLVER_CVODE_ADAMS ? HG_METHOD_ADAMS
                 : v->solver == HG_SOLVER_NEWMARK    ? HG_METHOD_NEWMARK
                                                     : HG_METHOD_BDF;
    opt.rtol = m->rtol;
    opt.atol = m->atol;
    opt.max_steps = 500000;
    hg_solver_free(m->solver);
    m->solver = hg_solver_new(HG_NY, N_ROOTS, rhs, roots, m, &opt, err, errlen);
    return m->solver ? 0 : -1;
}

/* ------------------------------------------------------------------ events */

static void backlash_event(hg_model *m, const int *dir)
{
    hg_runtime *rt = &m->rt;
    int old = rt->mode;
    /* dir[0]: root of x - b, dir[1]: root of x + b; +1 upwards, -1 downwards */
    rt->mode = dir[0] > 0 ? HG_MODE_DRIVE : dir[1] < 0 ? HG_MODE_BACK : HG_MODE_FREE;
    /* the root lies on the boundary: put x exactly there so the restart does not see it again */
    rt->y[HG_Y_X] = dir[0] != 0 ? m->p.backlash.b : -m->p.backlash.b;
    if (rt->mode != old) {
        rt->n_impacts++;
        hg_model_log(m, "logEvents", "t = %.9f s: mesh contact %s -> %s", rt->t,
              old > 0 ? "drive" : old < 0 ? "back" : "free",
              rt->mode > 0 ? "drive" : rt->mode < 0 ? "back" : "free");
    }
}

static void window_event(hg_model *m)
{
    hg_runtime *rt = &m->rt;
    double T = rt->t - rt->win_t0;
    if (T > 0.0) {
        rt->eta_cycle = sqrt((rt->y[HG_Y_ETA2] - rt->win_eta2_0) / T);
        rt->P_loss_cycle = (rt->y[HG_Y_E_FRIC] - rt->win_efric_0) / T;
    }
    rt->windows++;
    hg_model_log(m, "logEvents", "t = %.6f s: averaging window %d complete: eta_cycle = %.6f, "
          "P_loss_cycle = %.4g W", rt->t, rt->windows, rt->eta_cycle, rt->P_loss_cycle);
    rt->win_phi0 = rt->y[HG_Y_PHI_P];
    rt->win_t0 = rt->t;
    rt->win_eta2_0 = rt->y[HG_Y_ETA2];
    rt->win_efric_0 = rt->y[HG_Y_E_FRIC];
}

/* Keep the pinion angle small (rtol acts on |phi_p|) by whole load-share periods. */
static void wrap_angle(hg_model *m)
{
    hg_runtime *rt = &m->rt;
    double period = 3.0 * TWO_PI / m->gear.N_p, shift;
    if (fabs(rt->y[HG_Y_PHI_P]) < WRAP_PERIODS * period) return;
    shift = period * floor(rt->y[HG_Y_PHI_P] / period);
    rt->y[HG_Y_PHI_P] -= shift;
    rt->win_phi0 -= shift;
    rt->restart = 1;
}

static int inputs_changed(const hg_dyn_inputs *a, const hg_dyn_inputs *b)
{
    return a->T_s != b->T_s || a->T_w != b->T_w || a->T_bath != b->T_bath || a->w_set != b->w_set;
}

/* The step limit of this communication step. Variable-step solvers: the user's max_step, or
 * automatically 1/STEPS_PER_MESH of a mesh period for the compliant meshes (physics 8.8; none for
 * the rigid one). The fixed-step solver: steps_per_mesh_cycle per mesh period, never longer than
 * the user's max_step nor than 1/STEPS_PER_MODE of the period of the highest natural mode, which a
 * fixed step must resolve whatever the speed. */
static double step_limit(const hg_model *m)
{
    double f_mesh = fabs(m->rt.y[HG_Y_W_P]) * m->gear.N_p / TWO_PI, h;
    if (!m->fixed_step && (m->max_step > 0.0 || m->p.mesh == HG_MESH_MODEL_RIGID))
        return m->max_step;
    h = f_mesh > 0.0 ? 1.0 / (m->steps_per_mesh * f_mesh) : MAX_AUTO_STEP;
    h = fmin(h, MAX_AUTO_STEP);
    if (m->fixed_step) {
        h = fmin(h, 1.0 / (STEPS_PER_MODE * m->f_max));
        if (m->max_step > 0.0) h = fmin(h, m->max_step);
    }
    return h;
}

static int begin_step(hg_model *m, const hg_vars *v, const hg_dyn_inputs *du, char *err,
                      size_t errlen)
{
    hg_runtime *rt = &m->rt;
    hg_dyn_inputs u;
    hg_model_inputs(v, &u);
    if (inputs_changed(&u, &rt->u_end) || inputs_changed(du, &rt->du)) rt->restart = 1;
    rt->u0 = u;
    rt->du = *du;
    rt->t_u0 = rt->t;
    wrap_angle(m);
    if (hg_solver_set_max_step(m->solver, step_limit(m), err, errlen)) return -1;
    if (rt->restart && hg_solver_restart(m->solver, rt->t, rt->y, err, errlen)) return -1;
    rt->restart = 0;
    return 0;
}

/* The map holds its edge values beyond its grid: say so once per run. */
static void check_map_range(hg_model *m)
{
    hg_runtime *rt = &m->rt;
    const hg_effmap *map = m->p.map;
    double w = rt->y[HG_Y_W_P], T = rt->u_end.T_s, K = rt->u_end.T_bath;
    if (!map || rt->map_warned || hg_effmap_inside(map, w, T, K)) return;
    rt->map_warned = 1;
    hg_model_log(m, "logStatusWarning",
                 "t = %.6g s: operating point %.0f rpm, T_s = %.1f N.m, T_bath = %.1f degC lies "
                 "outside the efficiency map (%.0f-%.0f rpm, %.0f-%.0f N.m, %.0f-%.0f degC): the "
                 "map holds its edge values there",
                 rt->t, fabs(w) * 30.0 / 3.141592653589793, T, K - 273.15,
                 map->w[0] * 30.0 / 3.141592653589793, map->w[map->n_w - 1] * 30.0 / 3.141592653589793,
                 map->T[0], map->T[map->n_T - 1], map->K[0] - 273.15, map->K[map->n_K - 1] - 273.15);
}

int hg_model_step(hg_model *m, hg_vars *v, const hg_dyn_inputs *du, double h, char *err,
                  size_t errlen)
{
    hg_runtime *rt = &m->rt;
    double t_end = rt->t + h;
    int events = 0, dir[N_ROOTS];
    if (begin_step(m, v, du, err, errlen)) return -1;
    while (rt->t < t_end) {
        hg_advance_result r = hg_solver_advance(m->solver, t_end, &rt->t, rt->y, dir, err, errlen);
        if (r == HG_ADVANCE_FAILED) return -1;
        if (r == HG_ADVANCE_REACHED) break;
        if (++events > MAX_EVENTS_PER_STEP) {
            snprintf(err, errlen, "more than %d contact events in one step at t = %.9g s "
                     "(chattering); reduce the step or use a smaller rtol", MAX_EVENTS_PER_STEP,
                     rt->t);
            return -1;
        }
        if (dir[2] || dir[3]) window_event(m);
        /* a contact change alters the right-hand side: restart; a window end changes nothing
         * the integrator sees but its root function, which it re-evaluates at the root */
        if ((dir[0] || dir[1]) &&
            (backlash_event(m, dir), hg_solver_restart(m->solver, rt->t, rt->y, err, errlen)))
            return -1;
    }
    rt->t = t_end;
    inputs_at(rt, t_end, &rt->u_end);
    check_map_range(m);
    hg_model_write_outputs(m, v);
    return 0;
}

/* ------------------------------------------------------------------ outputs */

static void write_pairs(hg_vars *v, const hg_dyn_eval *ev)
{
    int k;
    for (k = 0; k < HG_MAX_PAIRS; k++) {
        const hg_pair_friction *f = &ev->pair[k];
        v->pair_W[k] = ev->W_pair[k];
        v->pair_mu[k] = f->mu;
        v->pair_F_v[k] = f->F_v;
        v->pair_F_b[k] = f->F_b;
        v->pair_h_c[k] = f->h_c;
        v->pair_lambda[k] = f->lambda;
        v->pair_T_c[k] = f->T_c;
        v->pair_u_e[k] = f->u_e;
        v->pair_V_s[k] = f->V_s;
        v->pair_R_e[k] = f->R_e;
        v->pair_R_s[k] = f->R_s;
        v->pair_p_h[k] = f->p_h;
        v->pair_g_V[k] = f->g_V;
        v->pair_g_E[k] = f->g_E;
    }
}

static void solver_stats(const hg_model *m, hg_vars *v)
{
    long steps = 0, evals = 0;
    if (m->solver) hg_solver_stats(m->solver, &steps, &evals);
    v->solver_steps = steps > 2147483647L ? 2147483647 : (int)steps;
    v->rhs_evals = evals > 2147483647L ? 2147483647 : (int)evals;
}

void hg_model_write_outputs(hg_model *m, hg_vars *v)
{
    const hg_runtime *rt = &m->rt;
    const double *y = rt->y;
    hg_dyn_inputs u;
    hg_dyn_eval ev;
    double warm[HG_MAX_PAIRS];
    memcpy(warm, rt->T_c_warm, sizeof warm); /* outputs must not perturb the integration */
    inputs_at(rt, rt->t, &u);
    hg_dyn_evaluate(&m->p, &u, rt->mode, y, 1, warm, &ev);
    v->w_s = y[HG_Y_W_S];
    v->w_p = y[HG_Y_W_P];
    v->w_g = y[HG_Y_W_G];
    v->w_w = y[HG_Y_W_W];
    v->DTE = y[HG_Y_X];
    v->W_t = ev.W_t;
    v->T_fp = ev.T_fp;
    v->T_fg = ev.T_fg;
    v->P_loss = ev.P_loss;
    v->P_in = ev.P_in;
    v->eta = ev.eta;
    v->eta_cycle = rt->eta_cycle;
    v->P_loss_cycle = rt->P_loss_cycle;
    v->T_w_out = ev.T_w;
    v->k_m = ev.mesh.k_m;
    v->contact = exact_backlash(&m->p) ? rt->mode
                 : m->p.mesh == HG_MESH_MODEL_VARYING ? hg_backlash_mode(y[HG_Y_X], m->p.backlash.b)
                 : ev.W_t >= 0.0 ? HG_MODE_DRIVE : HG_MODE_BACK;
    v->n_impacts = rt->n_impacts;
    solver_stats(m, v);
    v->E_in = y[HG_Y_E_IN];
    v->E_out = y[HG_Y_E_OUT];
    v->E_friction = y[HG_Y_E_FRIC];
    v->E_damping = y[HG_Y_E_DAMP];
    v->E_excitation = y[HG_Y_E_EXC];
    v->E_stored = hg_dyn_stored_energy(&m->p, y, &ev);
    write_pairs(v, &ev);
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
        snprintf(err, errlen, "cannot restore a state into a model that is not set up");
        return -1;
    }
    m->rt = *in;
    m->rt.restart = 1;
    hg_model_write_outputs(m, v);
    return 0;
}
