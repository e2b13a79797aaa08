/* Truncated Fourier series of the tooth contact data (paper eqs. 1-4, D1 of docs/physics.md §0):
 *   y(psi) = mean + sum_{i=1..n} [ s_i sin(i psi) + c_i cos(i psi) ]                          */
#ifndef HG_FOURIER_H
#define HG_FOURIER_H

#define HG_MAX_HARMONICS 32

typedef struct {
    int n; /* number of harmonics */
    double mean;
    double s[HG_MAX_HARMONICS];
    double c[HG_MAX_HARMONICS];
} hg_series;

/* sin(i psi), cos(i psi) for i = 1..n by the angle-addition recurrence (one sin/cos call). */
typedef struct {
    int n;
    double sin_i[HG_MAX_HARMONICS];
    double cos_i[HG_MAX_HARMONICS];
} hg_harmonics;

void hg_harmonics_eval(double psi, int n, hg_harmonics *h);

/* y(psi) from precomputed harmonics (h->n >= series n). */
double hg_series_value(const hg_series *y, const hg_harmonics *h);

/* dy/dpsi from precomputed harmonics. */
double hg_series_slope(const hg_series *y, const hg_harmonics *h);

/* Scales mean and every coefficient by factor. */
void hg_series_scale(hg_series *y, double factor);

#endif
