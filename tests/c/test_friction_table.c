/* The friction table against the direct solve it replaces: gear set 1, both paper oils, thermal
 * and isothermal EHL, at operating points spread over the table's whole validity range (phase,
 * load down to the rebuild limit, speed and temperature drifts up to the rebuild thresholds).
 * Errors are measured relative to the friction force of the pair at the same phase under the
 * full load of the key, the scale on which the mesh loss is summed. And how the key moves when
 * the operating point leaves it (hg_ft_key_next). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "io/constants.h"
#include "hg_vars.h"
#include "io/datafile.h"
#include "model/friction_table.h"
#include "paper_oils.h"

#define RPM 0.10471975511965977
#define N_POINTS 4000
#define GEAR_SPEED_RIPPLE 0.015 /* the gear speed's excursion from w_p / ratio */

static double direct_at(const hg_friction_config *cfg, const hg_pair_point *pt, double W,
                        double w_p, double w_g, double T)
{
    hg_pair_contact c;
    hg_pair_friction f;
    double warm = NAN;
    c.W = W;
    hg_gearset_entrainment(pt->up, pt->ug, pt->vc, w_p, w_g, c.u_p, c.u_g);
    c.R_x = pt->R_x, c.R_y = pt->R_y, c.T_bath = T;
    hg_friction_pair(cfg, &c, &warm, &f);
    return f.F_f;
}

static double direct(const hg_friction_config *cfg, const hg_gearset *g, double psi, double W,
                     double w_p, double w_g, double T)
{
    hg_pair_point pt;
    hg_gearset_pair_point(g, HG_FLANK_DRIVE, 0, psi, &pt);
    return direct_at(cfg, &pt, W, w_p, w_g, T);
}

/* Uniform in [a, b] from a fixed linear congruential sequence (reproducible everywhere). */
static double uniform(unsigned long *state, double a, double b)
{
    *state = (*state * 6364136223846793005UL + 1442695040888963407UL) & 0xffffffffffffUL;
    return a + (b - a) * (double)(*state >> 16) / 4294967296.0;
}

/* Worst relative error over random points inside the range the key covers, of the table solved
 * at the key (nodes 0) or of the one the model uses, interpolated between the node tables around
 * the key's speed (nodes 1: hg_ft_set_table). */
static double worst_error(const hg_friction_config *cfg, const hg_gearset *g, double rpm,
                          double T_bath, double W_t, int rigid, int nodes)
{
    static hg_friction_table own;
    static hg_ft_set set;
    const hg_friction_table *tab = &own, *t;
    hg_ft_key key;
    unsigned long seed = 12345;
    double w_p = rpm * RPM, ratio = (double)g->N_g / g->N_p, worst = 0.0;
    int n;
    hg_ft_key_for(w_p, ratio, T_bath, W_t, &key);
    if (nodes) {
        hg_ft_set_alloc(&set, cfg, g, rigid);
        set.key = key;
        set.keyed = 1;
        tab = hg_ft_set_table(&set, cfg, g, HG_FLANK_DRIVE, 0);
        if (!tab) { /* a node's mu beyond HG_FT_MU_MAX (the isothermal shear, cold): the model
                       solves the friction directly there */
            hg_ft_set_free(&set);
            return 0.0;
        }
    } else {
        hg_friction_table_build(&own, cfg, g, HG_FLANK_DRIVE, 0, &key, rigid);
    }
    t = tab;
    for (n = 0; n < N_POINTS; n++) {
        double psi = uniform(&seed, 0.0, HG_TWO_PI), d = HG_FT_SPEED_DRIFT;
        double W_t_now = uniform(&seed, 0.0625, HG_FT_LOAD_FILL) * key.W_max;
        double ls = uniform(&seed, 0.0, 1.0), W = ls * W_t_now;
        double wp = w_p * (1.0 + uniform(&seed, -d, d));
        double ripple = rigid ? 0.0 : GEAR_SPEED_RIPPLE;
        double wg = wp / ratio * (1.0 + uniform(&seed, -ripple, ripple));
        double T = T_bath + uniform(&seed, -HG_FT_T_DRIFT, HG_FT_T_DRIFT);
        hg_pair_point pt;
        double scale, err;
        hg_gearset_pair_point(g, HG_FLANK_DRIVE, 0, psi, &pt);
        if (pt.ls <= 0.0) continue; /* out of contact the pair carries nothing */
        scale = direct(cfg, g, psi, W_t_now, wp, wg, T);
        err = fabs(hg_friction_table_F(t, psi, W, wp, wg, T) - direct(cfg, g, psi, W, wp, wg, T));
        if (scale > 0.0 && err / scale > worst) worst = err / scale;
    }
    if (nodes) hg_ft_set_free(&set);
    return worst;
}

