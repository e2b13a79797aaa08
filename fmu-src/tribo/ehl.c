/* Mixed-EHL friction and thermal model of one flank pair: see ehl.h. */
#include "tribo/ehl.h"

#include <math.h>
#include <stdio.h>
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
    p->thermal = 1;
}

int hg_ehl_params_check(const hg_ehl_params *p, char *err, size_t errlen)
{
    struct {
        const char *name;
        double v, lo, hi;
    } r[] = {
        {"k_s", p->k_s, 1e-3, 1e4},
        {"rho_s", p->rho_s, 1.0, 1e5},
        {"c_s", p->c_s, 1.0, 1e5},
        {"tau_0", p->tau_0, 0.0, 1e10},
        {"varsigma_a", p->varsigma_a, 0.0, 10.0},
        {"sigma_s", p->sigma_s, 1e-10, 1e-4},
        {"eta_beta_sigma", p->eta_beta_sigma, 0.0, 1.0},
        {"sigma_over_beta", p->sigma_over_beta, 1e-8, 1.0},
        {"T_inlet_rise", p->T_inlet_rise, 0.0, 500.0},
        {"Lambda_cap", p->Lambda_cap, 0.0, 10.0},
        {"k_f_override", p->k_f_override, -1e300, 10.0},
        {"T_c_max", p->T_c_max, 200.0, 2000.0},
        {"T_c_tol", p->T_c_tol, 0.0, 1.0},
    };
    size_t i;
    if (p->E_star > 0.0) {
        if (!(p->E_star >= 1e6 && p->E_star <= 1e13)) {
            snprintf(err, errlen, "E_star = %g Pa is outside [1e6, 1e13]", p->E_star);
            return -1;
        }
    } else if (!(p->E >= 1e6 && p->E <= 1e13) || !(p->nu >= 0.0 && p->nu < 0.5)) {
        snprintf(err, errlen, "E = %g Pa, nu = %g: need E in [1e6, 1e13] and 0 <= nu < 0.5",
                 p->E, p->nu);
        return -1;
    }
    for (i = 0; i < sizeof r / sizeof r[0]; i++) {
        if (!(r[i].v >= r[i].lo && r[i].v <= r[i].hi)) {
            snprintf(err, errlen, "%s = %g is outside [%g, %g]", r[i].name, r[i].v, r[i].lo,
                     r[i].hi);
            return -1;
        }
    }
    if ((p->hertz != HG_HERTZ_EXACT && p->hertz != HG_HERTZ_APPROX) ||
        (p->roelands_Z != HG_Z_SIMPLE && p->roelands_Z != HG_Z_EXACT) ||
        (p->shear_pressure != HG_SHEAR_P_MEAN && p->shear_pressure != HG_SHEAR_P_MAX) ||
        (p->thermal != 0 && p->thermal != 1)) {
        snprintf(err, errlen, "invalid switch: hertz %d, roelands_Z %d, shear_pressure %d, "
                 "thermal %d", p->hertz, p->roelands_Z, p->shear_pressure, p->thermal);
        return -1;
    }
    return 0;
}

/* Everything tau(T) needs; T is the only variable during the T_c solve. */
typedef struct {
    const hg_lubricant *lub;
    hg_alpha_interp ai; /* alpha*(T) coefficients */
    double ln_a;        /* ln of Vogel a */
    double ln1p_p;      /* ln(1 + p/p0), p = p_m or p_max */
    double gdot_over_F; /* gamma_dot / F(gamma_dot) [1/s] */
    double tau_cap;     /* Lambda p_m, or HUGE_VAL */
    int z_exact;
    double T_last, Z_last, dZdT_last; /* previous Z_exact within one call (warm start) */
    double eta, Z;      /* of the last evaluation */
} shear_ctx;

