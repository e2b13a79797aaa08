/* Gear-set data: reading, checking and evaluating the Fourier series (paper eqs. 1-4), per flank
 * and torque level (docs/data-files.md, docs/physics.md §10.8). */
#include "mesh/gearset.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "io/constants.h"
#include "io/datafile.h"

#define LS_CONTACT_FLOOR 1e-3 /* load shares below this count as out of contact (docs/physics.md §10.7) */
#define CHECK_POINTS 720      /* samples over three mesh cycles for the sanity checks */

static const char *const FLANK_NAMES[HG_N_FLANKS] = {"drive", "coast"};
static const char *const SERIES_NAMES[HG_N_SERIES] = {"k_m",  "R_p",  "ls",   "R_x",
                                                         "R_y",  "up_x", "up_y", "ug_x",
                                                         "ug_y", "vc_x", "vc_y"};

static int read_series(const hg_datafile *f, const char *prefix, const char *name, hg_series *y,
                       char *err, size_t errlen)
{
    char key[96];
    size_t ns = 0, nc = 0;
    int n_sin;
    snprintf(key, sizeof key, "%s%s.mean", prefix, name);
    if (hg_datafile_numbers(f, key, 1, 1, &y->mean, NULL, err, errlen)) return -1;
    snprintf(key, sizeof key, "%s%s.sin", prefix, name);
    n_sin = hg_datafile_count(f, key);
    if (hg_datafile_numbers(f, key, 0, HG_MAX_HARMONICS, y->s, &ns, err, errlen)) return -1;
    snprintf(key, sizeof key, "%s%s.cos", prefix, name);
    if (hg_datafile_numbers(f, key, 0, HG_MAX_HARMONICS, y->c, &nc, err, errlen)) return -1;
    if (ns != nc) {
        hg_errorf(err, errlen, "series '%s%s': %d sine but %zu cosine coefficients", prefix, name,
                  n_sin, nc);
        return -1;
    }
    y->n = (int)ns;
    return 0;
}

static int read_teeth(const hg_datafile *f, const char *key, int *N, char *err, size_t errlen)
{
    double v;
    if (hg_datafile_number(f, key, 3, 200, "", &v, err, errlen)) return -1;
    if (v != floor(v)) {
        hg_errorf(err, errlen, "key '%s' = %g is not a whole number of teeth", key, v);
        return -1;
    }
    *N = (int)v;
    return 0;
}

/* blank.*: all eight keys or none; lengths within 1 mm .. 5 m, angles within (0, pi/2) rad. */
static int read_blank(const hg_datafile *f, hg_gearset *g, char *err, size_t errlen)
{
    static const char *const names[HG_N_BLANK] = {"ring_d", "ring_b", "r_m_p", "r_m_g",
                                                  "delta_p", "delta_g", "beta_p", "beta_g"};
    char key[32];
    int k, given = 0;
    for (k = 0; k < HG_N_BLANK; k++) {
        snprintf(key, sizeof key, "blank.%s", names[k]);
        given += hg_datafile_count(f, key) >= 0;
    }
    if (given == 0) return 0;
    for (k = 0; k < HG_N_BLANK; k++) {
        int angle = k >= HG_BLANK_DELTA_P;
        snprintf(key, sizeof key, "blank.%s", names[k]);
        if (hg_datafile_count(f, key) < 0) {
            hg_errorf(err, errlen, "key '%s' missing: the blank keys go together (blank.ring_d, "
                      "ring_b, r_m_p, r_m_g [m], delta_p, delta_g, beta_p, beta_g [rad])", key);
            return -1;
        }
        if (hg_datafile_number(f, key, angle ? 1e-6 : 1e-3, angle ? 1.5707 : 5.0,
                               angle ? "rad" : "m", &g->blank[k], err, errlen))
            return -1;
    }
    g->has_blank = 1;
    return 0;
}

