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

/* Natural cubic spline along one axis: the second derivatives y'' at the nodes from the
 * tridiagonal system with y''_0 = y''_{n-1} = 0, solved by the Thomas algorithm. The spline is
 * linear in the node values, so the second derivatives of a table along an axis are formed once,
 * at load. C2 inside the table: an operating point held on a grid line (a speed governor does
 * exactly that) sees a smooth right-hand side; a piecewise-linear or C1 interpolant would put a
 * kink there that the integrator steps through again and again. */
typedef struct {
    double inv_h[HG_MAP_MAX_AXIS]; /* 1 / (x[j+1] - x[j]) */
    double h[HG_MAP_MAX_AXIS];     /* x[j] - x[j-1] */
    double c[HG_MAP_MAX_AXIS];     /* the forward sweep's upper coefficient */
    double inv_diag[HG_MAP_MAX_AXIS];
    int n;
} spline_axis;

/* The axis's part of the sweep: the same for every line of values along it. */
static void spline_axis_init(const double *x, int n, spline_axis *a)
{
    int j;
    a->n = n;
    for (j = 0; j + 1 < n; j++) a->inv_h[j] = 1.0 / (x[j + 1] - x[j]);
    for (j = 1; j < n - 1; j++) {
        double h0 = x[j] - x[j - 1], h1 = x[j + 1] - x[j];
        double diag = 2.0 * (h0 + h1) - (j > 1 ? h0 * a->c[j - 1] : 0.0);
        a->h[j] = h0;
        a->inv_diag[j] = 1.0 / diag;
        a->c[j] = h1 * a->inv_diag[j];
    }
}

/* The second derivatives m[0], m[stride], ... of the values y[0], y[stride], ... */
static void second_derivatives(const spline_axis *a, const double *y, size_t stride, double *m)
{
    double d[HG_MAP_MAX_AXIS];
    int j, n = a->n;
    for (j = 0; j < n; j++) m[j * stride] = 0.0;
    for (j = 1; j < n - 1; j++) { /* forward sweep */
        double rhs = 6.0 * ((y[(j + 1) * stride] - y[j * stride]) * a->inv_h[j] -
                            (y[j * stride] - y[(j - 1) * stride]) * a->inv_h[j - 1]);
        d[j] = (rhs - (j > 1 ? a->h[j] * d[j - 1] : 0.0)) * a->inv_diag[j];
    }
    for (j = n - 2; j >= 1; j--) /* back substitution */
        m[j * stride] = d[j] - (j < n - 2 ? a->c[j] * m[(j + 1) * stride] : 0.0);
}

/* The spline along one axis at x as a local form: y(x) = sum over the interval's two nodes p of
 * al[p] y_p + be[p] y''_p (y'' = M y). Returns the interval's first node i; beyond the ends the
 * edge value is held (al = 1 at the edge node, be = 0). */
static int spline_local(const double *x, int n, double at, double al[2], double be[2])
{
    int i = 0;
    double h, a, b;
    al[0] = al[1] = be[0] = be[1] = 0.0;
    if (n == 1 || at <= x[0]) {
        al[0] = 1.0;
        return 0;
    }
    if (at >= x[n - 1]) {
        al[1] = 1.0;
        return n - 2;
    }
    while (at >= x[i + 1]) i++;
    h = x[i + 1] - x[i];
    a = (x[i + 1] - at) / h;
    b = 1.0 - a;
    al[0] = a;
    al[1] = b;
    be[0] = h * h / 6.0 * (a * a * a - a);
    be[1] = h * h / 6.0 * (b * b * b - b);
    return i;
}

/* The second derivatives along one axis (0 temperature, 1 speed, 2 torque) of the table src
 * [K][w][T] at every node of the others, into dst. */
