/* Gear-set tooth contact data (docs/data-files.md, `hypoid-gearset 1`) and its evaluation at a
 * mesh angle theta = N_p phi_p, on a flank and at a transmitted torque. */
#ifndef HG_GEARSET_H
#define HG_GEARSET_H

#include <stddef.h>

#include "mesh/fourier.h"

#define HG_MAX_PAIRS 3  /* tooth pairs in mesh at once (the load-share series, pairs k = 0, 1, 2) */
#define HG_MAX_LEVELS 8 /* torque levels a gear-set file may hold */
enum { HG_FLANK_DRIVE, HG_FLANK_COAST, HG_N_FLANKS };

/* The series of one flank at one torque level: k_m [N/m] and R_p [m] over one mesh cycle
 * (psi = theta); per pair over three mesh cycles (pair k at psi_k = (theta + 2 pi (k - 1)) / 3)
 * the load share ls [1], the reduced radii R_x, R_y [m], the pinion's material flank velocity
 * up_x, up_y per unit pinion speed, the gear's ug_x, ug_y per unit gear speed and the contact
 * point's velocity vc_x, vc_y per unit pinion speed [m] (optional in a file: 0, a contact point
 * fixed in space). */
enum {
    HG_S_K_M, HG_S_R_P, HG_S_LS, HG_S_R_X, HG_S_R_Y, HG_S_UP_X, HG_S_UP_Y, HG_S_UG_X, HG_S_UG_Y,
    HG_S_VC_X, HG_S_VC_Y, HG_N_SERIES
};
typedef struct {
    hg_series y[HG_N_SERIES];
} hg_flank_series;

/* The gear blank of the axle's loss ledger (optional keys 'blank.<name>', docs/data-files.md):
 * ring gear pitch diameter and face width, mean pitch radii of pinion and gear [m]; pitch angles
 * and mean spiral angles of pinion and gear [rad]. */
enum {
    HG_BLANK_RING_D, HG_BLANK_RING_B, HG_BLANK_R_M_P, HG_BLANK_R_M_G, HG_BLANK_DELTA_P,
    HG_BLANK_DELTA_G, HG_BLANK_BETA_P, HG_BLANK_BETA_G, HG_N_BLANK
};

typedef struct {
    char name[128];
    int N_p, N_g;
    int has_blank;                 /* 1 when the file gives the blank (all eight keys) */
    double blank[HG_N_BLANK];      /* in the order of the enum, m and rad */
    hg_series e_0;                 /* unloaded static transmission error, one cycle [m]: it
                                      defines x, so both flanks and all torques share it */
    int n_levels;                  /* 1 for a file without torque_levels */
    double T_level[HG_MAX_LEVELS]; /* pinion torque of each level, increasing [N m] */
    int n_flanks;                  /* 1: the coast flank uses the drive flank's series */
    hg_flank_series s[HG_N_FLANKS][HG_MAX_LEVELS];
} hg_gearset;

/* Reads and checks a gear-set file; err names the file and line on failure. */
int hg_gearset_load(const char *path, hg_gearset *g, char *err, size_t errlen);

/* Scales every level's k_m on both flanks and e_0 (k_m_scale, e_0_scale). */
void hg_gearset_scale(hg_gearset *g, double k_m_scale, double e_0_scale);

/* Means of k_m [N/m] and R_p [m] over a mesh cycle on `flank` at pinion torque T [N m]. */
void hg_gearset_means(const hg_gearset *g, int flank, double T, double *k_m0, double *R_p0);

typedef struct {
    double k_m;   /* mesh stiffness [N/m] */
    double dk_m;  /* dk_m/dtheta [N/m/rad] */
    double dk_dT; /* dk_m/dT of the torque interpolation [N/m/(N m)] */
    double R_p;   /* pinion contact radius [m] */
    double e_0;   /* unloaded static transmission error [m] */
    double de_0;  /* de_0/dtheta [m/rad] */
} hg_mesh_point;

/* The mesh series of `flank` interpolated linearly on the pinion torque T [N m] between the
 * levels (held beyond the first and the last). */
void hg_gearset_mesh(const hg_gearset *g, int flank, double T, double theta, hg_mesh_point *out);

typedef struct {
    double ls[HG_MAX_PAIRS];     /* load shares, clamped and renormalised to sum 1 */
    double R_x[HG_MAX_PAIRS], R_y[HG_MAX_PAIRS];
    double up[HG_MAX_PAIRS][2];  /* material flank velocity per unit pinion speed [m] */
    double ug[HG_MAX_PAIRS][2];  /* material flank velocity per unit gear speed [m] */
    double vc[HG_MAX_PAIRS][2];  /* contact point velocity per unit pinion speed [m] */
} hg_pair_geometry;

/* Load shares always; radii and velocities only when with_contact is non-zero; `flank` and T as
 * for hg_gearset_mesh. */
void hg_gearset_pairs(const hg_gearset *g, int flank, double T, double theta, int with_contact,
                      hg_pair_geometry *out);

/* The levels whose series apply on `flank` at pinion torque T [N m]: the data's flank (the drive
 * flank's for the coast flank of a file without one), levels lo and hi = lo + 1 blended linearly
 * with the weight w of hi, and dw/dT [1/(N m)]; beyond the first and the last level lo = hi and
 * w = 0 (so always for one level). hg_gearset_mesh and hg_gearset_pairs blend with it. */
typedef struct {
    int flank, lo, hi;
    double w, dw_dT;
} hg_level_pick;

void hg_gearset_level_at(const hg_gearset *g, int flank, double T, hg_level_pick *b);

/* Whether torque levels a and b of `flank` (as for hg_gearset_level_at) hold the same contact
 * series (R_x ... vc_y; the loaded surrogate's levels differ in k_m, R_p and ls alone), so that
 * whatever depends on the contact alone is the same at both. */
int hg_gearset_same_contact(const hg_gearset *g, int flank, int a, int b);

/* One pair on `flank` (as for hg_gearset_level_at) at torque level `level` and at its own phase
 * psi = (theta + 2 pi k) / 3 (period 2 pi): its load share clamped (not renormalised), radii and
 * velocities per unit speed. */
typedef struct {
    double ls, R_x, R_y, up[2], ug[2], vc[2];
} hg_pair_point;

void hg_gearset_pair_point(const hg_gearset *g, int flank, int level, double psi,
                           hg_pair_point *out);

/* A load-share series value clamped to [0, 1] above the contact floor (docs/physics.md §10.7),
 * and the three pairs' shares renormalised to sum 1. */
double hg_gearset_share_clamp(double ls_raw);
void hg_gearset_normalise_shares(double ls[HG_MAX_PAIRS]);

/* The phase psi of pair k at mesh angle theta. */
double hg_gearset_pair_phase(double theta, int k);

/* The surface velocities relative to the moving contact point that entrain the lubricant
 * (docs/physics.md §1) [m/s]: u_p = w_p (up - vc), u_g = w_g ug - w_p vc, from the material flank
 * velocities up, ug and the contact point's vc per unit speed; w_p, w_g [rad/s]. */
void hg_gearset_entrainment(const double up[2], const double ug[2], const double vc[2],
                            double w_p, double w_g, double u_p[2], double u_g[2]);

#endif