/* torque_levels: pinion torques [N m], non-negative and increasing; absent: one level. */
static int read_levels(const char *path, const hg_datafile *f, hg_gearset *g, char *err,
                       size_t errlen)
{
    int line = hg_datafile_line(f, "torque_levels");
    size_t n, i;
    g->n_levels = 1;
    if (line < 0) return 0;
    if (hg_datafile_numbers(f, "torque_levels", 1, HG_MAX_LEVELS, g->T_level, &n, err, errlen))
        return -1;
    for (i = 0; i < n; i++)
        if (g->T_level[i] < 0.0 || (i > 0 && g->T_level[i] <= g->T_level[i - 1])) {
            hg_errorf(err, errlen,
                      "%s, line %d: torque_levels value %zu = %g N m must be >= 0 and above the "
                      "one before: the levels must increase",
                      path, line, i + 1, g->T_level[i]);
            return -1;
        }
    g->n_levels = (int)n;
    return 0;
}

/* flanks: 'drive' or 'drive coast'; absent: the drive data serve both flanks. */
static int read_flanks(const char *path, const hg_datafile *f, hg_gearset *g, char *err,
                       size_t errlen)
{
    int line = hg_datafile_line(f, "flanks");
    char text[64];
    g->n_flanks = 1;
    if (line < 0) return 0;
    if (hg_datafile_text(f, "flanks", text, sizeof text, err, errlen)) return -1;
    if (strcmp(text, "drive coast") == 0)
        g->n_flanks = 2;
    else if (strcmp(text, "drive") != 0) {
        hg_errorf(err, errlen, "%s, line %d: flanks '%s': must be 'drive' or 'drive coast'", path,
                  line, text);
        return -1;
    }
    if (g->n_flanks == 2 && hg_datafile_count(f, "coast.1.k_m.mean") < 0) {
        hg_errorf(err, errlen,
                  "%s, line %d: flanks '%s' asks for a coast flank, but the file has no coast "
                  "series (no key 'coast.1.k_m.mean')",
                  path, line, text);
        return -1;
    }
    return 0;
}

/* The contact point's velocity vc_x, vc_y is optional: a file without it (one before it, or a
 * contact point fixed in space) leaves the zeroed series. */
static int optional_series(const hg_datafile *f, const char *prefix, int i)
{
    char key[96];
    if (i != HG_S_VC_X && i != HG_S_VC_Y) return 0;
    snprintf(key, sizeof key, "%svc_x.mean", prefix);
    if (hg_datafile_count(f, key) >= 0) return 0;
    snprintf(key, sizeof key, "%svc_y.mean", prefix);
    return hg_datafile_count(f, key) < 0;
}

/* The series of every flank and level: keys '<flank>.<level>.<series>.*' when the file has
 * torque_levels or flanks, else the plain '<series>.*' of the one-series layout. */
static int read_blocks(const hg_datafile *f, int layered, hg_gearset *g, char *err, size_t errlen)
{
    int fl, lv, i;
    for (fl = 0; fl < g->n_flanks; fl++)
        for (lv = 0; lv < g->n_levels; lv++) {
            char prefix[32] = "";
            if (layered) snprintf(prefix, sizeof prefix, "%s.%d.", FLANK_NAMES[fl], lv + 1);
            for (i = 0; i < HG_N_SERIES; i++)
                if (!optional_series(f, prefix, i) &&
                    read_series(f, prefix, SERIES_NAMES[i], &g->s[fl][lv].y[i], err, errlen))
                    return -1;
        }
    return 0;
}

static int check_positive(const char *path, const char *where, const char *what, double v,
                          double theta, char *err, size_t errlen)
{
    if (v > 0.0 && isfinite(v)) return 0;
    hg_errorf(err, errlen, "%s: series %s%s evaluates to %g at mesh angle %.3f rad: must be > 0",
              path, where, what, v, theta);
    return -1;
}

/* One flank at one level must describe a physical mesh everywhere, not only at the fitted
 * samples. */
