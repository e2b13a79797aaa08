/* 4-DoF torsional dynamics of the hypoid pair: see dynamics.h. */
#include "model/dynamics.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

#include "hg_vars.h"
#include "io/constants.h"

#define SLIDE_EPS 1e-4 /* regularisation of the sliding direction [m/s] (docs/physics.md §8.8) */
#define SPIN_EPS 1e-3  /* regularisation of the rotation direction of the map losses [rad/s] */
#define KM_FILTER_CYCLES 3.0 /* time constant of the torque filter in mesh periods (§10.8) */
#define KM_FILTER_W_MIN 1.0  /* pinion speed below which the filter's time constant stops
                                growing [rad/s] */

/* The flank whose tooth data apply: the back flank's in back contact (the exact dead zone's
 * mode, so that the data change where the solver restarts at the contact change), else x < 0 for
 * the smoothed dead zone, which has no modes. */
static int active_flank(const hg_dyn_params *p, int mode, double x)
{
    int back = p->backlash.eps == 0.0 ? mode == HG_MODE_BACK : x < 0.0;
    return back ? HG_FLANK_COAST : HG_FLANK_DRIVE;
}

static double shaft1_torque(const hg_dyn_params *p, const double *y)
{
    return p->k_t1 * y[HG_Y_TWIST1] + p->c_t1 * (y[HG_Y_W_S] - y[HG_Y_W_P]);
}

static double shaft2_torque(const hg_dyn_params *p, const double *y)
{
    return p->k_t2 * y[HG_Y_TWIST2] + p->c_t2 * (y[HG_Y_W_G] - y[HG_Y_W_W]);
}

int hg_dyn_quasi_static_input(const hg_dyn_params *p)
{
    return p->mesh == HG_MESH_MODEL_RIGID && p->quasi_static_input;
}

int hg_dyn_quasi_static_output(const hg_dyn_params *p)
{
    return p->mesh == HG_MESH_MODEL_RIGID && p->quasi_static_output;
}

double hg_dyn_input_speed(const hg_dyn_params *p, const double *y)
{
    return hg_dyn_quasi_static_input(p) ? y[HG_Y_W_P] : y[HG_Y_W_S];
}

int hg_dyn_loaded_law(const hg_dyn_params *p)
{
    return p->mesh == HG_MESH_MODEL_VARYING && p->gear->n_levels > 1;
}

/* The force law of a layered file at theta and approach a on the flank in contact, from the
 * tables or from the series. */
static void law_force(const hg_dyn_params *p, const hg_dyn_eval *ev, double theta, double a,
                      hg_law_force *out)
{
    hg_law_levels lv;
    hg_mesh_law law;
    if (p->phase) {
        hg_phase_table_law_force(p->phase, ev->pick.flank, &ev->cell, a, out);
        return;
    }
    hg_mesh_law_of_series(p->gear, ev->flank, theta, &lv, &law);
    hg_mesh_law_force(&law, a, out);
}

/* Without backlash (or with a rigid mesh) both flanks touch: the net force loads one of them. */
static void net_force_loads(hg_dyn_eval *ev)
{
    ev->W_drive = ev->W_t > 0.0 ? ev->W_t : 0.0;
    ev->W_coast = ev->W_t < 0.0 ? -ev->W_t : 0.0;
}

/* Contact loads of the flanks. With backlash each flank carries its spring share and the damper
 * acts through its engagement (a damper between separated teeth does not act); a flank in contact
 * whose force turns tensile (teeth parting faster than the damper allows) carries no load. */
static void flank_loads(const hg_dyn_params *p, int mode, double x, double theta,
                        hg_dyn_eval *ev)
{
    hg_flank_split fl;
    double W_d, W_b;
    if (p->mesh != HG_MESH_MODEL_VARYING) {
        ev->g = 1.0;
        ev->W_t = ev->mesh.k_m * ev->f + p->c_m * ev->xdot;
        net_force_loads(ev);
        return;
    }
    hg_backlash_flanks(&p->backlash, x, mode, &fl);
    if (hg_dyn_loaded_law(p)) {
        /* the law's force through the engagement: the force of the energy U(f_d) + U(-f_b) */
        hg_law_force F_d, F_b;
        law_force(p, ev, theta, fl.f_d, &F_d);
        law_force(p, ev, theta, -fl.f_b, &F_b);
        W_d = F_d.W * fl.g_d + p->c_m * fl.g_d * ev->xdot;
        W_b = -F_b.W * fl.g_b + p->c_m * fl.g_b * ev->xdot;
        ev->U_mesh = F_d.U + F_b.U;
        ev->dU_mesh = F_d.dU + F_b.dU;
    } else {
        W_d = ev->mesh.k_m * fl.f_d + p->c_m * fl.g_d * ev->xdot;
        W_b = ev->mesh.k_m * fl.f_b + p->c_m * fl.g_b * ev->xdot;
    }
    ev->g = fl.g_d + fl.g_b;
    ev->W_t = W_d + W_b;
    ev->W_drive = W_d > 0.0 ? W_d : 0.0;
    ev->W_coast = W_b < 0.0 ? -W_b : 0.0;
}

