/* Tabulated gear-set series: see phase_table.h. */
#include "mesh/phase_table.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "io/constants.h"

#define W_MESH (HG_TWO_PI / HG_PT_N_MESH) /* node spacing in theta */
#define W_PAIR (HG_TWO_PI / HG_PT_N_PAIR) /* node spacing in psi */
/* Their reciprocals: the right-hand side multiplies (a division costs it several multiplies) */
#define PER_W_MESH (HG_PT_N_MESH / HG_TWO_PI)
#define PER_PERIOD (1.0 / HG_PT_N_PAIR)

/* Value and slope times the node spacing w. */
static void node(const hg_series *y, const hg_harmonics *h, double w, double out[2])
{
    out[0] = hg_series_value(y, h);
    out[1] = hg_series_slope(y, h) * w;
}

void hg_phase_table_build(hg_phase_table *t, const hg_gearset *g, int fl, int lv)
{
    const hg_series *y = g->s[fl][lv].y;
    const hg_series *mesh[HG_PT_N_MESH_CH] = {&y[HG_S_K_M], &y[HG_S_R_P], &g->e_0};
    const hg_series *pair[HG_PT_N_PAIR_CH] = {&y[HG_S_LS],   &y[HG_S_UP_X], &y[HG_S_UP_Y],
                                              &y[HG_S_UG_X], &y[HG_S_UG_Y], &y[HG_S_R_X],
                                              &y[HG_S_R_Y],  &y[HG_S_VC_X], &y[HG_S_VC_Y]};
    int i, c;
    for (i = 0; i < HG_PT_N_MESH; i++) {
        hg_harmonics h;
        hg_harmonics_eval(W_MESH * i, HG_MAX_HARMONICS, &h);
        for (c = 0; c < HG_PT_N_MESH_CH; c++) node(mesh[c], &h, W_MESH, t->mesh[i][c]);
    }
    for (i = 0; i < HG_PT_N_PAIR; i++) {
        hg_harmonics h;
        hg_harmonics_eval(W_PAIR * i, HG_MAX_HARMONICS, &h);
        for (c = 0; c < HG_PT_N_PAIR_CH; c++) node(pair[c], &h, W_PAIR, t->pair[i][c]);
    }
}

void hg_phase_tables_free(hg_phase_tables *ts)
{
    free(ts->t);
    free(ts->k_levels);
    ts->t = NULL;
    ts->k_levels = NULL;
    ts->n_flanks = ts->n_levels = 0;
}

/* One channel of the force law's nodes: value and slope times the node spacing of each level. */
static void put(double node[2][HG_MAX_LEVELS], int lv, double v, double dv)
{
    node[0][lv] = v;
    node[1][lv] = dv * W_MESH;
}

/* The force law's nodes of flank fl, from its levels' tables and its levels ts->law[fl]. */
static void build_levels(hg_pt_levels *K, const hg_phase_tables *ts, int fl)
{
    int i, lv;
    for (i = 0; i < HG_PT_N_MESH; i++) {
        double k[HG_MAX_LEVELS], dk[HG_MAX_LEVELS];
        hg_mesh_law law;
        for (lv = 0; lv < ts->n_levels; lv++) {
            const double *node = ts->t[fl * ts->n_levels + lv].mesh[i][HG_PT_K_M];
            k[lv] = node[0];
            dk[lv] = node[1] * PER_W_MESH;
        }
        hg_mesh_law_points(&ts->law[fl], k, dk, &law);
        for (lv = 0; lv < ts->n_levels; lv++) {
            put(K->ln_a[i], lv, law.ln_a[lv], law.dln_a[lv]);
            put(K->P[i], lv, law.P[lv], law.dP[lv]);
            put(K->B[i], lv, law.B[lv], law.dB[lv]);
        }
    }
}

static int build_here(hg_phase_table *t, int fl, int lv, void *gear)
{
    hg_phase_table_build(t, gear, fl, lv);
    return 0;
}

int hg_phase_tables_build(hg_phase_tables *ts, const hg_gearset *g)
{
    return hg_phase_tables_build_with(ts, g, build_here, (void *)g);
}

int hg_phase_tables_build_with(hg_phase_tables *ts, const hg_gearset *g, hg_pt_one_fn one,
                               void *ctx)
{
    int fl, lv, n = g->n_flanks * g->n_levels, layered = g->n_levels > 1;
    if (ts->n_flanks * ts->n_levels != n || ts->n_flanks != g->n_flanks) {
        hg_phase_tables_free(ts);
        if (!(ts->t = malloc((size_t)n * sizeof *ts->t)) ||
            (layered && !(ts->k_levels = calloc((size_t)g->n_flanks, sizeof *ts->k_levels)))) {
            hg_phase_tables_free(ts);
            return -1;
        }
    }
    ts->n_flanks = g->n_flanks;
    ts->n_levels = g->n_levels;
    for (fl = 0; fl < g->n_flanks; fl++)
        for (lv = 0; lv < g->n_levels; lv++)
            if (one(&ts->t[fl * g->n_levels + lv], fl, lv, ctx)) {
                hg_phase_tables_free(ts);
                return -1;
            }
    for (fl = 0; fl < g->n_flanks && layered; fl++) {
        hg_mesh_law_levels_of(g, fl, &ts->law[fl]);
        build_levels(&ts->k_levels[fl], ts, fl);
    }
    return 0;
}

