/* The force law of a loaded mesh: see mesh_law.h. */
#include "model/mesh_law.h"

#include <math.h>
#include <string.h>

void hg_mesh_law_levels(int n, const double W[], hg_law_levels *lv)
{
    int l;
    lv->n = n;
    for (l = 0; l < n; l++) {
        lv->W[l] = W[l];
        lv->per_W[l] = 1.0 / W[l];
        if (l + 1 < n) lv->ln_W[l] = log(W[l + 1] / W[l]);
    }
}

/* Static point l at theta: its approach a = W_l / k_l, 1 / a, r = (da/dtheta) / a = -k'/k and
 * P = W_l a_l [J]. */
typedef struct {
    double a, per_a, r, P;
} hg_point;

static hg_point point(const hg_mesh_law *m, int l)
{
    hg_point q;
    double per_k = 1.0 / m->k[l];
    q.a = m->lv->W[l] * per_k;
    q.per_a = m->k[l] * m->lv->per_W[l];
    q.r = -m->dk[l] * per_k;
    q.P = m->lv->W[l] * q.a;
    return q;
}

/* Segment l between points l and l + 1: the exponent p = ln(W_l+1/W_l) / ln(a_l+1/a_l), 1/(p + 1)
 * and dp/dtheta, from one division. */
typedef struct {
    double p, q, dp;
} hg_segment;

static hg_segment segment(const hg_mesh_law *m, int l, const hg_point *lo, const hg_point *hi)
{
    hg_segment s;
    double ln_a = log(hi->a * lo->per_a), ln_W = m->lv->ln_W[l], sum = ln_W + ln_a;
    double d = 1.0 / (ln_a * sum); /* 1/ln_a = sum d, 1/(p + 1) = ln_a/sum = ln_a^2 d */
    s.p = ln_W * sum * d;
    s.q = ln_a * ln_a * d;
    s.dp = s.p * (lo->r - hi->r) * sum * d;
    return s;
}

/* Adds the energy and its dtheta of the power law of segment s from its start (point lo, or
 * a = 0 for the first segment, first != 0) to where it carries W at a, W a changing with theta
 * by dWa: the integral (W a - W_l a_l) / (p + 1) and its derivative. */
static void segment_energy(hg_segment s, const hg_point *lo, int first, double Wa, double dWa,
                           double *U, double *dU)
{
    double P_l = first ? 0.0 : lo->P, E = Wa - P_l;
    *U += E * s.q;
    *dU += (dWa - P_l * lo->r) * s.q - E * s.dp * s.q * s.q;
}

/* The segment holding approach a (a > a_l, the whole segments below it), last + 1 beyond the
 * last level's point (a > a_l <=> a k_l > W_l: no division). */
static int segment_of(const hg_mesh_law *m, double a)
{
    int l = 0, last = m->lv->n - 2;
    while (l <= last && a * m->k[l + 1] > m->lv->W[l + 1]) l++;
    return l;
}

void hg_mesh_law_points(const hg_law_levels *lv, const double k[], const double dk[],
                        hg_mesh_law *law)
{
    hg_point lo, hi;
    int l;
    law->lv = lv;
    for (l = 0; l < lv->n; l++) {
        law->k[l] = k[l];
        law->dk[l] = dk[l];
    }
    law->B[0] = law->dB[0] = 0.0;
    hi = point(law, 0);
    for (l = 0; l + 1 < lv->n; l++) { /* segment by segment, each up to its upper point */
        lo = hi;
        hi = point(law, l + 1);
        law->B[l + 1] = law->B[l];
        law->dB[l + 1] = law->dB[l];
        segment_energy(segment(law, l, &lo, &hi), &lo, l == 0, hi.P, hi.P * hi.r, &law->B[l + 1],
                       &law->dB[l + 1]);
    }
}

