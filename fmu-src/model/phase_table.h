/* The gear set's Fourier series tabulated once per instance over their periods, so that the
 * right-hand side interpolates instead of summing up to 32 harmonics of seven series for three
 * pairs at every call. Cubic Hermite interpolation from the exact values and slopes at the
 * nodes: C1, with errors of order (h n)^4 / 384 of the n-th harmonic's amplitude (below 1e-4 of
 * it for 32 harmonics on 512 nodes); the mesh point's derivatives dk_m, de_0 are those of the
 * interpolant, so the energy audit stays an identity. Checked against the series in
 * tests/c/test_phase_table.c. */
#ifndef HG_PHASE_TABLE_H
#define HG_PHASE_TABLE_H

#include "model/gearset.h"

#define HG_PT_N_MESH 256 /* nodes over one mesh cycle (theta) */
#define HG_PT_N_PAIR 512 /* nodes over one load-share period (psi) */

enum { HG_PT_K_M, HG_PT_R_P, HG_PT_E_0, HG_PT_N_MESH_CH };
enum { HG_PT_LS, HG_PT_R_X, HG_PT_R_Y, HG_PT_UP_X, HG_PT_UP_Y, HG_PT_UG_X, HG_PT_UG_Y,
       HG_PT_VC_X, HG_PT_VC_Y, HG_PT_N_PAIR_CH };

typedef struct {
    double mesh[HG_PT_N_MESH][HG_PT_N_MESH_CH][2]; /* value and d/dtheta at each node */
    double pair[HG_PT_N_PAIR][HG_PT_N_PAIR_CH][2]; /* value and d/dpsi (ls before clamping) */
} hg_phase_table;

/* Tabulates the series of a single-series set g (hg_gearset_single_series; after scaling). */
void hg_phase_table_build(hg_phase_table *t, const hg_gearset *g);

/* As hg_gearset_mesh and hg_gearset_pairs (with contact data), from the table. */
void hg_phase_table_mesh(const hg_phase_table *t, double theta, hg_mesh_point *out);
void hg_phase_table_pairs(const hg_phase_table *t, double theta, hg_pair_geometry *out);

#endif
