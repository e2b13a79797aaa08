/* Tabulated gear-set series: see phase_table.h. */
#include "model/phase_table.h"

#include <math.h>

#define TWO_PI 6.283185307179586

static void node(const hg_series *y, const hg_harmonics *h, double out[2])
{
    out[0] = hg_series_value(y, h);
    out[1] = hg_series_slope(y, h);
}

void hg_phase_table_build(hg_phase_table *t, const hg_gearset *g)
{
    const hg_series *y = g->s[HG_FLANK_DRIVE][0].y;
    const hg_series *mesh[HG_PT_N_MESH_CH] = {&y[HG_S_K_M], &y[HG_S_R_P], &g->e_0};
    const hg_series *pair[HG_PT_N_PAIR_CH] = {&y[HG_S_LS],   &y[HG_S_R_X],   &y[HG_S_R_Y],
                                              &y[HG_S_UP_X], &y[HG_S_UP_Y], &y[HG_S_UG_X],
                                              &y[HG_S_UG_Y], &y[HG_S_VC_X], &y[HG_S_VC_Y]};
    int i, c;
    for (i = 0; i < HG_PT_N_MESH; i++) {
        hg_harmonics h;
        hg_harmonics_eval(TWO_PI * i / HG_PT_N_MESH, HG_MAX_HARMONICS, &h);
        for (c = 0; c < HG_PT_N_MESH_CH; c++) node(mesh[c], &h, t->mesh[i][c]);
    }
    for (i = 0; i < HG_PT_N_PAIR; i++) {
        hg_harmonics h;
        hg_harmonics_eval(TWO_PI * i / HG_PT_N_PAIR, HG_MAX_HARMONICS, &h);
        for (c = 0; c < HG_PT_N_PAIR_CH; c++) node(pair[c], &h, t->pair[i][c]);
    }
}

/* Cubic Hermite basis at fraction s of a cell of width w: weights of the two values (a) and
 * the two slopes (b), and of their derivatives (da, db). */
typedef struct {
    int i0, i1;
    double a0, b0, a1, b1, da0, db0, da1, db1;
} cell;

static void locate(double x, int n, cell *c)
{
    double u = x / TWO_PI * n, s, s2, s3, w = TWO_PI / n;
    u -= n * floor(u / n);
    if (!(u >= 0.0 && u < n)) u = 0.0; /* a non-finite angle: any node (the state is lost) */
    c->i0 = (int)u;
    if (c->i0 >= n) c->i0 = n - 1;
    c->i1 = (c->i0 + 1) % n;
    s = u - c->i0, s2 = s * s, s3 = s2 * s;
    c->a0 = 2.0 * s3 - 3.0 * s2 + 1.0;
    c->b0 = w * (s3 - 2.0 * s2 + s);
    c->a1 = 3.0 * s2 - 2.0 * s3;
    c->b1 = w * (s3 - s2);
    c->da0 = 6.0 * (s2 - s) / w;
    c->db0 = 3.0 * s2 - 4.0 * s + 1.0;
    c->da1 = -c->da0;
    c->db1 = 3.0 * s2 - 2.0 * s;
}

static double value(const cell *c, const double *p0, const double *p1)
{
    return c->a0 * p0[0] + c->b0 * p0[1] + c->a1 * p1[0] + c->b1 * p1[1];
}

static double slope(const cell *c, const double *p0, const double *p1)
{
    return c->da0 * p0[0] + c->db0 * p0[1] + c->da1 * p1[0] + c->db1 * p1[1];
}

void hg_phase_table_mesh(const hg_phase_table *t, double theta, hg_mesh_point *out)
{
    cell c;
    locate(theta, HG_PT_N_MESH, &c);
#define CH(k) t->mesh[c.i0][k], t->mesh[c.i1][k]
    out->k_m = value(&c, CH(HG_PT_K_M));
    out->dk_m = slope(&c, CH(HG_PT_K_M));
    out->R_p = value(&c, CH(HG_PT_R_P));
    out->e_0 = value(&c, CH(HG_PT_E_0));
    out->de_0 = slope(&c, CH(HG_PT_E_0));
    out->dk_dT = 0.0; /* one torque level */
#undef CH
}

void hg_phase_table_pairs(const hg_phase_table *t, double theta, hg_pair_geometry *out)
{
    int k;
    for (k = 0; k < HG_MAX_PAIRS; k++) {
        cell c;
        locate(hg_gearset_pair_phase(theta, k), HG_PT_N_PAIR, &c);
#define CH(j) t->pair[c.i0][j], t->pair[c.i1][j]
        out->ls[k] = hg_gearset_share_clamp(value(&c, CH(HG_PT_LS)));
        out->R_x[k] = value(&c, CH(HG_PT_R_X));
        out->R_y[k] = value(&c, CH(HG_PT_R_Y));
        out->up[k][0] = value(&c, CH(HG_PT_UP_X));
        out->up[k][1] = value(&c, CH(HG_PT_UP_Y));
        out->ug[k][0] = value(&c, CH(HG_PT_UG_X));
        out->ug[k][1] = value(&c, CH(HG_PT_UG_Y));
        out->vc[k][0] = value(&c, CH(HG_PT_VC_X));
        out->vc[k][1] = value(&c, CH(HG_PT_VC_Y));
#undef CH
    }
    hg_gearset_normalise_shares(out->ls);
}
