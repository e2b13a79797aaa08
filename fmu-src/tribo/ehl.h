/* Mixed-EHL conjunctional friction and thermal model of one hypoid flank pair (paper section
 * 2.2, eqs. 5-19; docs/physics.md §1–7). The entry point consumes the seam struct hg_pair_contact and
 * fills hg_pair_friction (tribo/pair_contact.h).
 *
 * Pure: the result depends only on the arguments. The only state carried between calls is the
 * caller's warm start *T_c_warm. No caching struct is needed: the full thermal evaluation costs
 * well under 1 us per pair (bench/bench_ehl.c), dominated by the exact Hertz solve and a few
 * exp() per T_c iteration. */
#ifndef HG_TRIBO_EHL_H
#define HG_TRIBO_EHL_H

#include "tribo/contact.h"
#include "tribo/lubricant.h"
#include "tribo/rheology.h"
#include "tribo/pair_contact.h"

typedef enum { HG_Z_SIMPLE = 0, HG_Z_EXACT = 1 } hg_roelands_z_mode;
/* The pressure of the shear stress: one pressure (p_m, p_max), or the mean of the stress over the
 * Hertzian pressure field (8-point Gauss quadrature over the ellipse). */
typedef enum { HG_SHEAR_P_MEAN = 0, HG_SHEAR_P_MAX = 1, HG_SHEAR_P_HERTZ = 2 } hg_shear_pressure;
/* The Havriliak-Negami relaxation time: constant (the paper), or following the viscosity
 * (time-temperature-pressure superposition, lambda = lambda_0 eta(p, T)/eta_0(HG_HN_T_REF)). */
typedef enum { HG_RELAX_CONSTANT = 0, HG_RELAX_TTS = 1 } hg_relaxation;
#define HG_HN_T_REF 343.15 /* [K] where Table 2's lambda_0 was measured (70 degC, ambient p) */

#define HG_EHL_LOAD_MIN 1.0 /* [N] below this the pair carries no friction (docs/physics.md §13.14) */
#define HG_EHL_H_MIN 1e-9   /* [m] floor on h_c */

typedef struct {
    double E;               /* Young's modulus of both flanks [Pa] (210e9, assumed) */
    double nu;              /* Poisson's ratio [-] (0.30, assumed) */
    double E_star;          /* paper's E* = E/(1-nu^2) [Pa]; > 0 overrides E and nu (default 0) */
    double k_s;             /* steel conductivity [W/(m K)] (30, paper) */
    double rho_s;           /* steel density [kg/m^3] (7850) */
    double c_s;             /* steel specific heat [J/(kg K)] (460) */
    double tau_0;           /* boundary shear strength [Pa] (2e6, paper eq. 11) */
    double varsigma_a;      /* pressure coefficient of boundary shear [-] (0.17, paper) */
    double sigma_s;         /* RMS roughness of each flank [m] (0.25e-6); sigma_c = sqrt2 sigma_s */
    double eta_beta_sigma;  /* eta_s beta_s sigma_c [-] (0.0104, paper) */
    double sigma_over_beta; /* composite sigma_c/beta_s [-] (1e-3) */
    double T_inlet_rise;    /* T_in = T_bath + this [K] (20, paper eq. 15) */
    double Lambda_cap;      /* limiting shear coefficient Lambda: each pressure's stress limited
                               smoothly to Lambda p (hg_shear_limit); 0 = off (default) */
    double k_f_override;    /* lubricant conductivity [W/(m K)]; <= 0: the lubricant's k_f */
    double T_c_max;         /* cap on T_c [K] (573.15) */
    double T_c_tol;         /* convergence of T_c [K] (1e-6) */
    int hertz;              /* hg_hertz_mode (HG_HERTZ_EXACT) */
    int roelands_Z;         /* hg_roelands_z_mode (HG_Z_SIMPLE) */
    const hg_z_table *z_table; /* the lubricant's Z_exact over T (hg_z_table_build) for
                                  HG_Z_EXACT, or NULL: Z_exact solved at each temperature */
    int shear_pressure;     /* hg_shear_pressure (HG_SHEAR_P_MEAN) */
    int relaxation;         /* hg_relaxation (HG_RELAX_CONSTANT) */
    int thermal;            /* 1: solve T_c (default); 0: isothermal, shear at T_in */
    int inlet_heating;      /* 1: the film thinned by the inlet's shear heating (Gupta et al.'s
                               thermal reduction factor, film.h); 0: isothermal film (the paper) */
} hg_ehl_params;

