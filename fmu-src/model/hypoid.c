/* The HypoidGearPair model object: see hypoid.h. */
#include "model/hypoid.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "model/modal.h"
#include "solver/solver.h"

#define TWO_PI 6.283185307179586
#define N_ROOTS 4             /* x - b, x + b, window end forwards, window end backwards */
#define WRAP_PERIODS 64       /* wrap the pinion angle after this many load-share periods */
#define MAX_EVENTS_PER_STEP 100000
#define GOVERNOR_ZETA 0.7     /* damping ratio of the speed governor's closed loop */
#define STEPS_PER_MESH 30     /* CVODE's automatic max_step: 1/30 of a mesh period (physics 8.8) */
#define MAX_AUTO_STEP 1e-3    /* [s] */

struct hg_model {
    char *resource_dir;
    hg_log_fn log;
    void *log_ctx;
    hg_gearset gear;
    hg_lubricant lub;
    hg_effmap map; /* friction_model = map only */
    hg_dyn_params p;
    hg_solver *solver;
    double atol[HG_NY];
    double rtol;
    double max_step;      /* user's max_step, 0 = automatic */
    int steps_per_mesh;   /* per mesh cycle: the fixed step (newmark) or the automatic max_step */
    int fixed_step;       /* the solver takes fixed steps (newmark) */
    double window_angle; /* pinion angle of one averaging window [rad] */
    hg_runtime rt;
};

#if defined(__GNUC__)
__attribute__((format(printf, 3, 4)))
#endif
static void logf_(hg_model *m, const char *category, const char *fmt, ...)
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

/* ------------------------------------------------------------------ set-up */

/* user_file if set (absolute, or relative to the resources), else resources/<builtin>. */
static int resolve_path(const hg_model *m, const char *user_file, const char *builtin, char *path,
                        size_t len, char *err, size_t errlen)
{
    int n;
    if (user_file && *user_file)
        n = user_file[0] == '/' ? snprintf(path, len, "%s", user_file)
                                : snprintf(path, len, "%s/%s", m->resource_dir, user_file);
    else
        n = snprintf(path, len, "%s/%s", m->resource_dir, builtin);
    if (n < 0 || (size_t)n >= len) {
        snprintf(err, errlen, "data file path is too long: '%.80s...'", path);
        return -1;
    }
    return 0;
}

static int load_gearset(hg_model *m, const hg_vars *v, char *err, size_t errlen)
{
    char path[4096], builtin[64], why[HG_ERRLEN];
    snprintf(builtin, sizeof builtin, "gearsets/gearset%d.txt", v->gear_set);
    if (resolve_path(m, v->gear_set_file, builtin, path, sizeof path, err, errlen)) return -1;
    if (hg_gearset_load(path, &m->gear, why, sizeof why)) {
        snprintf(err, errlen, "%s = '%s': %s", v->gear_set_file[0] ? "gear_set_file" : "gear_set",
                 v->gear_set_file[0] ? v->gear_set_file : builtin, why);
        return -1;
    }
    hg_series_scale(&m->gear.k_m, v->k_m_scale);
    hg_series_scale(&m->gear.e_0, v->e_0_scale);
    return 0;
}

static int load_lubricant(hg_model *m, const hg_vars *v, char *err, size_t errlen)
{
    static const char *const builtin[] = {"lubricants/OS265962.txt", "lubricants/OS265963.txt"};
    const char *name = builtin[v->lubricant == 2];
    char path[4096], why[HG_ERRLEN];
    if (resolve_path(m, v->lubricant_file, name, path, sizeof path, err, errlen)) return -1;
    if (hg_lubricant_load(path, &m->lub, why, sizeof why)) {
        snprintf(err, errlen, "%s = '%s': %s", v->lubricant_file[0] ? "lubricant_file" : "lubricant",
                 v->lubricant_file[0] ? v->lubricant_file : name, why);
        return -1;
    }
    return 0;
}

