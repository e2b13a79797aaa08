/* The force law of a loaded mesh (docs/physics.md §10.8, "In the FMU"): the normal spring force
 * W(a) at an approach a of the teeth beyond first touch, instantaneous, through the static
 * points of the gear set's torque levels. Level l carries W_l at a_l = W_l / k_m,l(theta) (its
 * secant stiffness); between two levels the law is the power law through both points,
 *   W = W_l (a / a_l)^p_l,   p_l = ln(W_l+1 / W_l) / ln(a_l+1 / a_l),
 * the first one continued down to a = 0 and the last point's tangent beyond the last level. So
 * the static deflection at every level is the data's, and the stiffness a vibration sees is the
 * law's tangent dW/da = p W / a, the contact's own tangent stiffness (within 1 % at 100 N m for
 * the loaded surrogate; tools/mesh_law_reference.py). The law's energy and its change with the
 * mesh angle at fixed a keep the energy audit closed. Pure functions. */
#ifndef HG_MESH_LAW_H
#define HG_MESH_LAW_H

#include "mesh/gearset.h"

/* What of the law is constant for a run: the levels' loads and the logarithms of their ratios
 * (the exponents' numerators), computed once per gear set (hg_mesh_law_levels_of). */
typedef struct {
    int n;                          /* levels, >= 2 */
    double W[HG_MAX_LEVELS];        /* normal load of each level, increasing [N] */
    double per_W[HG_MAX_LEVELS];    /* 1 / W_l [1/N] */
    double ln_W[HG_MAX_LEVELS - 1]; /* ln(W_l+1 / W_l) */
} hg_law_levels;

/* The levels from their loads W[l] [N]. */
void hg_mesh_law_levels(int n, const double W[], hg_law_levels *lv);

/* The law at one mesh angle theta: each level's static point in logarithms, ln a_l = ln(W_l /
 * k_m,l), its load times its approach and the law's energy there, each with its total
 * d/dtheta (the point moving with theta), so that an evaluation needs only the segment it falls
 * in: one logarithm and one exponential. */
typedef struct {
    const hg_law_levels *lv;
    double ln_a[HG_MAX_LEVELS];  /* ln(a_l / 1 m) */
    double dln_a[HG_MAX_LEVELS]; /* its d/dtheta, -(dk_m,l/dtheta) / k_m,l [1/rad] */
    double P[HG_MAX_LEVELS];     /* W_l a_l [J] */
    double dP[HG_MAX_LEVELS];    /* [J/rad] */
    double B[HG_MAX_LEVELS];     /* energy at point l, the integral of W from 0 to a_l (l >= 1;
                                    B[0] = 0, the first segment's energy counts from a = 0) [J] */
    double dB[HG_MAX_LEVELS];    /* [J/rad] */
} hg_mesh_law;

/* The law of the levels lv (which must outlive it) with their stiffness k[l] [N/m] and
 * dk/dtheta dk[l] [N/m/rad] at theta, the points' energies from them in closed form. */
void hg_mesh_law_points(const hg_law_levels *lv, const double k[], const double dk[],
                        hg_mesh_law *law);

typedef struct {
    double W;  /* spring force [N] */
    double k;  /* its tangent dW/da [N/m] */
    double U;  /* elastic energy, the integral of W from 0 to a [J] */
    double dU; /* dU/dtheta at fixed a [J/rad] */
} hg_law_force;

/* The law at approach a [m]; all zero for a <= 0 (the teeth apart). */
void hg_mesh_law_force(const hg_mesh_law *law, double a, hg_law_force *out);

/* The segment an approach falls in, what an evaluation there needs: its points' ln a_l and
 * d/dtheta, W_l a_l of its lower point and the energy where its own part starts (its lower
 * point; the last point beyond it), each with its d/dtheta. */
typedef struct {
    int l;      /* between points l and l + 1 (l = n - 2 also beyond the last point) */
    int beyond; /* the approach lies beyond the last point: its tangent */
    double ln_a0, dln_a0, ln_a1, dln_a1;
    double P, dP; /* W_l a_l (0 for the first segment, whose energy counts from a = 0) */
    double B, dB; /* energy at point l, or at the last point when beyond [J] */
} hg_law_segment;

/* The segment of an approach of logarithm ln_a among the points' ln_a[] of lv: l, and whether
 * it lies beyond the last point. */
int hg_mesh_law_locate(const hg_law_levels *lv, const double ln_a[], double ln_a_x, int *beyond);

/* The law at approach a > 0 [m] (ln_a its logarithm) in the segment sg. */
void hg_mesh_law_segment_force(const hg_law_levels *lv, const hg_law_segment *sg, double a,
                               double ln_a, hg_law_force *out);

/* The approach [m] at which the law carries the load W >= 0 [N] (the law's inverse). */
double hg_mesh_law_approach(const hg_mesh_law *law, double W);

/* The gear set's levels on the data's flank (hg_level_pick.flank): the normal load of each, its
 * pinion torque over its mean contact radius [N], the load the model transmits at that torque. */
void hg_mesh_law_levels_of(const hg_gearset *g, int data_flank, hg_law_levels *lv);

/* The law of `flank` (as for hg_gearset_level_at) at theta from the series (hg_gearset_mesh's
 * alternative for a layered file), its levels in lv. */
void hg_mesh_law_of_series(const hg_gearset *g, int flank, double theta, hg_law_levels *lv,
                           hg_mesh_law *law);

/* Mean over a mesh cycle of the law's tangent at the static load of pinion torque T [N m] on
 * `flank` [N/m], at a level's own load the mean of the slopes on either side of its point: the
 * stiffness of the linearised mesh (modal analysis, docs/physics.md §8.4); below
 * the first level at the first level's load (the tangent of a contact vanishes with its load). */
double hg_mesh_law_tangent_mean(const hg_gearset *g, int flank, double T);

#endif