/* Mesh stiffness, radii, transmission error, f(x), x' and the flank loads. */
static void mesh_state(const hg_dyn_params *p, int mode, const double *y, hg_dyn_eval *ev)
{
    double w_p = y[HG_Y_W_P], theta = p->gear->N_p * y[HG_Y_PHI_P];
    if (p->mesh == HG_MESH_MODEL_VARYING) {
        ev->flank = active_flank(p, mode, y[HG_Y_X]);
        hg_gearset_level_at(p->gear, ev->flank, y[HG_Y_T_KM], &ev->pick);
        if (p->phase) { /* tabulated */
            hg_phase_table_locate(theta, &ev->cell);
            ev->located = 1;
            hg_phase_table_mesh(p->phase, &ev->pick, &ev->cell, &ev->mesh);
        } else {
            hg_gearset_mesh(p->gear, ev->flank, y[HG_Y_T_KM], theta, &ev->mesh);
        }
        ev->f = hg_backlash_f(&p->backlash, y[HG_Y_X], mode);
        ev->Phi = hg_backlash_potential(&p->backlash, y[HG_Y_X], mode);
    } else {
        hg_gearset_level_at(p->gear, ev->flank, y[HG_Y_T_KM], &ev->pick);
        memset(&ev->mesh, 0, sizeof ev->mesh);
        ev->mesh.k_m = p->k_m0;
        ev->mesh.R_p = p->R_p0;
        ev->f = y[HG_Y_X];
        ev->Phi = 0.5 * ev->f * ev->f;
    }
    ev->R_g = ev->mesh.R_p * p->ratio;
    if (p->mesh == HG_MESH_MODEL_RIGID) return;
    /* eq. 25: x' = R_p w_p - R_g w_g - e_0', e_0' = (de_0/dtheta) N_p w_p */
    ev->xdot = ev->mesh.R_p * w_p - ev->R_g * y[HG_Y_W_G] - ev->mesh.de_0 * p->gear->N_p * w_p;
    flank_loads(p, mode, y[HG_Y_X], theta, ev);
}

/* The friction tables of the two levels b picks (built now if they are not), whether both are
 * usable. */
static int friction_tables(const hg_dyn_params *p, const hg_level_pick *b,
                           const hg_friction_table **lo, const hg_friction_table **hi)
{
    *lo = hg_ft_set_table(p->tables, &p->friction, p->gear, b->flank, b->lo);
    *hi = b->hi == b->lo ? *lo : hg_ft_set_table(p->tables, &p->friction, p->gear, b->flank, b->hi);
    return *lo && *hi;
}

/* The pairs' geometry at mesh angle theta and, with contact data, their friction forces
 * ev->pair[k].F_f: from the tables in the right-hand side (the friction table needs no radii nor
 * contact point velocities), else from the series and the friction model; the series and the
 * tables of the flank in contact, blended between the torque levels around the filtered
 * torque. */
