/* The loss ledger and sump: see ledger.h and docs/axle.md. */
#include "model/ledger.h"

#include <math.h>

#include "axle/seals.h"
#include "io/constants.h"
#include "io/errmsg.h"
#include "mesh/gearset.h"
#include "tribo/rheology.h"

#define DEG (HG_PI / 180.0)
#define SPIN_EPS 1e-2   /* regularisation of the rotation direction of the loss torques [rad/s] */
#define RHO_EXPANSION 7e-4 /* volumetric expansion of gear oils [1/K] (assumed, docs/axle.md) */
#define T_15C 288.15
#define T_40C 313.15       /* Linke's reference viscosity [K] */
#define NU_40_LINKE_MIN 0.2e-6 /* lg lg(nu_40 + 0.8) exists for nu_40 > 0.2 mm^2/s [m^2/s] */
#define T_PRELOAD 293.15   /* the workshop sets the preloads at 20 degC [K] */
#define ALPHA_STEEL 11.5e-6 /* thermal expansion of the steel shaft and bearings [1/K] (docs/axle.md) */
#define LN_MM2_PER_M2 13.815510557964274   /* ln(1e6) */
#define LN_RPM_PER_RAD_S 2.2564674958127555 /* ln(30 / pi) */
#define Y0_PER_Y 0.55      /* ISO 76: Y_0 = 0.22 cot(alpha), Y = 0.4 cot(alpha) for tapered rollers */

/* The built-in gear sets' blanks: Paouris et al. 2016 Table 1 and the blank data of
 * resources/gearsets/gearsetN.txt (ring outer pitch diameter 2 A_e2 sin(delta_2)). */
typedef struct {
    double A_e2, ring_b, r_m_p, r_m_g, delta_p, delta_g, beta_p, beta_g; /* m, deg */
} builtin_blank;

/* A_e2: outer cone distance of the ring gear; ring_d = 2 A_e2 sin(delta_g) */
static const builtin_blank BLANKS[3] = {
    {95.60e-3, 30.00e-3, 31.57e-3, 68.53e-3, 29.05, 59.65, 46.00, 27.60},
    {112.53e-3, 38.20e-3, 34.48e-3, 81.00e-3, 27.77, 61.60, 40.00, 26.96},
    {107.80e-3, 36.50e-3, 28.10e-3, 82.26e-3, 22.74, 66.70, 40.00, 26.62},
};

/* a parameter left at 0 takes the blank of the built-in set or of the gear-set file (`have`);
 * a user's file without blank.* keys needs it set */
static int blank_value(const char *name, double given, double fallback, int have, double *out,
                       char *err, size_t errlen)
{
    if (given > 0.0) {
        *out = given;
        return 0;
    }
    if (!have) {
        hg_errorf(err, errlen, "axle_losses = full with a gear_set_file needs the gear blank: "
                  "set %s (it is 0, i.e. 'from the gear set'), or give the file the blank.* "
                  "keys (hypoid tca import --blank ..., docs/data-files.md)", name);
        return -1;
    }
    *out = fallback;
    return 0;
}

static int blank(hg_ledger *a, const hg_vars *v, int set, const double *file_blank, char *err,
                 size_t errlen)
{
    const builtin_blank *b = &BLANKS[set ? set - 1 : 0];
    double d[HG_N_BLANK] = {2.0 * b->A_e2 * sin(b->delta_g * DEG), b->ring_b, b->r_m_p, b->r_m_g,
                            b->delta_p * DEG, b->delta_g * DEG, b->beta_p * DEG,
                            b->beta_g * DEG};
    int have = set || file_blank, k;
    double ring_d;
    if (!set && file_blank)
        for (k = 0; k < HG_N_BLANK; k++) d[k] = file_blank[k];
    if (blank_value("ring_d [m]", v->ring_d, d[HG_BLANK_RING_D], have, &ring_d, err, errlen) ||
        blank_value("ring_b [m]", v->ring_b, d[HG_BLANK_RING_B], have, &a->churn.b, err,
                    errlen) ||
        blank_value("r_m_p [m]", v->r_m_p, d[HG_BLANK_R_M_P], have, &a->pinion.r_m, err,
                    errlen) ||
        blank_value("r_m_g [m]", v->r_m_g, d[HG_BLANK_R_M_G], have, &a->gear.r_m, err, errlen) ||
        blank_value("delta_p [rad]", v->delta_p, d[HG_BLANK_DELTA_P], have, &a->pinion.delta,
                    err, errlen) ||
        blank_value("delta_g [rad]", v->delta_g, d[HG_BLANK_DELTA_G], have, &a->gear.delta, err,
                    errlen) ||
        blank_value("beta_p [rad]", v->beta_p, d[HG_BLANK_BETA_P], have, &a->pinion.beta, err,
                    errlen) ||
        blank_value("beta_g [rad]", v->beta_g, d[HG_BLANK_BETA_G], have, &a->gear.beta, err,
                    errlen))
        return -1;
    a->churn.R_p = 0.5 * ring_d;
    a->pinion.alpha_n = a->gear.alpha_n = v->alpha_n;
    if (v->oil_level <= 0.0 || v->oil_level > a->churn.R_p) {
        hg_errorf(err, errlen, "oil_level = %g m: the oil must wet the ring gear (> 0) and stay "
                  "at or below its axis (<= ring pitch radius %g m)", v->oil_level, a->churn.R_p);
        return -1;
    }
    a->churn.h = v->oil_level;
    a->churn.V_0 = v->V_oil;
    return 0;
}

