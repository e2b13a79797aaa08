/* The tabulated gear-set series against the series themselves (the built-in single-series gear
 * sets 1-3, off the nodes, either flank):
 * values within a small fraction of each series' ripple, the mesh derivatives within a small
 * fraction of theirs, load shares still summing to 1. */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "io/datafile.h"
#include "model/phase_table.h"

#define TWO_PI 6.283185307179586
#define N_POINTS 3001

static double amplitude(const hg_series *y)
{
    double a = 0.0;
    int i;
    for (i = 0; i < y->n; i++) a += fabs(y->s[i]) + fabs(y->c[i]);
    return a;
}

/* d/dtheta amplitude: harmonic i contributes i times its coefficients. */
static double slope_amplitude(const hg_series *y)
{
    double a = 0.0;
    int i;
    for (i = 0; i < y->n; i++) a += (i + 1) * (fabs(y->s[i]) + fabs(y->c[i]));
    return a;
}

static void compare(const char *path)
{
    static hg_gearset g;
    static hg_phase_table t;
    char err[HG_ERRLEN] = "";
    double worst_v = 0.0, worst_d = 0.0, worst_pair = 0.0;
    const hg_series *y;
    int j, k;
    CHECK(hg_gearset_load(path, &g, err, sizeof err) == 0);
    CHECK(hg_gearset_single_series(&g));
    y = g.s[HG_FLANK_DRIVE][0].y;
    hg_phase_table_build(&t, &g);
    for (j = 0; j < N_POINTS; j++) {
        double theta = 3.0 * TWO_PI * (j + 0.37) / N_POINTS, sum = 0.0;
        hg_mesh_point a, b;
        hg_pair_geometry p, q, r;
        hg_pt_cell cell;
        hg_gearset_mesh(&g, HG_FLANK_DRIVE, 0.0, theta, &a);
        hg_phase_table_locate(theta, &cell);
        hg_phase_table_mesh(&t, &cell, &b);
        worst_v = fmax(worst_v, fabs(a.k_m - b.k_m) / amplitude(&y[HG_S_K_M]));
        worst_v = fmax(worst_v, fabs(a.R_p - b.R_p) / amplitude(&y[HG_S_R_P]));
        worst_d = fmax(worst_d, fabs(a.dk_m - b.dk_m) / slope_amplitude(&y[HG_S_K_M]));
        worst_d = fmax(worst_d, fabs(a.de_0 - b.de_0) / slope_amplitude(&g.e_0));
        hg_gearset_pairs(&g, HG_FLANK_COAST, 0.0, theta, 1, &p);
        hg_phase_table_pairs(&t, &cell, 1, &q);
        hg_phase_table_pairs(&t, &cell, 0, &r); /* the sliding data alone: the same values */
        for (k = 0; k < HG_MAX_PAIRS; k++) {
            CHECK(r.ls[k] == q.ls[k] && r.up[k][1] == q.up[k][1] && r.ug[k][0] == q.ug[k][0]);
            sum += q.ls[k];
            worst_pair = fmax(worst_pair, fabs(p.ls[k] - q.ls[k]));
            if (p.ls[k] <= 0.0) continue;
            worst_pair = fmax(worst_pair, fabs(p.R_x[k] - q.R_x[k]) / amplitude(&y[HG_S_R_X]));
            worst_pair = fmax(worst_pair, fabs(p.up[k][0] - q.up[k][0]) / amplitude(&y[HG_S_UP_X]));
            worst_pair = fmax(worst_pair, fabs(p.ug[k][1] - q.ug[k][1]) / amplitude(&y[HG_S_UG_Y]));
            worst_pair = fmax(worst_pair, fabs(p.vc[k][1] - q.vc[k][1]) / fabs(y[HG_S_VC_Y].mean));
        }
        CHECK_CLOSE(sum, 1.0, 1e-12, 0.0);
    }
    printf("%s: mesh values %.1e, mesh slopes %.1e, pair data %.1e of the ripple\n", path,
           worst_v, worst_d, worst_pair);
    CHECK(worst_v < 1e-6 && worst_d < 1e-4 && worst_pair < 2e-6);
}

int main(void)
{
    compare("resources/gearsets/gearset1.txt");
    compare("resources/gearsets/gearset2.txt");
    compare("resources/gearsets/gearset3.txt");
    CHECK_DONE();
}
