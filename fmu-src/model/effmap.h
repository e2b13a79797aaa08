/* Efficiency maps (`hypoid-effmap 2`, docs/data-files.md): conjunctional efficiency of the full
 * model tabulated over pinion speed, pinion torque and bath temperature, for drive and coast,
 * interpolated by natural cubic splines along each axis (C2) and held constant beyond the edges.
 * A map records what it was made from: the content hashes (hg_datafile_hash) and names of the
 * gear-set and lubricant files, and the model version. */
#ifndef HG_EFFMAP_H
#define HG_EFFMAP_H

#include <stddef.h>

#include "io/datafile.h"

#define HG_MAP_MAX_AXIS 64

enum { HG_MAP_DRIVE = 0, HG_MAP_COAST = 1 };

typedef struct {
    char hash[HG_HASH_HEX]; /* content hash of the data file the map was made from */
    char source[256];       /* its name, for messages */
} hg_effmap_source;

typedef struct {
    char name[128];
    hg_effmap_source gear_set, lubricant;
    char model_version[32];
    int n_w, n_T, n_K;
    double w[HG_MAP_MAX_AXIS]; /* pinion speeds [rad/s], ascending, >= 0 */
    double T[HG_MAP_MAX_AXIS]; /* pinion torques [N m], ascending, >= 0 */
    double K[HG_MAP_MAX_AXIS]; /* bath temperatures [K], ascending */
    double *eta;               /* [direction][K][w][T], in (0, 1] */
    double *D;                 /* [8][direction][K][w][T]: eta with the spline's second
                                * derivative taken along the axes of each bit set (speed 1,
                                * torque 2, temperature 4): an evaluation reads the 2 x 2 x 2
                                * nodes around the point only */
} hg_effmap;

int hg_effmap_load(const char *path, hg_effmap *map, char *err, size_t errlen);
void hg_effmap_free(hg_effmap *map);

/* 1 when (|w|, |T|, K) lies within the table's ranges. */
int hg_effmap_inside(const hg_effmap *map, double w, double T, double K);

/* Efficiency at |pinion speed| w, |pinion torque| T, bath temperature K in a direction. */
double hg_effmap_eta(const hg_effmap *map, int direction, double w, double T, double K);

#endif