static void along_axis(const hg_effmap *map, int axis, const double *src, double *dst)
{
    int n[3] = {map->n_K, map->n_w, map->n_T}, i, j;
    const double *x[3] = {map->K, map->w, map->T};
    size_t stride[3] = {(size_t)map->n_w * map->n_T, (size_t)map->n_T, 1};
    int o1 = axis == 0 ? 1 : 0, o2 = axis == 2 ? 1 : 2; /* the other two axes */
    spline_axis a;
    spline_axis_init(x[axis], n[axis], &a);
    for (i = 0; i < n[o1]; i++)
        for (j = 0; j < n[o2]; j++) {
            size_t first = i * stride[o1] + j * stride[o2];
            second_derivatives(&a, src + first, stride[axis], dst + first);
        }
}

/* The tables of second derivatives: D[s] with the spline's second derivative taken along speed
 * (bit 0), torque (bit 1) and temperature (bit 2) of s; D[0] is the table itself. An evaluation
 * then needs only the 2 x 2 x 2 nodes around the point, whatever the size of the grid. */
static void derivative_tables(hg_effmap *map)
{
    size_t per_dir = (size_t)map->n_K * map->n_w * map->n_T;
    int d, s;
    for (d = 0; d < 2; d++) {
        double *D[8];
        for (s = 0; s < 8; s++) D[s] = map->D + ((size_t)s * 2 + d) * per_dir;
        memcpy(D[0], map->eta + (size_t)d * per_dir, per_dir * sizeof(double));
        for (s = 1; s < 8; s++) { /* the lowest set bit taken last, on the table of s without it */
            int bit = s & -s;
            along_axis(map, bit == 1 ? 1 : (bit == 2 ? 2 : 0), D[s & ~bit], D[s]);
        }
    }
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
    map->D = malloc(16 * (size_t)map->n_K * map->n_w * map->n_T * sizeof(double));
    if (!map->eta || !map->D) {
        hg_errorf(err, errlen, "%s: out of memory", path);
        goto done;
    }
    if (read_table(f, path, map, err, errlen) || hg_datafile_check_all_used(f, err, errlen))
        goto done;
    derivative_tables(map);
    rc = 0;
done:
    if (rc) hg_effmap_free(map);
    hg_datafile_free(f);
    return rc;
}

void hg_effmap_free(hg_effmap *map)
{
    free(map->eta);
    free(map->D);
    map->eta = map->D = NULL;
}

int hg_effmap_inside(const hg_effmap *map, double w, double T, double K)
{
    w = fabs(w), T = fabs(T);
    return w >= map->w[0] && w <= map->w[map->n_w - 1] && T >= map->T[0] &&
           T <= map->T[map->n_T - 1] && K >= map->K[0] && K <= map->K[map->n_K - 1];
}

double hg_effmap_eta(const hg_effmap *map, int direction, double w, double T, double K)
{
    double aw[2], bw[2], aT[2], bT[2], aK[2], bK[2], eta = 0.0;
    size_t per_K = (size_t)map->n_w * map->n_T, per_dir = map->n_K * per_K;
    int iw = spline_local(map->w, map->n_w, w < 0 ? -w : w, aw, bw);
    int iT = spline_local(map->T, map->n_T, T < 0 ? -T : T, aT, bT);
    int iK = spline_local(map->K, map->n_K, K, aK, bK);
    int s, p, q, r;
    for (s = 0; s < 8; s++) {
        const double *D = map->D + ((size_t)s * 2 + direction) * per_dir;
        const double *cw = s & 1 ? bw : aw, *cT = s & 2 ? bT : aT, *cK = s & 4 ? bK : aK;
        for (r = 0; r < 2 && iK + r < map->n_K; r++) {
            if (cK[r] == 0.0) continue;
            for (p = 0; p < 2 && iw + p < map->n_w; p++) {
                const double *row = D + (size_t)(iK + r) * per_K + (size_t)(iw + p) * map->n_T;
                double sum = 0.0;
                if (cw[p] == 0.0) continue;
                for (q = 0; q < 2 && iT + q < map->n_T; q++) sum += cT[q] * row[iT + q];
                eta += cK[r] * cw[p] * sum;
            }
        }
    }
    return eta;
}