static void pair_forces(const hg_dyn_params *p, const double *y, int with_contact,
                        int all_pairs, double T_c_warm[HG_MAX_PAIRS], hg_dyn_eval *ev,
                        hg_pair_geometry *geo)
{
    double w_p = y[HG_Y_W_P], w_g = y[HG_Y_W_G], W = ev->W_drive + ev->W_coast;
    double theta = p->gear->N_p * y[HG_Y_PHI_P], F[HG_MAX_PAIRS];
    const hg_friction_table *lo = NULL, *hi = NULL;
    const hg_level_pick *b = &ev->pick;
    int k, tabulated;
    tabulated = p->tables && !all_pairs && with_contact && friction_tables(p, b, &lo, &hi);
    if (p->phase && with_contact && !all_pairs) { /* the right-hand side: the tables */
        if (!ev->located) hg_phase_table_locate(theta, &ev->cell);
        ev->located = 1;
        hg_phase_table_pairs(p->phase, b, &ev->cell, !tabulated, geo);
    } else {
        hg_gearset_pairs(p->gear, ev->flank, y[HG_Y_T_KM], theta, with_contact, geo);
    }
    for (k = 0; k < HG_MAX_PAIRS; k++) ev->W_pair[k] = geo->ls[k] * W;
    if (!with_contact) return;
    if (tabulated) {
        hg_friction_table_pairs_blend(lo, hi, b->w, theta, ev->W_pair, w_p, w_g, ev->T_oil, F);
        for (k = 0; k < HG_MAX_PAIRS; k++) {
            ev->pair[k].F_f = F[k];
            ev->pair[k].F_v = 0.0; /* tabulated: no viscous share (pair_friction's P_visc) */
        }
        return;
    }
    for (k = 0; k < HG_MAX_PAIRS; k++) {
        hg_pair_contact c;
        c.W = ev->W_pair[k];
        hg_gearset_entrainment(geo->up[k], geo->ug[k], geo->vc[k], w_p, w_g, c.u_p, c.u_g);
        c.R_x = geo->R_x[k];
        c.R_y = geo->R_y[k];
        c.T_bath = ev->T_oil;
        hg_friction_pair(&p->friction, &c, &T_c_warm[k], &ev->pair[k]);
    }
}

/* Friction torques from the sliding direction (docs/physics.md §9.1): T_fp w_p + T_fg w_g = -P_loss,
 * moment arms from the material flank velocities (r x F), entrainment from the surfaces'
 * velocities relative to the moving contact point (the friction model's), the sliding velocity
 * w_p up - w_g ug the same either way. Pairs carry the flank loads, so nothing while the teeth
 * are apart; on the coast flank its own contact data apply (the drive flank's when the file has
 * no coast flank). */
static void pair_friction(const hg_dyn_params *p, const double *y,
                          int all_pairs, double T_c_warm[HG_MAX_PAIRS], hg_dyn_eval *ev)
{
    int k, with_contact = p->friction.model != HG_FRICTION_MODEL_NONE || all_pairs;
    double w_p = y[HG_Y_W_P], w_g = y[HG_Y_W_G];
    hg_pair_geometry geo;
    pair_forces(p, y, with_contact, all_pairs, T_c_warm, ev, &geo);
    if (!with_contact) return;
    for (k = 0; k < HG_MAX_PAIRS; k++) {
        double vs_x = w_p * geo.up[k][0] - w_g * geo.ug[k][0];
        double vs_y = w_p * geo.up[k][1] - w_g * geo.ug[k][1];
        double norm = ev->pair[k].F_f / sqrt(vs_x * vs_x + vs_y * vs_y + SLIDE_EPS * SLIDE_EPS);
        double P_k = norm * (vs_x * vs_x + vs_y * vs_y);
        ev->T_fp -= norm * (vs_x * geo.up[k][0] + vs_y * geo.up[k][1]);
        ev->T_fg += norm * (vs_x * geo.ug[k][0] + vs_y * geo.ug[k][1]);
        ev->P_loss += P_k;
        if (ev->pair[k].F_v > 0.0) /* not tabulated (F_v = 0) */
            ev->P_visc += P_k * ev->pair[k].F_v / ev->pair[k].F_f;
    }
}

/* max(x, 0), +0 for NaN and -0: fmax(x, 0.0) without its call (the right-hand side makes a dozen
 * of them; libm's fmax is not inlined). */
static double at_least_zero(double x) { return x > 0.0 ? x : 0.0; }

/* The map level: the loss (1 - eta) of the power entering the mesh from the driving side, as a
 * torque on the pinion, so that T_fp w_p = -P_loss exactly. The map holds the mesh alone, so
 * its torque is the driving shaft's less what that side's bearings and seals (and, at the gear,
 * churning) take on the way (ev->axle, evaluated before). */
