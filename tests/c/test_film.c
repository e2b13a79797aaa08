/* Central film thickness: Chittenden (paper eq. 10) against Hamrock-Dowson 1977 at theta_e = 0
 * (docs/physics.md §3), trends, and the docs/physics.md §12 value. */
#include "check.h"
#include "tribo/contact.h"
#include "tribo/film.h"

/* docs/physics.md §12 inlet state of OS265962 at T_in = 60 degC */
#define ETA0 0.038796418835629
#define ALPHA 14.43e-9
#define ES (210e9 / 0.91)
#define W 2380.0
#define RX 17.65e-3

/* Hamrock-Dowson 1977 central film (pure rolling along x), the independent reference:
 *   h_c = 2.69 R_x U^0.67 G^0.53 W^-0.067 (1 - 0.61 exp(-0.73 k))
 * with U = eta_0 u/(E' R_x), W = W/(E' R_x^2), k the ellipticity [m] */
static double hamrock_dowson(double eta0, double alpha_star, double u, double load,
                             double E_star, double R_x, double k)
{
    double U = eta0 * u / (E_star * R_x), G = alpha_star * E_star;
    double Wd = load / (E_star * R_x * R_x);
    return 2.69 * R_x * pow(U, 0.67) * pow(G, 0.53) * pow(Wd, -0.067) *
           (1.0 - 0.61 * exp(-0.73 * k));
}

int main(void)
{
    size_t i;
    double u, prev;
    /* theta_e = 0: R_e = R_x, R_s = R_y. docs/physics.md §3 reference calculation (Chittenden / HD):
     * 664/652, 683/702, 683/705 nm for R_y/R_x = 5, 20, 127.5 */
    {
        const double ratio[] = {5.0, 20.0, 127.5};
        const double ch[] = {664e-9, 683e-9, 683e-9}, hd[] = {652e-9, 702e-9, 705e-9};
        const double agree[] = {0.03, 0.03, 0.035}; /* see below */
        for (i = 0; i < 3; i++) {
            double k = hg_ellipticity(ratio[i], HG_HERTZ_EXACT, NULL, NULL);
            double hc = hg_film_chittenden(ETA0, ALPHA, 3.81, W, ES, RX, RX * ratio[i]);
            double hh = hamrock_dowson(ETA0, ALPHA, 3.81, W, ES, RX, k);
            printf("R_y/R_x %6.1f  Chittenden %.1f nm  Hamrock-Dowson %.1f nm  (%+.2f %%)\n",
                   ratio[i], hc * 1e9, hh * 1e9, 100.0 * (hc / hh - 1.0));
            CHECK_CLOSE(hc, ch[i], 0.005, 0);
            CHECK_CLOSE(hh, hd[i], 0.005, 0);
            /* "within a few %": 1.8 % and 2.7 % at ratios 5 and 20; at 127.5 the two
             * formulas differ by 3.1 % (705 vs 683 nm in docs/physics.md §3 itself), hence 3.5 % there */
            CHECK_CLOSE(hc, hh, agree[i], 0);
        }
    }
    /* docs/physics.md §12: h_c = 610 nm at R_e = 53.9 mm, R_s = 25.9 mm (theta_e = 55.4 deg) */
    {
        const double up[2] = {2.46, 4.28}, ug[2] = {1.87, 2.00};
        hg_kinematics kin;
        double Re, Rs;
        hg_kinematics_eval(up, ug, &kin);
        hg_entrainment_radii(RX, 2.25, kin.cos2_e, kin.sin2_e, &Re, &Rs);
        CHECK_CLOSE(hg_film_chittenden(ETA0, ALPHA, kin.u_e, W, ES, Re, Rs), 610e-9, 0.005, 0);
        /* h_c rises with speed (U^0.68), falls weakly with load (W^-0.073) */
        prev = 0.0;
        for (u = 0.01; u < 40.0; u *= 1.3) {
            double h = hg_film_chittenden(ETA0, ALPHA, u, W, ES, Re, Rs);
            CHECK(h > prev);
            prev = h;
        }
        CHECK_CLOSE(hg_film_chittenden(ETA0, ALPHA, 2 * kin.u_e, W, ES, Re, Rs) /
                        hg_film_chittenden(ETA0, ALPHA, kin.u_e, W, ES, Re, Rs),
                    pow(2.0, 0.68), 1e-12, 0);
        CHECK(hg_film_chittenden(ETA0, ALPHA, kin.u_e, 2 * W, ES, Re, Rs) <
              hg_film_chittenden(ETA0, ALPHA, kin.u_e, W, ES, Re, Rs));
        /* more viscous / higher alpha* -> thicker */
        CHECK(hg_film_chittenden(2 * ETA0, ALPHA, kin.u_e, W, ES, Re, Rs) >
              hg_film_chittenden(ETA0, ALPHA, kin.u_e, W, ES, Re, Rs));
        CHECK(hg_film_chittenden(ETA0, 1.2 * ALPHA, kin.u_e, W, ES, Re, Rs) >
              hg_film_chittenden(ETA0, ALPHA, kin.u_e, W, ES, Re, Rs));
    }
    /* degenerate inputs give 0, never NaN */
    CHECK(hg_film_chittenden(ETA0, ALPHA, 0.0, W, ES, RX, 1.0) == 0.0);
    CHECK(hg_film_chittenden(ETA0, ALPHA, 1.0, 0.0, ES, RX, 1.0) == 0.0);
    /* Gupta et al.'s thermal reduction factor by hand: L = 17, S = 0.72, p_h/E* = 0.0031:
     * numerator 1 - 13.2 0.0031 17^0.42 = 0.8654994, denominator 1 + 0.213 (1 + 2.23 0.72^0.83)
     * 17^0.64 = 4.5227301 -> 0.1913666; no thermal loading -> 1; a loading beyond the fit's range
     * (L = 6720 at 2 GPa, numerator -3.65) -> 0; thinner as the loading or the sliding grows */
    CHECK_CLOSE(hg_film_thermal_reduction(17.0, 0.72, 0.0031), 0.19136658, 1e-7, 0);
    CHECK(hg_film_thermal_reduction(0.0, 0.72, 0.0031) == 1.0);
    CHECK(hg_film_thermal_reduction(6720.0, 0.72, 0.0087) == 0.0);
    CHECK(hg_film_thermal_reduction(20.0, 0.72, 0.0031) < hg_film_thermal_reduction(17.0, 0.72, 0.0031));
    CHECK(hg_film_thermal_reduction(17.0, 1.0, 0.0031) < hg_film_thermal_reduction(17.0, 0.72, 0.0031));
    CHECK_DONE();
}
