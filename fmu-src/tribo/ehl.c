/* Mixed-EHL friction and thermal model of one flank pair: see ehl.h. */
#include "tribo/ehl.h"

#include <math.h>
#include <string.h>

#include "tribo/asperity.h"
#include "tribo/film.h"
#include "tribo/rheology.h"
#include "tribo/thermal.h"

void hg_ehl_params_default(hg_ehl_params *p)
{
    memset(p, 0, sizeof *p);
    p->E = 210e9;
    p->nu = 0.30;
    p->E_star = 0.0;
    p->k_s = 30.0;
    p->rho_s = 7850.0;
    p->c_s = 460.0;
    p->tau_0 = 2e6;
    p->varsigma_a = 0.17;
    p->sigma_s = 0.25e-6;
    p->eta_beta_sigma = 0.0104;
    p->sigma_over_beta = 1e-3;
    p->T_inlet_rise = 20.0;
    p->Lambda_cap = 0.0;
    p->k_f_override = 0.0;
    p->T_c_max = 573.15;
    p->T_c_tol = 1e-6;
    p->hertz = HG_HERTZ_EXACT;
    p->roelands_Z = HG_Z_SIMPLE;
    p->shear_pressure = HG_SHEAR_P_MEAN;
    p->relaxation = HG_RELAX_CONSTANT;
    p->thermal = 1;
}

/* Gauss-Legendre nodes and weights on [0, 1] (8 points, exact to degree 15): the mean of tau over
 * the Hertzian ellipse, p = p_max s with s = sqrt(1 - rho^2), is int_0^1 tau(p_max s) 2 s ds. */
#define N_HERTZ 8
static const double GL_S[N_HERTZ] = {0.019855071751231912, 0.10166676129318664,
                                     0.2372337950418355,   0.4082826787521751,
                                     0.5917173212478248,   0.7627662049581645,
                                     0.8983332387068134,   0.9801449282487681};
static const double GL_W[N_HERTZ] = {0.05061426814518853, 0.11119051722668721,
                                     0.15685332293894344, 0.18134189168918083,
                                     0.18134189168918083, 0.15685332293894344,
                                     0.11119051722668721, 0.05061426814518853};

/* Everything tau(T) needs; T is the only variable during the T_c solve. */
typedef struct {
    hg_rheology rh;     /* Vogel, alpha*(T), Roelands Z (and Z_exact's warm start) */
    int n;              /* pressure nodes: 1 (p_m or p_max) or N_HERTZ (the Hertzian field) */
    double ln1p_p[N_HERTZ]; /* ln(1 + p_i/p0) */
    double tau_L[N_HERTZ];  /* limiting shear stress Lambda p_i [Pa] (0: none) */
    double w[N_HERTZ];      /* weights of the mean over the ellipse (sum 1) */
    double gamma_dot;   /* [1/s] */
    double gdot_over_F; /* gamma_dot / F(gamma_dot) with the constant lambda [1/s] */
    double lambda_per_eta; /* TTS: lambda = this eta(p, T) [s/(Pa s)]; 0: constant lambda */
    double hn_alpha, hn_beta;
    double eta, Z;      /* of the last evaluation (first node) */
} shear_ctx;

/* Viscous stress of one node, tau_v = eta gamma_dot / F, and d ln tau_v / d ln eta. With TTS,
 * lambda = lambda_per_eta eta, so d ln F / d ln eta = alpha beta x/(1 + x), x = (lambda gdot)^alpha. */
static double viscous_stress(const shear_ctx *s, double eta, double *dln_deta)
{
    double x, F;
    if (!(s->lambda_per_eta > 0.0)) {
        *dln_deta = 1.0;
        return eta * s->gdot_over_F;
    }
    x = pow(s->lambda_per_eta * eta * s->gamma_dot, s->hn_alpha);
    F = s->hn_beta == 1.0 ? 1.0 + x : pow(1.0 + x, s->hn_beta);
    *dln_deta = 1.0 - s->hn_alpha * s->hn_beta * x / (1.0 + x);
    return eta * s->gamma_dot / F;
}

/* tau(T): the mean over the pressure nodes of eta(p_i, T) gamma_dot / F, each limited smoothly
 * by Lambda p_i (eqs. 7-9; Roelands + Vogel), and dtau/dT. */
static double shear_of_T(double T, void *vctx, double *dtau_dT)
{
    shear_ctx *s = vctx;
    hg_rheo_state r;
    double tau = 0.0, dtau = 0.0;
    int i;
    hg_rheology_at(&s->rh, T, &r);
    hg_rheology_Z(&s->rh, T, &r);
    for (i = 0; i < s->n; i++) {
        double dlneta, dln, slope, eta = exp(hg_roelands_ln_eta(&r, s->ln1p_p[i], &dlneta));
        double tv = viscous_stress(s, eta, &dln), ti = hg_shear_limit(tv, s->tau_L[i], &slope);
        if (i == 0) s->eta = eta;
        tau += s->w[i] * ti;
        dtau += s->w[i] * slope * tv * dln * dlneta;
    }
    s->Z = r.Z;
    *dtau_dT = dtau;
    return tau;
}