/* The map level: a rigid gear whose efficiency comes from a map of the full model. */
static int load_map(hg_model *m, const hg_vars *v, char *err, size_t errlen)
{
    char path[4096], builtin[96], why[HG_ERRLEN];
    hg_effmap_free(&m->map);
    m->p.map = NULL;
    if (v->friction_model != HG_FRICTION_MODEL_MAP) return 0;
    if (v->mesh_model != HG_MESH_MODEL_RIGID) {
        snprintf(err, errlen, "friction_model = map describes the whole gear's losses: it needs "
                 "mesh_model = rigid (mesh_model is %d)", v->mesh_model);
        return -1;
    }
    if (!v->efficiency_map_file[0] && v->lubricant_file[0]) {
        snprintf(err, errlen, "friction_model = map with lubricant_file = '%s' needs an "
                 "efficiency_map_file made for that lubricant (hypoid effmap)", v->lubricant_file);
        return -1;
    }
    snprintf(builtin, sizeof builtin, "maps/gearset%d_%s.txt", v->gear_set,
             v->lubricant == 2 ? "OS265963" : "OS265962");
    if (resolve_path(m, v->efficiency_map_file, builtin, path, sizeof path, err, errlen)) return -1;
    if (hg_effmap_load(path, &m->map, why, sizeof why)) {
        snprintf(err, errlen, "%s = '%s': %s",
                 v->efficiency_map_file[0] ? "efficiency_map_file" : "built-in efficiency map",
                 v->efficiency_map_file[0] ? v->efficiency_map_file : builtin, why);
        return -1;
    }
    m->p.map = &m->map;
    return 0;
}

static void ehl_params(hg_model *m, const hg_vars *v)
{
    hg_ehl_params *e = &m->p.friction.ehl;
    hg_ehl_params_default(e);
    e->E = v->E;
    e->nu = v->nu;
    e->k_s = v->k_s;
    e->rho_s = v->rho_s;
    e->c_s = v->c_s;
    e->tau_0 = v->tau_0;
    e->varsigma_a = v->varsigma_a;
    e->sigma_s = v->sigma_s;
    e->eta_beta_sigma = v->eta_beta_sigma;
    e->sigma_over_beta = v->sigma_over_beta;
    e->T_inlet_rise = v->T_inlet_rise;
    e->Lambda_cap = v->Lambda_cap;
    e->k_f_override = v->k_f;
    e->hertz = v->hertz_model == HG_HERTZ_MODEL_APPROX ? HG_HERTZ_APPROX : HG_HERTZ_EXACT;
    e->roelands_Z = v->roelands_z == HG_ROELANDS_Z_EXACT ? HG_Z_EXACT : HG_Z_SIMPLE;
    e->shear_pressure = v->shear_pressure == HG_SHEAR_PRESSURE_MAX ? HG_SHEAR_P_MAX : HG_SHEAR_P_MEAN;
    e->thermal = v->friction_model == HG_FRICTION_MODEL_EHL_THERMAL;
    m->p.friction.lub = &m->lub;
}

static int damping(hg_model *m, hg_vars *v, char *err, size_t errlen)
{
    hg_modal_input in;
    hg_modes modes;
    hg_dampers d;
    double zeta[3];
    char why[HG_ERRLEN];
    in.I_s = v->I_s;
    in.I_p = v->I_p;
    in.I_g = v->I_g;
    in.I_w = v->I_w;
    in.k_t1 = v->k_t1;
    in.k_t2 = v->k_t2;
    in.k_m = m->p.k_m0;
    in.R_p = m->p.R_p0;
    in.R_g = m->p.R_p0 * m->p.ratio;
    zeta[0] = v->zeta_2;
    zeta[1] = v->zeta_3;
    zeta[2] = v->zeta_4;
    if (hg_modal_analysis(&in, &modes, why, sizeof why) ||
        hg_modal_dampers(&in, zeta, &d, why, sizeof why)) {
        snprintf(err, errlen, "modal damping: %s", why);
        return -1;
    }
    if (d.used_fallback)
        logf_(m, "logStatusWarning",
              "modal damping ratios (%g, %g, %g) cannot all be met with non-negative dampers; "
              "least-squares fallback achieves (%.4f, %.4f, %.4f)",
              zeta[0], zeta[1], zeta[2], d.zeta_achieved[0], d.zeta_achieved[1],
              d.zeta_achieved[2]);
    m->p.c_t1 = v->c_t1 = d.c_t1;
    m->p.c_m = v->c_m = d.c;
    m->p.c_t2 = v->c_t2 = d.c_t2;
    v->f_2 = modes.f_hz[1];
    v->f_3 = modes.f_hz[2];
    v->f_4 = modes.f_hz[3];
    return 0;
}

