/* Fourier series of the tooth contact data: recurrence against direct sums, slope against a
 * central difference, scaling. */
#include <math.h>

#include "check.h"
#include "mesh/fourier.h"

static double direct(const hg_series *y, double psi)
{
    double v = y->mean;
    int i;
    for (i = 0; i < y->n; i++) v += y->s[i] * sin((i + 1) * psi) + y->c[i] * cos((i + 1) * psi);
    return v;
}

static double direct_slope(const hg_series *y, double psi)
{
    double d = 0.0;
    int i;
    for (i = 0; i < y->n; i++)
        d += (i + 1) * (y->s[i] * cos((i + 1) * psi) - y->c[i] * sin((i + 1) * psi));
    return d;
}

int main(void)
{
    hg_series y = {0};
    hg_harmonics h;
    int i, j;
    y.n = HG_MAX_HARMONICS;
    y.mean = 1.7e8;
    for (i = 0; i < y.n; i++) {
        y.s[i] = 1e6 / (i + 1) * ((i % 3) - 1.0);
        y.c[i] = 5e5 / ((i + 1) * (i + 1));
    }
    for (j = -50; j <= 400; j++) {
        double psi = 0.037 * j, d = 1e-4, num;
        hg_harmonics_eval(psi, y.n, &h);
        CHECK_CLOSE(hg_series_value(&y, &h), direct(&y, psi), 1e-13, 0.0);
        CHECK_CLOSE(hg_series_slope(&y, &h), direct_slope(&y, psi), 1e-11, 1e-6);
        /* and the slope really is the derivative: 4th-order central difference */
        num = (-direct(&y, psi + 2 * d) + 8 * direct(&y, psi + d) - 8 * direct(&y, psi - d) +
               direct(&y, psi - 2 * d)) / (12 * d);
        CHECK_CLOSE(hg_series_slope(&y, &h), num, 1e-5, 0.05);
    }
    /* a known closed form: mean 2, 3 sin(psi) - cos(2 psi) */
    {
        hg_series z = {0};
        z.n = 2;
        z.mean = 2.0;
        z.s[0] = 3.0;
        z.c[1] = -1.0;
        hg_harmonics_eval(0.7, 2, &h);
        CHECK_CLOSE(hg_series_value(&z, &h), 2.0 + 3.0 * sin(0.7) - cos(1.4), 1e-15, 0.0);
        CHECK_CLOSE(hg_series_slope(&z, &h), 3.0 * cos(0.7) + 2.0 * sin(1.4), 1e-15, 0.0);
        hg_series_scale(&z, 0.5);
        CHECK_CLOSE(hg_series_value(&z, &h), 0.5 * (2.0 + 3.0 * sin(0.7) - cos(1.4)), 1e-15, 0.0);
    }
    /* zero harmonics: the mean alone */
    {
        hg_series m = {0};
        m.mean = 4.5;
        hg_harmonics_eval(1.0, 0, &h);
        CHECK(hg_series_value(&m, &h) == 4.5 && hg_series_slope(&m, &h) == 0.0);
    }
    CHECK_DONE();
}