/* Pair 0's phase theta / 3 in nodes of the pair grid is theta in nodes of the mesh grid. */
void hg_phase_table_locate(double theta, hg_pt_cell *c)
{
    double u = theta * PER_W_MESH, s, s2, s3;
    u -= HG_PT_N_PAIR * floor(u * PER_PERIOD);
    if (!(u >= 0.0 && u < HG_PT_N_PAIR)) u = 0.0; /* the period's end after rounding (the same
                                                     node), or a non-finite angle: any node (the
                                                     state is lost) */
    c->i = (int)u;
    if (c->i >= HG_PT_N_PAIR) c->i = HG_PT_N_PAIR - 1;
    s = u - c->i, s2 = s * s, s3 = s2 * s;
    c->a0 = 2.0 * s3 - 3.0 * s2 + 1.0;
    c->b0 = s3 - 2.0 * s2 + s;
    c->a1 = 3.0 * s2 - 2.0 * s3;
    c->b1 = s3 - s2;
    c->da0 = 6.0 * (s2 - s);
    c->db0 = 3.0 * s2 - 4.0 * s + 1.0;
    c->da1 = -c->da0;
    c->db1 = 3.0 * s2 - 2.0 * s;
}

static double value(const hg_pt_cell *c, const double *p0, const double *p1)
{
    return c->a0 * p0[0] + c->b0 * p0[1] + c->a1 * p1[0] + c->b1 * p1[1];
}

/* d/dtheta of the mesh channel (the slopes are per node spacing). */
static double slope(const hg_pt_cell *c, const double *p0, const double *p1)
{
    return (c->da0 * p0[0] + c->db0 * p0[1] + c->da1 * p1[0] + c->db1 * p1[1]) * PER_W_MESH;
}

/* The table of level `level` of the flank b picks. */
static const hg_phase_table *table_of(const hg_phase_tables *ts, const hg_level_pick *b, int level)
{
    return &ts->t[b->flank * ts->n_levels + level];
}

static void mesh_one(const hg_phase_table *t, const hg_pt_cell *c, hg_mesh_point *out)
{
    int i0 = c->i % HG_PT_N_MESH, i1 = (c->i + 1) % HG_PT_N_MESH;
#define CH(k) t->mesh[i0][k], t->mesh[i1][k]
    out->k_m = value(c, CH(HG_PT_K_M));
    out->dk_m = slope(c, CH(HG_PT_K_M));
    out->R_p = value(c, CH(HG_PT_R_P));
    out->e_0 = value(c, CH(HG_PT_E_0));
    out->de_0 = slope(c, CH(HG_PT_E_0));
    out->dk_dT = 0.0;
#undef CH
}

/* a + w (b - a), the blend of hg_gearset_mesh and hg_gearset_pairs */
static double blend(double a, double b, double w) { return a + w * (b - a); }

void hg_phase_table_mesh(const hg_phase_tables *ts, const hg_level_pick *b, const hg_pt_cell *c,
                         hg_mesh_point *out)
{
    hg_mesh_point hi;
    mesh_one(table_of(ts, b, b->lo), c, out);
    if (!(b->w > 0.0)) return; /* one level: no blend (and dk_m/dT = 0) */
    mesh_one(table_of(ts, b, b->hi), c, &hi);
    out->dk_dT = b->dw_dT * (hi.k_m - out->k_m);
    out->k_m = blend(out->k_m, hi.k_m, b->w);
    out->dk_m = blend(out->dk_m, hi.dk_m, b->w);
    out->R_p = blend(out->R_p, hi.R_p, b->w); /* e_0: one series for every flank and level */
}

/* Value v and d/dtheta dv of lane l of the nodes n0, n1 at the cell c (value() and slope()). */
static void lane(const hg_pt_cell *c, const double (*n0)[HG_MAX_LEVELS],
                 const double (*n1)[HG_MAX_LEVELS], int l, double *v, double *dv)
{
    *v = c->a0 * n0[0][l] + c->b0 * n0[1][l] + c->a1 * n1[0][l] + c->b1 * n1[1][l];
    *dv = (c->da0 * n0[0][l] + c->db0 * n0[1][l] + c->da1 * n1[0][l] + c->db1 * n1[1][l]) *
          PER_W_MESH;
}

