/* Stepping helpers of the model object: see stepping.h. */
#include "model/stepping.h"

#include <math.h>
#include <string.h>

#include "io/constants.h"

#define WRAP_PERIODS 1024     /* wrap the pinion angle after this many load-share periods */
#define MAX_AUTO_STEP 1e-3    /* [s] */
#define STEPS_PER_MODE 8      /* fixed steps per period of the highest natural mode, at least */
#define ERK_STEPS_PER_MODE 3  /* the explicit method's steps per period of the highest natural
                                 mode, at least (hg_stepping_step_limit) */
#define TILE_SLACK 1e-9       /* a communication step within this fraction of a whole number of
                                 the explicit method's longest steps takes that number */
#define HOLD_STEPS 4          /* steps with held inputs before the integrator may pass a step's
                                 end (hg_stepping_may_pass) */

#define START_PASSES 4 /* fixed-point passes of the start's load on its own friction */

/* Spring states carrying the mesh force W_t: the mesh deflected by W_t / k_m (by the inverse of
 * a layered file's force law) beyond the backlash
 * on the loaded flank, the output shaft by what the gear passes on (R_g W_t plus the gear's loss
 * torques T_g); under load_mode = speed the governor's integral holds the torque that differs
 * from T_s i, so that T_w balances the output shaft. */
static void set_springs(double *y, const hg_dyn_params *p, const hg_vars *v,
                        const hg_mesh_point *mesh, const hg_mesh_law *law, double W_t, double T_g)
{
    double T_2 = W_t * mesh->R_p * p->ratio + T_g;
    double a = law ? copysign(hg_mesh_law_approach(law, fabs(W_t)), W_t) : W_t / mesh->k_m;
    if (p->mesh != HG_MESH_MODEL_RIGID)
        y[HG_Y_X] = a + (W_t > 0 ? p->backlash.b : W_t < 0 ? -p->backlash.b : 0.0);
    if (p->speed_governor) {
        y[HG_Y_TWIST2] = T_2 / v->k_t2;
        y[HG_Y_GOV] = p->K_i > 0.0 ? (T_2 - v->T_s * p->ratio) / p->K_i : 0.0;
    } else if (p->half_shaft) { /* the half-shaft carries it on: no input enters the start */
        y[HG_Y_TWIST2] = T_2 / v->k_t2;
        y[HG_Y_TWIST_HS] = T_2 / p->k_hs;
    } else {
        y[HG_Y_TWIST2] = v->T_w / v->k_t2;
    }
}

/* Static equilibrium at speed (docs/physics.md §8.6): the input shaft twisted by T_s, the pinion
 * balanced by the mesh force and its own loss torques, R_p W_t = T_s + T_p (T_p = T_fp plus its
 * bearings and seals), and the output side by what the gear passes on. The losses depend on the
 * load: START_PASSES fixed-point passes from the frictionless W_t = T_s / R_p (each changes W_t
 * by about mu times the last change). */
void hg_stepping_start(hg_runtime *rt, const hg_setup *s, const hg_vars *v, double t0)
{
    const hg_dyn_params *p = &s->p;
    hg_mesh_point mesh;
    hg_law_levels lv;
    hg_mesh_law law;
    hg_dyn_eval ev;
    double *y = rt->y, W_t, T_g = 0.0;
    int k, flank = v->T_s < 0.0 ? HG_FLANK_COAST : HG_FLANK_DRIVE;
    memset(rt, 0, sizeof *rt);
    rt->t = rt->t_u0 = t0;
    rt->w_wheel0 = v->w_p0 / p->ratio;
    hg_vars_inputs(v, &rt->u0);
    hg_stepping_wheel_input(rt, s, &rt->u0, &rt->du);
    rt->u_end = rt->u0;
    if (hg_dyn_loaded_law(p)) hg_mesh_law_of_series(&s->gear, flank, 0.0, &lv, &law);
    if (p->mesh == HG_MESH_MODEL_VARYING)
        hg_gearset_mesh(&s->gear, flank, fabs(v->T_s), 0.0, &mesh);
    else {
        mesh.k_m = p->k_m0;
        mesh.R_p = p->R_p0;
    }
    y[HG_Y_TWIST1] = hg_dyn_quasi_static_input(p) ? 0.0 : v->T_s / v->k_t1;
    y[HG_Y_W_S] = y[HG_Y_W_P] = v->w_p0;
    y[HG_Y_W_G] = y[HG_Y_W_W] = v->w_p0 / p->ratio;
    y[HG_Y_T_OIL] = v->T_oil0;
    y[HG_Y_T_KM] = fabs(v->T_s);
    for (k = 0; k < HG_MAX_PAIRS; k++) rt->T_c_warm[k] = -1.0;
    W_t = v->T_s / mesh.R_p;
    for (k = 0; k <= START_PASSES; k++) {
        set_springs(y, p, v, &mesh, hg_dyn_loaded_law(p) ? &law : NULL, W_t, T_g);
        rt->mode = hg_backlash_mode(y[HG_Y_X], p->backlash.b);
        if (k == START_PASSES) break;
        hg_dyn_evaluate(p, &rt->u0, rt->mode, y, 0, rt->T_c_warm, &ev);
        W_t = (v->T_s + ev.T_fp + ev.axle.T_p) / mesh.R_p;
        T_g = ev.T_fg + ev.axle.T_g;
    }
    rt->eta_cycle = rt->eta_axle_cycle = 1.0;
    rt->restart = 1;
}

