/* Gear-set data: reading, checking and evaluating the Fourier series (paper eqs. 1-4). */
#include "model/gearset.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "io/datafile.h"

#define TWO_PI 6.283185307179586
#define LS_CONTACT_FLOOR 1e-3 /* load shares below this count as out of contact (docs/physics.md §10.7) */
#define CHECK_POINTS 720      /* samples over three mesh cycles for the sanity checks */

static int read_series(const hg_datafile *f, const char *name, hg_series *y, char *err,
                       size_t errlen)
{
    char key[64];
    size_t ns = 0, nc = 0;
    int n_sin;
    snprintf(key, sizeof key, "%s.mean", name);
    if (hg_datafile_numbers(f, key, 1, 1, &y->mean, NULL, err, errlen)) return -1;
    snprintf(key, sizeof key, "%s.sin", name);
    n_sin = hg_datafile_count(f, key);
    if (hg_datafile_numbers(f, key, 0, HG_MAX_HARMONICS, y->s, &ns, err, errlen)) return -1;
    snprintf(key, sizeof key, "%s.cos", name);
    if (hg_datafile_numbers(f, key, 0, HG_MAX_HARMONICS, y->c, &nc, err, errlen)) return -1;
    if (ns != nc) {
        hg_errorf(err, errlen, "series '%s': %d sine but %zu cosine coefficients", name, n_sin,
                  nc);
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

static int check_positive(const char *path, const char *what, double v, double theta, char *err,
                          size_t errlen)
{
    if (v > 0.0 && isfinite(v)) return 0;
    hg_errorf(err, errlen, "%s: series %s evaluates to %g at mesh angle %.3f rad: must be > 0",
              path, what, v, theta);
    return -1;
}

/* The series must describe a physical mesh everywhere, not only at the fitted samples. */
static int check_gearset(const char *path, const hg_gearset *g, char *err, size_t errlen)
{
    int j, k;
    for (j = 0; j < CHECK_POINTS; j++) {
        double theta = 3.0 * TWO_PI * j / CHECK_POINTS, raw_sum = 0.0;
        hg_mesh_point m;
        hg_pair_geometry p;
        hg_gearset_mesh(g, theta, &m);
        if (check_positive(path, "k_m", m.k_m, theta, err, errlen) ||
            check_positive(path, "R_p", m.R_p, theta, err, errlen))
            return -1;
        hg_gearset_pairs(g, theta, 1, &p);
        for (k = 0; k < HG_MAX_PAIRS; k++) {
            hg_harmonics h;
            hg_harmonics_eval((theta + TWO_PI * k) / 3.0, g->ls.n, &h);
            raw_sum += hg_series_value(&g->ls, &h);
            if (p.ls[k] > 0.0 && (check_positive(path, "R_x", p.R_x[k], theta, err, errlen) ||
                                  check_positive(path, "R_y", p.R_y[k], theta, err, errlen)))
                return -1;
        }
        if (fabs(raw_sum - 1.0) > 0.05) {
            hg_errorf(err, errlen,
                      "%s: the load shares of the three pairs sum to %.4f at mesh angle %.3f rad "
                      "(must be 1 within 0.05)",
                      path, raw_sum, theta);
            return -1;
        }
    }
    return 0;
}

int hg_gearset_load(const char *path, hg_gearset *g, char *err, size_t errlen)
{
    static const char *const names[] = {"k_m", "R_p", "e_0", "ls", "R_x",
                                        "R_y", "up_x", "up_y", "ug_x", "ug_y"};
    hg_series *const series[] = {&g->k_m, &g->R_p, &g->e_0, &g->ls, &g->R_x,
                                 &g->R_y, &g->up_x, &g->up_y, &g->ug_x, &g->ug_y};
    hg_datafile *f = hg_datafile_load(path, "hypoid-gearset", 1, err, errlen);
    size_t i;
    int rc = -1;
    if (!f) return -1;
    memset(g, 0, sizeof *g);
    if (hg_datafile_text(f, "name", g->name, sizeof g->name, err, errlen) ||
        read_teeth(f, "N_p", &g->N_p, err, errlen) || read_teeth(f, "N_g", &g->N_g, err, errlen))
        goto done;
    for (i = 0; i < sizeof names / sizeof names[0]; i++)
        if (read_series(f, names[i], series[i], err, errlen)) goto done;
    if (hg_datafile_check_all_used(f, err, errlen)) goto done;
    rc = check_gearset(path, g, err, errlen);
done:
    hg_datafile_free(f);
    return rc;
}

void hg_gearset_mesh(const hg_gearset *g, double theta, hg_mesh_point *out)
{
    hg_harmonics h;
    int n = g->k_m.n;
    if (g->R_p.n > n) n = g->R_p.n;
    if (g->e_0.n > n) n = g->e_0.n;
    hg_harmonics_eval(theta, n, &h);
    out->k_m = hg_series_value(&g->k_m, &h);
    out->dk_m = hg_series_slope(&g->k_m, &h);
    out->R_p = hg_series_value(&g->R_p, &h);
    out->e_0 = hg_series_value(&g->e_0, &h);
    out->de_0 = hg_series_slope(&g->e_0, &h);
}

static int max_harmonics(const hg_gearset *g)
{
    const hg_series *const s[] = {&g->ls, &g->R_x, &g->R_y, &g->up_x, &g->up_y, &g->ug_x,
                                  &g->ug_y};
    int i, n = 0;
    for (i = 0; i < 7; i++)
        if (s[i]->n > n) n = s[i]->n;
    return n;
}

void hg_gearset_pairs(const hg_gearset *g, double theta, int with_contact, hg_pair_geometry *out)
{
    int k, n = with_contact ? max_harmonics(g) : g->ls.n;
    double sum = 0.0;
    for (k = 0; k < HG_MAX_PAIRS; k++) {
        hg_harmonics h;
        double ls;
        hg_harmonics_eval((theta + TWO_PI * k) / 3.0, n, &h);
        /* clamp to [0, 1] continuously, dropping the truncation ripple in the no-contact gap */
        ls = hg_series_value(&g->ls, &h) - LS_CONTACT_FLOOR;
        out->ls[k] = ls < 0.0 ? 0.0 : (ls > 1.0 ? 1.0 : ls);
        sum += out->ls[k];
        if (!with_contact) continue;
        out->R_x[k] = hg_series_value(&g->R_x, &h);
        out->R_y[k] = hg_series_value(&g->R_y, &h);
        out->up[k][0] = hg_series_value(&g->up_x, &h);
        out->up[k][1] = hg_series_value(&g->up_y, &h);
        out->ug[k][0] = hg_series_value(&g->ug_x, &h);
        out->ug[k][1] = hg_series_value(&g->ug_y, &h);
    }
    for (k = 0; k < HG_MAX_PAIRS; k++) out->ls[k] = sum > 0.0 ? out->ls[k] / sum : 1.0 / 3.0;
}
