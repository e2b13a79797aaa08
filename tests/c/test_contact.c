/* Contact geometry: elliptic integrals, exact and approximate Hertz (docs/physics.md §2.3, §12),
 * kinematics and R_e, R_s (docs/physics.md §1, §2.2). */
#include "check.h"
#include "io/constants.h"
#include "tribo/contact.h"

int main(void)
{
    double K, E, k, Eb, Fb;
    size_t i;
    hg_hertz h;
    hg_kinematics kin;

    /* complete elliptic integrals against published values (Abramowitz & Stegun table 17.1;
     * also scipy.special.ellipk/ellipe) */
    {
        const double m[] = {0.1, 0.5, 0.9, 0.99, 0.999999};
        const double Kref[] = {1.6124413487202192, 1.8540746773013719, 2.5780921133481733,
                               3.6956373629898747, 8.294051463601061};
        const double Eref[] = {1.5307576368977633, 1.3506438810476755, 1.1047747327040733,
                               1.0159935450252240, 1.0000038970261722};
        for (i = 0; i < 5; i++) {
            hg_ellip_KE(m[i], &K, &E);
            CHECK_CLOSE(K, Kref[i], 1e-13, 0);
            CHECK_CLOSE(E, Eref[i], 1e-13, 0);
        }
        hg_ellip_KE(0.0, &K, &E);
        CHECK_CLOSE(K, HG_PI / 2, 1e-15, 0);
        CHECK_CLOSE(E, HG_PI / 2, 1e-15, 0);
        /* complementary form: the AGM (m1 > 0.1) and the series about m = 1 (m1 <= 0.1) */
        {
            const double m1[] = {0.15, 0.1, 0.05, 1e-4};
            const double K1[] = {2.38901648632558, 2.5780921133481733, 2.908337248444552,
                                 5.991589340506996};
            const double E1[] = {1.1433957918831659, 1.1047747327040733, 1.0604737277662784,
                                 1.000274582430663};
            double Ka, Ea, Kb, Eb2;
            for (i = 0; i < 4; i++) {
                hg_ellip_KE_c(m1[i], &K, &E);
                CHECK_CLOSE(K, K1[i], 2e-15, 0);
                CHECK_CLOSE(E, E1[i], 2e-15, 0);
            }
            hg_ellip_KE_c(nextafter(0.1, 1.0), &Ka, &Ea); /* just on the AGM side */
            hg_ellip_KE_c(0.1, &Kb, &Eb2);                /* series */
            CHECK_CLOSE(Ka, Kb, 1e-14, 0);
            CHECK_CLOSE(Ea, Eb2, 1e-14, 0);
        }
        hg_ellip_KE_c(1e-6, &K, &E); /* m = 1 - 1e-6 */
        CHECK_CLOSE(K, 8.294051463601061, 1e-10, 0); /* m1 of 0.999999 rounds at 1e-11 */
    }

    /* exact ellipticity (reference: root of the same equation with scipy, 1e-15) and the
     * Hamrock-Brewe approximation, docs/physics.md §2.3 table */
    {
        const double ratio[] = {1.5, 5, 30, 127.5, 300, 1e4};
        const double kref[] = {1.3101029621127507, 2.890181039836407, 8.876183089807984,
                               20.960223013089156, 34.3390714219459, 242.4326256923897};
        const double Eref[] = {1.3911375419208456, 1.1205197240849323, 1.0195565580561023,
                               1.0044747365217133, 1.001875807944734, 1.0000542510374917};
        const double kapp[] = {0, 2.878, 8.993, 22.57, 38.90, 0};
        const double da[] = {0, -0.3, +0.9, +5.1, 8.7, 0}, db[] = {0, +0.1, -0.4, -2.4, -4.1, 0};
        for (i = 0; i < 6; i++) {
            k = hg_ellipticity(ratio[i], HG_HERTZ_EXACT, &Eb, &Fb);
            CHECK_CLOSE(k, kref[i], 1e-12, 0);
            CHECK_CLOSE(Eb, Eref[i], 1e-12, 0);
            /* the defining equation holds */
            CHECK_CLOSE((k * k * Eb - Fb) / (Fb - Eb), ratio[i], 1e-12, 0);
            if (kapp[i] > 0) {
                hg_hertz ex, ap;
                CHECK_CLOSE(hg_ellipticity(ratio[i], HG_HERTZ_APPROX, NULL, NULL), kapp[i], 0.002,
                            0);
                hg_hertz_eval(1000.0, 0.01, 0.01 * ratio[i], 230.8e9, HG_HERTZ_EXACT, &ex);
                hg_hertz_eval(1000.0, 0.01, 0.01 * ratio[i], 230.8e9, HG_HERTZ_APPROX, &ap);
                CHECK_CLOSE(100.0 * (ap.a_c / ex.a_c - 1.0), da[i], 0, 0.06);
                CHECK_CLOSE(100.0 * (ap.b_c / ex.b_c - 1.0), db[i], 0, 0.06);
            }
        }
        /* circle and the near-circular branch */
        k = hg_ellipticity(1.0, HG_HERTZ_EXACT, &Eb, &Fb);
        CHECK(k == 1.0 && fabs(Eb - HG_PI / 2) < 1e-15 && fabs(Fb - HG_PI / 2) < 1e-15);
        k = hg_ellipticity(1.0 + 1e-8, HG_HERTZ_EXACT, NULL, NULL);
        CHECK_CLOSE(k - 1.0, 2.0 / HG_PI * 1e-8, 1e-3, 0);
        k = hg_ellipticity(1.001, HG_HERTZ_EXACT, &Eb, &Fb);
        CHECK_CLOSE((k * k * Eb - Fb) / (Fb - Eb), 1.001, 1e-9, 0);
        /* k is smooth and increasing in the ratio */
        {
            double prev = 1.0, r;
            for (r = 1.01; r < 2e5; r *= 1.07) {
                k = hg_ellipticity(r, HG_HERTZ_EXACT, NULL, NULL);
                CHECK(k > prev && isfinite(k));
                prev = k;
            }
        }
        /* clamped beyond HG_HERTZ_RATIO_MAX, finite */
        k = hg_ellipticity(1e300, HG_HERTZ_EXACT, &Eb, &Fb);
        CHECK(isfinite(k) && isfinite(Eb) && isfinite(Fb) && k > 1e3);
    }

    /* docs/physics.md §12: W = 2380 N, R_x = 17.65 mm, R_y = 2.25 m, E* = 210 GPa/(1-0.09) */
    hg_hertz_eval(2380.0, 17.65e-3, 2.25, 210e9 / 0.91, HG_HERTZ_EXACT, &h);
    CHECK_CLOSE(h.a_c, 5.34e-3, 0.005, 0);
    CHECK_CLOSE(h.b_c, 0.255e-3, 0.005, 0);
    CHECK_CLOSE(h.k, 21.0, 0.005, 0);
    CHECK_CLOSE(h.p_m, 0.557e9, 0.005, 0);
    CHECK_CLOSE(h.p_max, 0.84e9, 0.006, 0); /* printed to 2 digits: 0.8355 */
    CHECK_CLOSE(h.A, HG_PI * h.a_c * h.b_c, 1e-15, 0);
    CHECK(h.s_x == h.b_c && h.s_y == h.a_c);
    hg_hertz_eval(4760.0, 17.65e-3, 2.25, 210e9 / 0.91, HG_HERTZ_EXACT, &h);
    CHECK_CLOSE(h.a_c, 6.73e-3, 0.005, 0);
    CHECK_CLOSE(h.b_c, 0.321e-3, 0.005, 0);
    CHECK_CLOSE(h.p_m, 0.70e9, 0.005, 0);
    /* swapped radii: same ellipse, turned */
    {
        hg_hertz h2;
        hg_hertz_eval(4760.0, 2.25, 17.65e-3, 210e9 / 0.91, HG_HERTZ_EXACT, &h2);
        CHECK_CLOSE(h2.a_c, h.a_c, 1e-14, 0);
        CHECK(h2.s_x == h2.a_c && h2.s_y == h2.b_c);
    }
    /* zero load */
    hg_hertz_eval(0.0, 17.65e-3, 2.25, 230.8e9, HG_HERTZ_EXACT, &h);
    CHECK(h.a_c == 0.0 && h.p_m == 0.0);

    /* kinematics, docs/physics.md §12 pitch row: u_e = 3.81, |V_s| = 2.36, theta_e = 55.4 deg,
     * R_e / R_s = 53.9 / 25.9 mm */
    {
        const double up[2] = {2.46, 4.28}, ug[2] = {1.87, 2.00};
        double Re, Rs, th;
        hg_kinematics_eval(up, ug, &kin);
        CHECK_CLOSE(kin.u_e, 3.81, 0.005, 0);
        CHECK_CLOSE(kin.v_s, 2.36, 0.005, 0);
        th = hg_entrainment_angle(kin.U_e);
        CHECK_CLOSE(th * 180.0 / HG_PI, 55.4, 0.005, 0);
        CHECK_CLOSE(kin.cos2_e, cos(th) * cos(th), 1e-14, 0);
        hg_entrainment_radii(17.65e-3, 2.25, kin.cos2_e, kin.sin2_e, &Re, &Rs);
        CHECK_CLOSE(Re, 53.9e-3, 0.005, 0);
        CHECK_CLOSE(Rs, 25.9e-3, 0.005, 0);
        CHECK_CLOSE(kin.U_p, sqrt(2.46 * 2.46 + 4.28 * 4.28), 1e-15, 0);
    }
    /* zero entrainment: theta_e = 0, R_e = R_x */
    {
        const double up[2] = {1.0, 2.0}, ug[2] = {-1.0, -2.0};
        double Re, Rs;
        hg_kinematics_eval(up, ug, &kin);
        CHECK(kin.u_e == 0.0 && kin.cos2_e == 1.0 && kin.sin2_e == 0.0);
        CHECK(hg_entrainment_angle(kin.U_e) == 0.0);
        hg_entrainment_radii(0.02, 2.0, kin.cos2_e, kin.sin2_e, &Re, &Rs);
        CHECK_CLOSE(Re, 0.02, 1e-15, 0);
        CHECK_CLOSE(Rs, 2.0, 1e-15, 0);
    }
    CHECK_DONE();
}
