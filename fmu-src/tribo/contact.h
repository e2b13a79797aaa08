/* Contact geometry of one flank pair: kinematics in the ellipse frame and the Hertzian ellipse
 * (docs/physics.md §1–2, paper section 2.2). Frame: x along the minor axis of the contact ellipse
 * (across the contact line), y along the major axis. Pure functions, SI units. */
#ifndef HG_TRIBO_CONTACT_H
#define HG_TRIBO_CONTACT_H

/* Ratios R_y/R_x above this are treated as this (line-contact limit, k ~ 2.5e4). */
#define HG_HERTZ_RATIO_MAX 1e8

typedef enum {
    HG_HERTZ_EXACT = 0, /* ellipticity from the elliptic-integral equation (Halley on ln k) */
    HG_HERTZ_APPROX = 1 /* Hamrock-Brewe 1983 curve fits */
} hg_hertz_mode;

/* Entrainment and sliding (docs/physics.md §1; paper eq. 9, 10 inputs). */
typedef struct {
    double U_e[2];  /* entrainment vector (u_p + u_g)/2 [m/s] */
    double u_e;     /* |U_e| [m/s] */
    double V_s[2];  /* sliding vector u_p - u_g [m/s] */
    double v_s;     /* |V_s| [m/s] */
    double cos2_e;  /* cos^2 theta_e, theta_e measured from the MINOR axis (1 when u_e = 0) */
    double sin2_e;  /* sin^2 theta_e */
    double U_p;     /* U_tot,p = |u_p| [m/s] */
    double U_g;     /* U_tot,g = |u_g| [m/s] */
} hg_kinematics;

/* Hertzian ellipse (docs/physics.md §2.3). */
typedef struct {
    double k;      /* ellipticity a_c/b_c >= 1 */
    double E_bar;  /* complete elliptic integral of the second kind E(m), m = 1 - 1/k^2 */
    double F_bar;  /* complete elliptic integral of the first kind K(m) */
    double R;      /* (1/R_x + 1/R_y)^-1 [m] */
    double a_c;    /* semi-major axis [m] */
    double b_c;    /* semi-minor axis [m] */
    double s_x;    /* semi-axis along x [m] (= b_c unless R_x > R_y) */
    double s_y;    /* semi-axis along y [m] (= a_c unless R_x > R_y) */
    double A;      /* A_EHL = pi a_c b_c [m^2] */
    double p_m;    /* mean pressure W/A [Pa] */
    double p_max;  /* 1.5 p_m [Pa] */
} hg_hertz;

/* U_e, V_s, theta_e (as cos^2/sin^2, no trigonometry) and surface speeds. */
void hg_kinematics_eval(const double u_p[2], const double u_g[2], hg_kinematics *kin);

/* theta_e = atan2(|U_e,y|, |U_e,x|) [rad], 0 when U_e = 0 (docs/physics.md §1). */
double hg_entrainment_angle(const double U_e[2]);

/* R_e (along entrainment) and R_s (side leakage) from Euler's theorem (docs/physics.md §2.2) [m]. */
void hg_entrainment_radii(double R_x, double R_y, double cos2_e, double sin2_e, double *R_e,
                          double *R_s);

/* Complete elliptic integrals K(m), E(m), parameter m = e^2 in [0, 1): by the arithmetic-geometric
 * mean, or for m > 0.9 by the logarithmic series about m = 1 (fewer operations, same accuracy,
 * ~1e-16). The _c form takes the complementary parameter m1 = 1 - m (accurate as m -> 1). */
void hg_ellip_KE(double m, double *K, double *E);
void hg_ellip_KE_c(double m1, double *K, double *E);

/* Ellipticity k >= 1 for the curvature ratio R_y/R_x >= 1 (clamped to [1, HG_HERTZ_RATIO_MAX]):
 * exact root of (k^2 E - K)/(K - E) = R_y/R_x, m = 1 - 1/k^2 (Halley's method on ln k from the
 * Hamrock-Brewe value, two iterations, accurate to ~1e-15), or the Hamrock-Brewe fit. Writes
 * E(m) and K(m) (or their fits) to *E_bar and *F_bar when non-NULL. */
double hg_ellipticity(double ratio, hg_hertz_mode mode, double *E_bar, double *F_bar);

/* Hertz ellipse for load W [N] >= 0, reduced radii R_x, R_y > 0 [m] (either may be the larger)
 * and the paper's E* = E/(1-nu^2) [Pa] (= Hamrock's E'). */
void hg_hertz_eval(double W, double R_x, double R_y, double E_star, hg_hertz_mode mode,
                   hg_hertz *h);

#endif
