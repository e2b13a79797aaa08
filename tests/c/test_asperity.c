/* Greenwood-Tripp functions F_2 and F_5/2 (docs/physics.md §5.3) against an independent quadrature and the
 * reference table; W_asp, A_asp and F_b (paper eqs. 11-13). */
#include "check.h"
#include "io/constants.h"
#include "tribo/asperity.h"
#include "tribo/contact.h"

/* F_n(lambda) by quadrature, written independently of the generator: s = lambda + t^2 and
 * t = e^u turn the integral into int 2 t^(2n+2) exp(-(lambda + t^2)^2/2) du over the real line,
 * whose integrand decays double-exponentially, so the trapezoidal rule converges spectrally. */
static double F_quad(double n, double lambda)
{
    const double h = 0.004, lo = -40.0, hi = 4.0;
    double sum = 0.0, u;
    for (u = lo; u <= hi + 0.5 * h; u += h) {
        double t = exp(u), s = lambda + t * t;
        sum += 2.0 * pow(t, 2.0 * n + 2.0) * exp(-0.5 * s * s);
    }
    return sum * h / sqrt(2.0 * HG_PI);
}

int main(void)
{
    int i;
    double l;
    /* the quadrature itself against the exact F_n(0) = 2^(n/2 - 1) Gamma((n+1)/2) / sqrt(pi) */
    CHECK_CLOSE(F_quad(2.0, 0.0), 0.5, 1e-13, 0);
    CHECK_CLOSE(F_quad(2.5, 0.0), pow(2.0, 0.25) * tgamma(1.75) / sqrt(HG_PI), 1e-13, 0);
    CHECK_CLOSE(hg_gt_F52(0.0), pow(2.0, 0.25) * tgamma(1.75) / sqrt(HG_PI), 1e-12, 0);

    /* docs/physics.md §5.3 reference table (5 significant digits) */
    {
        const double lam[] = {0, 0.5, 1, 1.5, 2, 2.5, 3, 3.5, 4};
        const double f2[] = {0.50000,   0.20964,   7.5340e-2, 2.2847e-2, 5.7687e-3,
                             1.1993e-3, 2.0344e-4, 2.7946e-5, 3.0902e-6};
        const double f52[] = {0.61663,   0.24040,   8.0562e-2, 2.2863e-2, 5.4237e-3,
                              1.0637e-3, 1.7087e-4, 2.2312e-5, 2.3534e-6};
        for (i = 0; i < 9; i++) {
            CHECK_CLOSE(hg_gt_F2(lam[i]), f2[i], 5e-5, 0);
            CHECK_CLOSE(hg_gt_F52(lam[i]), f52[i], 5e-5, 0);
        }
    }

    /* against the quadrature over [0, 6] on a grid that avoids the table nodes, and beyond */
    for (l = 0.0; l <= 6.0; l += 0.0137) {
        CHECK_CLOSE(hg_gt_F2(l), F_quad(2.0, l), 1e-11, 0);
        CHECK_CLOSE(hg_gt_F52(l), F_quad(2.5, l), 2e-9, 0);
    }
    for (l = 6.0; l <= 14.0; l += 0.0913) {
        CHECK_CLOSE(hg_gt_F2(l), F_quad(2.0, l), 1e-9, 1e-300);
        CHECK_CLOSE(hg_gt_F52(l), F_quad(2.5, l), 1e-6, 1e-300);
    }
    /* continuity at the end of the table, monotone decrease, limits */
    CHECK_CLOSE(hg_gt_F52(6.0 - 1e-12), hg_gt_F52(6.0), 1e-9, 0);
    {
        double prev2 = 1.0, prev52 = 1.0;
        for (l = 0.0; l < 38.0; l += 0.001) {
            double a = hg_gt_F2(l), b = hg_gt_F52(l);
            CHECK(a <= prev2 && b <= prev52 && a >= 0.0 && b >= 0.0 && isfinite(a) && isfinite(b));
            prev2 = a;
            prev52 = b;
        }
    }
    CHECK(hg_gt_F2(-1.0) == 0.5 && hg_gt_F52(-1.0) == hg_gt_F52(0.0));
    CHECK(hg_gt_F2(1e6) == 0.0 && hg_gt_F52(1e6) == 0.0);

    /* eqs. 12, 13 and 11 at the docs/physics.md §12 point (lambda = 1.7266, A = 4.278e-6 m^2) */
    {
        const double lam = 1.7266, A = 4.2776e-6, Es = 210e9 / 0.91;
        double W, Aa, Fb;
        hg_greenwood_tripp(lam, 0.0104, 1e-3, Es, A, &W, &Aa);
        CHECK_CLOSE(W, 8.0 * sqrt(2.0) / 15.0 * HG_PI * 0.0104 * 0.0104 * sqrt(1e-3) * Es * A *
                           hg_gt_F52(lam),
                    1e-14, 0);
        CHECK_CLOSE(Aa, HG_PI * HG_PI * 0.0104 * 0.0104 * A * hg_gt_F2(lam), 1e-14, 0);
        CHECK_CLOSE(W / 2380.0, 4.1e-5, 0.03, 0); /* docs/physics.md §12: W_asp/W ~ 4e-5 */
        Fb = hg_boundary_friction(2e6, 0.17, Aa, W);
        CHECK_CLOSE(Fb, 2e6 * Aa + 0.17 * W, 1e-15, 0);
        CHECK_CLOSE(Fb, 0.0167, 0.03, 0); /* docs/physics.md §12: 0.02 */
    }
    CHECK_DONE();
}