/* Pair 0 of a layered set on flank fl at torque T and phase psi with the levels' series blended,
 * as the model's direct solve sees it (hg_gearset_pairs); ls > 0 marks contact. */
static void blended_point(const hg_gearset *g, int fl, double T, double psi, hg_pair_point *pt)
{
    hg_pair_geometry geo;
    hg_gearset_pairs(g, fl, T, 3.0 * psi, 1, &geo);
    pt->ls = geo.ls[0];
    pt->R_x = geo.R_x[0], pt->R_y = geo.R_y[0];
    pt->up[0] = geo.up[0][0], pt->up[1] = geo.up[0][1];
    pt->ug[0] = geo.ug[0][0], pt->ug[1] = geo.ug[0][1];
    pt->vc[0] = geo.vc[0][0], pt->vc[1] = geo.vc[0][1];
}

/* The tables of a layered set between its torque levels (hg_friction_table_pairs_blend of the two
 * levels' tables, pair 0 loaded) against the direct solve on the blended geometry: worst error
 * relative to the direct friction of the pair under the key's full load, at random phases,
 * torques between the first and the last level (on the levels too), loads and drifts as in
 * worst_error. */
static double worst_blend_error(const hg_friction_config *cfg, const hg_gearset *g, int fl,
                                double rpm, double T_bath)
{
    static hg_ft_set set;
    unsigned long seed = 777;
    double w_p = rpm * RPM, ratio = (double)g->N_g / g->N_p, worst = 0.0, k_m0, R_p0;
    double T_mid = 0.5 * (g->T_level[0] + g->T_level[g->n_levels - 1]);
    int n;
    hg_ft_set_alloc(&set, cfg, g, 0);
    hg_gearset_means(g, fl, T_mid, &k_m0, &R_p0);
    hg_ft_key_for(w_p, ratio, T_bath, T_mid / R_p0, &set.key);
    set.keyed = 1;
    for (n = 0; n < N_POINTS / 4; n++) {
        double psi = uniform(&seed, 0.0, HG_TWO_PI), d = HG_FT_SPEED_DRIFT;
        double T = n % 8 ? uniform(&seed, g->T_level[0], g->T_level[g->n_levels - 1])
                         : g->T_level[n / 8 % g->n_levels];
        double W_t_now = uniform(&seed, 0.0625, HG_FT_LOAD_FILL) * set.key.W_max;
        double W[HG_MAX_PAIRS] = {0.0, 0.0, 0.0}, F[HG_MAX_PAIRS];
        double wp = w_p * (1.0 + uniform(&seed, -d, d));
        double wg = wp / ratio * (1.0 + uniform(&seed, -GEAR_SPEED_RIPPLE, GEAR_SPEED_RIPPLE));
        double Tb = T_bath + uniform(&seed, -HG_FT_T_DRIFT, HG_FT_T_DRIFT);
        const hg_friction_table *lo, *hi;
        hg_level_pick b;
        hg_pair_point pt;
        double scale;
        W[0] = uniform(&seed, 0.0, 1.0) * W_t_now;
        blended_point(g, fl, T, psi, &pt);
        if (pt.ls <= 0.0) continue;
        hg_gearset_level_at(g, fl, T, &b);
        lo = hg_ft_set_table(&set, cfg, g, b.flank, b.lo);
        hi = hg_ft_set_table(&set, cfg, g, b.flank, b.hi);
        CHECK(lo && hi);
        if (!lo || !hi) break;
        hg_friction_table_pairs_blend(lo, hi, b.w, 3.0 * psi, W, wp, wg, Tb, F);
        scale = direct_at(cfg, &pt, W_t_now, wp, wg, Tb);
        if (scale > 0.0) worst = fmax(worst, fabs(F[0] - direct_at(cfg, &pt, W[0], wp, wg, Tb)) / scale);
    }
    hg_ft_set_free(&set);
    return worst;
}

