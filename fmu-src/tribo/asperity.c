/* Greenwood-Tripp asperity contact: see asperity.h. */
#include "tribo/asperity.h"

#include <math.h>

#include "io/constants.h"
#include "tribo/contact.h"
#include "tribo/f52_table.h"

#define SQRT_2PI 2.50662827463100050242
#define LN_GAMMA_7_2 1.2009736023470742 /* ln Gamma(3.5) = ln(15 sqrt(pi)/8) */

double hg_gt_F2(double lambda)
{
    double Q, phi, f;
    if (!(lambda > 0.0)) return 0.5; /* F_2(0) = 1/2 */
    Q = 0.5 * erfc(lambda / 1.41421356237309504880);
    phi = exp(-0.5 * lambda * lambda) / SQRT_2PI;
    f = (1.0 + lambda * lambda) * Q - lambda * phi;
    return f > 0.0 ? f : 0.0; /* rounding only; the exact value is positive */
}

/* ln F_5/2 beyond the table: asymptotic series of Gamma(n+1) e^(-l^2/4) D_(-n-1)(l)/sqrt(2 pi)
 * plus the matching term of f52_table.h. */
static double ln_f52_asym(double lambda)
{
    const double n = 2.5;
    double inv2 = 1.0 / (lambda * lambda), term = 1.0, sum = 1.0, r;
    int k;
    for (k = 1; k < HG_F52_ASYM_TERMS; k++) {
        term *= -(n + 2.0 * k - 1.0) * (n + 2.0 * k) * 0.5 * inv2 / k;
        sum += term;
    }
    r = HG_F52_LAMBDA_MAX / lambda;
    r *= r;
    return LN_GAMMA_7_2 - log(SQRT_2PI) - 0.5 * lambda * lambda - 3.5 * log(lambda) + log(sum) +
           HG_F52_ASYM_LN_SCALE * pow(r, HG_F52_ASYM_TERMS);
}

double hg_gt_F52(double lambda)
{
    double x, t, h = HG_F52_STEP, t2, t3, lnf;
    int i;
    if (!(lambda > 0.0)) return exp(hg_f52_ln[0]);
    if (lambda >= HG_F52_LAMBDA_MAX) {
        if (lambda > 40.0) return 0.0; /* exp(-800) underflows anyway */
        return exp(ln_f52_asym(lambda));
    }
    x = lambda / h;
    i = (int)x;
    if (i > HG_F52_COUNT - 2) i = HG_F52_COUNT - 2;
    t = x - i;
    t2 = t * t;
    t3 = t2 * t;
    /* cubic Hermite on ln F_5/2 with the tabulated slopes */
    lnf = (2.0 * t3 - 3.0 * t2 + 1.0) * hg_f52_ln[i] + (t3 - 2.0 * t2 + t) * h * hg_f52_dln[i] +
          (-2.0 * t3 + 3.0 * t2) * hg_f52_ln[i + 1] + (t3 - t2) * h * hg_f52_dln[i + 1];
    return exp(lnf);
}

void hg_greenwood_tripp(double lambda_s, double eta_beta_sigma, double sigma_over_beta,
                        double E_star, double A_EHL, double *W_asp, double *A_asp)
{
    double ebs2 = eta_beta_sigma * eta_beta_sigma;
    /* eq. 12 with 8 sqrt(2)/15 and the paper's E* */
    *W_asp = (8.0 * 1.41421356237309504880 / 15.0) * HG_PI * ebs2 * sqrt(sigma_over_beta) *
             E_star * A_EHL * hg_gt_F52(lambda_s);
    /* eq. 13 */
    *A_asp = HG_PI * HG_PI * ebs2 * A_EHL * hg_gt_F2(lambda_s);
}

double hg_boundary_friction(double tau_0, double varsigma_a, double A_asp, double W_asp)
{
    return tau_0 * A_asp + varsigma_a * W_asp; /* eq. 11 */
}
