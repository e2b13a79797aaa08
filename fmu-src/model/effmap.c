/* Efficiency maps: reading and trilinear interpolation (see effmap.h). */
#include "model/effmap.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io/datafile.h"

static int read_axis(const hg_datafile *f, const char *key, double lo, double *v, int *n,
                     char *err, size_t errlen)
{
    size_t count, i;
    if (hg_datafile_numbers(f, key, 1, HG_MAP_MAX_AXIS, v, &count, err, errlen)) return -1;
    for (i = 0; i < count; i++) {
        if (v[i] < lo || (i > 0 && !(v[i] > v[i - 1]))) {
            snprintf(err, errlen, "key '%s': values must be ascending and >= %g (value %zu is %g)",
                     key, lo, i + 1, v[i]);
            return -1;
        }
    }
    *n = (int)count;
    return 0;
}

static int read_table(const hg_datafile *f, hg_effmap *map, char *err, size_t errlen)
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
                    snprintf(err, errlen, "key '%s': efficiency %g (value %zu) is not in (0, 1]",
                             key, eta[i], i + 1);
                    return -1;
                }
            }
        }
    }
    return 0;
}

int hg_effmap_load(const char *path, hg_effmap *map, char *err, size_t errlen)
{
    hg_datafile *f = hg_datafile_load(path, "hypoid-effmap", 1, err, errlen);
    char why[HG_ERRLEN];
    int rc = -1;
    if (!f) return -1;
    memset(map, 0, sizeof *map);
    if (hg_datafile_text(f, "name", map->name, sizeof map->name, why, sizeof why) ||
        read_axis(f, "speeds", 0.0, map->w, &map->n_w, why, sizeof why) ||
        read_axis(f, "torques", 0.0, map->T, &map->n_T, why, sizeof why) ||
        read_axis(f, "temperatures", 1.0, map->K, &map->n_K, why, sizeof why))
        goto done;
    map->eta = malloc(2 * (size_t)map->n_K * map->n_w * map->n_T * sizeof(double));
    if (!map->eta) {
        snprintf(why, sizeof why, "out of memory");
        goto done;
    }
    rc = read_table(f, map, why, sizeof why) || hg_datafile_check_all_used(f, why, sizeof why);
done:
    if (rc) {
        snprintf(err, errlen, "%s: %s", path, why);
        hg_effmap_free(map);
        rc = -1;
    }
    hg_datafile_free(f);
    return rc;
}

void hg_effmap_free(hg_effmap *map)
{
    free(map->eta);
    map->eta = NULL;
}

/* Index i and weight s with x between axis[i] and axis[i+1] (clamped at the ends). */
static void bracket(const double *axis, int n, double x, int *i, double *s)
{
    int j = 0;
    if (n == 1 || x <= axis[0]) {
        *i = 0;
        *s = 0.0;
        return;
    }
    if (x >= axis[n - 1]) {
        *i = n - 2;
        *s = 1.0;
        return;
    }
    while (x > axis[j + 1]) j++;
    *i = j;
    *s = (x - axis[j]) / (axis[j + 1] - axis[j]);
}

double hg_effmap_eta(const hg_effmap *map, int direction, double w, double T, double K)
{
    int iw, iT, iK, a, b, c;
    double sw, sT, sK, eta = 0.0;
    size_t per_K = (size_t)map->n_w * map->n_T;
    const double *base = map->eta + (size_t)direction * map->n_K * per_K;
    bracket(map->w, map->n_w, w < 0 ? -w : w, &iw, &sw);
    bracket(map->T, map->n_T, T < 0 ? -T : T, &iT, &sT);
    bracket(map->K, map->n_K, K, &iK, &sK);
    for (c = 0; c <= (map->n_K > 1); c++)
        for (a = 0; a <= (map->n_w > 1); a++)
            for (b = 0; b <= (map->n_T > 1); b++) {
                double weight = (c ? sK : 1.0 - sK) * (a ? sw : 1.0 - sw) * (b ? sT : 1.0 - sT);
                eta += weight * base[(size_t)(iK + c) * per_K + (size_t)(iw + a) * map->n_T + iT + b];
            }
    return eta;
}
