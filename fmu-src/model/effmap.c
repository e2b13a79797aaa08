/* Efficiency maps: reading and C2 spline interpolation (see effmap.h). */
#include "model/effmap.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/datafile.h"

static int read_axis(const hg_datafile *f, const char *path, const char *key, double lo,
                     double *v, int *n, char *err, size_t errlen)
{
    size_t count, i;
    if (hg_datafile_numbers(f, key, 1, HG_MAP_MAX_AXIS, v, &count, err, errlen)) return -1;
    for (i = 0; i < count; i++) {
        if (v[i] < lo || (i > 0 && !(v[i] > v[i - 1]))) {
            hg_errorf(err, errlen, "%s: key '%s': values must be ascending and >= %g (value %zu is %g)",
                      path, key, lo, i + 1, v[i]);
            return -1;
        }
    }
    *n = (int)count;
    return 0;
}

static int read_source(const hg_datafile *f, const char *path, const char *what,
                       hg_effmap_source *src, char *err, size_t errlen)
{
    char key[32];
    size_t i;
    snprintf(key, sizeof key, "%s_source", what);
    if (hg_datafile_text(f, key, src->source, sizeof src->source, err, errlen)) return -1;
    snprintf(key, sizeof key, "%s_hash", what);
    if (hg_datafile_text(f, key, src->hash, sizeof src->hash, err, errlen)) return -1;
    for (i = 0; i < HG_HASH_HEX - 1; i++)
        if (!src->hash[i] || !strchr("0123456789abcdef", src->hash[i])) break;
    if (i != HG_HASH_HEX - 1) {
        hg_errorf(err, errlen, "%s: key '%s': expected 16 hex digits (the content hash `hypoid "
                  "effmap` writes), got '%s'", path, key, src->hash);
        return -1;
    }
    return 0;
}

static int read_table(const hg_datafile *f, const char *path, hg_effmap *map, char *err,
                      size_t errlen)
{
    static const char *const dir_names[] = {"drive", "coast"};
    size_t per_K = (size_t)map->n_w * (size_t)map->n_T, i;
    int d, k;
    for (d = 0; d < 2; d++) {
        for (k = 0; k < map->n_K; k++) {
            double *eta = map->eta + ((size_t)d * map->n_K + k) * per_K;
            char key[32];
            snprintf(key, sizeof key, "%s.%d", dir_names[d], k + 1);
            if (hg_datafile_numbers(f, key, per_K, per_K, eta, NULL, err, errlen)) return -1;
            for (i = 0; i < per_K; i++) {
                if (!(eta[i] > 0.0 && eta[i] <= 1.0)) {
                    hg_errorf(err, errlen, "%s: key '%s': efficiency %g (value %zu) is not in (0, 1]",
                              path, key, eta[i], i + 1);
                    return -1;
                }
            }
        }
    }
    return 0;
}

/* Natural cubic spline along one axis: y'' = M y at the nodes (M from the tridiagonal system with
 * y''_0 = y''_{n-1} = 0), so the spline is linear in the node values and its weights can be
 * formed once per evaluation. C2 inside the table: an operating point held on a grid line (a
 * speed governor does exactly that) sees a smooth right-hand side; a piecewise-linear or C1
 * interpolant would put a kink there that the integrator steps through again and again. */
static void spline_matrix(const double *x, int n, double *M)
{
    double c[HG_MAP_MAX_AXIS], d[HG_MAP_MAX_AXIS];
    int k, j;
    memset(M, 0, (size_t)n * n * sizeof *M);
    for (k = 0; k < n && n > 2; k++) { /* column k: second derivatives of the unit vector e_k */
        for (j = 1; j < n - 1; j++) { /* Thomas algorithm, forward sweep */
            double h0 = x[j] - x[j - 1], h1 = x[j + 1] - x[j];
            double rhs = 6.0 * (((j + 1 == k) - (j == k)) / h1 - ((j == k) - (j - 1 == k)) / h0);
            double diag = 2.0 * (h0 + h1) - (j > 1 ? h0 * c[j - 1] : 0.0);
            c[j] = h1 / diag;
            d[j] = (rhs - (j > 1 ? h0 * d[j - 1] : 0.0)) / diag;
        }
        for (j = n - 2; j >= 1; j--) /* back substitution */
            M[j * n + k] = d[j] - (j < n - 2 ? c[j] * M[(j + 1) * n + k] : 0.0);
    }
}