void hg_phase_table_law_force(const hg_phase_tables *ts, int data_flank, const hg_pt_cell *c,
                              double a, hg_law_force *out)
{
    const hg_pt_levels *K = &ts->k_levels[data_flank];
    const hg_law_levels *lv = &ts->law[data_flank];
    int i0 = c->i % HG_PT_N_MESH, i1 = (c->i + 1) % HG_PT_N_MESH, l;
    double ln_a[HG_MAX_LEVELS], dln_a[HG_MAX_LEVELS], ln_ax;
    hg_law_segment sg;
    memset(out, 0, sizeof *out);
    if (!(a > 0.0)) return;
    ln_ax = log(a);
    for (l = 0; l < lv->n; l++) lane(c, K->ln_a[i0], K->ln_a[i1], l, &ln_a[l], &dln_a[l]);
    sg.l = l = hg_mesh_law_locate(lv, ln_a, ln_ax, &sg.beyond);
    sg.ln_a0 = ln_a[l];
    sg.dln_a0 = dln_a[l];
    sg.ln_a1 = ln_a[l + 1];
    sg.dln_a1 = dln_a[l + 1];
    sg.P = sg.dP = 0.0;
    if (l > 0) lane(c, K->P[i0], K->P[i1], l, &sg.P, &sg.dP);
    lane(c, K->B[i0], K->B[i1], sg.beyond ? l + 1 : l, &sg.B, &sg.dB);
    hg_mesh_law_segment_force(lv, &sg, a, ln_ax, out);
}

/* The pairs' values of one table, the load shares before clamping. */
static void pairs_one(const hg_phase_table *t, const hg_pt_cell *c, int with_contact,
                      hg_pair_geometry *out)
{
    int k;
    for (k = 0; k < HG_MAX_PAIRS; k++) {
        int i0 = (c->i + k * HG_PT_N_MESH) % HG_PT_N_PAIR, i1 = (i0 + 1) % HG_PT_N_PAIR;
#define CH(j) t->pair[i0][j], t->pair[i1][j]
        /* each value straight into its place: through an array of the channels, the array's
         * unaligned re-reads stalled on its stores (a third of this function's time) */
        out->ls[k] = value(c, CH(HG_PT_LS));
        out->up[k][0] = value(c, CH(HG_PT_UP_X));
        out->up[k][1] = value(c, CH(HG_PT_UP_Y));
        out->ug[k][0] = value(c, CH(HG_PT_UG_X));
        out->ug[k][1] = value(c, CH(HG_PT_UG_Y));
        if (!with_contact) continue;
        out->R_x[k] = value(c, CH(HG_PT_R_X));
        out->R_y[k] = value(c, CH(HG_PT_R_Y));
        out->vc[k][0] = value(c, CH(HG_PT_VC_X));
        out->vc[k][1] = value(c, CH(HG_PT_VC_Y));
#undef CH
    }
}

/* The pairs' values blended between the tables lo and hi (upper weight w) as they are read:
 * pairs_one of each, then blend(), without the second table's values stored in between. */
static void pairs_two(const hg_phase_table *lo, const hg_phase_table *hi, double w,
                      const hg_pt_cell *c, int with_contact, hg_pair_geometry *out)
{
    int k;
    for (k = 0; k < HG_MAX_PAIRS; k++) {
        int i0 = (c->i + k * HG_PT_N_MESH) % HG_PT_N_PAIR, i1 = (i0 + 1) % HG_PT_N_PAIR;
#define BL(j) blend(value(c, lo->pair[i0][j], lo->pair[i1][j]), \
                    value(c, hi->pair[i0][j], hi->pair[i1][j]), w)
        out->ls[k] = BL(HG_PT_LS);
        out->up[k][0] = BL(HG_PT_UP_X);
        out->up[k][1] = BL(HG_PT_UP_Y);
        out->ug[k][0] = BL(HG_PT_UG_X);
        out->ug[k][1] = BL(HG_PT_UG_Y);
        if (!with_contact) continue;
        out->R_x[k] = BL(HG_PT_R_X);
        out->R_y[k] = BL(HG_PT_R_Y);
        out->vc[k][0] = BL(HG_PT_VC_X);
        out->vc[k][1] = BL(HG_PT_VC_Y);
#undef BL
    }
}

void hg_phase_table_pairs(const hg_phase_tables *ts, const hg_level_pick *b, const hg_pt_cell *c,
                          int with_contact, hg_pair_geometry *out)
{
    int k;
    if (b->w > 0.0)
        pairs_two(table_of(ts, b, b->lo), table_of(ts, b, b->hi), b->w, c, with_contact, out);
    else
        pairs_one(table_of(ts, b, b->lo), c, with_contact, out);
    for (k = 0; k < HG_MAX_PAIRS; k++) out->ls[k] = hg_gearset_share_clamp(out->ls[k]);
    hg_gearset_normalise_shares(out->ls);
}