/* Rebuilds counted while the operating point follows w_p(n) = w0 (1 + a s(n)) over n steps
 * (load and temperature fixed), through hg_ft_key_next as the model calls it. */
static int rebuilds(double w0, double a, int oscillate, int n)
{
    hg_ft_key key = {0};
    int valid = 0, count = 0, k;
    for (k = 0; k < n; k++) {
        double s = oscillate ? (k % 2 ? -1.0 : 1.0) : (double)k / (n - 1);
        double w_p = w0 * (1.0 + a * s);
        if (valid && hg_ft_key_covers(&key, w_p, 313.15, 4760.0)) continue;
        hg_ft_key_next(&key, valid, w_p, 36.0 / 13.0, 313.15, 4760.0);
        CHECK(hg_ft_key_covers(&key, w_p, 313.15, 4760.0)); /* the new key serves the point */
        valid = 1;
        count++;
    }
    return count;
}

/* hg_ft_key_next: a speed swing of +-0.8 windows (a span of 1.6) keeps one table after its
 * first two extremes (the key used to follow the instantaneous speed: a rebuild at every
 * extreme); a 30 % ramp needs no more rebuilds than one per window; a load rebuild keeps the
 * speed and temperature. */
static void test_key_next(void)
{
    hg_ft_key key;
    double w = 2000.0 * RPM;
    CHECK(rebuilds(w, 0.8 * HG_FT_SPEED_DRIFT, 1, 40) == 3);
    CHECK(rebuilds(w, 0.30, 0, 400) <= 1 + (int)ceil(0.30 / HG_FT_SPEED_DRIFT));
    hg_ft_key_for(w, 36.0 / 13.0, 313.15, 4760.0, &key);
    hg_ft_key_next(&key, 1, 1.01 * w, 36.0 / 13.0, 313.6, 9000.0);
    CHECK(key.w_p == w && key.T_bath == 313.15 && key.W_max == 18000.0);
}

/* hg_ft_load_range_on_lattice: the smallest 1000 N x 4^k at or above the range; a key moved
 * onto it as the Model Exchange policy does still covers the load that moved it, for loads from
 * 1 N to 1 MN; a load swinging up and back down through a launch and a tip-out meets three ranges
 * there, where the ranges at twice the load are new at every move (ten here). */
static void test_load_lattice(void)
{
    double W, seen[64], seen_lat[64], swing[] = {600.0, 1500.0, 2600.0, 4500.0, 7600.0, 100.0,
                                                 1400.0, 2100.0, 3100.0, 6200.0};
    int n = 0, n_lat = 0, k, j;
    CHECK(hg_ft_load_range_on_lattice(0.0) == 1000.0);
    CHECK(hg_ft_load_range_on_lattice(1000.0) == 1000.0);
    CHECK(hg_ft_load_range_on_lattice(1000.5) == 4000.0);
    CHECK(hg_ft_load_range_on_lattice(12390.0) == 16000.0);
    for (W = 1.0; W < 1e6; W *= 1.07) {
        hg_ft_key key;
        hg_ft_key_for(100.0, 36.0 / 13.0, 313.15, W, &key);
        key.W_max = hg_ft_load_range_on_lattice(key.W_max);
        CHECK(hg_ft_key_covers(&key, 100.0, 313.15, W));
    }
    for (k = 0; k < (int)(sizeof swing / sizeof swing[0]); k++) {
        hg_ft_key key;
        double lat;
        hg_ft_key_for(100.0, 36.0 / 13.0, 313.15, swing[k], &key);
        lat = hg_ft_load_range_on_lattice(key.W_max);
        for (j = 0; j < n && seen[j] != key.W_max; j++) continue;
        if (j == n) seen[n++] = key.W_max;
        for (j = 0; j < n_lat && seen_lat[j] != lat; j++) continue;
        if (j == n_lat) seen_lat[n_lat++] = lat;
    }
    CHECK(n == 10 && n_lat == 3);
}