static int finite_contact(const hg_pair_contact *c)
{
    return isfinite(c->W) && isfinite(c->u_p[0]) && isfinite(c->u_p[1]) &&
           isfinite(c->u_g[0]) && isfinite(c->u_g[1]) && isfinite(c->R_x) &&
           isfinite(c->R_y) && isfinite(c->T_bath);
}

void hg_ehl_pair(const hg_ehl_params *p, const hg_lubricant *lub, const hg_pair_contact *c,
                 double *T_c_warm, hg_pair_friction *out)
{
    hg_ehl_pair_ex(p, lub, c, T_c_warm, out, NULL);
}

/* One evaluation, filled stage by stage: the stages below read what the earlier ones wrote. */
typedef struct {
    const hg_ehl_params *p;
    const hg_lubricant *lub;
    const hg_pair_contact *c;
    const hg_hertz *hertz; /* the caller's ellipse for c (hg_ehl_hertz), or NULL: solved here */
    hg_pair_friction *out;
    hg_ehl_stats st;    /* every intermediate value (copied to the caller's stats on request) */
    hg_kinematics kin;
    shear_ctx sc;
    double h_c, A_visc, F_b, k_f;
} ehl_eval;

static double e_star(const hg_ehl_params *p)
{
    return p->E_star > 0.0 ? p->E_star : p->E / (1.0 - p->nu * p->nu);
}

/* Hertz (docs/physics.md §2) */
static void stage_hertz(ehl_eval *e)
{
    const hg_ehl_params *p = e->p;
    e->st.E_star = e_star(p);
    if (e->hertz)
        e->st.hertz = *e->hertz;
    else
        hg_hertz_eval(e->c->W, e->c->R_x, e->c->R_y, e->st.E_star, (hg_hertz_mode)p->hertz,
                      &e->st.hertz);
    e->out->p_h = e->st.hertz.p_max;
}

/* film at the inlet temperature (eq. 10; D7 of docs/physics.md §0), thinned by the inlet's shear
 * heating when asked (film.h) */
static void stage_film(ehl_eval *e)
{
    hg_rheo_state in;
    e->k_f = e->p->k_f_override > 0.0 ? e->p->k_f_override : e->lub->k_f;
    hg_rheology_init(&e->sc.rh, e->lub, e->p->roelands_Z == HG_Z_EXACT, e->p->z_table);
    hg_rheology_at(&e->sc.rh, e->st.T_in, &in);
    e->st.eta0_in = exp(in.ln_eta0);
    e->st.alpha_in = in.alpha;
    e->h_c = hg_film_chittenden(e->st.eta0_in, e->st.alpha_in, e->kin.u_e, e->c->W,
                                e->st.E_star, e->out->R_e, e->out->R_s);
    e->st.phi_T = 1.0;
    if (e->p->inlet_heating && e->kin.u_e > HG_SPEED_FLOOR) {
        double L = -in.dL0 * e->st.eta0_in * e->kin.u_e * e->kin.u_e / e->k_f;
        e->st.phi_T = hg_film_thermal_reduction(L, e->kin.v_s / e->kin.u_e,
                                                e->st.hertz.p_max / e->st.E_star);
        e->h_c *= e->st.phi_T;
    }
    if (!(e->h_c >= HG_EHL_H_MIN)) {
        e->h_c = HG_EHL_H_MIN;
        e->st.flags |= HG_EHL_H_FLOORED;
    }
    e->out->h_c = e->h_c;
    e->out->lambda = e->h_c / (1.41421356237309504880 * e->p->sigma_s);
}

/* asperities (eqs. 11-13) */
static void stage_asperities(ehl_eval *e)
{
    const hg_ehl_params *p = e->p;
    const hg_hertz *hz = &e->st.hertz;
    hg_greenwood_tripp(e->out->lambda, p->eta_beta_sigma, p->sigma_over_beta, e->st.E_star,
                       hz->A, &e->st.W_asp, &e->st.A_asp);
    if (e->st.A_asp > hz->A) e->st.A_asp = hz->A;
    e->A_visc = hz->A - e->st.A_asp;
    e->F_b = hg_boundary_friction(p->tau_0, p->varsigma_a, e->st.A_asp, e->st.W_asp);
}

/* relaxation time per unit viscosity for time-temperature-pressure superposition:
 * lambda(p, T) = lambda_0 eta(p, T)/eta_0(T_ref), Table 2's lambda_0 measured at T_ref and
 * ambient pressure */