static int pair_geometry(const char *shaft, const char *n1, double x1, const char *n2, double x2,
                         char *err, size_t errlen)
{
    if (x2 > x1) return 0;
    hg_errorf(err, errlen, "%s bearings: %s = %g m must lie farther from the mean point than "
              "%s = %g m (a pair with no spacing cannot carry the mesh force)", shaft, n2, x2, n1,
              x1);
    return -1;
}

/* one bearing's diameters: a bore inside its outside diameter */
static int bearing_size(const char *name, double d, double D, char *err, size_t errlen)
{
    if (D > d) return 0;
    hg_errorf(err, errlen, "%s_D = %g m must exceed its bore %s_d = %g m (a bearing's outside "
              "diameter lies outside its bore)", name, D, name, d);
    return -1;
}

/* a preload the pair's static rating can carry alone (ISO 76: Y_0 F_a <= C_0, s_0 = 1) */
static int preload_rating(const char *F_name, double F_pre, const char *C_name, double C_0,
                          double Y_max, char *err, size_t errlen)
{
    double limit = C_0 / (Y0_PER_Y * Y_max);
    if (F_pre <= limit) return 0;
    hg_errorf(err, errlen, "%s = %g N exceeds what the pair's static rating %s = %g N carries "
              "(C_0 / Y_0 = %g N with Y_0 = 0.55 Y, ISO 76)", F_name, F_pre, C_name, C_0, limit);
    return -1;
}

static int bearings(hg_ledger *a, const hg_vars *v, char *err, size_t errlen)
{
    static const char *NAME[HG_N_BRG] = {"brg_ph", "brg_pt", "brg_gn", "brg_gf"};
    const double d[HG_N_BRG] = {v->brg_ph_d, v->brg_pt_d, v->brg_gn_d, v->brg_gf_d};
    const double D[HG_N_BRG] = {v->brg_ph_D, v->brg_pt_D, v->brg_gn_D, v->brg_gf_D};
    const double Y[HG_N_BRG] = {v->brg_ph_Y, v->brg_pt_Y, v->brg_gn_Y, v->brg_gf_Y};
    int k;
    for (k = 0; k < HG_N_BRG; k++) {
        int pinion = k <= HG_BRG_P_TAIL;
        if (bearing_size(NAME[k], d[k], D[k], err, errlen)) return -1;
        a->brg[k] = (hg_trb){d[k], D[k], Y[k], pinion ? v->brg_p_R1 : v->brg_g_R1,
                             pinion ? v->brg_p_S1 : v->brg_g_S1,
                             v->brg_feed == HG_BRG_FEED_LOW_LEVEL ? HG_TRB_K_RS_LOW_LEVEL : 0.0};
    }
    if (preload_rating("F_pre_p", v->F_pre_p, "brg_p_C0", v->brg_p_C0, fmax(Y[0], Y[1]), err,
                       errlen) ||
        preload_rating("F_pre_g", v->F_pre_g, "brg_g_C0", v->brg_g_C0, fmax(Y[2], Y[3]), err,
                       errlen))
        return -1;
    a->x_brg[HG_BRG_P_HEAD] = v->brg_ph_x;
    a->x_brg[HG_BRG_P_TAIL] = v->brg_pt_x;
    /* the carrier's ring-side bearing lies behind the ring (away from its apex), the far one on
     * the other side of the differential */
    a->x_brg[HG_BRG_G_NEAR] = v->brg_gn_x;
    a->x_brg[HG_BRG_G_FAR] = -v->brg_gf_x;
    a->F_pre_p = v->F_pre_p;
    a->F_pre_g = v->F_pre_g;
    a->k_ax_p = v->k_ax_p;
    a->k_ax_g = v->k_ax_g;
    a->d_alpha = v->alpha_carrier - ALPHA_STEEL;
    return 0;
}

/* the radial loads of the pair k1, k1 + 1 per newton of F_t on the member (unit: the mesh
 * force's components per newton) */