static void map_loss(const hg_dyn_params *p, const double *y,
                     hg_dyn_eval *ev)
{
    double w_p = y[HG_Y_W_P], T_1 = ev->T_1, T_2p = ev->T_2 / p->ratio;
    int coast = -T_2p * w_p > T_1 * w_p; /* power enters from the wheel side */
    double drag = coast ? fabs(ev->axle.T_g) / p->ratio : fabs(ev->axle.T_p);
    double T_in = at_least_zero(fabs(coast ? T_2p : T_1) - drag);
    double eta = hg_effmap_eta(p->map, coast ? HG_MAP_COAST : HG_MAP_DRIVE, w_p, T_in, ev->T_oil);
    double T_loss = (1.0 - eta) * T_in, s = sqrt(w_p * w_p + SPIN_EPS * SPIN_EPS);
    ev->T_fp = -T_loss * w_p / s;
    ev->P_loss = T_loss * w_p * w_p / s;
}

static void losses(const hg_dyn_params *p, const double *y,
                   int all_pairs, double T_c_warm[HG_MAX_PAIRS], hg_dyn_eval *ev)
{
    if (p->friction.model != HG_FRICTION_MODEL_MAP &&
        (p->friction.model != HG_FRICTION_MODEL_NONE || all_pairs)) {
        pair_friction(p, y, all_pairs, T_c_warm, ev);
        return;
    }
    memset(ev->pair, 0, sizeof ev->pair); /* the pairs carry no friction */
    if (p->friction.model == HG_FRICTION_MODEL_MAP) map_loss(p, y, ev);
}

/* The other losses of the axle at the mesh load of ev (axle_losses = full). */
static void axle_losses(const hg_dyn_params *p, const double *y, hg_dyn_eval *ev)
{
    hg_ledger_losses(&p->ledger, y[HG_Y_W_P], y[HG_Y_W_G], ev->W_t, ev->mesh.R_p, ev->R_g,
                     ev->T_oil, &ev->axle);
}

/* The output shaft's torque on the gear at pinion acceleration acc: its spring's (t2), or with
 * the shaft quasi-static the wheel end's torque T_w plus what accelerates the wheel end. */
static double output_torque(const hg_dyn_params *p, int qo, double t2, double T_w, double acc)
{
    return qo ? T_w + p->I_w * acc / p->ratio : t2;
}

/* Rigid mesh: the pinion-gear body's acceleration and the mesh load it implies. With the input
 * shaft quasi-static (hg_dyn_quasi_static_input: the map level's, or input_shaft = quasi_static)
 * the body includes the input shaft's end, the shaft a massless spring carrying
 * T_1 = T_s - I_s acc to the pinion; with the output shaft quasi-static
 * (hg_dyn_quasi_static_output) it includes the wheel end, resisted by T_w, the shaft carrying
 * T_2 = T_w + I_w acc / i from the gear.
 * Friction needs the load and changes the acceleration: the axle's torques are taken into the
 * load first (from the frictionless load; they depend on it only through the bearing loads),
 * then one pass of the mesh friction from that load suffices (its torques change W_t by a
 * fraction mu of the inertial part). */
static void rigid_mesh(const hg_dyn_params *p, const hg_inputs *u, const double *y,
                       int all_pairs, double T_c_warm[HG_MAX_PAIRS], hg_dyn_eval *ev)
{
    int qs = hg_dyn_quasi_static_input(p), qo = hg_dyn_quasi_static_output(p);
    double i = p->ratio, I_s = qs ? p->I_s : 0.0;
    double J = I_s + p->I_p + (qo ? p->I_g + p->I_w : p->I_g) / (i * i);
    double T_in = qs ? u->T_s : shaft1_torque(p, y), t2 = qo ? 0.0 : shaft2_torque(p, y);
    double T_end = qo ? ev->T_w : t2, acc, T_p, T_g; /* the torque resisting at the body's end */
    acc = (T_in - T_end / i) / J;
    ev->T_2 = output_torque(p, qo, t2, ev->T_w, acc);
    ev->W_t = (p->I_g * acc / i + ev->T_2) / ev->R_g;
    net_force_loads(ev);
    axle_losses(p, y, ev);
    /* the load the mesh friction sees: with the axle's bearing, seal and churning torques, which
     * are not small against the mesh's (a no-load drag of several N m at the pinion) */
    acc = (T_in - T_end / i + ev->axle.T_p + ev->axle.T_g / i) / J;
    ev->T_1 = T_in - I_s * acc;
    ev->T_2 = output_torque(p, qo, t2, ev->T_w, acc);
    ev->W_t = (p->I_g * acc / i + ev->T_2 - ev->axle.T_g) / ev->R_g;
    net_force_loads(ev);
    losses(p, y, all_pairs, T_c_warm, ev);
    T_p = ev->T_fp + ev->axle.T_p;
    T_g = ev->T_fg + ev->axle.T_g;
    ev->acc_p = (T_in - T_end / i + T_p + T_g / i) / J;
    ev->T_1 = T_in - I_s * ev->acc_p;
    ev->T_2 = output_torque(p, qo, t2, ev->T_w, ev->acc_p);
    ev->W_t = (p->I_g * ev->acc_p / i + ev->T_2 - T_g) / ev->R_g;
    net_force_loads(ev);
}