/* w[0..n-1]: weights of the node values at x, held constant beyond the ends. */
static void spline_weights(const double *x, int n, const double *M, double at, double *w)
{
    int i = 0, j;
    double h, a, b;
    memset(w, 0, (size_t)n * sizeof *w);
    if (n == 1 || at <= x[0] || at >= x[n - 1]) {
        w[(n > 1 && at >= x[n - 1]) ? n - 1 : 0] = 1.0;
        return;
    }
    while (at >= x[i + 1]) i++;
    h = x[i + 1] - x[i];
    a = (x[i + 1] - at) / h;
    b = 1.0 - a;
    w[i] += a;
    w[i + 1] += b;
    for (j = 0; j < n; j++)
        w[j] += h * h / 6.0 * ((a * a * a - a) * M[i * n + j] + (b * b * b - b) * M[(i + 1) * n + j]);
}

int hg_effmap_load(const char *path, hg_effmap *map, char *err, size_t errlen)
{
    hg_datafile *f = hg_datafile_load(path, "hypoid-effmap", 2, err, errlen);
    int rc = -1;
    if (!f) return -1;
    memset(map, 0, sizeof *map);
    if (hg_datafile_text(f, "name", map->name, sizeof map->name, err, errlen) ||
        read_source(f, path, "gear_set", &map->gear_set, err, errlen) ||
        read_source(f, path, "lubricant", &map->lubricant, err, errlen) ||
        hg_datafile_text(f, "model_version", map->model_version, sizeof map->model_version, err,
                         errlen) ||
        read_axis(f, path, "speeds", 0.0, map->w, &map->n_w, err, errlen) ||
        read_axis(f, path, "torques", 0.0, map->T, &map->n_T, err, errlen) ||
        read_axis(f, path, "temperatures", 1.0, map->K, &map->n_K, err, errlen))
        goto done;
    map->eta = malloc(2 * (size_t)map->n_K * map->n_w * map->n_T * sizeof(double));
    map->M_w = malloc((size_t)map->n_w * map->n_w * sizeof(double));
    map->M_T = malloc((size_t)map->n_T * map->n_T * sizeof(double));
    map->M_K = malloc((size_t)map->n_K * map->n_K * sizeof(double));
    if (!map->eta || !map->M_w || !map->M_T || !map->M_K) {
        hg_errorf(err, errlen, "%s: out of memory", path);
        goto done;
    }
    if (read_table(f, path, map, err, errlen) || hg_datafile_check_all_used(f, err, errlen))
        goto done;
    spline_matrix(map->w, map->n_w, map->M_w);
    spline_matrix(map->T, map->n_T, map->M_T);
    spline_matrix(map->K, map->n_K, map->M_K);
    rc = 0;
done:
    if (rc) hg_effmap_free(map);
    hg_datafile_free(f);
    return rc;
}

void hg_effmap_free(hg_effmap *map)
{
    free(map->eta);
    free(map->M_w);
    free(map->M_T);
    free(map->M_K);
    map->eta = map->M_w = map->M_T = map->M_K = NULL;
}

int hg_effmap_inside(const hg_effmap *map, double w, double T, double K)
{
    w = fabs(w), T = fabs(T);
    return w >= map->w[0] && w <= map->w[map->n_w - 1] && T >= map->T[0] &&
           T <= map->T[map->n_T - 1] && K >= map->K[0] && K <= map->K[map->n_K - 1];
}

double hg_effmap_eta(const hg_effmap *map, int direction, double w, double T, double K)
{
    double ww[HG_MAP_MAX_AXIS], wT[HG_MAP_MAX_AXIS], wK[HG_MAP_MAX_AXIS], eta = 0.0;
    size_t per_K = (size_t)map->n_w * map->n_T;
    const double *base = map->eta + (size_t)direction * map->n_K * per_K;
    int a, b, c;
    spline_weights(map->w, map->n_w, map->M_w, w < 0 ? -w : w, ww);
    spline_weights(map->T, map->n_T, map->M_T, T < 0 ? -T : T, wT);
    spline_weights(map->K, map->n_K, map->M_K, K, wK);
    for (c = 0; c < map->n_K; c++) {
        if (wK[c] == 0.0) continue;
        for (a = 0; a < map->n_w; a++) {
            const double *row = base + (size_t)c * per_K + (size_t)a * map->n_T;
            double sum = 0.0;
            if (ww[a] == 0.0) continue;
            for (b = 0; b < map->n_T; b++) sum += wT[b] * row[b];
            eta += wK[c] * ww[a] * sum;
        }
    }
    return eta;
}
