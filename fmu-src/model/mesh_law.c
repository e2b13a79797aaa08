/* The force law of a loaded mesh: see mesh_law.h. */
#include "model/mesh_law.h"

#include <math.h>
#include <string.h>

void hg_mesh_law_points(int n, const double W[], const double k[], const double dk[],
                        hg_mesh_law *law)
{
    int l;
    law->n = n;
    for (l = 0; l < n; l++) {
        law->W[l] = W[l];
        law->a[l] = W[l] / k[l];
        law->da[l] = -law->a[l] * dk[l] / k[l];
    }
}

/* Segment l between points l and l + 1: the exponent p and dp/dtheta. */
typedef struct {
    double p, dp;
} hg_segment;

static hg_segment segment(const hg_mesh_law *m, int l)
{
    hg_segment s;
    double log_a = log(m->a[l + 1] / m->a[l]);
    s.p = log(m->W[l + 1] / m->W[l]) / log_a;
    s.dp = -s.p * (m->da[l + 1] / m->a[l + 1] - m->da[l] / m->a[l]) / log_a;
    return s;
}

/* Energy and its dtheta of the power law of segment s from the point l to where it carries
 * W at a with dW/dtheta = dW (the integral (W a - W_l a_l) / (p + 1) and its derivative). */
static void segment_energy(const hg_mesh_law *m, int l, hg_segment s, double W, double dW,
                           double a, double da, double *U, double *dU)
{
    double q = 1.0 / (s.p + 1.0), E = W * a - m->W[l] * m->a[l];
    *U += E * q;
    *dU += (dW * a + W * da - m->W[l] * m->da[l]) * q - E * s.dp * q * q;
}

void hg_mesh_law_force(const hg_mesh_law *m, double a, hg_law_force *out)
{
    int l = 0, last = m->n - 2;
    hg_segment s;
    double U, dU, L, dlnW;
    memset(out, 0, sizeof *out);
    if (!(a > 0.0)) return;
    s = segment(m, 0);
    /* the energy at the first point, of the first law from a = 0 */
    U = m->W[0] * m->a[0] / (s.p + 1.0);
    dU = (m->W[0] * m->da[0]) / (s.p + 1.0) - m->W[0] * m->a[0] * s.dp / ((s.p + 1.0) * (s.p + 1.0));
    while (l < last && a > m->a[l + 1]) { /* whole segments below a */
        segment_energy(m, l, s, m->W[l + 1], 0.0, m->a[l + 1], m->da[l + 1], &U, &dU);
        s = segment(m, ++l);
    }
    if (a > m->a[last + 1]) { /* beyond the last level: its tangent */
        double k_e = s.p * m->W[last + 1] / m->a[last + 1], dk_e, d = a - m->a[last + 1];
        dk_e = k_e * (s.dp / s.p - m->da[last + 1] / m->a[last + 1]);
        segment_energy(m, l, s, m->W[last + 1], 0.0, m->a[last + 1], m->da[last + 1], &U, &dU);
        out->W = m->W[last + 1] + k_e * d;
        out->k = k_e;
        out->U = U + m->W[last + 1] * d + 0.5 * k_e * d * d;
        out->dU = dU - m->W[last + 1] * m->da[last + 1] + 0.5 * dk_e * d * d -
                  k_e * d * m->da[last + 1];
        return;
    }
    L = log(a / m->a[l]);
    out->W = m->W[l] * exp(s.p * L);
    out->k = s.p * out->W / a;
    dlnW = s.dp * L - s.p * m->da[l] / m->a[l];
    segment_energy(m, l, s, out->W, out->W * dlnW, a, 0.0, &U, &dU);
    out->U = U;
    out->dU = dU;
}

double hg_mesh_law_approach(const hg_mesh_law *m, double W)
{
    int l = 0, last = m->n - 2;
    hg_segment s;
    if (!(W > 0.0)) return 0.0;
    while (l < last && W > m->W[l + 1]) l++;
    s = segment(m, l);
    if (W > m->W[last + 1]) /* beyond the last level */
        return m->a[last + 1] + (W - m->W[last + 1]) * m->a[last + 1] / (s.p * m->W[last + 1]);
    return m->a[l] * exp(log(W / m->W[l]) / s.p);
}

void hg_mesh_law_loads(const hg_gearset *g, int data_flank, double W[])
{
    int l;
    for (l = 0; l < g->n_levels; l++)
        W[l] = g->T_level[l] / g->s[data_flank][l].y[HG_S_R_P].mean;
}

void hg_mesh_law_of_series(const hg_gearset *g, int flank, double theta, hg_mesh_law *law)
{
    double W[HG_MAX_LEVELS], k[HG_MAX_LEVELS], dk[HG_MAX_LEVELS];
    hg_level_pick b;
    hg_harmonics h;
    int l;
    hg_gearset_level_at(g, flank, 0.0, &b);
    hg_harmonics_eval(theta, HG_MAX_HARMONICS, &h);
    for (l = 0; l < g->n_levels; l++) {
        k[l] = hg_series_value(&g->s[b.flank][l].y[HG_S_K_M], &h);
        dk[l] = hg_series_slope(&g->s[b.flank][l].y[HG_S_K_M], &h);
    }
    hg_mesh_law_loads(g, b.flank, W);
    hg_mesh_law_points(g->n_levels, W, k, dk, law);
}

#define TANGENT_ANGLES 256 /* mesh angles of the cycle averaged over */
#define NODE_SIDE 1e-9     /* relative load step to either side: at a level's load the law has a
                              kink, and the mean of its slopes is the vibration's stiffness */

double hg_mesh_law_tangent_mean(const hg_gearset *g, int flank, double T)
{
    double k_m0, R_p0, W, sum = 0.0;
    int j;
    if (T < g->T_level[0]) T = g->T_level[0]; /* the law's tangent vanishes with the load */
    hg_gearset_means(g, flank, T, &k_m0, &R_p0);
    W = T / R_p0;
    for (j = 0; j < TANGENT_ANGLES; j++) {
        hg_mesh_law law;
        hg_law_force f;
        int side;
        hg_mesh_law_of_series(g, flank, 6.283185307179586 * j / TANGENT_ANGLES, &law);
        for (side = -1; side <= 1; side += 2) { /* both slopes at a level's own load */
            hg_mesh_law_force(&law, hg_mesh_law_approach(&law, W * (1.0 + side * NODE_SIDE)), &f);
            sum += 0.5 * f.k;
        }
    }
    return sum / TANGENT_ANGLES;
}