void hg_stepping_wheel_input(hg_runtime *rt, const hg_setup *s, hg_inputs *u, hg_inputs *du)
{
    double h_before = rt->t - rt->t_u0; /* the step that just ended (0 before the first) */
    if (!s->p.half_shaft) return;
    if (!rt->wheel_given && u->w_wheel != 0.0) rt->wheel_given = 1;
    if (!rt->wheel_given) u->w_wheel = rt->w_wheel0;
    if (du->w_wheel == 0.0 && h_before > 0.0)
        du->w_wheel = (u->w_wheel - rt->w_wheel_last) / h_before;
    rt->w_wheel_last = u->w_wheel;
}

void hg_stepping_wheel_correct(hg_runtime *rt, const hg_setup *s, hg_inputs *u)
{
    const hg_dyn_params *p = &s->p;
    double h_before = rt->t - rt->t_u0; /* the step that just ended (0 before the first) */
    if (!p->half_shaft) return;
    if (h_before > 0.0) rt->imp_given += rt->T_wheel_given * h_before;
    /* before the first step T_wheel is the half-shaft's torque at the start, T_w_out */
    rt->T_wheel_given = hg_stepping_wheel_torque(
        rt, p->k_hs * rt->y[HG_Y_TWIST_HS] + p->c_hs * (rt->y[HG_Y_W_W] - rt->u0.w_wheel));
    if (s->I_vehicle > 0.0 && (rt->wheel_given || u->w_wheel != 0.0))
        u->w_wheel -= (rt->imp_given - rt->y[HG_Y_IMP_W]) / s->I_vehicle;
}

double hg_stepping_wheel_torque(const hg_runtime *rt, double T_w_now)
{
    double h = rt->t - rt->t_u0, mean;
    if (!(h > 0.0)) return T_w_now;
    mean = (rt->y[HG_Y_IMP_W] - rt->imp_w0) / h;
    if (!(rt->h_last > 0.0)) return mean;
    return mean + (mean - rt->T_w_mean_last) * 2.0 * h / (h + rt->h_last);
}

void hg_stepping_inputs_at(const hg_runtime *rt, double t, hg_inputs *u)
{
    hg_inputs_at(&rt->u0, &rt->du, t - rt->t_u0, u);
}

/* Bitwise: hg_inputs holds only (finite) doubles; a -0 for a 0 counts as a change. */
static int inputs_changed(const hg_inputs *a, const hg_inputs *b)
{
    return memcmp(a, b, sizeof *a) != 0;
}

hg_input_change hg_stepping_change(const hg_runtime *rt, const hg_inputs *u,
                                   const hg_inputs *du)
{
    if (inputs_changed(u, &rt->u_end)) return HG_INPUTS_JUMP;
    return inputs_changed(du, &rt->du) ? HG_INPUTS_KINK : HG_INPUTS_SAME;
}

int hg_stepping_jump_small(const hg_runtime *rt, const hg_setup *s, const double *f_old,
                           const double *f_new)
{
    double sum = 0.0;
    int k;
    for (k = 0; k < s->n_active; k++) {
        double e = rt->h_int * (f_new[k] - f_old[k]) / (s->rtol * fabs(rt->y[k]) + s->atol[k]);
        sum += e * e;
    }
    return sqrt(sum / s->n_active) <= 1.0;
}

