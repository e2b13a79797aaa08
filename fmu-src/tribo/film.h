/* Central film thickness of an elliptical EHL conjunction (docs/physics.md §3). */
#ifndef HG_TRIBO_FILM_H
#define HG_TRIBO_FILM_H

/* Chittenden et al. 1985 at entrainment angle theta_e (paper eq. 10):
 *   h_c = 4.31 R_e U_e^0.68 G^0.49 W_e^-0.073 [1 - exp(-1.23 (R_s/R_e)^(2/3))]
 *   U_e = eta_0 u_e/(E* R_e), G = alpha* E*, W_e = W/(E* R_e^2)
 * eta_0 [Pa s] and alpha* [1/Pa] at the inlet temperature (D7 of docs/physics.md §0), u_e = |U_e| [m/s],
 * W [N], E* the paper's E/(1-nu^2) [Pa], R_e, R_s [m]. Returns h_c [m]; 0 when u_e, W or
 * eta_0 is not positive (the caller floors it). */
double hg_film_chittenden(double eta0, double alpha_star, double u_e, double W, double E_star,
                          double R_e, double R_s);

#endif