void hg_mesh_law_force(const hg_mesh_law *m, double a, hg_law_force *out)
{
    hg_point lo, hi;
    hg_segment s;
    int l, last = m->lv->n - 2, top;
    double U, dU, L, dlnW;
    memset(out, 0, sizeof *out);
    if (!(a > 0.0)) return;
    top = segment_of(m, a);
    l = top > last ? last : top; /* the segment whose power law applies */
    lo = point(m, l);
    hi = point(m, l + 1);
    s = segment(m, l, &lo, &hi);
    if (top > last) { /* beyond the last level: its tangent */
        double W_e = m->lv->W[last + 1], da_e = hi.a * hi.r, d = a - hi.a;
        double k_e = s.p * W_e * hi.per_a, dk_e = k_e * (s.dp / s.p - hi.r);
        out->W = W_e + k_e * d;
        out->k = k_e;
        out->U = m->B[last + 1] + W_e * d + 0.5 * k_e * d * d;
        out->dU = m->dB[last + 1] - W_e * da_e + 0.5 * dk_e * d * d - k_e * d * da_e;
        return;
    }
    L = log(a * lo.per_a);
    out->W = m->lv->W[l] * exp(s.p * L);
    out->k = s.p * out->W / a;
    dlnW = s.dp * L - s.p * lo.r;
    U = m->B[l];
    dU = m->dB[l];
    segment_energy(s, &lo, l == 0, out->W * a, out->W * dlnW * a, &U, &dU);
    out->U = U;
    out->dU = dU;
}

double hg_mesh_law_approach(const hg_mesh_law *m, double W)
{
    const hg_law_levels *lv = m->lv;
    int l = 0, last = lv->n - 2;
    hg_point lo, hi;
    hg_segment s;
    if (!(W > 0.0)) return 0.0;
    while (l < last && W > lv->W[l + 1]) l++;
    lo = point(m, l);
    hi = point(m, l + 1);
    s = segment(m, l, &lo, &hi);
    if (W > lv->W[last + 1]) /* beyond the last level */
        return hi.a + (W - lv->W[last + 1]) / (s.p * lv->W[last + 1] * hi.per_a);
    return lo.a * exp(log(W * lv->per_W[l]) / s.p);
}

void hg_mesh_law_levels_of(const hg_gearset *g, int data_flank, hg_law_levels *lv)
{
    double W[HG_MAX_LEVELS];
    int l;
    for (l = 0; l < g->n_levels; l++)
        W[l] = g->T_level[l] / g->s[data_flank][l].y[HG_S_R_P].mean;
    hg_mesh_law_levels(g->n_levels, W, lv);
}

void hg_mesh_law_of_series(const hg_gearset *g, int flank, double theta, hg_law_levels *lv,
                           hg_mesh_law *law)
{
    double k[HG_MAX_LEVELS], dk[HG_MAX_LEVELS];
    hg_level_pick b;
    hg_harmonics h;
    int l;
    hg_gearset_level_at(g, flank, 0.0, &b);
    hg_harmonics_eval(theta, HG_MAX_HARMONICS, &h);
    for (l = 0; l < g->n_levels; l++) {
        k[l] = hg_series_value(&g->s[b.flank][l].y[HG_S_K_M], &h);
        dk[l] = hg_series_slope(&g->s[b.flank][l].y[HG_S_K_M], &h);
    }
    hg_mesh_law_levels_of(g, b.flank, lv);
    hg_mesh_law_points(lv, k, dk, law);
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
        hg_law_levels lv;
        hg_mesh_law law;
        hg_law_force f;
        int side;
        hg_mesh_law_of_series(g, flank, 6.283185307179586 * j / TANGENT_ANGLES, &lv, &law);
        for (side = -1; side <= 1; side += 2) { /* both slopes at a level's own load */
            hg_mesh_law_force(&law, hg_mesh_law_approach(&law, W * (1.0 + side * NODE_SIDE)), &f);
            sum += 0.5 * f.k;
        }
    }
    return sum / TANGENT_ANGLES;
}