static double lambda_per_eta(shear_ctx *sc, const hg_lubricant *lub)
{
    hg_rheo_state ref;
    hg_rheology_at(&sc->rh, HG_HN_T_REF, &ref);
    return lub->hn_lambda / exp(ref.ln_eta0);
}

/* shear rate and the pressures of the shear stress (eqs. 7-9) */
static void stage_shear(ehl_eval *e)
{
    const hg_hertz *hz = &e->st.hertz;
    const hg_lubricant *lub = e->lub;
    shear_ctx *sc = &e->sc;
    double v_s = e->kin.v_s, Lambda = e->p->Lambda_cap > 0.0 ? e->p->Lambda_cap : 0.0;
    int i;
    e->st.gamma_dot = (v_s > HG_SPEED_FLOOR ? v_s : HG_SPEED_FLOOR) / e->h_c;
    e->st.F_hn = hg_hn_factor(lub->hn_lambda, lub->hn_alpha, lub->hn_beta, e->st.gamma_dot);
    sc->gamma_dot = e->st.gamma_dot;
    sc->gdot_over_F = e->st.gamma_dot / e->st.F_hn;
    sc->hn_alpha = lub->hn_alpha;
    sc->hn_beta = lub->hn_beta;
    sc->lambda_per_eta = e->p->relaxation == HG_RELAX_TTS ? lambda_per_eta(sc, lub) : 0.0;
    if (e->p->shear_pressure == HG_SHEAR_P_HERTZ) {
        sc->n = N_HERTZ;
        for (i = 0; i < N_HERTZ; i++) {
            double p_i = hz->p_max * GL_S[i];
            sc->ln1p_p[i] = log1p(p_i / HG_ROELANDS_P0);
            sc->tau_L[i] = Lambda * p_i;
            sc->w[i] = 2.0 * GL_W[i] * GL_S[i];
        }
    } else {
        double p_s = e->p->shear_pressure == HG_SHEAR_P_MAX ? hz->p_max : hz->p_m;
        sc->n = 1;
        sc->ln1p_p[0] = log1p(p_s / HG_ROELANDS_P0);
        sc->tau_L[0] = Lambda * p_s;
        sc->w[0] = 1.0;
    }
    sc->eta = sc->Z = 0.0;
}

/* thermal network (eqs. 16-19) */
static void stage_network(ehl_eval *e)
{
    const hg_ehl_params *p = e->p;
    const hg_hertz *hz = &e->st.hertz;
    hg_ehl_stats *st = &e->st;
    double chi_s = p->k_s / (p->rho_s * p->c_s);
    st->l_p = hg_coleman_length(hz->s_y, hz->s_x, e->c->u_p[0], e->c->u_p[1]);
    st->l_g = hg_coleman_length(hz->s_y, hz->s_x, e->c->u_g[0], e->c->u_g[1]);
    st->R_fp = hg_moving_source_resistance(hz->A, p->k_s, chi_s, st->l_p, e->kin.U_p);
    st->R_fg = hg_moving_source_resistance(hz->A, p->k_s, chi_s, st->l_g, e->kin.U_g);
    st->R_cf = hg_film_resistance(e->h_c, e->k_f, hz->A);
    st->a_h = hg_heat_partition(st->R_fp, st->R_fg, st->R_cf);
}

/* conjunction temperature (eq. 14) and the shear stress there; at T_in when isothermal */
static void stage_temperature(ehl_eval *e, double *T_c_warm)
{
    hg_ehl_stats *st = &e->st;
    double dtau;
    if (e->p->thermal) {
        hg_tc_problem pb;
        hg_tc_result tr;
        pb.T_in = st->T_in;
        pb.c0 = st->R_fp * st->a_h * e->F_b * e->kin.v_s;
        pb.c1 = e->kin.v_s * (st->R_fp * st->a_h * e->A_visc + e->h_c / (8.0 * e->k_f));
        pb.T_max = e->p->T_c_max;
        pb.tol = e->p->T_c_tol > 0.0 ? e->p->T_c_tol : 1e-6;
        pb.max_eval = 100;
        hg_tc_solve(&pb, shear_of_T, &e->sc, T_c_warm ? *T_c_warm : NAN, &tr);
        st->tau = tr.tau;
        e->out->T_c = tr.T_c;
        st->n_eval = tr.n_eval;
        st->dT_first = tr.dT_first;
        if (tr.flags & HG_TC_CAPPED) st->flags |= HG_EHL_TC_CAPPED;
        if (tr.flags & HG_TC_NOT_CONVERGED) st->flags |= HG_EHL_TC_NOT_CONVERGED;
        if (tr.flags & HG_TC_HUGE_RISE) st->flags |= HG_EHL_HUGE_RISE;
    } else {
        st->tau = shear_of_T(st->T_in, &e->sc, &dtau);
    }
}

