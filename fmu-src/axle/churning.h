/* Churning of a gear dipping into an oil sump: Changenet and Velex's dimensionless drag torque.
 *
 * Sources (the formulas and constants):
 *   C. Changenet, P. Velex, "A model for the prediction of churning losses in geared
 *   transmissions - preliminary results", ASME J. Mech. Des. 129(1), 128-133, 2007 (eq. for
 *   C_m at low and moderate speeds);
 *   C. Changenet, P. Velex, "Housing influence on churning losses in geared transmissions",
 *   ASME J. Mech. Des. 130(6), 062603, 2008 (the critical Reynolds number and the high-speed
 *   C_m that depends on the face width).
 * Everything in SI units; the model layer supplies the oil's density and viscosity at T_oil. */
#ifndef HG_AXLE_CHURNING_H
#define HG_AXLE_CHURNING_H

/* Geometry of the dipping gear, idealised as a disc of the pitch radius R_p: */
typedef struct {
    double R_p; /* pitch radius [m] (the ring gear's outer pitch radius) */
    double b;   /* face width [m] */
    double h;   /* immersion depth: oil level above the lowest point of the pitch circle [m], 0 < h <= R_p */
    double V_0; /* oil volume of the sump [m^3] */
} hg_churn_geom;

/* Wetted area of a disc of radius R_p and width b immersed to the depth h (both faces and the
 * periphery): S_m = R_p^2 (2 theta - sin 2 theta) + 2 R_p b theta, theta = acos(1 - h/R_p). */
double hg_churn_submerged_area(double R_p, double b, double h);

/* Dimensionless churning torque C_m, with D_p = 2 R_p, Fr = omega^2 R_p / g, Re = omega R_p b / nu
 * and the immersion's Reynolds number Re_c = omega R_p h / nu:
 *   Re_c <= 6000 (Changenet & Velex 2007):
 *     C_m = C_low(Fr, Re) = 1.366 (h/D_p)^0.45 (V_0/D_p^3)^0.1 Fr^-0.6 Re^-0.21
 *   Re_c > 6000, the inertial regime, in which the torque no longer depends on viscosity:
 *     C_m = min(C_low(Fr, 6000 b/h), C_high),
 *     C_high = 3.644 (h/D_p)^0.1 (V_0/D_p^3)^-0.35 Fr^-0.88 (b/D_p)^0.85 (Changenet & Velex 2008)
 * i.e. the low-speed formula at the Reynolds number where it ends, or the high-speed formula
 * where that is smaller. Continuous wherever C_high >= C_low at Re_c = 6000 (every built-in
 * ring gear at the default oil level and volume, up to 27 000 r/min of the pinion), and never
 * increasing as the oil thins at a given speed (our choice, docs/axle.md: the two published
 * formulas differ by 2-5 times at Re_c = 6000 for these ring gears).
 * omega [rad/s] > 0, nu [m^2/s]. */
double hg_churn_cm(const hg_churn_geom *g, double nu, double omega);

/* Churning torque magnitude C_ch = 1/2 rho omega^2 S_m R_p^3 C_m [N m] (Changenet & Velex 2007),
 * rho [kg/m^3], nu [m^2/s], omega [rad/s] of either sign (0 gives 0). The loss is C_ch |omega|. */
double hg_churn_torque(const hg_churn_geom *g, double rho, double nu, double omega);

/* The parts of C_m and C_ch that depend on the geometry alone (the wetted area S_m, R_p^3 and
 * the constant sums of logarithms), computed once; the *_at forms take them and give results
 * identical to hg_churn_cm and hg_churn_torque bit for bit. */
typedef struct {
    double S_m, R3;                 /* [m^2], [m^3] */
    double ln_low0, ln_low_re_c;    /* ln(1.366 (h/D_p)^0.45 (V_0/D_p^3)^0.1), 0.21 ln(6000 b/h) */
    double ln_high0, ln_high_b;     /* ln(3.644 (h/D_p)^0.1 (V_0/D_p^3)^-0.35), 0.85 ln(b/D_p) */
    double ln_R_g, ln_R_b;          /* ln(R_p / g), ln(R_p b): ln Fr and ln Re from ln omega */
} hg_churn_terms;
void hg_churn_terms_of(const hg_churn_geom *g, hg_churn_terms *t);
double hg_churn_cm_at(const hg_churn_geom *g, const hg_churn_terms *t, double nu, double omega);
double hg_churn_torque_at(const hg_churn_geom *g, const hg_churn_terms *t, double rho, double nu,
                          double omega);
/* The same from ln nu and ln |omega| given as well (a caller that has them), so that Fr and Re
 * need no logarithm of their own: ln Fr = 2 ln omega + ln(R_p / g), ln Re = ln omega + ln(R_p b)
 * - ln nu (equal to hg_churn_torque_at's to rounding). */
double hg_churn_torque_ln(const hg_churn_geom *g, const hg_churn_terms *t, double rho, double nu,
                          double ln_nu, double omega, double ln_omega);

#endif