static void unit_reactions(const hg_ledger *a, const hg_member_geom *m, const hg_mesh_force *unit,
                           int k1, double *Fr_unit)
{
    hg_shaft_reactions(unit, m->r_m, a->x_brg[k1], a->x_brg[k1 + 1], &Fr_unit[k1],
                       &Fr_unit[k1 + 1]);
}

int hg_ledger_setup(hg_ledger *a, const hg_vars *v, int gear_set_builtin,
                    const double *file_blank, const hg_lubricant *lub, char *err, size_t errlen)
{
    int k;
    a->full = v->axle_losses == HG_AXLE_LOSSES_FULL;
    a->sump = v->thermal_model == HG_THERMAL_MODEL_SUMP;
    a->lub = lub;
    a->housing.A = v->A_housing;
    a->housing.L = v->L_housing;
    a->housing.eps = v->eps_housing;
    a->h_housing = v->h_housing;
    a->C_sump = v->C_sump;
    if (!a->full) return 0;
    a->ln_vogel_a = log(lub->vogel_a);
    if (blank(a, v, gear_set_builtin, file_blank, err, errlen) || bearings(a, v, err, errlen))
        return -1;
    if (pair_geometry("pinion", "brg_ph_x", v->brg_ph_x, "brg_pt_x", v->brg_pt_x, err, errlen))
        return -1;
    hg_churn_terms_of(&a->churn, &a->churn_terms);
    for (k = 0; k < HG_N_BRG; k++) hg_trb_geometry_of(&a->brg[k], &a->brg_geom[k]);
    for (k = 0; k < 2; k++) { /* the components and reactions are linear in F_t: per newton */
        a->unit_p[k] = hg_mesh_force_components(&a->pinion, 1.0, k ? 1.0 : -1.0, 1);
        a->unit_g[k] = hg_mesh_force_components(&a->gear, 1.0, k ? 1.0 : -1.0, 0);
        unit_reactions(a, &a->pinion, &a->unit_p[k], HG_BRG_P_HEAD, a->Fr_unit[k]);
        unit_reactions(a, &a->gear, &a->unit_g[k], HG_BRG_G_NEAR, a->Fr_unit[k]);
    }
    a->T_seal_p = hg_seal_torque(v->d_seal_p);
    a->T_seal_w = 2.0 * hg_seal_torque(v->d_seal_w);
    a->seal_linke = v->seal_model == HG_SEAL_MODEL_LINKE;
    a->d_seal_p = v->d_seal_p;
    a->d_seal_w = v->d_seal_w;
    a->nu_40 = hg_ledger_nu(lub, T_40C);
    if (a->seal_linke && !(a->nu_40 > NU_40_LINKE_MIN)) {
        hg_errorf(err, errlen, "seal_model = linke: the lubricant's kinematic viscosity at 40 degC, "
                  "%g mm^2/s, lies outside Linke's seal law (lg lg(nu_40 + 0.8) needs nu_40 > "
                  "0.2 mm^2/s); set seal_model = iso14179", a->nu_40 * 1e6);
        return -1;
    }
    if (a->seal_linke) a->linke_oil = hg_seal_linke_oil_term(a->nu_40);
    return 0;
}

double hg_ledger_rho(const hg_lubricant *lub, double T)
{
    return lub->rho_15 * (1.0 - RHO_EXPANSION * (T - T_15C));
}

/* nu at T from ln(vogel_a) and the density rho at T */
static double nu_of(const hg_lubricant *lub, double ln_vogel_a, double T, double rho)
{
    return exp(hg_vogel_ln_eta0(ln_vogel_a, lub->vogel_b, lub->vogel_c, T)) / rho;
}

double hg_ledger_nu(const hg_lubricant *lub, double T)
{
    return nu_of(lub, log(lub->vogel_a), T, hg_ledger_rho(lub, T));
}

/* bearing loads of one shaft from the mesh force F_t >= 0 on its member (F_t times its axial
 * component and the radial loads per newton, unit and Fr_unit) and the pair's preload */
static void shaft_bearings(const hg_ledger *a, const hg_mesh_force *unit, const double *Fr_unit,
                           double F_t, int k1, double F_pre, hg_ledger_eval *ev)
{
    int k2 = k1 + 1;
    ev->Fr[k1] = F_t * Fr_unit[k1];
    ev->Fr[k2] = F_t * Fr_unit[k2];
    hg_trb_pair_axial(ev->Fr[k1], a->brg[k1].Y, ev->Fr[k2], a->brg[k2].Y, F_t * unit->F_a, F_pre,
                      &ev->Fa[k1], &ev->Fa[k2]);
}

