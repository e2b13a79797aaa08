/* Lubricant properties (paper Table 2, docs/physics.md §4, §6.5) and the lubricant data file
 * "hypoid-lubricant 1" (docs/data-files.md). */
#ifndef HG_TRIBO_LUBRICANT_H
#define HG_TRIBO_LUBRICANT_H

#include <stddef.h>

#define HG_LUBRICANT_NAME_LEN 80
#define HG_LUBRICANT_K_F_MIN 0.01 /* lowest thermal conductivity a file may give [W/(m K)] */
#define HG_LUBRICANT_ETA_COLD 150.0 /* SAE J306: a gear oil's low-temperature viscosity limit,
                                       150 000 mPa s, that sets its W grade [Pa s] */
#define HG_LUBRICANT_T_BEYOND 40.0  /* K beyond the highest pressure-viscosity datum */

typedef struct {
    char name[HG_LUBRICANT_NAME_LEN]; /* human-readable name */
    double vogel_a;       /* Vogel eta_0 = a exp(b/(T - c)): a [Pa s] */
    double vogel_b;       /* b [K] */
    double vogel_c;       /* c [K] */
    double alpha_T[3];    /* temperatures of the alpha* data [K], strictly increasing */
    double alpha_star[3]; /* reciprocal asymptotic isoviscous pressure coefficient [1/Pa] */
    double hn_lambda;     /* Havriliak-Negami relaxation time lambda [s] (paper eq. 8) */
    double hn_alpha;      /* alpha_HN [-] */
    double hn_beta;       /* beta_HN [-] */
    double k_f;           /* thermal conductivity [W/(m K)] */
    double c_p_f;         /* specific heat [J/(kg K)] (not used by eqs. 14-19) */
    double rho_15;        /* density at 15 degC [kg/m^3] (informative) */
} hg_lubricant;

/* Reads a "hypoid-lubricant 1" file into *lub, checking each value's range and, across keys:
 * alpha*(T) of docs/physics.md §4.2 non-increasing on [alpha_T[0], alpha_T[2]], the Vogel pole c at least
 * 40 K below alpha_T[0], hn_alpha hn_beta <= 1. Returns 0, or -1 with err naming the file and,
 * where there is one, the line. *lub is only written on success. */
int hg_lubricant_load(const char *path, hg_lubricant *lub, char *err, size_t errlen);

/* The oil temperatures [K] the lubricant's data describe: from where its Vogel viscosity falls
 * to SAE J306's low-temperature limit HG_LUBRICANT_ETA_COLD, T_lo = c + b / ln(eta/a), to
 * HG_LUBRICANT_T_BEYOND above its highest pressure-viscosity datum. */
void hg_lubricant_T_range(const hg_lubricant *lub, double *T_lo, double *T_hi);

#endif