static int check_block(const char *path, const char *where, const hg_flank_series *b, char *err,
                       size_t errlen)
{
    int j, k;
    for (j = 0; j < CHECK_POINTS; j++) {
        double theta = 3.0 * HG_TWO_PI * j / CHECK_POINTS, raw_sum = 0.0;
        hg_harmonics h;
        hg_harmonics_eval(theta, HG_MAX_HARMONICS, &h);
        if (check_positive(path, where, "k_m", hg_series_value(&b->y[HG_S_K_M], &h), theta, err,
                           errlen) ||
            check_positive(path, where, "R_p", hg_series_value(&b->y[HG_S_R_P], &h), theta, err,
                           errlen))
            return -1;
        for (k = 0; k < HG_MAX_PAIRS; k++) {
            double ls;
            hg_harmonics_eval((theta + HG_TWO_PI * k) / 3.0, HG_MAX_HARMONICS, &h);
            ls = hg_series_value(&b->y[HG_S_LS], &h);
            raw_sum += ls;
            if (ls - LS_CONTACT_FLOOR > 0.0 &&
                (check_positive(path, where, "R_x", hg_series_value(&b->y[HG_S_R_X], &h), theta,
                                err, errlen) ||
                 check_positive(path, where, "R_y", hg_series_value(&b->y[HG_S_R_Y], &h), theta,
                                err, errlen)))
                return -1;
        }
        if (fabs(raw_sum - 1.0) > 0.05) {
            hg_errorf(err, errlen,
                      "%s: the load shares of the three pairs %ssum to %.4f at mesh angle %.3f rad "
                      "(must be 1 within 0.05)",
                      path, where, raw_sum, theta);
            return -1;
        }
    }
    return 0;
}

/* The levels of a layered flank are the static points of the mesh's force law (mesh/mesh_law.h):
 * their loads W_l = T_l / mean R_p,l and deflections W_l / k_m,l must both grow with the level. */
static int check_deflections(const char *path, const hg_gearset *g, int fl, char *err,
                             size_t errlen)
{
    int j, lv;
    for (j = 0; j < CHECK_POINTS / 3; j++) {
        double theta = HG_TWO_PI * 3 * j / CHECK_POINTS, W_lo = 0.0, a_lo = 0.0;
        hg_harmonics h;
        hg_harmonics_eval(theta, HG_MAX_HARMONICS, &h);
        for (lv = 0; lv < g->n_levels; lv++) {
            const hg_series *y = g->s[fl][lv].y;
            double W = g->T_level[lv] / y[HG_S_R_P].mean;
            double a = W / hg_series_value(&y[HG_S_K_M], &h);
            if (lv > 0 && !(W > W_lo && a > a_lo)) {
                hg_errorf(err, errlen,
                          "%s: series %s.%d.k_m: at mesh angle %.3f rad the %g N m level deflects "
                          "%g um under %g N, the %g N m level %g um under %g N: load and "
                          "deflection W/k_m must grow with the level",
                          path, FLANK_NAMES[fl], lv + 1, theta, g->T_level[lv], a * 1e6, W,
                          g->T_level[lv - 1], a_lo * 1e6, W_lo);
                return -1;
            }
            W_lo = W;
            a_lo = a;
        }
    }
    return 0;
}

static int check_gearset(const char *path, const hg_gearset *g, char *err, size_t errlen)
{
    int fl, lv;
    for (fl = 0; fl < g->n_flanks; fl++)
        for (lv = 0; lv < g->n_levels; lv++) {
            char where[64] = "";
            if (g->n_levels > 1 || g->n_flanks > 1)
                snprintf(where, sizeof where, "(%s flank, %g N m) ", FLANK_NAMES[fl],
                         g->T_level[lv]);
            if (check_block(path, where, &g->s[fl][lv], err, errlen)) return -1;
        }
    for (fl = 0; fl < g->n_flanks && g->n_levels > 1; fl++)
        if (check_deflections(path, g, fl, err, errlen)) return -1;
    return 0;
}

int hg_gearset_load(const char *path, hg_gearset *g, char *err, size_t errlen)
{
    hg_datafile *f = hg_datafile_load(path, "hypoid-gearset", 1, err, errlen);
    int rc = -1, layered;
    if (!f) return -1;
    memset(g, 0, sizeof *g);
    layered = hg_datafile_count(f, "torque_levels") >= 0 || hg_datafile_count(f, "flanks") >= 0;
    if (hg_datafile_text(f, "name", g->name, sizeof g->name, err, errlen) ||
        read_teeth(f, "N_p", &g->N_p, err, errlen) || read_teeth(f, "N_g", &g->N_g, err, errlen) ||
        read_blank(f, g, err, errlen) || read_levels(path, f, g, err, errlen) || read_flanks(path, f, g, err, errlen) ||
        read_series(f, "", "e_0", &g->e_0, err, errlen) ||
        read_blocks(f, layered, g, err, errlen) || hg_datafile_check_all_used(f, err, errlen))
        goto done;
    rc = check_gearset(path, g, err, errlen);
done:
    hg_datafile_free(f);
    return rc;
}