/* The node tables of neighbouring load ranges on the lattice share their columns: column j of a
 * table keyed 4 W_max is column j + 4 of the one keyed W_max, bit for bit (their loads are the
 * same half powers of 2, hg_ft_column_load), so the store solves only the four loads a new range
 * adds; a set's table between the node tables assembled column by column from the store is the
 * one interpolated between node tables built whole. */
static void test_columns_shared(const hg_friction_config *cfg, const hg_gearset *g)
{
    static hg_friction_table low, high, lo, hi, between;
    static hg_ft_set set;
    hg_ft_key key, k_lo, k_hi;
    const hg_friction_table *t;
    double ratio = (double)g->N_g / g->N_p;
    int i, j, same = 1;
    CHECK(hg_ft_column_load(4000.0, HG_FT_N_L - 1) == 4000.0);
    CHECK(hg_ft_column_load(4000.0, HG_FT_N_L - 3) == 2000.0);
    CHECK(fabs(hg_ft_column_load(4000.0, 0) / 4000.0 - 1.0 / 1024.0) < 1e-15);
    for (j = 0; j + 4 < HG_FT_N_L; j++)
        CHECK(hg_ft_column_load(16000.0, j) == hg_ft_column_load(4000.0, j + 4));
    hg_ft_key_for(1100.0 * RPM, ratio, 313.15, 2000.0, &key);
    key.W_max = 4000.0;
    hg_ft_node_keys(&key, ratio, &k_lo, &k_hi);
    hg_friction_table_build(&low, cfg, g, HG_FLANK_DRIVE, 0, &k_lo, 0);
    k_lo.W_max = 16000.0;
    hg_friction_table_build(&high, cfg, g, HG_FLANK_DRIVE, 0, &k_lo, 0);
    for (i = 1; i <= HG_FT_N_PSI; i++)
        for (j = 1; j + 4 <= HG_FT_N_L; j++)
            same = same && !memcmp(high.c[i][j], low.c[i][j + 4], sizeof high.c[i][j]);
    CHECK(same);
    hg_ft_set_alloc(&set, cfg, g, 0);
    set.key = key;
    set.keyed = 1;
    k_lo.W_max = 4000.0;
    hg_friction_table_build(&lo, cfg, g, HG_FLANK_DRIVE, 0, &k_lo, 0);
    hg_friction_table_build(&hi, cfg, g, HG_FLANK_DRIVE, 0, &k_hi, 0);
    hg_friction_table_between(&between, &lo, &hi, &key, 0);
    t = hg_ft_set_table(&set, cfg, g, HG_FLANK_DRIVE, 0);
    CHECK(t && !memcmp(t->c, between.c, sizeof between.c) && set.solved == 2 * HG_FT_N_L);
    hg_ft_set_free(&set);
}

/* Worst |ln mu| difference of two tables over their nodes (ghosts left out). */
static double worst_ln_mu_difference(const hg_friction_table *a, const hg_friction_table *b)
{
    double worst = 0.0;
    int i, j;
    for (i = 1; i <= HG_FT_N_PSI; i++)
        for (j = 1; j <= HG_FT_N_L; j++)
            worst = fmax(worst, fabs(a->c[i][j][HG_FT_CH_L] - b->c[i][j][HG_FT_CH_L]));
    return worst;
}