int hg_stepping_may_pass(const hg_runtime *rt)
{
    hg_inputs zero;
    memset(&zero, 0, sizeof zero);
    return rt->held >= HOLD_STEPS && !inputs_changed(&rt->du, &zero);
}

/* Keep the pinion angle small (rtol acts on |phi_p|) by whole load-share periods. */
static double load_share_period(const hg_setup *s) { return 3.0 * HG_TWO_PI / s->gear.N_p; }

int hg_stepping_wrap_due(const hg_runtime *rt, const hg_setup *s)
{
    return fabs(rt->y[HG_Y_PHI_P]) >= WRAP_PERIODS * load_share_period(s);
}

void hg_stepping_wrap(hg_runtime *rt, const hg_setup *s)
{
    double period = load_share_period(s), shift;
    if (!hg_stepping_wrap_due(rt, s)) return;
    shift = period * floor(rt->y[HG_Y_PHI_P] / period);
    rt->y[HG_Y_PHI_P] -= shift;
    rt->win_phi0 -= shift;
    rt->restart = 1;
}

void hg_stepping_begin(hg_runtime *rt, const hg_setup *s, const hg_inputs *u,
                       const hg_inputs *du, hg_input_change change)
{
    rt->held = change != HG_INPUTS_SAME ? 0 : rt->held < HOLD_STEPS ? rt->held + 1 : HOLD_STEPS;
    rt->u0 = *u;
    rt->du = *du;
    if (rt->t > rt->t_u0) { /* a step ended here: its mean wheel-end torque */
        rt->h_last = rt->t - rt->t_u0;
        rt->T_w_mean_last = (rt->y[HG_Y_IMP_W] - rt->imp_w0) / rt->h_last;
    }
    rt->t_u0 = rt->t;
    rt->imp_w0 = rt->y[HG_Y_IMP_W];
    hg_stepping_wrap(rt, s);
}

/* Variable-step solvers: the user's max_step, or automatically 1/steps_per_mesh of a mesh period
 * for the compliant meshes with CVODE (docs/physics.md §8.8; none for the rigid one). arkode_erk:
 * never longer than 1/ERK_STEPS_PER_MODE of the period of the highest natural mode (nor than the
 * user's max_step). Beyond it the method's error estimate of that mode's residue, kept near the
 * tolerance by the integrator's own errors, drives the step size, and the steps then follow the
 * last digits of the inputs: two hosts' runs of one co-simulation differed at the tolerance
 * (docs/model.md, "The explicit method's step limit"). That limit is cut down to the communication
 * step h_comm in equal parts: the fewest steps it allows, where the longest ones and a sliver to
 * the step's end cost a step more (and the controller's recovery from the sliver another). The
 * fixed-step solver:
 * steps_per_mesh_cycle per mesh period, never longer than the user's max_step nor than
 * 1/STEPS_PER_MODE of the period of the highest natural mode, which a fixed step must resolve
 * whatever the speed. */
double hg_stepping_step_limit(const hg_runtime *rt, const hg_setup *s, double h_comm)
{
    double f_mesh = fabs(rt->y[HG_Y_W_P]) * s->gear.N_p / HG_TWO_PI, h;
    if (s->explicit_rk) {
        h = 1.0 / (ERK_STEPS_PER_MODE * s->f_max);
        if (s->max_step > 0.0) h = fmin(h, s->max_step);
        return h_comm > 0.0 ? h_comm / ceil(h_comm / h * (1.0 - TILE_SLACK)) : h; /* equal parts */
    }
    if (!s->fixed_step && (s->max_step > 0.0 || s->p.mesh == HG_MESH_MODEL_RIGID))
        return s->max_step;
    h = f_mesh > 0.0 ? 1.0 / (s->steps_per_mesh * f_mesh) : MAX_AUTO_STEP;
    h = fmin(h, MAX_AUTO_STEP);
    if (s->fixed_step) {
        h = fmin(h, 1.0 / (STEPS_PER_MODE * s->f_max));
        if (s->max_step > 0.0) h = fmin(h, s->max_step);
    }
    return h;
}

int hg_stepping_contact_events(const hg_dyn_params *p)
{
    return p->mesh == HG_MESH_MODEL_VARYING && p->backlash.eps == 0.0;
}

