/* Conjunction temperature (paper eqs. 14-19 with correction D2, docs/physics.md §6): moving-source and
 * film resistances, heat partition, Coleman active length, and the implicit T_c solve.
 * Pure functions, SI units, temperatures in K. */
#ifndef HG_TRIBO_THERMAL_H
#define HG_TRIBO_THERMAL_H

#define HG_SPEED_FLOOR 1e-6 /* [m/s] floor for speeds that divide (docs/physics.md §4.5) */

/* Coleman active length (eq. 19): half-chord of the ellipse along the direction of motion of a
 * surface moving with (u, v), u along the minor axis (semi-axis b_c) and v along the major axis
 * (a_c): l = sqrt(a^2 b^2 (tan^2 theta + 1)/(a^2 + b^2 tan^2 theta)), tan theta = v/u.
 * Returns b_c when u = v = 0. [m] */
double hg_coleman_length(double a_c, double b_c, double u, double v);

/* Moving-heat-source resistance R_f,i = 1.06/(A k_s) sqrt(chi_s l_i/U_tot,i) [K/W] (eq. 18; D2 of docs/physics.md §0);
 * U_tot is floored at HG_SPEED_FLOOR. */
double hg_moving_source_resistance(double A, double k_s, double chi_s, double l, double U_tot);

/* Conduction through half the film R_c,f = h_c/(2 k_f A) [K/W] (eq. 18). */
double hg_film_resistance(double h_c, double k_f, double A);

/* Fraction of the heat entering the pinion a_h = (R_f,g + R_c,f)/(R_f,p + R_f,g + 2 R_c,f)
 * (eq. 17). */
double hg_heat_partition(double R_fp, double R_fg, double R_cf);

/* (Delta T_f)_av = R_f,p a_h q, q = F_f |V_s| [K] (eq. 16). */
double hg_flash_rise(double R_fp, double a_h, double q);

/* (Delta T_oil)_av = |V_s| tau h_c/(8 k_f) [K] (eq. 16). */
double hg_oil_rise(double v_s, double tau, double h_c, double k_f);

/* The implicit problem of docs/physics.md §6.6:
 *   g(T) = T_in + c0 + c1 tau(T) - T = 0,
 * c0 = R_f,p a_h F_b |V_s| [K] and c1 = |V_s| (R_f,p a_h (A_EHL - A_asp) + h_c/(8 k_f)) [K/Pa]
 * (eqs. 14, 16 with q = F_f |V_s|, F_f = (A_EHL - A_asp) tau + F_b); tau(T) is the shear stress
 * [Pa], non-increasing in T, so g is strictly decreasing with one root in
 * [T_in, T_in + g(T_in)]. */
typedef struct {
    double T_in;  /* inlet temperature [K] */
    double c0;    /* [K] >= 0 */
    double c1;    /* [K/Pa] >= 0 */
    double T_max; /* cap on T_c [K]; T_c = max(T_in, T_max) when g stays positive up to it */
    double tol;   /* absolute tolerance on T_c [K], e.g. 1e-6 */
    int max_eval; /* cap on evaluations of tau(T), e.g. 100 */
} hg_tc_problem;

enum {
    HG_TC_CAPPED = 1,      /* root above T_max: T_c = max(T_in, T_max) */
    HG_TC_NOT_CONVERGED = 2, /* max_eval reached; best bracket end returned */
    HG_TC_HUGE_RISE = 4    /* g(T_in) > 1000 K (only detected on a cold start) */
};

typedef struct {
    double T_c;      /* [K] */
    double tau;      /* tau(T_c) [Pa] */
    double dT_first; /* g(T_in) = isothermal first-guess rise [K], NaN when not evaluated */
    int n_eval;      /* evaluations of tau(T) */
    int flags;       /* HG_TC_* */
} hg_tc_result;

/* tau(T) [Pa] and, in *dtau_dT, its derivative [Pa/K] (used only to place the first points:
 * an approximate or NaN derivative costs iterations, never correctness). */
typedef double (*hg_tau_fn)(double T, void *ctx, double *dtau_dT);

/* Guaranteed-convergent solve of g(T) = 0 to |T_c - root| <= pb->tol (never plain
 * substitution):
 *  1. seed: safeguarded Newton steps from T_warm (the previous T_c; NaN or <= T_in for none) or
 *     from T_in; every evaluated point tightens a sign bracket [a: g >= 0, b: g <= 0]; a point
 *     where |g| <= tol/4 is within tol/4 of the root (g falls with slope <= -1, below), and its
 *     Newton step ends the solve there; else, once a step is below tol/4, one probe just beyond
 *     the root closes a bracket narrower than tol;
 *  2. complete the bracket if needed with fixed-point images T + g(T), which land on the far
 *     side of the root because g is decreasing with slope <= -1 (from g > 0 at or beyond the
 *     root, from g < 0 at or below it and never below T_in), expanding up to T_max otherwise;
 *  3. Brent's method (inverse quadratic interpolation, secant, bisection) on the bracket.
 * The result is that last Newton step's end, with tau carried along its derivative, or the chord
 * root of the final bracket (width <= tol), with tau interpolated along the chord, so T_c and
 * tau are smooth functions of the inputs between the points where the number of evaluations
 * changes, and move by far less than tol there. */
void hg_tc_solve(const hg_tc_problem *pb, hg_tau_fn tau_of_T, void *ctx, double T_warm,
                 hg_tc_result *res);

#endif