/* Temperature nodes: a key on the temperature lattice between multiples of HG_FT_T_NODE_STEP is
 * interpolated between the node tables there, a key on a node or off the lattice (the first
 * key, at the bath temperature itself) is not. The interpolant at the middle of two nodes, the
 * farthest from both, against the table solved at its temperature: ln mu within 1e-4 at the
 * design point and slow and cold (the tables' own error against the direct solve is 1.5e-3),
 * and a set's table there is the speed interpolation of the temperature interpolations of the
 * node tables, solved at the two node temperatures only. */
static void test_temperature_nodes(const hg_friction_config *cfg, const hg_gearset *g)
{
    static hg_friction_table lo, hi, between, solved, speed_lo, speed_hi;
    static hg_ft_set set;
    const double mid = 0.5 * HG_FT_T_NODE_STEP, at[2][2] = {{2000.0, 312.0}, {500.0, 248.0}};
    double T_lo = 0.0, T_hi = 0.0, ratio = (double)g->N_g / g->N_p;
    hg_ft_key key, k, k_lo, k_hi;
    const hg_friction_table *t;
    int n, s;
    CHECK(hg_ft_temperature_nodes(316.0, &T_lo, &T_hi) && T_lo == 312.0 && T_hi == 320.0);
    CHECK(hg_ft_temperature_nodes(250.0, &T_lo, &T_hi) && T_lo == 248.0 && T_hi == 256.0);
    CHECK(!hg_ft_temperature_nodes(320.0, &T_lo, &T_hi)); /* a node */
    CHECK(!hg_ft_temperature_nodes(313.15, &T_lo, &T_hi)); /* off the lattice */
    CHECK(!hg_ft_temperature_nodes(315.0, &T_lo, &T_hi));
    for (n = 0; n < 2; n++) {
        double w_p = at[n][0] * RPM, T = at[n][1] + mid, worst;
        hg_ft_key_for(w_p, ratio, T, 2000.0, &key);
        key.W_max = 4000.0;
        k = key;
        k.T_bath = at[n][1];
        hg_friction_table_build(&lo, cfg, g, HG_FLANK_DRIVE, 0, &k, 0);
        k.T_bath = at[n][1] + HG_FT_T_NODE_STEP;
        hg_friction_table_build(&hi, cfg, g, HG_FLANK_DRIVE, 0, &k, 0);
        hg_friction_table_build(&solved, cfg, g, HG_FLANK_DRIVE, 0, &key, 0);
        hg_friction_table_between_T(&between, &lo, &hi, T);
        worst = worst_ln_mu_difference(&between, &solved);
        printf("temperature nodes %.0f and %.0f K at %.0f rpm: ln mu between them within %.1e "
               "of the table solved at %.0f K\n", at[n][1], at[n][1] + HG_FT_T_NODE_STEP,
               at[n][0], worst, T);
        CHECK(worst < 1e-4 && between.key.T_bath == T && between.built);
    }
    /* the set: four node tables (two speeds, two temperatures), 2 x 2 x 21 columns solved */
    hg_ft_set_alloc(&set, cfg, g, 0);
    set.key = key;
    set.keyed = 1;
    hg_ft_node_keys(&key, ratio, &k_lo, &k_hi);
    for (s = 0; s < 2; s++) {
        hg_ft_key ks = s ? k_hi : k_lo;
        ks.T_bath = at[1][1];
        hg_friction_table_build(&lo, cfg, g, HG_FLANK_DRIVE, 0, &ks, 0);
        ks.T_bath = at[1][1] + HG_FT_T_NODE_STEP;
        hg_friction_table_build(&hi, cfg, g, HG_FLANK_DRIVE, 0, &ks, 0);
        hg_friction_table_between_T(s ? &speed_hi : &speed_lo, &lo, &hi, key.T_bath);
    }
    hg_friction_table_between(&between, &speed_lo, &speed_hi, &key, 0);
    t = hg_ft_set_table(&set, cfg, g, HG_FLANK_DRIVE, 0);
    CHECK(t && !memcmp(t->c, between.c, sizeof between.c) && set.solved == 4 * HG_FT_N_L);
    hg_ft_set_free(&set);
}