/* frictional moment of the pair k1, k1 + 1 [N m] at their shaft's speed terms sp */
static double pair_moment(const hg_ledger *a, int k1, const hg_trb_speed *sp,
                          const hg_ledger_eval *ev)
{
    double M = 0.0;
    int k;
    for (k = k1; k <= k1 + 1; k++) {
        hg_trb_moment m = hg_trb_friction_at(&a->brg[k], &a->brg_geom[k], sp, ev->Fr[k],
                                             ev->Fa[k]);
        M += m.M_rr + m.M_sl;
    }
    return M;
}

/* the direction of rotation at w, regularised: w / sqrt(w^2 + SPIN_EPS^2) */
static double spin(double w)
{
    return w / sqrt(w * w + SPIN_EPS * SPIN_EPS);
}

/* torque of magnitude M opposing rotation at w (its direction s = spin(w)), and the power it
 * takes */
static double opposing(double M, double w, double s, double *T)
{
    *T -= M * s;
    return M * s * w;
}

void hg_ledger_losses(const hg_ledger *a, double w_p, double w_g, double W_t, double R_p,
                      double R_g, double T_oil, hg_ledger_eval *ev)
{
    double s = W_t >= 0.0 ? 1.0 : -1.0, rho, dT = T_oil - T_PRELOAD, s_p, s_g;
    hg_trb_oil oil;
    hg_trb_speed sp_p, sp_g; /* the shafts': both bearings of a shaft turn at its speed */
    *ev = (hg_ledger_eval){0};
    if (!a->full) return;
    rho = hg_ledger_rho(a->lub, T_oil);
    ev->nu = nu_of(a->lub, a->ln_vogel_a, T_oil, rho);
    hg_trb_oil_of(ev->nu, &oil); /* both shafts' bearings */
    ev->F_pre_p = hg_trb_preload(a->F_pre_p, a->k_ax_p, a->d_alpha,
                                 a->x_brg[HG_BRG_P_TAIL] - a->x_brg[HG_BRG_P_HEAD], dT);
    ev->F_pre_g = hg_trb_preload(a->F_pre_g, a->k_ax_g, a->d_alpha,
                                 a->x_brg[HG_BRG_G_NEAR] - a->x_brg[HG_BRG_G_FAR], dT);
    shaft_bearings(a, &a->unit_p[s > 0.0], a->Fr_unit[s > 0.0],
                   fabs(W_t) * R_p / a->pinion.r_m, HG_BRG_P_HEAD, ev->F_pre_p, ev);
    /* the carrier: the ring-side bearing takes a thrust away from the ring's apex */
    shaft_bearings(a, &a->unit_g[s > 0.0], a->Fr_unit[s > 0.0],
                   fabs(W_t) * R_g / a->gear.r_m, HG_BRG_G_NEAR, ev->F_pre_g, ev);
    s_p = spin(w_p), s_g = spin(w_g); /* once per shaft for all its losses */
    hg_trb_speed_at(&oil, w_p, &sp_p);
    hg_trb_speed_at(&oil, w_g, &sp_g);
    ev->P_bearings_p = opposing(pair_moment(a, HG_BRG_P_HEAD, &sp_p, ev), w_p, s_p, &ev->T_p);
    ev->P_bearings_g = opposing(pair_moment(a, HG_BRG_G_NEAR, &sp_g, ev), w_g, s_g, &ev->T_g);
    ev->P_bearings = ev->P_bearings_p + ev->P_bearings_g;
    ev->T_seal_p = a->T_seal_p;
    ev->T_seal_w = a->T_seal_w;
    if (a->seal_linke) {
        double f = hg_seal_linke_factor_at(T_oil, a->linke_oil);
        ev->T_seal_p = hg_seal_torque_linke(a->d_seal_p, f);
        ev->T_seal_w = 2.0 * hg_seal_torque_linke(a->d_seal_w, f);
    }
    ev->P_seals = opposing(ev->T_seal_p, w_p, s_p, &ev->T_p) +
                  opposing(ev->T_seal_w, w_g, s_g, &ev->T_g);
    /* the churning's ln nu and ln |w_g| from the bearings' ln(nu [mm^2/s]), ln(n [r/min]) */
    ev->P_churn = opposing(hg_churn_torque_ln(&a->churn, &a->churn_terms, rho, ev->nu,
                                              oil.ln_v - LN_MM2_PER_M2, w_g,
                                              sp_g.ln_n - LN_RPM_PER_RAD_S),
                           w_g, s_g, &ev->T_g);
}

double hg_ledger_heat_out(const hg_ledger *a, double T_oil, double T_amb, double v_air)
{
    double h = a->h_housing > 0.0 ? a->h_housing
                                  : hg_housing_h_conv(&a->housing, T_oil - T_amb, v_air);
    return hg_housing_heat_h(&a->housing, h, T_oil, T_amb);
}