/* The larger of a and b, neither NaN. */
static double larger(double a, double b) { return a > b ? a : b; }

static double efficiency_of(double P_loss, double P_in)
{
    if (P_in > 0.0) return at_least_zero(1.0 - P_loss / P_in);
    return P_loss > 0.0 ? 0.0 : 1.0;
}

/* What one side supplies: the power at its free end while that end drives with more than the
 * losses P_scale (the paper's input power in steady drive), else what its member delivers (an
 * inertia carries the power: coast, tip-out, a torque reversal); in between the member's excess
 * fades in linearly, so that the efficiencies stay continuous when the end's power changes sign. */
static double source_power(double P_end, double P_member, double P_scale)
{
    double s = P_end <= 0.0 ? 0.0 : P_end >= P_scale ? 1.0 : P_end / P_scale;
    return P_end + at_least_zero(P_member - P_end) * (1.0 - s);
}

/* Efficiencies on the power that enters from the side that drives at this instant. The pinion
 * delivers (R_p W_t - T_fp) w_p into the mesh, the gear -(R_g W_t + T_fg) w_g; into the axle
 * each member delivers that plus what its own bearings, seals and churning take. Free ends:
 * T_s w_s and -T_w w_w. */
static void efficiency(const hg_inputs *u, const double *y, hg_dyn_eval *ev)
{
    double w_p = y[HG_Y_W_P], w_g = y[HG_Y_W_G];
    double end_s = u->T_s * ev->w_s, end_w = -ev->T_w * y[HG_Y_W_W];
    double mesh_p = (ev->mesh.R_p * ev->W_t - ev->T_fp) * w_p;
    double mesh_g = -(ev->R_g * ev->W_t + ev->T_fg) * w_g;
    ev->P_in = larger(at_least_zero(source_power(end_s, mesh_p, ev->P_loss)),
                      at_least_zero(source_power(end_w, mesh_g, ev->P_loss)));
    ev->eta = efficiency_of(ev->P_loss, ev->P_in);
    ev->P_axle = ev->P_loss + ev->axle.P_churn + ev->axle.P_bearings + ev->axle.P_seals;
    ev->P_in_axle =
        larger(at_least_zero(source_power(end_s, mesh_p - ev->axle.T_p * w_p, ev->P_axle)),
               at_least_zero(source_power(end_w, mesh_g - ev->axle.T_g * w_g, ev->P_axle)));
    ev->eta_axle = efficiency_of(ev->P_axle, ev->P_in_axle);
}

/* dT_km/dt: a first-order filter of the transmitted torque |W_t| R_p with a time constant of
 * KM_FILTER_CYCLES mesh periods, so that the mesh force does not modulate its own stiffness
 * within a cycle (docs/physics.md §10.8); zero for tooth data of one torque level. */
static double torque_filter_rate(const hg_dyn_params *p, const double *y, const hg_dyn_eval *ev)
{
    double w = fabs(y[HG_Y_W_P]) > KM_FILTER_W_MIN ? fabs(y[HG_Y_W_P]) : KM_FILTER_W_MIN;
    double tau = KM_FILTER_CYCLES * HG_TWO_PI / (p->gear->N_p * w);
    if (p->gear->n_levels < 2) return 0.0;
    return (fabs(ev->W_t) * ev->mesh.R_p - y[HG_Y_T_KM]) / tau;
}

/* Q_dot = hg_ledger_heat_out(T_oil, T_amb, v_air), through the memo when there is one. */
static double housing_heat(const hg_dyn_params *p, double T_oil, double T_amb, double v_air)
{
    hg_heat_memo *m = p->heat;
    if (!m) return hg_ledger_heat_out(&p->ledger, T_oil, T_amb, v_air);
    if (!m->valid || m->T_oil != T_oil || m->T_amb != T_amb || m->v_air != v_air) {
        m->Q_dot = hg_ledger_heat_out(&p->ledger, T_oil, T_amb, v_air);
        m->T_oil = T_oil, m->T_amb = T_amb, m->v_air = v_air;
        m->valid = 1;
    }
    return m->Q_dot;
}