void hg_gearset_scale(hg_gearset *g, double k_m_scale, double e_0_scale)
{
    int fl, lv;
    for (fl = 0; fl < g->n_flanks; fl++)
        for (lv = 0; lv < g->n_levels; lv++) hg_series_scale(&g->s[fl][lv].y[HG_S_K_M], k_m_scale);
    hg_series_scale(&g->e_0, e_0_scale);
}

void hg_gearset_level_at(const hg_gearset *g, int flank, double T, hg_level_pick *b)
{
    int i = 0, n = g->n_levels;
    b->flank = flank < g->n_flanks ? flank : HG_FLANK_DRIVE;
    b->lo = b->hi = 0;
    b->w = b->dw_dT = 0.0;
    if (n == 1 || T <= g->T_level[0]) return;
    if (T >= g->T_level[n - 1]) {
        b->lo = b->hi = n - 1;
        return;
    }
    while (T > g->T_level[i + 1]) i++;
    b->lo = i;
    b->hi = i + 1;
    b->dw_dT = 1.0 / (g->T_level[i + 1] - g->T_level[i]);
    b->w = (T - g->T_level[i]) * b->dw_dT;
}

/* The series of the two levels of hg_gearset_level_at and the weight of the upper one. */
typedef struct {
    const hg_flank_series *lo, *hi;
    double w, dw_dT;
} hg_level_blend;

static void blend_at(const hg_gearset *g, int flank, double T, hg_level_blend *b)
{
    hg_level_pick k;
    hg_gearset_level_at(g, flank, T, &k);
    b->lo = &g->s[k.flank][k.lo];
    b->hi = &g->s[k.flank][k.hi];
    b->w = k.w;
    b->dw_dT = k.dw_dT;
}

static double blended(const hg_level_blend *b, int i, const hg_harmonics *h)
{
    double lo = hg_series_value(&b->lo->y[i], h);
    return b->w > 0.0 ? lo + b->w * (hg_series_value(&b->hi->y[i], h) - lo) : lo;
}

/* Most harmonics among series first .. last of both levels. */
static int harmonics_needed(const hg_level_blend *b, int first, int last)
{
    int i, n = 0;
    for (i = first; i <= last; i++) {
        if (b->lo->y[i].n > n) n = b->lo->y[i].n;
        if (b->hi->y[i].n > n) n = b->hi->y[i].n;
    }
    return n;
}

void hg_gearset_mesh(const hg_gearset *g, int flank, double T, double theta, hg_mesh_point *out)
{
    hg_harmonics h;
    hg_level_blend b;
    const hg_series *lo, *hi;
    int n;
    blend_at(g, flank, T, &b);
    n = harmonics_needed(&b, HG_S_K_M, HG_S_R_P);
    hg_harmonics_eval(theta, g->e_0.n > n ? g->e_0.n : n, &h);
    lo = &b.lo->y[HG_S_K_M];
    hi = &b.hi->y[HG_S_K_M];
    out->k_m = blended(&b, HG_S_K_M, &h);
    out->dk_dT = b.dw_dT * (hg_series_value(hi, &h) - hg_series_value(lo, &h));
    out->dk_m = hg_series_slope(lo, &h) + b.w * (hg_series_slope(hi, &h) - hg_series_slope(lo, &h));
    out->R_p = blended(&b, HG_S_R_P, &h);
    out->e_0 = hg_series_value(&g->e_0, &h);
    out->de_0 = hg_series_slope(&g->e_0, &h);
}

void hg_gearset_means(const hg_gearset *g, int flank, double T, double *k_m0, double *R_p0)
{
    hg_level_blend b;
    blend_at(g, flank, T, &b);
    *k_m0 = b.lo->y[HG_S_K_M].mean + b.w * (b.hi->y[HG_S_K_M].mean - b.lo->y[HG_S_K_M].mean);
    *R_p0 = b.lo->y[HG_S_R_P].mean + b.w * (b.hi->y[HG_S_R_P].mean - b.lo->y[HG_S_R_P].mean);
}