static void dynamics_params(hg_model *m, const hg_vars *v)
{
    hg_dyn_params *p = &m->p;
    double J, w_n;
    p->I_s = v->I_s;
    p->I_p = v->I_p;
    p->I_g = v->I_g;
    p->I_w = v->I_w;
    p->k_t1 = v->k_t1;
    p->k_t2 = v->k_t2;
    p->mesh = v->mesh_model;
    p->backlash.b = p->mesh == HG_MESH_MODEL_VARYING ? v->b : 0.0;
    p->backlash.eps = p->mesh == HG_MESH_MODEL_VARYING && v->backlash_model == HG_BACKLASH_MODEL_SMOOTHED
                          ? v->backlash_smoothing
                          : 0.0;
    p->k_m0 = m->gear.k_m.mean;
    p->R_p0 = m->gear.R_p.mean;
    p->ratio = (double)m->gear.N_g / m->gear.N_p;
    p->gear = &m->gear;
    p->friction.model = v->friction_model;
    p->friction.mu_const = v->mu_const;
    p->speed_governor = v->load_mode == HG_LOAD_MODE_SPEED;
    /* PI governor on the wheel speed, tuned on the rigid-body inertia seen at the wheel */
    J = (v->I_s + v->I_p) * p->ratio * p->ratio + v->I_g + v->I_w;
    w_n = TWO_PI * v->governor_bandwidth;
    p->K_p = 2.0 * GOVERNOR_ZETA * w_n * J;
    p->K_i = w_n * w_n * J;
}

/* Absolute tolerances: atol is on the DTE [m]; angles scale by 1/R, speeds by omega_4/R. */
static void tolerances(hg_model *m, const hg_vars *v)
{
    double a = v->atol, R_p = m->p.R_p0, R_g = R_p * m->p.ratio, w4 = TWO_PI * v->f_4;
    double E = a * m->p.k_m0 * 1e-4; /* energy: a force of k_m * 0.1 mm through a */
    double *t = m->atol;
    t[HG_Y_TWIST1] = t[HG_Y_PHI_P] = a / R_p;
    t[HG_Y_TWIST2] = t[HG_Y_GOV] = a / R_g;
    t[HG_Y_X] = a;
    t[HG_Y_W_S] = t[HG_Y_W_P] = a * w4 / R_p;
    t[HG_Y_W_G] = t[HG_Y_W_W] = a * w4 / R_g;
    t[HG_Y_E_IN] = t[HG_Y_E_OUT] = t[HG_Y_E_FRIC] = t[HG_Y_E_DAMP] = t[HG_Y_E_EXC] = E;
    t[HG_Y_ETA2] = 1e-9;
    m->rtol = v->rtol;
    m->fixed_step = v->solver == HG_SOLVER_NEWMARK;
    m->max_step = m->fixed_step ? 0.0 : v->max_step;
    m->steps_per_mesh = m->fixed_step ? v->steps_per_mesh_cycle : STEPS_PER_MESH;
}

static void inputs_of(const hg_vars *v, hg_dyn_inputs *u)
{
    u->T_s = v->T_s;
    u->T_w = v->T_w;
    u->T_bath = v->T_bath;
    u->w_set = v->w_set;
}

/* Static equilibrium at speed (physics 8.6): shafts twisted by their torques, mesh deflected by
 * W_t / k_m beyond the backlash on the loaded flank. */
static void initial_state(hg_model *m, const hg_vars *v, double t0)
{
    hg_runtime *rt = &m->rt;
    hg_mesh_point mesh;
    double *y = rt->y, T_w = v->load_mode == HG_LOAD_MODE_SPEED ? v->T_s * m->p.ratio : v->T_w;
    int k;
    memset(rt, 0, sizeof *rt);
    rt->t = rt->t_u0 = t0;
    inputs_of(v, &rt->u0);
    rt->u_end = rt->u0;
    if (m->p.mesh == HG_MESH_MODEL_VARYING)
        hg_gearset_mesh(&m->gear, 0.0, &mesh);
    else {
        mesh.k_m = m->p.k_m0;
        mesh.R_p = m->p.R_p0;
    }
    y[HG_Y_TWIST1] = v->T_s / v->k_t1;
    y[HG_Y_TWIST2] = T_w / v->k_t2;
    if (m->p.mesh != HG_MESH_MODEL_RIGID)
        y[HG_Y_X] = v->T_s / (mesh.R_p * mesh.k_m) +
                    (v->T_s > 0 ? m->p.backlash.b : v->T_s < 0 ? -m->p.backlash.b : 0.0);
    y[HG_Y_W_S] = y[HG_Y_W_P] = v->w_p0;
    y[HG_Y_W_G] = y[HG_Y_W_W] = v->w_p0 / m->p.ratio;
    rt->mode = hg_backlash_mode(y[HG_Y_X], m->p.backlash.b);
    for (k = 0; k < HG_MAX_PAIRS; k++) rt->T_c_warm[k] = -1.0;
    rt->eta_cycle = 1.0;
    rt->restart = 1;
}