/* hg_ft_temperature_on_lattice: an even number of kelvin, within HG_FT_T_DRIFT of the
 * temperature, so a key moved onto it as friction_table_policy.c does still covers the
 * temperature that moved it, from -60 to 200 degC; an oil warming from 20 to 60 degC and cooling
 * back at another rate keys its tables on 21 temperatures, the same both ways, where keys at the
 * temperature itself are new at every kelvin either way (about 80 here). */
static void test_temperature_lattice(void)
{
    double T, seen[256], seen_lat[256], T_lat;
    int n = 0, n_lat = 0, j, k;
    hg_ft_key key, lat;
    CHECK(hg_ft_temperature_on_lattice(293.15) == 294.0);
    CHECK(hg_ft_temperature_on_lattice(292.9) == 292.0);
    CHECK(hg_ft_temperature_on_lattice(295.0) == 296.0);
    for (T = 213.15; T < 473.15; T += 0.0137) {
        T_lat = hg_ft_temperature_on_lattice(T);
        CHECK(T_lat == 2.0 * floor(0.5 * T_lat) && fabs(T - T_lat) <= HG_FT_T_DRIFT);
        hg_ft_key_for(100.0, 36.0 / 13.0, T_lat, 2000.0, &key);
        if (!hg_ft_key_covers(&key, 100.0, T, 2000.0)) {
            CHECK(0);
            break;
        }
    }
    hg_ft_key_for(100.0, 36.0 / 13.0, 293.15, 2000.0, &key);
    lat = key;
    lat.T_bath = hg_ft_temperature_on_lattice(lat.T_bath);
    for (k = 0; k <= 9714; k++) { /* 20 -> 60 degC in steps of 0.01 K, back in 0.007 K */
        T = k <= 4000 ? 293.15 + 0.01 * k : 333.15 - 0.007 * (k - 4000);
        if (!hg_ft_key_covers(&key, 100.0, T, 2000.0))
            hg_ft_key_next(&key, 1, 100.0, 36.0 / 13.0, T, 2000.0);
        if (!hg_ft_key_covers(&lat, 100.0, T, 2000.0)) {
            hg_ft_key_next(&lat, 1, 100.0, 36.0 / 13.0, T, 2000.0);
            lat.T_bath = hg_ft_temperature_on_lattice(lat.T_bath);
        }
        CHECK(hg_ft_key_covers(&lat, 100.0, T, 2000.0));
        for (j = 0; j < n && seen[j] != key.T_bath; j++) continue;
        if (j == n && n < 256) seen[n++] = key.T_bath;
        for (j = 0; j < n_lat && seen_lat[j] != lat.T_bath; j++) continue;
        if (j == n_lat && n_lat < 256) seen_lat[n_lat++] = lat.T_bath;
    }
    printf("an oil warming 20 -> 60 -> 20 degC: %d key temperatures on the lattice, %d at the "
           "temperature itself\n", n_lat, n);
    CHECK(n_lat == 21 && n >= 60);
}

/* Beyond twice its window the table holds its drift terms: built at 0.3 rpm (the 10 rpm torque
 * reversal's standstill), where ln mu rises by ~23 per rad/s, an unheld extrapolation to
 * 0.8 rad/s (the speed that step reached) gave mu ~ 3e5, a friction so stiff that arkode_erk's
 * energy audit missed its bound; held, F there is F at the edge, a friction coefficient. */
static void test_drift_held(const hg_friction_config *cfg, const hg_gearset *g)
{
    static hg_friction_table t;
    hg_ft_key key;
    double ratio = (double)g->N_g / g->N_p, w = 0.3 * RPM, W = 3000.0, F_far, F_edge;
    double edge = 2.0 * HG_FT_SPEED_DRIFT; /* two windows: both speeds are below the 1 rad/s floor */
    hg_ft_key_for(w, ratio, 313.15, 4760.0, &key);
    hg_friction_table_build(&t, cfg, g, HG_FLANK_DRIVE, 0, &key, 0);
    F_far = hg_friction_table_F(&t, 1.0, W, 0.8, 0.8 / ratio, 313.15 + 30.0);
    F_edge = hg_friction_table_F(&t, 1.0, W, w + edge, w / ratio + edge,
                                 313.15 + 2.0 * HG_FT_T_DRIFT);
    CHECK(F_far == F_edge);
    CHECK(F_far > 0.0 && F_far < 0.2 * W);
    CHECK(hg_friction_table_F(&t, 1.0, W, -0.8, -0.8 / ratio, 313.15) > 0.0);
}