double hg_gearset_share_clamp(double ls_raw)
{
    /* clamp to [0, 1] continuously, dropping the truncation ripple in the no-contact gap */
    double ls = ls_raw - LS_CONTACT_FLOOR;
    return ls < 0.0 ? 0.0 : (ls > 1.0 ? 1.0 : ls);
}

void hg_gearset_normalise_shares(double ls[HG_MAX_PAIRS])
{
    double sum = 0.0;
    int k;
    for (k = 0; k < HG_MAX_PAIRS; k++) sum += ls[k];
    for (k = 0; k < HG_MAX_PAIRS; k++) ls[k] = sum > 0.0 ? ls[k] / sum : 1.0 / 3.0;
}

double hg_gearset_pair_phase(double theta, int k) { return (theta + HG_TWO_PI * k) / 3.0; }

void hg_gearset_entrainment(const double up[2], const double ug[2], const double vc[2],
                            double w_p, double w_g, double u_p[2], double u_g[2])
{
    int i;
    for (i = 0; i < 2; i++) {
        u_p[i] = w_p * (up[i] - vc[i]);
        u_g[i] = w_g * ug[i] - w_p * vc[i];
    }
}

static int same_series(const hg_series *a, const hg_series *b)
{
    int i;
    if (a->n != b->n || a->mean != b->mean) return 0;
    for (i = 0; i < a->n; i++)
        if (a->s[i] != b->s[i] || a->c[i] != b->c[i]) return 0;
    return 1;
}

int hg_gearset_same_contact(const hg_gearset *g, int flank, int a, int b)
{
    const hg_flank_series *s = g->s[flank < g->n_flanks ? flank : HG_FLANK_DRIVE];
    int i;
    for (i = HG_S_R_X; i <= HG_S_VC_Y; i++)
        if (!same_series(&s[a].y[i], &s[b].y[i])) return 0;
    return 1;
}

void hg_gearset_pair_point(const hg_gearset *g, int flank, int level, double psi,
                           hg_pair_point *out)
{
    const hg_series *y = g->s[flank < g->n_flanks ? flank : HG_FLANK_DRIVE][level].y;
    hg_harmonics h;
    hg_harmonics_eval(psi, HG_MAX_HARMONICS, &h);
    out->ls = hg_gearset_share_clamp(hg_series_value(&y[HG_S_LS], &h));
    out->R_x = hg_series_value(&y[HG_S_R_X], &h);
    out->R_y = hg_series_value(&y[HG_S_R_Y], &h);
    out->up[0] = hg_series_value(&y[HG_S_UP_X], &h);
    out->up[1] = hg_series_value(&y[HG_S_UP_Y], &h);
    out->ug[0] = hg_series_value(&y[HG_S_UG_X], &h);
    out->ug[1] = hg_series_value(&y[HG_S_UG_Y], &h);
    out->vc[0] = hg_series_value(&y[HG_S_VC_X], &h);
    out->vc[1] = hg_series_value(&y[HG_S_VC_Y], &h);
}

void hg_gearset_pairs(const hg_gearset *g, int flank, double T, double theta, int with_contact,
                      hg_pair_geometry *out)
{
    int k, n;
    hg_level_blend b;
    blend_at(g, flank, T, &b);
    n = harmonics_needed(&b, HG_S_LS, with_contact ? HG_S_VC_Y : HG_S_LS);
    for (k = 0; k < HG_MAX_PAIRS; k++) {
        hg_harmonics h;
        hg_harmonics_eval(hg_gearset_pair_phase(theta, k), n, &h);
        out->ls[k] = hg_gearset_share_clamp(blended(&b, HG_S_LS, &h));
        if (!with_contact) continue;
        out->R_x[k] = blended(&b, HG_S_R_X, &h);
        out->R_y[k] = blended(&b, HG_S_R_Y, &h);
        out->up[k][0] = blended(&b, HG_S_UP_X, &h);
        out->up[k][1] = blended(&b, HG_S_UP_Y, &h);
        out->ug[k][0] = blended(&b, HG_S_UG_X, &h);
        out->ug[k][1] = blended(&b, HG_S_UG_Y, &h);
        out->vc[k][0] = blended(&b, HG_S_VC_X, &h);
        out->vc[k][1] = blended(&b, HG_S_VC_Y, &h);
    }
    hg_gearset_normalise_shares(out->ls);
}
