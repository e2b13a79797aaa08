/* Lubricant rheology (docs/physics.md §4; paper eqs. 7-8): Vogel eta_0(T), alpha*(T), Roelands
 * eta(p, T) with Z from alpha* (simple or exact), Havriliak-Negami shear thinning.
 * Temperatures in K, pressures in Pa, viscosities in Pa s. Pure functions. */
#ifndef HG_TRIBO_RHEOLOGY_H
#define HG_TRIBO_RHEOLOGY_H

#include "tribo/lubricant.h"

#define HG_ROELANDS_P0 1.96e8     /* [Pa] (1/p0 = 5.1e-9 1/Pa) */
#define HG_ROELANDS_LN_ETA_R 9.67 /* -ln(6.31e-5 Pa s) */
/* Guards (docs/physics.md §4.3): the Roelands index A = ln eta_0 + 9.67 is floored at HG_ROELANDS_A_MIN
 * (eta_0 >= 0.17 mPa s; our oils have A >= 2.8 up to 300 degC); Vogel is evaluated at
 * T >= c + HG_VOGEL_DT_MIN (its pole is at T = c); ln eta is capped at HG_LN_ETA_MAX. These only
 * act far outside the range of gear oils and keep every result finite. */
#define HG_ROELANDS_A_MIN 1.0
#define HG_VOGEL_DT_MIN 40.0
#define HG_LN_ETA_MAX 230.0
/* hg_ehl_pair evaluates the rheology (Vogel, alpha*) at T clamped to
 * [c + HG_VOGEL_DT_MIN, HG_RHEO_T_MAX]: beyond 500 degC any extrapolation of gear-oil data is
 * meaningless, and the cap keeps the extrapolated alpha* away from zero. */
#define HG_RHEO_T_MAX 773.15

/* ln eta_0 = ln a + b/(T - c), T clamped to >= c + HG_VOGEL_DT_MIN (Vogel). */
double hg_vogel_ln_eta0(double ln_a, double b, double c, double T);

/* alpha*(T) interpolant of docs/physics.md §4.2 with its coefficients computed once: the quadratic through
 * the three data points inside [alpha_T[0], alpha_T[2]], log-linear outside with the slope of
 * ln alpha* of the quadratic at the nearest end (C1-continuous). */
typedef struct {
    double T0, T1, T2; /* data temperatures [K] */
    double y0, y2;     /* alpha* at T0 and T2 [1/Pa] */
    double d1, d2;     /* Newton divided differences of the quadratic */
    double s0, s2;     /* d ln alpha* / dT of the quadratic at T0 and T2 [1/K] */
} hg_alpha_interp;

/* Z_exact of one lubricant over the temperatures the rheology is evaluated at
 * ([c + HG_VOGEL_DT_MIN, HG_RHEO_T_MAX]), tabulated: cubic Hermite between nodes at most
 * HG_ZTAB_DT apart, from Z_exact and its exact temperature derivative at each node. The nodes
 * include the alpha* data temperatures alpha_T[0] and alpha_T[2], where alpha*(T) joins its
 * quadratic and log-linear pieces (its curvature jumps there), so Z(T) is smooth within every
 * cell; interpolated, it stays within 2e-11 of Z_exact (tests/c/test_ehl_properties.c). Cells
 * with a node outside Z_exact's validated domain (where it falls back to Z_simple) are solved
 * directly. Read-only once built: one table serves every evaluation of the lubricant. */
#define HG_ZTAB_DT 0.5 /* [K] */
#define HG_ZTAB_MAX 2400
typedef struct {
    double T_node[3]; /* starts of the three uniform segments: T_lo, alpha_T[0], alpha_T[2] */
    double dT[3];     /* their node spacings [K] */
    int first[4];     /* index of each segment's first node; first[3] = number of nodes */
    double Z[HG_ZTAB_MAX], dZ[HG_ZTAB_MAX]; /* Z_exact and dZ/dT [1/K] at the nodes */
    unsigned char exact[HG_ZTAB_MAX];        /* the node lies in Z_exact's validated domain */
} hg_z_table;

/* The rheology of one lubricant, evaluated temperature by temperature (docs/physics.md §4): build it once
 * per call of the friction model with hg_rheology_init. It carries the warm start of Z_exact
 * between temperatures, so it is the caller's scratch, not shared data. */
typedef struct {
    const hg_lubricant *lub;
    hg_alpha_interp ai; /* alpha*(T) coefficients */
    double ln_a;        /* ln of Vogel a */
    int z_exact;        /* Z from Blok's alpha* exactly (1) or Z_simple (0) */
    const hg_z_table *z_table; /* Z_exact tabulated (z_exact), or NULL: solved at each T */
    double T_last, Z_last, dZdT_last; /* previous Z_exact (warm start) */
} hg_rheology;

