/* The gear set's Fourier series tabulated once per instance over their periods, one table per
 * flank and torque level of the file, so that the right-hand side interpolates instead of summing
 * up to 32 harmonics of eleven series for three pairs (and two levels) at every call. Between two
 * torque levels the tables' values are blended linearly with the weights of hg_gearset_level_at,
 * as hg_gearset_mesh and hg_gearset_pairs blend the series: the blend commutes with the
 * interpolation, so the tables' error is that of one level. Cubic Hermite interpolation from the exact values and slopes at the
 * nodes: C1, with errors of order (h n)^4 / 384 of the n-th harmonic's amplitude (below 1e-4 of
 * it for 32 harmonics on 512 nodes); the mesh point's derivatives dk_m, de_0 are those of the
 * interpolant, so the energy audit stays an identity. Checked against the series in
 * tests/c/test_phase_table.c. */
#ifndef HG_PHASE_TABLE_H
#define HG_PHASE_TABLE_H

#include "mesh/gearset.h"
#include "mesh/mesh_law.h"

#define HG_PT_N_MESH 256 /* nodes over one mesh cycle (theta) */
/* Nodes over one load-share period (psi = (theta + 2 pi k) / 3): three times the mesh's, so that
 * the three pairs' nodes lie on the mesh's nodes and one cell (hg_phase_table_locate) serves the
 * mesh and all three pairs. */
#define HG_PT_N_PAIR (3 * HG_PT_N_MESH)

enum { HG_PT_K_M, HG_PT_R_P, HG_PT_E_0, HG_PT_N_MESH_CH };
/* The pair channels: first those the sliding friction needs when the friction itself comes from
 * a table (load share and flank velocities), then the contact data of the direct solve. */
enum { HG_PT_LS, HG_PT_UP_X, HG_PT_UP_Y, HG_PT_UG_X, HG_PT_UG_Y, HG_PT_R_X, HG_PT_R_Y,
       HG_PT_VC_X, HG_PT_VC_Y, HG_PT_N_PAIR_CH };

/* Each node holds the value and the slope times the node spacing (d/dtheta 2 pi / HG_PT_N_MESH
 * for the mesh, d/dpsi 2 pi / HG_PT_N_PAIR for the pairs), so that one set of cubic Hermite
 * weights serves both. */
typedef struct {
    double mesh[HG_PT_N_MESH][HG_PT_N_MESH_CH][2];
    double pair[HG_PT_N_PAIR][HG_PT_N_PAIR_CH][2]; /* ls before clamping */
} hg_phase_table;

/* Where a mesh angle falls: its cell of the pair grid of pair 0 (the mesh's and the other pairs'
 * follow by whole node offsets) and the cubic Hermite weights at its fraction s of the cell: of
 * the two values (a), of the two scaled slopes (b), and their derivatives per cell (da, db). */
typedef struct {
    int i; /* node of pair 0, 0 ... HG_PT_N_PAIR - 1 */
    double a0, b0, a1, b1, da0, db0, da1, db1;
} hg_pt_cell;

/* The force law of one flank at each mesh node (hg_mesh_law's ln a_l, W_l a_l and the energy
 * at each level's point, from the node's k_m in closed form), the levels side by side (value,
 * and slope times the node spacing, as in hg_phase_table.mesh), interpolated lane by lane (the
 * unused levels zero). Between the nodes the law's points are these interpolants, which differ
 * from those of the interpolated k_m by the tables' error (tests/c/test_phase_table.c); the
 * force stays continuous through every point (the segments end where ln a meets ln a_l). */
typedef struct {
    double ln_a[HG_PT_N_MESH][2][HG_MAX_LEVELS];
    double P[HG_PT_N_MESH][2][HG_MAX_LEVELS];
    double B[HG_PT_N_MESH][2][HG_MAX_LEVELS];
} hg_pt_levels;

/* The tables of every flank and torque level of a gear set, t[flank * n_levels + level], and for
 * a layered file the force law's constants and stiffness nodes of each flank. */
typedef struct {
    int n_flanks, n_levels;
    hg_phase_table *t;
    hg_law_levels law[HG_N_FLANKS]; /* n_levels > 1 */
    hg_pt_levels *k_levels;         /* [flank], n_levels > 1, else NULL */
} hg_phase_tables;

/* Tabulates every series of g (after scaling) into ts, which must be zeroed or built before; -1
 * when out of memory (ts then holds none). */
int hg_phase_tables_build(hg_phase_tables *ts, const hg_gearset *g);

/* The table of flank fl and torque level lv of g alone (plain bytes: what hg_phase_tables_build
 * puts at t[fl * n_levels + lv]). */
void hg_phase_table_build(hg_phase_table *t, const hg_gearset *g, int fl, int lv);

/* As hg_phase_tables_build, each flank's and level's table made by one(t, fl, lv, ctx), which
 * must give hg_phase_table_build's bytes (the model takes them from its table store); -1 when
 * out of memory or one fails (ts then holds none). */
typedef int (*hg_pt_one_fn)(hg_phase_table *t, int fl, int lv, void *ctx);
int hg_phase_tables_build_with(hg_phase_tables *ts, const hg_gearset *g, hg_pt_one_fn one,
                               void *ctx);
void hg_phase_tables_free(hg_phase_tables *ts);

void hg_phase_table_locate(double theta, hg_pt_cell *c);

/* As hg_gearset_mesh and hg_gearset_pairs with the levels b picks, from the tables at the cell
 * of theta; the pairs' radii and contact point velocities only when with_contact is non-zero
 * (the load shares and flank velocities always). */
void hg_phase_table_mesh(const hg_phase_tables *ts, const hg_level_pick *b, const hg_pt_cell *c,
                         hg_mesh_point *out);
void hg_phase_table_pairs(const hg_phase_tables *ts, const hg_level_pick *b, const hg_pt_cell *c,
                          int with_contact, hg_pair_geometry *out);

/* The force law of a layered file (mesh/mesh_law.h) on the data's flank (hg_level_pick.flank)
 * at the cell of theta and approach a [m], from the nodes (hg_pt_levels): every level's ln a_l
 * to find the segment, W_l a_l and the energy of that segment's point alone. */
void hg_phase_table_law_force(const hg_phase_tables *ts, int data_flank, const hg_pt_cell *c,
                              double a, hg_law_force *out);

#endif