/* friction (eqs. 5, 6, 11) */
static void stage_friction(ehl_eval *e)
{
    hg_pair_friction *out = e->out;
    out->F_v = e->A_visc * e->st.tau;
    out->F_b = e->F_b;
    out->F_f = out->F_v + out->F_b;
    out->mu = out->F_f / e->c->W;
}

/* regime parameters on the entrainment radius (docs/physics.md §7), diagnostics only */
static void stage_regime(ehl_eval *e)
{
    hg_pair_friction *out = e->out;
    double E_star = e->st.E_star, R_e = out->R_e, W = e->c->W;
    double U = e->st.eta0_in * (e->kin.u_e > HG_SPEED_FLOOR ? e->kin.u_e : HG_SPEED_FLOOR) /
               (E_star * R_e);
    double G = e->st.alpha_in * E_star, W_e = W / (E_star * R_e * R_e);
    double cW = cbrt(W_e), iU2 = 1.0 / (U * U);
    out->g_V = G * W_e * W_e * W_e * iU2; /* G W^3/U^2 */
    out->g_E = W_e * W_e * cW * cW * iU2; /* W^(8/3)/U^2 */
}

/* the diagnostics that the forces do not need */
static void stage_diagnostics(ehl_eval *e)
{
    hg_ehl_stats *st = &e->st;
    double dtau;
    /* the last evaluation need not be at T_c: refresh eta and Z */
    if (e->p->thermal) (void)shear_of_T(e->out->T_c, &e->sc, &dtau);
    if (e->p->Lambda_cap > 0.0 && st->tau >= 0.5 * e->p->Lambda_cap * st->hertz.p_m)
        st->flags |= HG_EHL_TAU_CAPPED;
    st->theta_e = hg_entrainment_angle(e->kin.U_e);
    st->dT_flash = hg_flash_rise(st->R_fp, st->a_h, e->out->F_f * e->kin.v_s);
    st->dT_oil = hg_oil_rise(e->kin.v_s, st->tau, e->h_c, e->k_f);
    st->eta_c = e->sc.eta;
    st->Z_c = e->sc.Z;
}

/* Whether c is a contact the stages evaluate (else forces stay 0). */
static int in_contact(const hg_pair_contact *c)
{
    return finite_contact(c) && c->W >= HG_EHL_LOAD_MIN && c->R_x > 0.0 && c->R_y > 0.0;
}

static void pair_eval(const hg_ehl_params *p, const hg_lubricant *lub, const hg_pair_contact *c,
                      const hg_hertz *hertz, double *T_c_warm, hg_pair_friction *out,
                      hg_ehl_stats *st)
{
    ehl_eval e;
    memset(&e, 0, sizeof e);
    memset(out, 0, sizeof *out);
    e.p = p, e.lub = lub, e.c = c, e.hertz = hertz, e.out = out;
    e.st.dT_first = NAN;
    e.st.T_in = c->T_bath + p->T_inlet_rise;
    out->T_c = e.st.T_in;
    if (finite_contact(c)) {
        hg_kinematics_eval(c->u_p, c->u_g, &e.kin);
        out->u_e = e.kin.u_e;
        out->V_s = e.kin.v_s;
    }
    if (!in_contact(c)) {
        e.st.flags = HG_EHL_NO_CONTACT; /* nothing to compute; forces stay 0 */
    } else {
        hg_entrainment_radii(c->R_x, c->R_y, e.kin.cos2_e, e.kin.sin2_e, &out->R_e, &out->R_s);
        stage_hertz(&e);
        stage_film(&e);
        stage_asperities(&e);
        stage_shear(&e);
        stage_network(&e);
        stage_temperature(&e, T_c_warm);
        stage_friction(&e);
        stage_regime(&e);
        if (st) stage_diagnostics(&e);
    }
    if (T_c_warm) *T_c_warm = out->T_c;
    if (st) *st = e.st;
}

void hg_ehl_pair_ex(const hg_ehl_params *p, const hg_lubricant *lub, const hg_pair_contact *c,
                    double *T_c_warm, hg_pair_friction *out, hg_ehl_stats *st)
{
    pair_eval(p, lub, c, NULL, T_c_warm, out, st);
}

void hg_ehl_hertz(const hg_ehl_params *p, const hg_pair_contact *c, hg_hertz *h)
{
    memset(h, 0, sizeof *h);
    if (in_contact(c)) hg_hertz_eval(c->W, c->R_x, c->R_y, e_star(p), (hg_hertz_mode)p->hertz, h);
}

void hg_ehl_pair_hertz(const hg_ehl_params *p, const hg_lubricant *lub,
                       const hg_pair_contact *c, const hg_hertz *h, double *T_c_warm,
                       hg_pair_friction *out)
{
    pair_eval(p, lub, c, h, T_c_warm, out, NULL);
}