/* tau(T) = eta(p, T) gamma_dot / F(gamma_dot), capped (eqs. 7-9; Roelands + Vogel), and
 * dtau/dT. With L0 = ln eta_0 = ln a + b/(T - c), A = L0 + 9.67 and
 * ln eta = L0 + A (e^(Z lp) - 1):
 *   d ln eta/dT = L0' + A' (e^(Z lp) - 1) + A e^(Z lp) lp Z',
 * Z' = Z (d ln(alpha*) / dT - A'/A) for Z_simple = alpha* p0 / A; for Z_exact from its partial
 * derivatives (implicit differentiation in hg_roelands_Z_exact). */
static double shear_of_T(double T, void *vctx, double *dtau_dT)
{
    shear_ctx *s = vctx;
    const hg_lubricant *lub = s->lub;
    int clamped = !(T - lub->vogel_c > HG_VOGEL_DT_MIN) || T > HG_RHEO_T_MAX;
    double T_r = T > HG_RHEO_T_MAX ? HG_RHEO_T_MAX
                                   : (clamped ? lub->vogel_c + HG_VOGEL_DT_MIN : T);
    double ln_eta0 = hg_vogel_ln_eta0(s->ln_a, lub->vogel_b, lub->vogel_c, T_r);
    double A = hg_roelands_A(ln_eta0), dlna, alpha = hg_alpha_interp_eval(&s->ai, T_r, &dlna);
    double Z, dZ, eZ, ln_eta, tau, dL0, dA, dlneta;
    dL0 = clamped ? 0.0 : -lub->vogel_b / ((T_r - lub->vogel_c) * (T_r - lub->vogel_c));
    dA = ln_eta0 + HG_ROELANDS_LN_ETA_R > HG_ROELANDS_A_MIN ? dL0 : 0.0;
    if (clamped) dlna = 0.0;
    if (s->z_exact) {
        double dZ_dA, dZ_dlna, guess = 0.0;
        if (s->Z_last > 0.0) guess = s->Z_last + s->dZdT_last * (T - s->T_last);
        Z = hg_roelands_Z_exact(alpha, A, guess > 0.0 ? guess : s->Z_last, &dZ_dA, &dZ_dlna);
        dZ = dZ_dA * dA + dZ_dlna * dlna;
        if (!isfinite(dZ)) dZ = 0.0;
        s->T_last = T, s->Z_last = Z, s->dZdT_last = dZ;
    } else {
        Z = hg_roelands_Z_simple(alpha, A);
        dZ = Z * (dlna - dA / A); /* Z = alpha* p0 / A */
    }
    eZ = exp(Z * s->ln1p_p);
    ln_eta = ln_eta0 + A * (eZ - 1.0); /* Roelands */
    dlneta = dL0 + dA * (eZ - 1.0) + A * eZ * s->ln1p_p * dZ;
    if (ln_eta > HG_LN_ETA_MAX) {
        ln_eta = HG_LN_ETA_MAX;
        dlneta = 0.0;
    }
    s->eta = exp(ln_eta);
    s->Z = Z;
    tau = s->eta * s->gdot_over_F;
    if (tau >= s->tau_cap) {
        *dtau_dT = 0.0;
        return s->tau_cap;
    }
    *dtau_dT = tau * dlneta;
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

void hg_ehl_pair_ex(const hg_ehl_params *p, const hg_lubricant *lub, const hg_pair_contact *c,
                    double *T_c_warm, hg_pair_friction *out, hg_ehl_stats *st)
{
    hg_kinematics kin;
    hg_hertz hz;
    shear_ctx sc;
    hg_tc_result tr;
    double T_in = c->T_bath + p->T_inlet_rise, E_star, T_r, ln_eta0_in, eta0_in, alpha_in;
    double h_c, sigma_c, lam, W_asp, A_asp, F_b, gdot, F_hn, k_f, chi_s, l_p, l_g;
    double R_fp, R_fg, R_cf, a_h, A_visc, tau, F_v, U, G, W_e, W = c->W;
    int flags = 0;

    memset(out, 0, sizeof *out);
    if (st) {
        memset(st, 0, sizeof *st);
        st->dT_first = NAN;
        st->T_in = T_in;
    }
    out->T_c = T_in;
    if (!finite_contact(c)) { /* nothing sensible to compute; forces stay 0 */
        if (st) st->flags = HG_EHL_NO_CONTACT;
        if (T_c_warm) *T_c_warm = T_in;
        return;
    }
    hg_kinematics_eval(c->u_p, c->u_g, &kin);
    out->u_e = kin.u_e;
    out->V_s = kin.v_s;
    if (!(W >= HG_EHL_LOAD_MIN) || !(c->R_x > 0.0) || !(c->R_y > 0.0)) {
        if (st) st->flags = HG_EHL_NO_CONTACT;
        if (T_c_warm) *T_c_warm = T_in;
        return;
    }
    hg_entrainment_radii(c->R_x, c->R_y, kin.cos2_e, kin.sin2_e, &out->R_e, &out->R_s);

    /* Hertz (physics 2) */
    E_star = p->E_star > 0.0 ? p->E_star : p->E / (1.0 - p->nu * p->nu);
    hg_hertz_eval(W, c->R_x, c->R_y, E_star, (hg_hertz_mode)p->hertz, &hz);
    out->p_h = hz.p_max;

    /* film at the inlet temperature (eq. 10, D7) */
    sc.lub = lub;
    hg_alpha_interp_init(lub, &sc.ai);
    sc.ln_a = log(lub->vogel_a);
    T_r = T_in > lub->vogel_c + HG_VOGEL_DT_MIN ? T_in : lub->vogel_c + HG_VOGEL_DT_MIN;
    if (T_r > HG_RHEO_T_MAX) T_r = HG_RHEO_T_MAX;
    ln_eta0_in = hg_vogel_ln_eta0(sc.ln_a, lub->vogel_b, lub->vogel_c, T_r);
    eta0_in = exp(ln_eta0_in);
    alpha_in = hg_alpha_interp_eval(&sc.ai, T_r, NULL);
    h_c = hg_film_chittenden(eta0_in, alpha_in, kin.u_e, W, E_star, out->R_e, out->R_s);
    if (!(h_c >= HG_EHL_H_MIN)) {
        h_c = HG_EHL_H_MIN;
        flags |= HG_EHL_H_FLOORED;
    }
    sigma_c = 1.41421356237309504880 * p->sigma_s;
    lam = h_c / sigma_c;
    out->h_c = h_c;
    out->lambda = lam;

    /* asperities (eqs. 11-13) */
    hg_greenwood_tripp(lam, p->eta_beta_sigma, p->sigma_over_beta, E_star, hz.A, &W_asp, &A_asp);
    if (A_asp > hz.A) A_asp = hz.A;
    A_visc = hz.A - A_asp;
    F_b = hg_boundary_friction(p->tau_0, p->varsigma_a, A_asp, W_asp);

    /* shear (eqs. 7-9) */
    gdot = (kin.v_s > HG_SPEED_FLOOR ? kin.v_s : HG_SPEED_FLOOR) / h_c;
    F_hn = hg_hn_factor(lub->hn_lambda, lub->hn_alpha, lub->hn_beta, gdot);
    sc.gdot_over_F = gdot / F_hn;
    sc.ln1p_p = log1p((p->shear_pressure == HG_SHEAR_P_MAX ? hz.p_max : hz.p_m) / HG_ROELANDS_P0);
    sc.tau_cap = p->Lambda_cap > 0.0 ? p->Lambda_cap * hz.p_m : HUGE_VAL;
    sc.z_exact = p->roelands_Z == HG_Z_EXACT;
    sc.T_last = sc.Z_last = sc.dZdT_last = 0.0;
    sc.eta = sc.Z = 0.0;

    /* thermal network (eqs. 16-19) */
    k_f = p->k_f_override > 0.0 ? p->k_f_override : lub->k_f;
    chi_s = p->k_s / (p->rho_s * p->c_s);
    l_p = hg_coleman_length(hz.s_y, hz.s_x, c->u_p[0], c->u_p[1]);
    l_g = hg_coleman_length(hz.s_y, hz.s_x, c->u_g[0], c->u_g[1]);
    R_fp = hg_moving_source_resistance(hz.A, p->k_s, chi_s, l_p, kin.U_p);
    R_fg = hg_moving_source_resistance(hz.A, p->k_s, chi_s, l_g, kin.U_g);
    R_cf = hg_film_resistance(h_c, k_f, hz.A);
    a_h = hg_heat_partition(R_fp, R_fg, R_cf);

    if (p->thermal) {
        hg_tc_problem pb;
        pb.T_in = T_in;
        pb.c0 = R_fp * a_h * F_b * kin.v_s;
        pb.c1 = kin.v_s * (R_fp * a_h * A_visc + h_c / (8.0 * k_f));
        pb.T_max = p->T_c_max;
        pb.tol = p->T_c_tol > 0.0 ? p->T_c_tol : 1e-6;
        pb.max_eval = 100;
        hg_tc_solve(&pb, shear_of_T, &sc, T_c_warm ? *T_c_warm : NAN, &tr);
        tau = tr.tau;
        out->T_c = tr.T_c;
        /* the last evaluation need not be at T_c: refresh eta and Z for the diagnostics */
        if (st) {
            double dtau;
            (void)shear_of_T(tr.T_c, &sc, &dtau);
        }
        if (tr.flags & HG_TC_CAPPED) flags |= HG_EHL_TC_CAPPED;
        if (tr.flags & HG_TC_NOT_CONVERGED) flags |= HG_EHL_TC_NOT_CONVERGED;
        if (tr.flags & HG_TC_HUGE_RISE) flags |= HG_EHL_HUGE_RISE;
    } else {
        double dtau;
        tau = shear_of_T(T_in, &sc, &dtau);
        tr.n_eval = 0;
        tr.dT_first = NAN;
    }

    /* friction (eqs. 5, 6, 11) */
    F_v = A_visc * tau;
    out->F_v = F_v;
    out->F_b = F_b;
    out->F_f = F_v + F_b;
    out->mu = out->F_f / W;

    /* regime parameters on the entrainment radius (physics 7), diagnostics only */
    U = eta0_in * (kin.u_e > HG_SPEED_FLOOR ? kin.u_e : HG_SPEED_FLOOR) / (E_star * out->R_e);
    G = alpha_in * E_star;
    W_e = W / (E_star * out->R_e * out->R_e);
    {
        double cW = cbrt(W_e), iU2 = 1.0 / (U * U);
        out->g_V = G * W_e * W_e * W_e * iU2; /* G W^3/U^2 */
        out->g_E = W_e * W_e * cW * cW * iU2; /* W^(8/3)/U^2 */
    }

    if (T_c_warm) *T_c_warm = out->T_c;
    if (st) {
        st->flags = flags | (p->Lambda_cap > 0.0 && tau >= sc.tau_cap ? HG_EHL_TAU_CAPPED : 0);
        st->n_eval = tr.n_eval;
        st->theta_e = hg_entrainment_angle(kin.U_e);
        st->hertz = hz;
        st->E_star = E_star;
        st->eta0_in = eta0_in;
        st->alpha_in = alpha_in;
        st->W_asp = W_asp;
        st->A_asp = A_asp;
        st->gamma_dot = gdot;
        st->F_hn = F_hn;
        st->l_p = l_p;
        st->l_g = l_g;
        st->R_fp = R_fp;
        st->R_fg = R_fg;
        st->R_cf = R_cf;
        st->a_h = a_h;
        st->dT_first = tr.dT_first;
        st->dT_flash = hg_flash_rise(R_fp, a_h, out->F_f * kin.v_s);
        st->dT_oil = hg_oil_rise(kin.v_s, tau, h_c, k_f);
        st->eta_c = sc.eta;
        st->Z_c = sc.Z;
        st->tau = tau;
    }
}