static int rhs(double t, const double *y, double *ydot, void *user);
static int roots(double t, const double *y, double *g, void *user);
static void write_outputs(hg_model *m, hg_vars *v);

static int make_solver(hg_model *m, const hg_vars *v, char *err, size_t errlen)
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

int hg_model_setup(hg_model *m, hg_vars *v, double t0, char *err, size_t errlen)
{
    if (load_gearset(m, v, err, errlen) || load_lubricant(m, v, err, errlen)) return -1;
    dynamics_params(m, v);
    ehl_params(m, v);
    if (load_map(m, v, err, errlen)) return -1;
    if (damping(m, v, err, errlen)) return -1;
    v->R_p0 = m->p.R_p0;
    v->k_m0 = m->p.k_m0;
    v->ratio = m->p.ratio;
    v->N_p = m->gear.N_p;
    v->N_g = m->gear.N_g;
    tolerances(m, v);
    m->window_angle = v->n_avg_cycles * TWO_PI / m->gear.N_p;
    initial_state(m, v, t0);
    if (make_solver(m, v, err, errlen)) return -1;
    logf_(m, "logEvents",
          "set-up: %s, i = %.4f, k_m0 = %.4g N/m, R_p0 = %.3f mm, modes %.1f / %.1f / %.1f Hz, "
          "dampers c_t1 = %.4g, c = %.4g, c_t2 = %.4g; eta_cycle holds 1 until the first window "
          "of %d mesh cycles completes",
          m->gear.name, m->p.ratio, m->p.k_m0, 1e3 * m->p.R_p0, v->f_2, v->f_3, v->f_4,
          m->p.c_t1, m->p.c_m, m->p.c_t2, v->n_avg_cycles);
    write_outputs(m, v);
    return 0;
}

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
        logf_(m, "logEvents", "t = %.9f s: mesh contact %s -> %s", rt->t,
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
    logf_(m, "logEvents", "t = %.6f s: averaging window %d complete: eta_cycle = %.6f, "
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

static int begin_step(hg_model *m, const hg_vars *v, const hg_dyn_inputs *du, char *err,
                      size_t errlen)
{
    hg_runtime *rt = &m->rt;
    double h_max = m->max_step, f_mesh;
    hg_dyn_inputs u;
    inputs_of(v, &u);
    if (inputs_changed(&u, &rt->u_end) || inputs_changed(du, &rt->du)) rt->restart = 1;
    rt->u0 = u;
    rt->du = *du;
    rt->t_u0 = rt->t;
    wrap_angle(m);
    /* automatic: resolve the mesh cycle, unless there is no mesh dynamics and the step is free */
    if (h_max <= 0.0 && (m->fixed_step || m->p.mesh != HG_MESH_MODEL_RIGID)) {
        f_mesh = fabs(rt->y[HG_Y_W_P]) * m->gear.N_p / TWO_PI;
        h_max = f_mesh > 0.0 ? 1.0 / (m->steps_per_mesh * f_mesh) : MAX_AUTO_STEP;
        if (h_max > MAX_AUTO_STEP) h_max = MAX_AUTO_STEP;
    }
    if (hg_solver_set_max_step(m->solver, h_max, err, errlen)) return -1;
    if (rt->restart && hg_solver_restart(m->solver, rt->t, rt->y, err, errlen)) return -1;
    rt->restart = 0;
    return 0;
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
        if (dir[0] || dir[1]) backlash_event(m, dir);
        if (dir[2] || dir[3]) window_event(m);
        if (hg_solver_restart(m->solver, rt->t, rt->y, err, errlen)) return -1;
    }
    rt->t = t_end;
    inputs_at(rt, t_end, &rt->u_end);
    write_outputs(m, v);
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

static void write_outputs(hg_model *m, hg_vars *v)
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
    write_outputs(m, v);
    return 0;
}