/* Diagnostics, filled by hg_ehl_pair_ex when a non-NULL pointer is passed. */
enum {
    HG_EHL_NO_CONTACT = 1,   /* W < HG_EHL_LOAD_MIN or invalid geometry: no friction */
    HG_EHL_H_FLOORED = 2,    /* h_c raised to HG_EHL_H_MIN */
    HG_EHL_TAU_CAPPED = 4,   /* limiting shear dominant at T_c: tau >= Lambda p_m / 2 */
    HG_EHL_TC_CAPPED = 8,    /* T_c at T_c_max */
    HG_EHL_TC_NOT_CONVERGED = 16,
    HG_EHL_HUGE_RISE = 32    /* isothermal first-guess rise > 1000 K (cold starts only) */
};

typedef struct {
    int flags;          /* HG_EHL_* */
    int n_eval;         /* evaluations of tau(T) in the T_c solve (0 when isothermal) */
    double T_in;        /* [K] */
    double theta_e;     /* entrainment angle from the minor axis [rad] */
    hg_hertz hertz;     /* k, a_c, b_c, A, p_m, p_max, ... */
    double E_star;      /* [Pa] */
    double eta0_in;     /* eta_0(T_in) [Pa s] */
    double alpha_in;    /* alpha*(T_in) [1/Pa] */
    double phi_T;       /* inlet-heating reduction of the film [-] (1 without it) */
    double W_asp;       /* [N] */
    double A_asp;       /* [m^2] */
    double gamma_dot;   /* [1/s] */
    double F_hn;        /* Havriliak-Negami factor [-] */
    double l_p, l_g;    /* Coleman lengths [m] */
    double R_fp, R_fg, R_cf; /* [K/W] */
    double a_h;         /* heat partition to the pinion [-] */
    double dT_first;    /* isothermal first-guess rise [K] (NaN unless computed) */
    double dT_flash;    /* (Delta T_f)_av at T_c [K] */
    double dT_oil;      /* (Delta T_oil)_av at T_c [K] */
    double eta_c;       /* eta(p, T_c) [Pa s] */
    double Z_c;         /* Roelands Z at T_c */
    double tau;         /* shear stress at T_c [Pa] */
} hg_ehl_stats;

/* Defaults of every field (values in the comments above). */
void hg_ehl_params_default(hg_ehl_params *p);

/* One flank pair. *T_c_warm: the caller's warm start for T_c [K] (NaN or <= 0: none), set to the
 * new T_c on return (T_in when there is no contact or no heating). Every field of *out is
 * written; never NaN/Inf for finite inputs. Loads below HG_EHL_LOAD_MIN: zero forces and film
 * fields, T_c = T_in. */
void hg_ehl_pair(const hg_ehl_params *p, const hg_lubricant *lub, const hg_pair_contact *c,
                 double *T_c_warm, hg_pair_friction *out);

/* Same, with optional diagnostics (stats may be NULL). */
void hg_ehl_pair_ex(const hg_ehl_params *p, const hg_lubricant *lub, const hg_pair_contact *c,
                    double *T_c_warm, hg_pair_friction *out, hg_ehl_stats *stats);

/* The Hertz ellipse hg_ehl_pair solves for c (its load and radii, p's E* and Hertz mode; zeroed
 * where hg_ehl_pair finds no contact), for a caller that evaluates one load and geometry at
 * several speeds or temperatures: hg_ehl_pair_hertz then takes it instead of solving it again,
 * with the same result to the last bit. */
void hg_ehl_hertz(const hg_ehl_params *p, const hg_pair_contact *c, hg_hertz *h);
void hg_ehl_pair_hertz(const hg_ehl_params *p, const hg_lubricant *lub,
                       const hg_pair_contact *c, const hg_hertz *h, double *T_c_warm,
                       hg_pair_friction *out);

#endif
