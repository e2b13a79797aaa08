/* The tabulated gear-set series against the series themselves (the built-in single-series gear
 * sets 1-3 and the layered two-flank ones, off the nodes, either flank, torques below, between
 * and beyond the levels):
 * values within a small fraction of each series' ripple, the mesh derivatives within a small
 * fraction of theirs, load shares still summing to 1; the layered files' force law from the
 * tables against the law from the series. */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "io/constants.h"
#include "io/datafile.h"
#include "mesh/phase_table.h"

#define N_POINTS 3001

/* The ripple's scale: the sum of the harmonics' amplitudes (the mean for a constant series). */
static double amplitude(const hg_series *y)
{
    double a = 0.0;
    int i;
    for (i = 0; i < y->n; i++) a += fabs(y->s[i]) + fabs(y->c[i]);
    return a > 0.0 ? a : fabs(y->mean);
}

/* d/dtheta amplitude: harmonic i contributes i times its coefficients. */
static double slope_amplitude(const hg_series *y)
{
    double a = 0.0;
    int i;
    for (i = 0; i < y->n; i++) a += (i + 1) * (fabs(y->s[i]) + fabs(y->c[i]));
    return a;
}

/* The force law of a layered file from the tables against the law from the series at theta,
 * below, at and between the levels' points and beyond the last: the worst differences of W
 * relative to W and of U and dU/dtheta relative to U into worst[0], worst[1] (the tables
 * interpolate the law's energy at the points: hg_pt_levels). */
static void compare_law(const hg_gearset *g, const hg_phase_tables *ts, int fl, double theta,
                        const hg_pt_cell *cell, double worst[2])
{
    static const double at[] = {0.4, 1.0, 1.3};
    hg_law_levels lv;
    hg_mesh_law ls;
    hg_level_pick b;
    int l, i;
    hg_gearset_level_at(g, fl, 0.0, &b);
    hg_mesh_law_of_series(g, fl, theta, &lv, &ls);
    for (l = 0; l < g->n_levels; l++)
        for (i = 0; i < 3; i++) {
            hg_law_force t, s;
            double a = at[i] * exp(ls.ln_a[l]);
            hg_phase_table_law_force(ts, b.flank, cell, a, &t);
            hg_mesh_law_force(&ls, a, &s);
            worst[0] = fmax(worst[0], fabs(t.W - s.W) / s.W);
            worst[1] = fmax(worst[1], fabs(t.dU - s.dU) / s.U);
            worst[1] = fmax(worst[1], fabs(t.U - s.U) / s.U);
        }
}

/* The tables against the direct blend of the series (hg_gearset_mesh, hg_gearset_pairs) on
 * flank fl at pinion torque T, off the nodes; the worst differences relative to the ripple of the
 * lower level's series, returned in worst[0 ... 2] (mesh values, mesh slopes, pair data), for
 * a layered file the force law's in worst[3], worst[4] (compare_law). */
