/* Backlash dead zone, exact and smoothed: see backlash.h. */
#include "model/backlash.h"

#include <math.h>

static double ramp(double u, double eps) { return 0.5 * (u + sqrt(u * u + eps * eps)); }

/* Antiderivative of ramp: (u^2 + u sqrt(u^2 + eps^2) + eps^2 asinh(u/eps)) / 4. */
static double ramp_integral(double u, double eps)
{
    return 0.25 * (u * u + u * sqrt(u * u + eps * eps) + eps * eps * asinh(u / eps));
}

double hg_backlash_f(const hg_backlash *bl, double x, int mode)
{
    if (bl->eps > 0.0) return ramp(x - bl->b, bl->eps) - ramp(-x - bl->b, bl->eps);
    if (mode == HG_MODE_DRIVE) return x - bl->b;
    if (mode == HG_MODE_BACK) return x + bl->b;
    return 0.0;
}

double hg_backlash_potential(const hg_backlash *bl, double x, int mode)
{
    double f;
    if (bl->eps > 0.0)
        return ramp_integral(x - bl->b, bl->eps) + ramp_integral(-x - bl->b, bl->eps) -
               2.0 * ramp_integral(-bl->b, bl->eps);
    f = hg_backlash_f(bl, x, mode);
    return 0.5 * f * f;
}

int hg_backlash_mode(double x, double b)
{
    if (x >= b) return HG_MODE_DRIVE;
    if (x <= -b) return HG_MODE_BACK;
    return HG_MODE_FREE;
}
