/* Backlash dead zone f(x) (Kahraman & Singh; b is the half backlash): exact branches and modes,
 * the smoothed variant's bound and smoothness, and both potentials (dPhi/dx = f). */
#include <math.h>

#include "check.h"
#include "mesh/backlash.h"

static void exact(void)
{
    const hg_backlash bl = {70e-6, 0.0}, zero = {0.0, 0.0};
    CHECK_CLOSE(hg_backlash_f(&bl, 100e-6, HG_MODE_DRIVE), 30e-6, 1e-12, 0.0);
    CHECK(hg_backlash_f(&bl, 10e-6, HG_MODE_FREE) == 0.0);
    CHECK_CLOSE(hg_backlash_f(&bl, -100e-6, HG_MODE_BACK), -30e-6, 1e-12, 0.0);
    /* a mode keeps its branch a little beyond the boundary (no step straddles a change) */
    CHECK_CLOSE(hg_backlash_f(&bl, 69e-6, HG_MODE_DRIVE), -1e-6, 1e-9, 0.0);
    CHECK(hg_backlash_mode(70e-6, 70e-6) == HG_MODE_DRIVE);
    CHECK(hg_backlash_mode(69.999e-6, 70e-6) == HG_MODE_FREE);
    CHECK(hg_backlash_mode(-70e-6, 70e-6) == HG_MODE_BACK);
    CHECK(hg_backlash_mode(0.0, 70e-6) == HG_MODE_FREE);
    CHECK(hg_backlash_mode(1e-9, 0.0) == HG_MODE_DRIVE && hg_backlash_mode(-1e-9, 0.0) == HG_MODE_BACK);
    CHECK(hg_backlash_f(&zero, 2e-6, HG_MODE_DRIVE) == 2e-6);
    /* potential: f^2/2 on the branch */
    CHECK_CLOSE(hg_backlash_potential(&bl, 100e-6, HG_MODE_DRIVE), 0.5 * 30e-6 * 30e-6, 1e-12, 0);
    CHECK(hg_backlash_potential(&bl, 10e-6, HG_MODE_FREE) == 0.0);
}

/* The exact f of the position (mode from x). */
static double exact_f(double x, double b)
{
    hg_backlash bl;
    bl.b = b;
    bl.eps = 0.0;
    return hg_backlash_f(&bl, x, hg_backlash_mode(x, b));
}

static void smoothed(void)
{
    const double b = 70e-6, eps = 2e-6;
    const hg_backlash bl = {b, eps};
    double x, worst = 0.0;
    for (x = -200e-6; x <= 200e-6; x += 0.37e-6) {
        double f = hg_backlash_f(&bl, x, HG_MODE_FREE), d = 1e-9;
        double dPhi = (hg_backlash_potential(&bl, x + d, 0) - hg_backlash_potential(&bl, x - d, 0))
                      / (2 * d);
        double slope = (hg_backlash_f(&bl, x + d, 0) - hg_backlash_f(&bl, x - d, 0)) / (2 * d);
        worst = fmax(worst, fabs(f - exact_f(x, b)));
        CHECK_CLOSE(dPhi, f, 1e-5, 1e-13);      /* the potential is the antiderivative */
        CHECK(slope >= 0.0 && slope <= 1.0 + 1e-9); /* monotone, never stiffer than k_m */
        CHECK_CLOSE(hg_backlash_f(&bl, -x, 0), -f, 1e-12, 1e-18); /* odd */
    }
    CHECK(worst <= 0.5 * eps * (1 + 1e-9)); /* documented bound: eps/2, reached at x = +-b */
    CHECK_CLOSE(hg_backlash_f(&bl, b, 0), 0.5 * eps, 1e-2, 0.0); /* where the bound is reached */
    CHECK(hg_backlash_potential(&bl, 0.0, 0) == 0.0);
    /* far from the corners the smoothed spring approaches the exact one as eps^2/(4 (x - b)) */
    CHECK_CLOSE(hg_backlash_f(&bl, 170e-6, 0), 100e-6, 1e-4, 0.0);
    CHECK(fabs(hg_backlash_f(&bl, 0.0, 0)) < 1e-18);
}

/* The split by flank: the shares add up to f, each flank's engagement is its share's slope, and
 * separated teeth have zero engagement (the mesh damper does not act between them). */
static void flanks(void)
{
    const double b = 70e-6, eps = 2e-6;
    const hg_backlash sm = {b, eps}, ex = {b, 0.0};
    const int modes[] = {HG_MODE_BACK, HG_MODE_FREE, HG_MODE_DRIVE};
    hg_flank_split s, sp, sn;
    double x, d = 1e-10;
    int i;
    for (x = -200e-6; x <= 200e-6; x += 0.37e-6) {
        hg_backlash_flanks(&sm, x, 0, &s);
        hg_backlash_flanks(&sm, x + d, 0, &sp);
        hg_backlash_flanks(&sm, x - d, 0, &sn);
        CHECK(s.f_d + s.f_b == hg_backlash_f(&sm, x, 0));
        CHECK(s.f_d >= 0.0 && s.f_b <= 0.0);
        CHECK_CLOSE(s.g_d, (sp.f_d - sn.f_d) / (2 * d), 1e-5, 1e-9);
        CHECK_CLOSE(s.g_b, (sp.f_b - sn.f_b) / (2 * d), 1e-5, 1e-9);
        CHECK(s.g_d >= 0.0 && s.g_d <= 1.0 && s.g_b >= 0.0 && s.g_b <= 1.0);
        /* ten smoothing widths inside the gap the engagement is (eps/2(b - x))^2 +
         * (eps/2(b + x))^2 to leading order (the slope of the ramp far below its corner) */
        if (fabs(x) < b - 10 * eps)
            CHECK_CLOSE(s.g_d + s.g_b, pow(eps / (2 * (b - x)), 2) + pow(eps / (2 * (b + x)), 2),
                        0.02, 0.0);
    }
    for (i = 0; i < 3; i++) {
        hg_backlash_flanks(&ex, 10e-6 + 100e-6 * (modes[i]), modes[i], &s);
        CHECK(s.f_d + s.f_b == hg_backlash_f(&ex, 10e-6 + 100e-6 * modes[i], modes[i]));
        CHECK(s.g_d == (modes[i] == HG_MODE_DRIVE) && s.g_b == (modes[i] == HG_MODE_BACK));
        CHECK(s.f_d == (modes[i] == HG_MODE_DRIVE ? 40e-6 : 0.0) || fabs(s.f_d - 40e-6) < 1e-18);
    }
    hg_backlash_flanks(&ex, -90e-6, HG_MODE_BACK, &s);
    CHECK_CLOSE(s.f_b, -20e-6, 1e-12, 0.0);
    CHECK(s.f_d == 0.0 && s.g_d == 0.0);
}

int main(void)
{
    exact();
    smoothed();
    flanks();
    CHECK_DONE();
}