/* The rheology at one temperature, with the temperature derivatives [1/K]. The rheology is
 * evaluated at T clamped to [c + HG_VOGEL_DT_MIN, HG_RHEO_T_MAX]; where clamped, the derivatives
 * of ln eta_0 and ln alpha* are 0. */
typedef struct {
    double T_r;     /* the clamped temperature [K] */
    double ln_eta0; /* Vogel ln eta_0 [ln Pa s] */
    double A;       /* Roelands index (hg_roelands_A) */
    double alpha;   /* alpha*(T_r) [1/Pa] */
    double Z;       /* Roelands Z (0 until hg_rheology_Z) */
    double dL0, dA, dlnalpha, dZ; /* d/dT of ln eta_0, A, ln alpha*, Z */
} hg_rheo_state;

/* z_table: the lubricant's Z_exact table (hg_z_table_build) when z_exact, or NULL. */
void hg_rheology_init(hg_rheology *r, const hg_lubricant *lub, int z_exact,
                      const hg_z_table *z_table);

/* Fills t for lub (about a thousand Z_exact solves, each warm-started from the node before). */
void hg_z_table_build(hg_z_table *t, const hg_lubricant *lub);

/* ln eta_0, A and alpha* at T (everything but Z). */
void hg_rheology_at(const hg_rheology *r, double T, hg_rheo_state *s);

/* Adds Z and dZ/dT at the same T to *s (Z_exact warm-started from the previous call). */
void hg_rheology_Z(hg_rheology *r, double T, hg_rheo_state *s);

/* Roelands ln eta(p, T) = ln eta_0 + A [(1 + p/p0)^Z - 1] given ln1p_p = ln(1 + p/p0), capped at
 * HG_LN_ETA_MAX, and in *dlneta_dT its temperature derivative [1/K] (paper eq. 9). */
double hg_roelands_ln_eta(const hg_rheo_state *s, double ln1p_p, double *dlneta_dT);

/* Roelands index A = max(ln eta_0 + 9.67, HG_ROELANDS_A_MIN). */
double hg_roelands_A(double ln_eta0);

/* Z_simple = alpha* p0 / A: the Roelands initial slope equals alpha*. */
double hg_roelands_Z_simple(double alpha_star, double A);

/* Validated domain of Z_exact: alpha* p0 >= HG_Z_EXACT_S_MIN (alpha* >= 0.05 1/GPa) and
 * A <= HG_Z_EXACT_A_MAX; outside it (only reachable by extrapolating alpha*(T) far beyond the
 * data) Z_exact falls back to Z_simple. */
#define HG_Z_EXACT_S_MIN 0.0098
#define HG_Z_EXACT_A_MAX 300.0

/* Z_exact: the Z for which Blok's alpha* = [int_0^inf eta(0)/eta(p) dp]^-1 of the Roelands law
 * equals the given alpha*. With u = A((1+p/p0)^Z - 1) the integral is (p0/(Z A)) L, and
 * L = int_0^inf e^-u (1+u/A)^(1/Z-1) du = A e^A A^(-1/Z) Gamma(1/Z, A), so
 * alpha* p0 = Z / C(1/Z, A) with C(a, x) = e^x x^-a Gamma(a, x) evaluated by its continued
 * fraction (no quadrature); solved by Newton on ln(1/Z) (relative accuracy ~1e-14, hence smooth
 * in T). Z_guess > 0 warm-starts it (<= 0: none).
 * dZ_dA and dZ_dlnalpha (may be NULL) receive the partial derivatives of Z_exact with respect to
 * A and ln alpha*, by implicit differentiation. Returns 0 when alpha* <= 0. */
double hg_roelands_Z_exact(double alpha_star, double A, double Z_guess, double *dZ_dA,
                           double *dZ_dlnalpha);

/* Havriliak-Negami F(gamma_dot) = (1 + (lambda gamma_dot)^alpha_HN)^beta_HN (paper eq. 8);
 * the shear stress is tau = eta gamma_dot / F (eq. 7). */
double hg_hn_factor(double lambda, double alpha_hn, double beta_hn, double gamma_dot);

/* Limiting shear stress (Bair and Winer 1979, smooth): tau = tau_L (1 - exp(-tau_v/tau_L)) for
 * tau_L > 0, else tau_v; *slope = dtau/dtau_v in (0, 1]. Equals tau_v for tau_v << tau_L and
 * approaches tau_L from below. */
double hg_shear_limit(double tau_v, double tau_L, double *slope);

#endif
