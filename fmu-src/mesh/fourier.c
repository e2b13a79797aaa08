/* Fourier series evaluation with the angle-addition recurrence: see fourier.h. */
#include "mesh/fourier.h"

#include <math.h>

void hg_harmonics_eval(double psi, int n, hg_harmonics *h)
{
    double s1 = sin(psi), c1 = cos(psi);
    int i;
    h->n = n;
    if (n < 1) return;
    h->sin_i[0] = s1;
    h->cos_i[0] = c1;
    for (i = 1; i < n; i++) { /* sin((i+1)psi) = sin(i psi) cos psi + cos(i psi) sin psi */
        h->sin_i[i] = h->sin_i[i - 1] * c1 + h->cos_i[i - 1] * s1;
        h->cos_i[i] = h->cos_i[i - 1] * c1 - h->sin_i[i - 1] * s1;
    }
}

double hg_series_value(const hg_series *y, const hg_harmonics *h)
{
    double v = y->mean;
    int i;
    for (i = 0; i < y->n; i++) v += y->s[i] * h->sin_i[i] + y->c[i] * h->cos_i[i];
    return v;
}

double hg_series_slope(const hg_series *y, const hg_harmonics *h)
{
    double d = 0.0;
    int i;
    for (i = 0; i < y->n; i++) d += (i + 1) * (y->s[i] * h->cos_i[i] - y->c[i] * h->sin_i[i]);
    return d;
}

void hg_series_scale(hg_series *y, double factor)
{
    int i;
    y->mean *= factor;
    for (i = 0; i < y->n; i++) {
        y->s[i] *= factor;
        y->c[i] *= factor;
    }
}
