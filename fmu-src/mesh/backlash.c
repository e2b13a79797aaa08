/* Backlash dead zone, exact and smoothed: see backlash.h. */
#include "mesh/backlash.h"

#include <math.h>

static double ramp(double u, double eps) { return 0.5 * (u + sqrt(u * u + eps * eps)); }

/* Antiderivative of ramp: (u^2 + u sqrt(u^2 + eps^2) + eps^2 asinh(u/eps)) / 4. */
static double ramp_integral(double u, double eps)
{
    return 0.25 * (u * u + u * sqrt(u * u + eps * eps) + eps * eps * asinh(u / eps));
}

/* d ramp/du in [0, 1] */
static double ramp_slope(double u, double eps) { return 0.5 * (1.0 + u / sqrt(u * u + eps * eps)); }

void hg_backlash_flanks(const hg_backlash *bl, double x, int mode, hg_flank_split *s)
{
    s->f_d = s->f_b = s->g_d = s->g_b = 0.0;
    if (bl->eps > 0.0) {
        s->f_d = ramp(x - bl->b, bl->eps);
        s->f_b = -ramp(-x - bl->b, bl->eps);
        s->g_d = ramp_slope(x - bl->b, bl->eps);
        s->g_b = ramp_slope(-x - bl->b, bl->eps);
    } else if (mode == HG_MODE_DRIVE) {
        s->f_d = x - bl->b;
        s->g_d = 1.0;
    } else if (mode == HG_MODE_BACK) {
        s->f_b = x + bl->b;
        s->g_b = 1.0;
    }
}

double hg_backlash_f(const hg_backlash *bl, double x, int mode)
{
    hg_flank_split s;
    hg_backlash_flanks(bl, x, mode, &s);
    return s.f_d + s.f_b;
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