double hg_dyn_oil_temperature(const hg_dyn_params *p, const hg_inputs *u, const double *y)
{
    return p->ledger.sump ? y[HG_Y_T_OIL] : u->T_bath;
}

/* The torque resisting at the wheel end: the input T_w, the governor's, or the half-shaft's
 * spring-damper to the wheel turning at the input w_wheel, T_hs = k_hs twist + c_hs slip. */
static double wheel_end_torque(const hg_dyn_params *p, const hg_inputs *u, const double *y,
                               double *slip)
{
    *slip = 0.0;
    if (p->speed_governor)
        return u->T_s * p->ratio + p->K_p * (y[HG_Y_W_W] - u->w_set / p->ratio) +
               p->K_i * y[HG_Y_GOV];
    if (!p->half_shaft) return u->T_w;
    *slip = y[HG_Y_W_W] - u->w_wheel;
    return p->k_hs * y[HG_Y_TWIST_HS] + p->c_hs * *slip;
}

/* What hg_dyn_evaluate sums or sets on some paths only, zeroed; every path sets the rest (a
 * memset of all of it took a quarter of the function's own time). */
static void eval_start(hg_dyn_eval *ev)
{
    int k;
    ev->T_fp = ev->T_fg = ev->P_loss = ev->P_visc = 0.0; /* sums over the pairs */
    ev->xdot = ev->g = ev->acc_p = 0.0;                  /* the rigid mesh leaves them */
    ev->P_exc = ev->T_km_dot = 0.0;                      /* the varying mesh's */
    ev->U_mesh = ev->dU_mesh = 0.0;                      /* a layered file's force law */
    ev->flank = HG_FLANK_DRIVE;                          /* off the varying mesh */
    ev->located = 0;
    for (k = 0; k < HG_MAX_PAIRS; k++) ev->W_pair[k] = 0.0; /* without pair friction */
}

void hg_dyn_evaluate(const hg_dyn_params *p, const hg_inputs *u, int mode, const double *y,
                     int all_pairs, double T_c_warm[HG_MAX_PAIRS], hg_dyn_eval *ev)
{
    double d1, d2 = hg_dyn_quasi_static_output(p) ? 0.0 : y[HG_Y_W_G] - y[HG_Y_W_W];
    eval_start(ev);
    ev->w_s = hg_dyn_input_speed(p, y);
    d1 = ev->w_s - y[HG_Y_W_P];
    ev->T_oil = hg_dyn_oil_temperature(p, u, y);
    mesh_state(p, mode, y, ev);
    ev->T_w = wheel_end_torque(p, u, y, &ev->slip_hs);
    if (p->mesh == HG_MESH_MODEL_RIGID) {
        rigid_mesh(p, u, y, all_pairs, T_c_warm, ev);
    } else {
        ev->T_1 = shaft1_torque(p, y);
        ev->T_2 = shaft2_torque(p, y);
        axle_losses(p, y, ev);
        losses(p, y, all_pairs, T_c_warm, ev);
    }
    efficiency(u, y, ev);
    ev->Q_dot = housing_heat(p, ev->T_oil, u->T_amb, u->v_air);
    ev->P_damp = p->c_t1 * d1 * d1 + p->c_t2 * d2 * d2 + p->c_m * ev->g * ev->xdot * ev->xdot +
                 p->c_hs * ev->slip_hs * ev->slip_hs;
    if (p->mesh == HG_MESH_MODEL_VARYING) {
        double N_p_w = p->gear->N_p * y[HG_Y_W_P];
        ev->T_km_dot = torque_filter_rate(p, y, ev);
        if (hg_dyn_loaded_law(p)) /* the law's energy changes with theta, not with T_km */
            ev->P_exc = (ev->dU_mesh - ev->W_t * ev->mesh.de_0) * N_p_w;
        else
            ev->P_exc = -ev->W_t * ev->mesh.de_0 * N_p_w +
                        (ev->mesh.dk_m * N_p_w + ev->mesh.dk_dT * ev->T_km_dot) * ev->Phi;
    }
}

