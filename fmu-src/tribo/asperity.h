/* Asperity (boundary) contact: Greenwood-Tripp with Gaussian heights (paper eqs. 11-13,
 * docs/physics.md §5). Pure functions, SI units. */
#ifndef HG_TRIBO_ASPERITY_H
#define HG_TRIBO_ASPERITY_H

/* F_n(lambda) = 1/sqrt(2 pi) int_lambda^inf (s - lambda)^n exp(-s^2/2) ds.
 * F_2: closed form (1 + lambda^2) Q(lambda) - lambda phi(lambda), Q = erfc(lambda/sqrt 2)/2.
 * F_5/2: cubic Hermite in ln F_5/2 on the generated table (f52_table.h) for lambda in [0, 6],
 * asymptotic series beyond. Both return F(0) for lambda < 0 (the film ratio is never negative). */
double hg_gt_F2(double lambda);
double hg_gt_F52(double lambda);

/* Greenwood-Tripp load and real contact area (eqs. 12-13, prefactor 8 sqrt2/15 paired with the
 * paper's E* = E/(1-nu^2), docs/physics.md §5.2):
 *   W_asp = (8 sqrt2/15) pi (eta beta sigma)^2 sqrt(sigma/beta) E* A_EHL F_5/2(lambda_s)   [N]
 *   A_asp = pi^2 (eta beta sigma)^2 A_EHL F_2(lambda_s)                                   [m^2]
 * lambda_s = h_c/sigma_c; eta_beta_sigma = eta_s beta_s sigma_c; sigma_over_beta is the
 * composite sigma_c/beta_s. */
void hg_greenwood_tripp(double lambda_s, double eta_beta_sigma, double sigma_over_beta,
                        double E_star, double A_EHL, double *W_asp, double *A_asp);

/* Boundary friction F_b = tau_0 A_asp + varsigma_a W_asp [N] (eq. 11). */
double hg_boundary_friction(double tau_0, double varsigma_a, double A_asp, double W_asp);

#endif