static void compare_at(const hg_gearset *g, const hg_phase_tables *ts, int fl, double T,
                       double worst[5])
{
    hg_level_pick b;
    const hg_series *y;
    int j, k;
    hg_gearset_level_at(g, fl, T, &b);
    y = g->s[b.flank][b.lo].y;
    for (j = 0; j < N_POINTS; j++) {
        double theta = 3.0 * HG_TWO_PI * (j + 0.37) / N_POINTS, sum = 0.0;
        hg_mesh_point a, m;
        hg_pair_geometry p, q, r;
        hg_pt_cell cell;
        hg_gearset_mesh(g, fl, T, theta, &a);
        hg_phase_table_locate(theta, &cell);
        hg_phase_table_mesh(ts, &b, &cell, &m);
        worst[0] = fmax(worst[0], fabs(a.k_m - m.k_m) / amplitude(&y[HG_S_K_M]));
        worst[0] = fmax(worst[0], fabs(a.R_p - m.R_p) / amplitude(&y[HG_S_R_P]));
        worst[0] = fmax(worst[0], fabs(a.e_0 - m.e_0) / amplitude(&g->e_0));
        worst[0] = fmax(worst[0], fabs(a.dk_dT - m.dk_dT) * (b.dw_dT > 0.0 ? 1.0 / b.dw_dT : 1.0) /
                                      amplitude(&y[HG_S_K_M]));
        worst[1] = fmax(worst[1], fabs(a.dk_m - m.dk_m) / slope_amplitude(&y[HG_S_K_M]));
        worst[1] = fmax(worst[1], fabs(a.de_0 - m.de_0) / slope_amplitude(&g->e_0));
        hg_gearset_pairs(g, fl, T, theta, 1, &p);
        hg_phase_table_pairs(ts, &b, &cell, 1, &q);
        hg_phase_table_pairs(ts, &b, &cell, 0, &r); /* the sliding data alone: the same values */
        for (k = 0; k < HG_MAX_PAIRS; k++) {
            CHECK(r.ls[k] == q.ls[k] && r.up[k][1] == q.up[k][1] && r.ug[k][0] == q.ug[k][0]);
            sum += q.ls[k];
            worst[2] = fmax(worst[2], fabs(p.ls[k] - q.ls[k]));
            if (p.ls[k] <= 0.0) continue;
            worst[2] = fmax(worst[2], fabs(p.R_x[k] - q.R_x[k]) / amplitude(&y[HG_S_R_X]));
            worst[2] = fmax(worst[2], fabs(p.R_y[k] - q.R_y[k]) / amplitude(&y[HG_S_R_Y]));
            worst[2] = fmax(worst[2], fabs(p.up[k][0] - q.up[k][0]) / amplitude(&y[HG_S_UP_X]));
            worst[2] = fmax(worst[2], fabs(p.ug[k][1] - q.ug[k][1]) / amplitude(&y[HG_S_UG_Y]));
            worst[2] = fmax(worst[2], fabs(p.vc[k][1] - q.vc[k][1]) / fabs(y[HG_S_VC_Y].mean));
        }
        CHECK_CLOSE(sum, 1.0, 1e-12, 0.0);
        if (g->n_levels > 1) compare_law(g, ts, fl, theta, &cell, &worst[3]);
    }
}

/* Every flank at torques below, on, between and above the file's levels; bounds on the worst
 * mesh value, mesh slope and pair datum relative to the ripple. */
static void compare(const char *path, double bound_v, double bound_d, double bound_pair,
                    double bound_W, double bound_dU)
{
    static hg_gearset g;
    static hg_phase_tables ts;
    static const double T[] = {0.0, 10.0, 25.0, 37.0, 100.0, 141.0, 399.0, 400.0, 650.0};
    char err[HG_ERRLEN] = "";
    double worst[5] = {0.0, 0.0, 0.0, 0.0, 0.0};
    int fl, i;
    CHECK(hg_gearset_load(path, &g, err, sizeof err) == 0);
    CHECK(hg_phase_tables_build(&ts, &g) == 0);
    CHECK(ts.n_flanks == g.n_flanks && ts.n_levels == g.n_levels);
    for (fl = 0; fl < HG_N_FLANKS; fl++)
        for (i = 0; i < (int)(sizeof T / sizeof T[0]); i++) compare_at(&g, &ts, fl, T[i], worst);
    printf("%s (%d flank(s), %d level(s)): mesh values %.1e, mesh slopes %.1e, pair data %.1e of "
           "the ripple; law: W %.1e of W, U and dU/dtheta %.1e of U\n", path, g.n_flanks,
           g.n_levels, worst[0], worst[1], worst[2], worst[3], worst[4]);
    CHECK(worst[0] < bound_v && worst[1] < bound_d && worst[2] < bound_pair);
    CHECK(worst[3] <= bound_W && worst[4] <= bound_dU);
    hg_phase_tables_free(&ts);
}

int main(void)
{
    compare("resources/gearsets/gearset1.txt", 1e-6, 1e-4, 2e-6, 0.0, 0.0);
    compare("resources/gearsets/gearset2.txt", 1e-6, 1e-4, 2e-6, 0.0, 0.0);
    compare("resources/gearsets/gearset3.txt", 1e-6, 1e-4, 2e-6, 0.0, 0.0);
    /* the loaded k_m has more of its ripple in the high harmonics (the kinks where pairs take up
     * load): 2e-4 of its ripple is 1.1e-5 of its mean */
    compare("resources/gearsets/loaded/gearset1.txt", 3e-4, 2e-3, 2e-6, 3e-5, 4e-3);
    compare("resources/gearsets/loaded/gearset2.txt", 3e-4, 2e-3, 2e-6, 3e-5, 4e-3);
    compare("resources/gearsets/loaded/gearset3.txt", 3e-4, 2e-3, 2e-6, 3e-5, 4e-3);
    CHECK_DONE();
}