/* The three pairs at once (hg_friction_table_pairs, the right-hand side's call) give what each
 * pair gives alone at its own phase (theta + 2 pi k) / 3, over a load-share period and loads
 * across the table's range and beyond it, with the drifts held. */
static void test_pairs_at_once(const hg_friction_config *cfg, const hg_gearset *g)
{
    static hg_friction_table t;
    hg_ft_key key;
    double ratio = (double)g->N_g / g->N_p, w = 2000.0 * RPM, worst = 0.0;
    int n, k;
    hg_ft_key_for(w, ratio, 313.15, 4760.0, &key);
    hg_friction_table_build(&t, cfg, g, HG_FLANK_DRIVE, 0, &key, 0);
    for (n = 0; n < 600; n++) {
        double theta = -3.0 * HG_TWO_PI + 6.0 * HG_TWO_PI * (n + 0.41) / 600.0, F[HG_MAX_PAIRS];
        double W[HG_MAX_PAIRS] = {3.0 + 15.0 * n, 4760.0 * (n % 7) / 6.0, 9000.0 - 14.0 * n};
        double wp = w * (1.0 + 0.1 * sin(n)), wg = w / ratio * (1.0 + 0.1 * cos(n));
        double T = 313.15 + 3.0 * sin(0.3 * n);
        hg_friction_table_pairs(&t, theta, W, wp, wg, T, F);
        for (k = 0; k < HG_MAX_PAIRS; k++) {
            double one = hg_friction_table_F(&t, hg_gearset_pair_phase(theta, k), W[k], wp, wg, T);
            double scale = hg_friction_table_F(&t, hg_gearset_pair_phase(theta, k), 4760.0, wp,
                                               wg, T);
            CHECK((F[k] == 0.0) == (one == 0.0));
            worst = fmax(worst, fabs(F[k] - one) / scale);
        }
    }
    printf("three pairs at once vs one at a time: worst difference %.1e of the pair friction\n",
           worst);
    CHECK(worst < 1e-12);
}

/* The layered two-flank set 1 (25-400 N m), thermal EHL with the first paper oil. Its levels
 * share their contact series, so the five levels of a flank share one table; with the levels'
 * radii and velocities made to differ (by 5 % per level, as a TCA whose contact changes with
 * load would have them) the blend of the levels' tables against the direct solve on the
 * blended geometry, both flanks, at the design speed and slow and cold. */
static void test_layered(hg_friction_config *cfg, const hg_lubricant *oil)
{
    static hg_gearset g;
    static hg_ft_set set;
    char err[HG_ERRLEN] = "";
    int fl, lv, s;
    CHECK(hg_gearset_load("resources/gearsets/loaded/gearset1.txt", &g, err, sizeof err) == 0);
    hg_ft_set_alloc(&set, cfg, &g, 0);
    for (fl = 0; fl < HG_N_FLANKS; fl++)
        for (lv = 0; lv < g.n_levels; lv++)
            CHECK(set.shared[fl * g.n_levels + lv] == fl * g.n_levels);
    hg_ft_set_free(&set);
    for (fl = 0; fl < HG_N_FLANKS; fl++)
        for (lv = 0; lv < g.n_levels; lv++)
            for (s = HG_S_R_X; s <= HG_S_VC_Y; s++)
                hg_series_scale(&g.s[fl][lv].y[s], 1.0 + 0.05 * lv);
    CHECK(!hg_gearset_same_contact(&g, HG_FLANK_DRIVE, 0, 1));
    cfg->model = HG_FRICTION_MODEL_EHL_THERMAL;
    hg_ehl_params_default(&cfg->ehl);
    cfg->ehl.thermal = 1;
    cfg->lub = oil;
    for (fl = 0; fl < HG_N_FLANKS; fl++) {
        double e1 = worst_blend_error(cfg, &g, fl, 2000.0, 313.15);
        double e2 = worst_blend_error(cfg, &g, fl, 500.0, 253.15);
        printf("layered set 1, %s flank: tables blended between levels vs the direct solve on "
               "the blended geometry, worst relative error %.2e / %.2e\n",
               fl == HG_FLANK_DRIVE ? "drive" : "coast", e1, e2);
        /* one level's 1.5e-3 and the blend's error of second order in the levels' change (w = 0
         * instead of the blend gives 6e-2) */
        CHECK(fmax(e1, e2) < 2.5e-3);
    }
}

