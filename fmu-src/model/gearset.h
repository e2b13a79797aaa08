/* Gear-set tooth contact data (docs/data-files.md, `hypoid-gearset 1`) and its evaluation at a
 * mesh angle theta = N_p phi_p. */
#ifndef HG_GEARSET_H
#define HG_GEARSET_H

#include <stddef.h>

#include "model/fourier.h"
#include "tribo/pair_contact.h"

typedef struct {
    char name[128];
    int N_p, N_g;
    hg_series k_m, R_p, e_0; /* one mesh cycle, psi = theta [N/m, m, m] */
    /* three mesh cycles, pair k at psi_k = (theta + 2 pi (k - 1)) / 3 */
    hg_series ls;         /* load share [1] */
    hg_series R_x, R_y;   /* reduced radii [m] */
    hg_series up_x, up_y; /* pinion surface velocity per unit pinion speed [m] */
    hg_series ug_x, ug_y; /* gear surface velocity per unit gear speed [m] */
} hg_gearset;

/* Reads and checks a gear-set file; err names the file and line on failure. */
int hg_gearset_load(const char *path, hg_gearset *g, char *err, size_t errlen);

typedef struct {
    double k_m;   /* mesh stiffness [N/m] */
    double dk_m;  /* dk_m/dtheta [N/m/rad] */
    double R_p;   /* pinion contact radius [m] */
    double e_0;   /* unloaded static transmission error [m] */
    double de_0;  /* de_0/dtheta [m/rad] */
} hg_mesh_point;

void hg_gearset_mesh(const hg_gearset *g, double theta, hg_mesh_point *out);

typedef struct {
    double ls[HG_MAX_PAIRS];     /* load shares, clamped and renormalised to sum 1 */
    double R_x[HG_MAX_PAIRS], R_y[HG_MAX_PAIRS];
    double up[HG_MAX_PAIRS][2];  /* per unit pinion speed [m] */
    double ug[HG_MAX_PAIRS][2];  /* per unit gear speed [m] */
} hg_pair_geometry;

/* Load shares always; radii and velocities only when with_contact is non-zero. */
void hg_gearset_pairs(const hg_gearset *g, double theta, int with_contact, hg_pair_geometry *out);

#endif