void hg_dyn_derivatives(const hg_dyn_params *p, const hg_inputs *u, const double *y,
                        const hg_dyn_eval *ev, double *ydot)
{
    double T_1 = ev->T_1, T_2 = ev->T_2;
    ydot[HG_Y_TWIST1] = y[HG_Y_W_S] - y[HG_Y_W_P];
    ydot[HG_Y_TWIST2] = y[HG_Y_W_G] - y[HG_Y_W_W];
    ydot[HG_Y_PHI_P] = y[HG_Y_W_P];
    ydot[HG_Y_X] = ev->xdot;
    ydot[HG_Y_W_S] = (u->T_s - T_1) / p->I_s;                                      /* eq. 20 */
    if (hg_dyn_quasi_static_input(p)) /* twist and speed of the input end are not states */
        ydot[HG_Y_TWIST1] = ydot[HG_Y_W_S] = 0.0;
    if (p->mesh == HG_MESH_MODEL_RIGID) {
        ydot[HG_Y_W_P] = ev->acc_p;
        ydot[HG_Y_W_G] = ev->acc_p / p->ratio;
    } else {
        ydot[HG_Y_W_P] = (T_1 - ev->mesh.R_p * ev->W_t + ev->T_fp + ev->axle.T_p) / p->I_p; /* eq. 21 */
        ydot[HG_Y_W_G] = (ev->R_g * ev->W_t - T_2 + ev->T_fg + ev->axle.T_g) /
                         p->I_g; /* eq. 22, D3 of docs/physics.md §0 */
    }
    ydot[HG_Y_W_W] = (T_2 - ev->T_w) / p->I_w;                                     /* eq. 23 */
    if (hg_dyn_quasi_static_output(p)) { /* the wheel end turns with the gear, the twist held */
        ydot[HG_Y_TWIST2] = 0.0;
        ydot[HG_Y_W_W] = ydot[HG_Y_W_G];
    }
    ydot[HG_Y_GOV] = p->speed_governor ? y[HG_Y_W_W] - u->w_set / p->ratio : 0.0;
    ydot[HG_Y_E_IN] = u->T_s * ev->w_s;
    ydot[HG_Y_TWIST_HS] = ev->slip_hs;
    ydot[HG_Y_IMP_W] = ev->T_w;
    /* the work leaves at the wheel end, or at the wheel past the half-shaft */
    ydot[HG_Y_E_OUT] = ev->T_w * (y[HG_Y_W_W] - ev->slip_hs);
    ydot[HG_Y_E_FRIC] = ev->P_loss;
    ydot[HG_Y_E_DAMP] = ev->P_damp;
    ydot[HG_Y_E_EXC] = ev->P_exc;
    ydot[HG_Y_ETA2] = ev->eta * ev->eta;
    /* the sump: C_sump dT_oil/dt = the axle's losses - the heat to the air */
    ydot[HG_Y_T_OIL] = p->ledger.sump ? (ev->P_axle - ev->Q_dot) / p->ledger.C_sump : 0.0;
    ydot[HG_Y_Q_H] = ev->Q_dot;
    ydot[HG_Y_E_CHURN] = ev->axle.P_churn;
    ydot[HG_Y_E_BEAR] = ev->axle.P_bearings;
    ydot[HG_Y_E_SEAL] = ev->axle.P_seals;
    ydot[HG_Y_ETA_AXLE2] = ev->eta_axle * ev->eta_axle;
    ydot[HG_Y_T_KM] = ev->T_km_dot;
}

double hg_dyn_stored_energy(const hg_dyn_params *p, const double *y, const hg_dyn_eval *ev)
{
    double ws = hg_dyn_input_speed(p, y), wp = y[HG_Y_W_P], wg = y[HG_Y_W_G], ww = y[HG_Y_W_W];
    double t1 = y[HG_Y_TWIST1], t2 = y[HG_Y_TWIST2], ths = y[HG_Y_TWIST_HS];
    double mesh = p->mesh == HG_MESH_MODEL_RIGID ? 0.0
                  : hg_dyn_loaded_law(p)           ? ev->U_mesh
                                                   : ev->mesh.k_m * ev->Phi;
    return 0.5 * (p->I_s * ws * ws + p->I_p * wp * wp + p->I_g * wg * wg + p->I_w * ww * ww) +
           0.5 * (p->k_t1 * t1 * t1 + p->k_t2 * t2 * t2 + p->k_hs * ths * ths) + mesh;
}
