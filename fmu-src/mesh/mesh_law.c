/* The force law of a loaded mesh: see mesh_law.h. */
#include "mesh/mesh_law.h"

#include <math.h>
#include <string.h>

#include "io/constants.h"

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

/* Segment l between points l and l + 1: the exponent p = ln(W_l+1/W_l) / ln(a_l+1/a_l), 1/(p + 1)
 * and dp/dtheta, from one division. */
typedef struct {
    double p, q, dp;
} hg_segment;

static hg_segment segment(const hg_law_levels *lv, const hg_law_segment *sg)
{
    hg_segment s;
    double ln_a = sg->ln_a1 - sg->ln_a0, ln_W = lv->ln_W[sg->l], sum = ln_W + ln_a;
    double d = 1.0 / (ln_a * sum); /* 1/ln_a = sum d, 1/(p + 1) = ln_a/sum = ln_a^2 d */
    s.p = ln_W * sum * d;
    s.q = ln_a * ln_a * d;
    s.dp = s.p * (sg->dln_a0 - sg->dln_a1) * sum * d;
    return s;
}

/* Adds the energy and its dtheta of the power law of segment s from its start (sg's lower point,
 * or a = 0 for the first segment) to where it carries W at a, W a changing with theta by dWa:
 * the integral (W a - W_l a_l) / (p + 1) and its derivative. */
static void segment_energy(const hg_law_segment *sg, hg_segment s, double Wa, double dWa,
                           double *U, double *dU)
{
    double E = Wa - sg->P;
    *U += E * s.q;
    *dU += (dWa - sg->dP) * s.q - E * s.dp * s.q * s.q;
}

/* Segment l of the law m (beyond its last point when `beyond`). */
static hg_law_segment segment_of(const hg_mesh_law *m, int l, int beyond)
{
    hg_law_segment sg;
    int base = beyond ? l + 1 : l;
    sg.l = l;
    sg.beyond = beyond;
    sg.ln_a0 = m->ln_a[l];
    sg.dln_a0 = m->dln_a[l];
    sg.ln_a1 = m->ln_a[l + 1];
    sg.dln_a1 = m->dln_a[l + 1];
    sg.P = l > 0 ? m->P[l] : 0.0;
    sg.dP = l > 0 ? m->dP[l] : 0.0;
    sg.B = m->B[base];
    sg.dB = m->dB[base];
    return sg;
}

void hg_mesh_law_points(const hg_law_levels *lv, const double k[], const double dk[],
                        hg_mesh_law *law)
{
    int l;
    law->lv = lv;
    for (l = 0; l < lv->n; l++) {
        double a = lv->W[l] / k[l];
        law->ln_a[l] = log(a);
        law->dln_a[l] = -dk[l] / k[l];
        law->P[l] = lv->W[l] * a;
        law->dP[l] = law->P[l] * law->dln_a[l];
    }
    law->B[0] = law->dB[0] = 0.0;
    for (l = 0; l + 1 < lv->n; l++) { /* segment by segment, each up to its upper point */
        hg_law_segment sg = segment_of(law, l, 0);
        law->B[l + 1] = law->B[l];
        law->dB[l + 1] = law->dB[l];
        segment_energy(&sg, segment(lv, &sg), law->P[l + 1], law->dP[l + 1], &law->B[l + 1],
                       &law->dB[l + 1]);
    }
}

int hg_mesh_law_locate(const hg_law_levels *lv, const double ln_a[], double ln_a_x, int *beyond)
{
    int l = 0, last = lv->n - 2;
    while (l < last && ln_a_x > ln_a[l + 1]) l++; /* the segment whose power law applies */
    *beyond = ln_a_x > ln_a[last + 1];
    return l;
}

void hg_mesh_law_segment_force(const hg_law_levels *lv, const hg_law_segment *sg, double a,
                               double ln_a, hg_law_force *out)
{
    hg_segment s = segment(lv, sg);
    double L, dlnW, U = sg->B, dU = sg->dB;
    if (sg->beyond) { /* beyond the last level: its tangent */
        double W_e = lv->W[sg->l + 1], a_e = exp(sg->ln_a1), d = a - a_e;
        double da_e = a_e * sg->dln_a1, k_e = s.p * W_e / a_e;
        double dk_e = k_e * (s.dp / s.p - sg->dln_a1);
        out->W = W_e + k_e * d;
        out->k = k_e;
        out->U = U + W_e * d + 0.5 * k_e * d * d;
        out->dU = dU - W_e * da_e + 0.5 * dk_e * d * d - k_e * d * da_e;
        return;
    }
    L = ln_a - sg->ln_a0;
    out->W = lv->W[sg->l] * exp(s.p * L);
    out->k = s.p * out->W / a;
    dlnW = s.dp * L - s.p * sg->dln_a0;
    segment_energy(sg, s, out->W * a, out->W * dlnW * a, &U, &dU);
    out->U = U;
    out->dU = dU;
}

void hg_mesh_law_force(const hg_mesh_law *m, double a, hg_law_force *out)
{
    hg_law_segment sg;
    double ln_a;
    int l, beyond;
    memset(out, 0, sizeof *out);
    if (!(a > 0.0)) return;
    ln_a = log(a);
    l = hg_mesh_law_locate(m->lv, m->ln_a, ln_a, &beyond);
    sg = segment_of(m, l, beyond);
    hg_mesh_law_segment_force(m->lv, &sg, a, ln_a, out);
}

double hg_mesh_law_approach(const hg_mesh_law *m, double W)
{
    const hg_law_levels *lv = m->lv;
    int l = 0, last = lv->n - 2;
    hg_law_segment sg;
    hg_segment s;
    if (!(W > 0.0)) return 0.0;
    while (l < last && W > lv->W[l + 1]) l++;
    sg = segment_of(m, l, 0);
    s = segment(lv, &sg);
    if (W > lv->W[last + 1]) { /* beyond the last level */
        double a_e = exp(m->ln_a[last + 1]);
        return a_e + (W - lv->W[last + 1]) * a_e / (s.p * lv->W[last + 1]);
    }
    return exp(m->ln_a[l] + log(W * lv->per_W[l]) / s.p);
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
        hg_mesh_law_of_series(g, flank, HG_TWO_PI * j / TANGENT_ANGLES, &lv, &law);
        for (side = -1; side <= 1; side += 2) { /* both slopes at a level's own load */
            hg_mesh_law_force(&law, hg_mesh_law_approach(&law, W * (1.0 + side * NODE_SIDE)), &f);
            sum += 0.5 * f.k;
        }
    }
    return sum / TANGENT_ANGLES;
}
