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

/* Thermal reduction factor of the central film for the shear heating of the inlet (Gupta, Cheng,
 * Zhu, Forster, Schrand, Tribol. Trans. 35 (1992) 269-274):
 *   phi_T = (1 - 13.2 (p_h/E*) L^0.42) / (1 + 0.213 (1 + 2.23 S^0.83) L^0.64)
 * with the thermal loading L = beta eta_0 u_e^2 / k_f (beta = -d ln eta_0/dT [1/K], eta_0 [Pa s]
 * and k_f [W/(m K)] at the inlet temperature, u_e the entrainment speed [m/s]) and the
 * slide-to-roll ratio S = |V_s|/u_e. The numerator is floored at 0 (it falls below zero only at
 * thermal loadings beyond those of the fit, where the denominator already thins the film a
 * hundredfold). Returns phi_T in [0, 1]; 1 when L = 0. */
double hg_film_thermal_reduction(double L, double srr, double ph_over_E);

#endif