void hg_stepping_roots(const hg_runtime *rt, const hg_setup *s, const double *y, double *g)
{
    int events = hg_stepping_contact_events(&s->p);
    g[0] = events ? y[HG_Y_X] - s->p.backlash.b : 1.0;
    g[1] = events ? y[HG_Y_X] + s->p.backlash.b : 1.0;
    g[2] = y[HG_Y_PHI_P] - (rt->win_phi0 + s->window_angle);
    g[3] = y[HG_Y_PHI_P] - (rt->win_phi0 - s->window_angle);
}

static const char *mode_name(int mode)
{
    return mode > 0 ? "drive" : mode < 0 ? "back" : "free";
}

void hg_stepping_contact_event(hg_runtime *rt, const hg_setup *s, const int *dir,
                               const hg_logger *lg)
{
    int old = rt->mode;
    /* dir[0]: root of x - b, dir[1]: root of x + b; +1 upwards, -1 downwards */
    rt->mode = dir[0] > 0 ? HG_MODE_DRIVE : dir[1] < 0 ? HG_MODE_BACK : HG_MODE_FREE;
    /* the root lies on the boundary: put x exactly there so the restart does not see it again */
    rt->y[HG_Y_X] = dir[0] != 0 ? s->p.backlash.b : -s->p.backlash.b;
    if (rt->mode != old) {
        rt->n_impacts++;
        hg_logf(lg, "logEvents", "t = %.9f s: mesh contact %s -> %s", rt->t, mode_name(old),
                mode_name(rt->mode));
    }
}

/* RMS over a window from the integral of the square; the integral's own error can leave it a
 * hair below zero when the efficiency is 0 throughout (losses with no power entering). */
static double rms_of(double integral, double T)
{
    return sqrt(fmax(integral, 0.0) / T);
}

void hg_stepping_window_event(hg_runtime *rt, const hg_logger *lg)
{
    double T = rt->t - rt->win_t0;
    if (T > 0.0) {
        rt->eta_cycle = rms_of(rt->y[HG_Y_ETA2] - rt->win_eta2_0, T);
        rt->P_loss_cycle = (rt->y[HG_Y_E_FRIC] - rt->win_efric_0) / T;
        rt->eta_axle_cycle = rms_of(rt->y[HG_Y_ETA_AXLE2] - rt->win_eta_axle2_0, T);
    }
    rt->windows++;
    hg_logf(lg, "logEvents", "t = %.6f s: averaging window %d complete: eta_cycle = %.6f, "
            "P_loss_cycle = %.4g W", rt->t, rt->windows, rt->eta_cycle, rt->P_loss_cycle);
    rt->win_phi0 = rt->y[HG_Y_PHI_P];
    rt->win_t0 = rt->t;
    rt->win_eta2_0 = rt->y[HG_Y_ETA2];
    rt->win_efric_0 = rt->y[HG_Y_E_FRIC];
    rt->win_eta_axle2_0 = rt->y[HG_Y_ETA_AXLE2];
}

static double rpm(double w) { return w * 30.0 / HG_PI; }

/* The map holds its edge values beyond its grid: say so once per run. */
static void check_map_range(hg_runtime *rt, const hg_effmap *map, int s_sump,
                            const hg_logger *lg)
{
    double w = rt->y[HG_Y_W_P], T = rt->u_end.T_s;
    double K = s_sump ? rt->y[HG_Y_T_OIL] : rt->u_end.T_bath;
    if (!map || rt->map_warned || hg_effmap_inside(map, w, T, K)) return;
    rt->map_warned = 1;
    hg_logf(lg, "logStatusWarning",
            "t = %.6g s: operating point %.0f rpm, T_s = %.1f N.m, T_oil = %.1f degC lies "
            "outside the efficiency map (%.0f-%.0f rpm, %.0f-%.0f N.m, %.0f-%.0f degC): the "
            "map holds its edge values there",
            rt->t, rpm(fabs(w)), T, K - 273.15, rpm(map->w[0]), rpm(map->w[map->n_w - 1]),
            map->T[0], map->T[map->n_T - 1],
            map->K[0] - 273.15, map->K[map->n_K - 1] - 273.15);
}

void hg_stepping_end(hg_runtime *rt, const hg_setup *s, double t_end, double h,
                     const hg_logger *lg)
{
    rt->t = t_end;
    hg_inputs_at(&rt->u0, &rt->du, h, &rt->u_end); /* du h, not du (t_end - t_u0): a host's sum */
    check_map_range(rt, s->p.map, s->p.ledger.sump, lg);
}
