/* Modal analysis of the linearised 4-DoF torsional hypoid model and the dampers that reproduce
 * given modal damping ratios (docs/physics.md §8.4, §8.5).
 *
 * DoF order everywhere: q = [phi_s, phi_p, phi_g, phi_w] (shaft 1 end, pinion, gear, wheel end).
 * Linearisation (f(x) -> x, mean radii):
 *   M = diag(I_s, I_p, I_g, I_w)
 *   K = k_t1 e1 e1^T + k_m v v^T + k_t2 e2 e2^T,
 *   e1 = [1,-1,0,0], v = [0,R_p,-R_g,0], e2 = [0,0,1,-1]
 *   C = c_t1 e1 e1^T + c   v v^T + c_t2 e2 e2^T  (same topology)
 *
 * Pure C99: no globals, no allocation, no LAPACK. The eigenproblem K phi = w^2 M phi is solved
 * exactly as the symmetric problem M^-1/2 K M^-1/2 y = w^2 y (M is diagonal) by cyclic Jacobi.
 */
#ifndef HG_MODAL_H
#define HG_MODAL_H

#include <stddef.h>

#define HG_MODAL_NDOF 4

/* Return codes */
#define HG_MODAL_OK 0
#define HG_MODAL_EINPUT (-1) /* invalid input; err names the quantity and its value */
#define HG_MODAL_ENUM (-2)   /* numerical failure (should not happen for valid input) */

/* |w^2| <= HG_MODAL_RIGID_TOL * max(w^2) is reported as exactly 0 (rigid-body mode). */
#define HG_MODAL_RIGID_TOL 1e-9

typedef struct {
    double I_s, I_p, I_g, I_w; /* inertias [kg m^2], > 0 */
    double k_t1, k_t2;         /* shaft torsional stiffnesses [N m/rad], > 0 */
    double k_m;                /* mesh stiffness along the line of action [N/m], > 0 */
    double R_p, R_g;           /* lever arms (directional rotation radii) [m], > 0 */
} hg_modal_input;

typedef struct {
    double omega[HG_MODAL_NDOF]; /* natural angular frequencies [rad/s], ascending; omega[0] = 0 */
    double f_hz[HG_MODAL_NDOF];  /* natural frequencies [Hz] = omega / (2 pi) */
    /* phi[mode][dof]: mass-normalised (Phi^T M Phi = I) mode shapes [kg^-1/2 m^-1]; sign chosen so
     * that the largest-magnitude component of each mode is positive. */
    double phi[HG_MODAL_NDOF][HG_MODAL_NDOF];
} hg_modes;

typedef struct {
    double c_t1;             /* shaft-1 damper [N m s/rad] */
    double c;                /* mesh damper along the line of action [N s/m] */
    double c_t2;             /* shaft-2 damper [N m s/rad] */
    double zeta_achieved[3]; /* phi_i^T C phi_i / (2 omega_i) for modes 2, 3, 4 [-] */
    int used_fallback;       /* 1 when the exact solve gave a negative damper and NNLS was used */
} hg_dampers;

/* Natural frequencies and mass-normalised mode shapes, sorted by ascending frequency.
 * Returns HG_MODAL_OK, or HG_MODAL_EINPUT when any input is non-finite or <= 0 (err, which may be
 * NULL, then names the quantity and value), or HG_MODAL_ENUM. */
int hg_modal_analysis(const hg_modal_input *in, hg_modes *out, char *err, size_t errlen);

/* Dampers (c_t1, c, c_t2) such that phi_i^T C phi_i = 2 zeta_i omega_i for the elastic modes
 * i = 2, 3, 4 (docs/physics.md §8.5, procedure 1). zeta[0..2] are the target ratios of modes 2, 3, 4,
 * each finite and in [0, 1]; the rigid mode is undamped by construction.
 *
 * The exact 3x3 solve is done on the scaled system (rows divided by the target, columns scaled to
 * unit maximum) with partial pivoting and one step of iterative refinement. When a damper comes out
 * negative (or the system is singular), the non-negative least-squares fallback minimises the
 * relative residuals (zeta_achieved_i - zeta_i) / w_i, w_i = zeta_i (or max zeta when zeta_i = 0),
 * by enumerating all 7 non-empty sets of free dampers plus the all-zero set and keeping the best
 * feasible one; used_fallback is then set. All-zero targets give all-zero dampers.
 * Return codes as hg_modal_analysis (bad zeta -> HG_MODAL_EINPUT). */
int hg_modal_dampers(const hg_modal_input *in, const double zeta[3], hg_dampers *out, char *err,
                     size_t errlen);

#endif
