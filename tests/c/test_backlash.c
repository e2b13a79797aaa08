/* Backlash dead zone f(x) (Kahraman & Singh; b is the half backlash) and contact modes. */
#include "check.h"
#include "model/dynamics.h"

int main(void)
{
    const double b = 70e-6;
    /* branches */
    CHECK_CLOSE(hg_backlash_f(100e-6, b, HG_MODE_DRIVE), 30e-6, 1e-12, 0.0);
    CHECK(hg_backlash_f(10e-6, b, HG_MODE_FREE) == 0.0);
    CHECK_CLOSE(hg_backlash_f(-100e-6, b, HG_MODE_BACK), -30e-6, 1e-12, 0.0);
    /* a mode keeps its branch a little beyond the boundary (no step straddles a change) */
    CHECK_CLOSE(hg_backlash_f(69e-6, b, HG_MODE_DRIVE), -1e-6, 1e-9, 0.0);
    /* modes from position, boundaries belong to the contact */
    CHECK(hg_backlash_mode(70e-6, b) == HG_MODE_DRIVE);
    CHECK(hg_backlash_mode(69.999e-6, b) == HG_MODE_FREE);
    CHECK(hg_backlash_mode(-70e-6, b) == HG_MODE_BACK);
    CHECK(hg_backlash_mode(0.0, b) == HG_MODE_FREE);
    /* zero backlash: a linear spring through the origin */
    CHECK(hg_backlash_mode(1e-9, 0.0) == HG_MODE_DRIVE && hg_backlash_mode(-1e-9, 0.0) == HG_MODE_BACK);
    CHECK(hg_backlash_f(2e-6, 0.0, HG_MODE_DRIVE) == 2e-6);
    /* continuity of the dead zone at the boundaries */
    CHECK(hg_backlash_f(b, b, HG_MODE_DRIVE) == 0.0 && hg_backlash_f(-b, b, HG_MODE_BACK) == 0.0);
    CHECK_DONE();
}