int main(void)
{
    hg_gearset g;
    hg_lubricant oil[2] = {paper_oil(62), paper_oil(63)};
    hg_friction_config cfg;
    char err[HG_ERRLEN] = "";
    int k, thermal, rigid;
    test_key_next();
    test_load_lattice();
    test_temperature_lattice();
    CHECK(hg_gearset_load("resources/gearsets/gearset1.txt", &g, err, sizeof err) == 0);
    for (k = 0; k < 2; k++)
        for (thermal = 0; thermal < 2; thermal++) {
            cfg.model = thermal ? HG_FRICTION_MODEL_EHL_THERMAL : HG_FRICTION_MODEL_EHL_ISOTHERMAL;
            cfg.mu_const = 0.0;
            hg_ehl_params_default(&cfg.ehl);
            cfg.ehl.thermal = thermal;
            cfg.lub = &oil[k];
            if (k == 0 && thermal) test_drift_held(&cfg, &g);
            if (k == 0 && thermal) test_pairs_at_once(&cfg, &g);
            if (k == 0 && thermal) test_columns_shared(&cfg, &g);
            if (k == 0 && thermal) test_temperature_nodes(&cfg, &g);
            for (rigid = 0; rigid < 4; rigid++) { /* rigid & 1: the gear speed follows; & 2:
                                                      between the node tables, as the model */
                int gf = rigid & 1, nodes = rigid >> 1;
                /* design; slow and cold; fast and hot (speeds between nodes) */
                double e1 = worst_error(&cfg, &g, 2000.0, 313.15, 4760.0, gf, nodes);
                double e2 = worst_error(&cfg, &g, 500.0, 253.15, 9000.0, gf, nodes);
                double e3 = worst_error(&cfg, &g, 4000.0, 373.15, 1500.0, gf, nodes);
                printf("friction table%s vs direct solve, %s %s%s: worst relative error %.2e / "
                       "%.2e / %.2e\n", nodes ? " between nodes" : "", oil[k].name,
                       thermal ? "thermal" : "isothermal", gf ? ", rigid mesh" : "", e1, e2, e3);
                /* a tenth of the 1.4 % of the loss that 0.01 %-point of efficiency allows at
                 * the design point; the isothermal shear, exponential in the pressure, a little
                 * more */
                CHECK(fmax(e1, fmax(e2, e3)) < (thermal ? 1.5e-3 : 2.5e-3));
                if (nodes) { /* keys on the temperature lattice between temperature nodes */
                    e1 = worst_error(&cfg, &g, 2000.0, 316.0, 4760.0, gf, nodes);
                    e2 = worst_error(&cfg, &g, 500.0, 252.0, 9000.0, gf, nodes);
                    e3 = worst_error(&cfg, &g, 4000.0, 372.0, 1500.0, gf, nodes);
                    printf("  between temperature nodes: %.2e / %.2e / %.2e\n", e1, e2, e3);
                    CHECK(fmax(e1, fmax(e2, e3)) < (thermal ? 1.5e-3 : 2.5e-3));
                }
            }
        }
    test_layered(&cfg, &oil[0]);
    CHECK_DONE();
}
