/* Modal analysis and modal-damping dampers of the 4-DoF torsional model: see modal.h. */
#include "model/modal.h"

#include <math.h>
#include <stdio.h>

#include "io/constants.h"
#include "io/errmsg.h"

#define N HG_MODAL_NDOF
#define NC 3 /* number of dampers / elastic modes */


/* ---------------------------------------------------------------------------------------------
 * Input checks
 * ------------------------------------------------------------------------------------------- */

static int check_positive(const char *name, double v, const char *unit, char *err, size_t errlen)
{
    if (isfinite(v) && v > 0.0) return 0;
    hg_errorf(err, errlen, "modal analysis: %s = %g %s must be finite and > 0", name, v, unit);
    return HG_MODAL_EINPUT;
}

static int validate_input(const hg_modal_input *in, char *err, size_t errlen)
{
    if (!in) {
        hg_errorf(err, errlen, "modal analysis: no input given");
        return HG_MODAL_EINPUT;
    }
    if (check_positive("I_s", in->I_s, "kg m^2", err, errlen) ||
        check_positive("I_p", in->I_p, "kg m^2", err, errlen) ||
        check_positive("I_g", in->I_g, "kg m^2", err, errlen) ||
        check_positive("I_w", in->I_w, "kg m^2", err, errlen) ||
        check_positive("k_t1", in->k_t1, "N m/rad", err, errlen) ||
        check_positive("k_t2", in->k_t2, "N m/rad", err, errlen) ||
        check_positive("k_m", in->k_m, "N/m", err, errlen) ||
        check_positive("R_p", in->R_p, "m", err, errlen) ||
        check_positive("R_g", in->R_g, "m", err, errlen))
        return HG_MODAL_EINPUT;
    return HG_MODAL_OK;
}

/* ---------------------------------------------------------------------------------------------
 * Undamped eigenproblem
 * ------------------------------------------------------------------------------------------- */

/* Stiffness matrix of docs/physics.md §8.4 [N m/rad] (k_m R^2 terms: N/m * m^2). */
static void build_K(const hg_modal_input *in, double K[N][N])
{
    const double k1 = in->k_t1, k2 = in->k_t2, km = in->k_m, Rp = in->R_p, Rg = in->R_g;
    int i, j;
    for (i = 0; i < N; i++)
        for (j = 0; j < N; j++) K[i][j] = 0.0;
    K[0][0] = k1;
    K[0][1] = K[1][0] = -k1;
    K[1][1] = k1 + km * Rp * Rp;
    K[1][2] = K[2][1] = -km * Rp * Rg;
    K[2][2] = km * Rg * Rg + k2;
    K[2][3] = K[3][2] = -k2;
    K[3][3] = k2;
}

static double off_diagonal_norm2(double A[N][N])
{
    double s = 0.0;
    int p, q;
    for (p = 0; p < N; p++)
        for (q = p + 1; q < N; q++) s += A[p][q] * A[p][q];
    return s;
}

/* One Jacobi rotation zeroing A[p][q] (A <- J^T A J, V <- V J). */
static void jacobi_rotate(double A[N][N], double V[N][N], int p, int q)
{
    const double theta = (A[q][q] - A[p][p]) / (2.0 * A[p][q]);
    const double t = (theta >= 0.0 ? 1.0 : -1.0) / (fabs(theta) + sqrt(theta * theta + 1.0));
    const double c = 1.0 / sqrt(t * t + 1.0), s = t * c;
    int k;
    for (k = 0; k < N; k++) { /* columns p, q */
        const double akp = A[k][p], akq = A[k][q];
        A[k][p] = c * akp - s * akq;
        A[k][q] = s * akp + c * akq;
    }
    for (k = 0; k < N; k++) { /* rows p, q */
        const double apk = A[p][k], aqk = A[q][k];
        A[p][k] = c * apk - s * aqk;
        A[q][k] = s * apk + c * aqk;
    }
    A[p][q] = A[q][p] = 0.0;
    for (k = 0; k < N; k++) {
        const double vkp = V[k][p], vkq = V[k][q];
        V[k][p] = c * vkp - s * vkq;
        V[k][q] = s * vkp + c * vkq;
    }
}

/* Cyclic Jacobi for symmetric A (destroyed): eigenvalues lam[k] = A[k][k], eigenvectors V[:][k]. */
static int jacobi_eigen(double A[N][N], double V[N][N], double lam[N])
{
    double scale = 0.0;
    int i, j, sweep, p, q;
    for (i = 0; i < N; i++)
        for (j = 0; j < N; j++) {
            V[i][j] = (i == j) ? 1.0 : 0.0;
            scale += A[i][j] * A[i][j];
        }
    for (sweep = 0; sweep < 60; sweep++) {
        if (off_diagonal_norm2(A) <= 1e-34 * scale) break;
        for (p = 0; p < N; p++)
            for (q = p + 1; q < N; q++)
                if (A[p][q] != 0.0) jacobi_rotate(A, V, p, q);
    }
    if (off_diagonal_norm2(A) > 1e-30 * scale) return HG_MODAL_ENUM;
    for (i = 0; i < N; i++) lam[i] = A[i][i];
    return HG_MODAL_OK;
}

/* Order of the eigenvalues, ascending (insertion sort on 4 indices). */
static void sort_order(const double lam[N], int order[N])
{
    int i, j;
    for (i = 0; i < N; i++) order[i] = i;
    for (i = 1; i < N; i++)
        for (j = i; j > 0 && lam[order[j]] < lam[order[j - 1]]; j--) {
            const int t = order[j];
            order[j] = order[j - 1];
            order[j - 1] = t;
        }
}

/* Mode shape from column col of V (eigenvector y of the symmetric problem): phi = M^-1/2 y, with
 * the largest-magnitude component made positive. */
static void store_mode(double V[N][N], int col, const double sqrt_m[N], double phi[N])
{
    int d, dmax = 0;
    for (d = 0; d < N; d++) {
        phi[d] = V[d][col] / sqrt_m[d];
        if (fabs(phi[d]) > fabs(phi[dmax])) dmax = d;
    }
    if (phi[dmax] < 0.0)
        for (d = 0; d < N; d++) phi[d] = -phi[d];
}

int hg_modal_analysis(const hg_modal_input *in, hg_modes *out, char *err, size_t errlen)
{
    double K[N][N], A[N][N], V[N][N], lam[N], sqrt_m[N], lam_max;
    int order[N], i, j, rc;
    if ((rc = validate_input(in, err, errlen)) != HG_MODAL_OK) return rc;
    if (!out) {
        hg_errorf(err, errlen, "modal analysis: no output given");
        return HG_MODAL_EINPUT;
    }
    build_K(in, K);
    sqrt_m[0] = sqrt(in->I_s);
    sqrt_m[1] = sqrt(in->I_p);
    sqrt_m[2] = sqrt(in->I_g);
    sqrt_m[3] = sqrt(in->I_w);
    for (i = 0; i < N; i++) /* M^-1/2 K M^-1/2 [1/s^2] */
        for (j = 0; j < N; j++) A[i][j] = K[i][j] / (sqrt_m[i] * sqrt_m[j]);
    if (jacobi_eigen(A, V, lam) != HG_MODAL_OK) {
        hg_errorf(err, errlen, "modal analysis: Jacobi eigen-solver did not converge");
        return HG_MODAL_ENUM;
    }
    sort_order(lam, order);
    lam_max = lam[order[N - 1]];
    for (i = 0; i < N; i++) {
        double w2 = lam[order[i]]; /* omega^2 [1/s^2] */
        if (fabs(w2) <= HG_MODAL_RIGID_TOL * lam_max) w2 = 0.0;
        if (w2 < 0.0) {
            hg_errorf(err, errlen, "modal analysis: negative eigenvalue omega^2 = %g 1/s^2", w2);
            return HG_MODAL_ENUM;
        }
        out->omega[i] = sqrt(w2);
        out->f_hz[i] = out->omega[i] / HG_TWO_PI;
        store_mode(V, order[i], sqrt_m, out->phi[i]);
    }
    return HG_MODAL_OK;
}

/* ---------------------------------------------------------------------------------------------
 * Dampers from modal damping ratios
 * ------------------------------------------------------------------------------------------- */

/* Relative motion of damper j in mode shape phi: shaft 1 [rad], mesh [m], shaft 2 [rad]. */
static void damper_strokes(const hg_modal_input *in, const double phi[N], double d[NC])
{
    d[0] = phi[0] - phi[1];
    d[1] = in->R_p * phi[1] - in->R_g * phi[2];
    d[2] = phi[2] - phi[3];
}

/* a[i][j] = contribution of unit damper j to zeta of elastic mode i+2: stroke^2 / (2 omega). */
static void zeta_per_unit_damper(const hg_modal_input *in, const hg_modes *m, double a[NC][NC])
{
    int i, j;
    for (i = 0; i < NC; i++) {
        double d[NC];
        damper_strokes(in, m->phi[i + 1], d);
        for (j = 0; j < NC; j++) a[i][j] = d[j] * d[j] / (2.0 * m->omega[i + 1]);
    }
}

static void mat_vec(double B[NC][NC], const double u[NC], double r[NC])
{
    int i;
    for (i = 0; i < NC; i++) r[i] = B[i][0] * u[0] + B[i][1] * u[1] + B[i][2] * u[2];
}

static double residual2(double B[NC][NC], const double u[NC], const double t[NC])
{
    double r[NC], s = 0.0;
    int i;
    mat_vec(B, u, r);
    for (i = 0; i < NC; i++) s += (r[i] - t[i]) * (r[i] - t[i]);
    return s;
}

/* Gaussian elimination with partial pivoting, B u = t. Returns -1 when (numerically) singular. */
static int solve3_gepp(double B[NC][NC], const double t[NC], double u[NC])
{
    double A[NC][NC + 1];
    int i, j, k;
    for (i = 0; i < NC; i++) {
        for (j = 0; j < NC; j++) A[i][j] = B[i][j];
        A[i][NC] = t[i];
    }
    for (k = 0; k < NC; k++) {
        int p = k;
        for (i = k + 1; i < NC; i++)
            if (fabs(A[i][k]) > fabs(A[p][k])) p = i;
        if (fabs(A[p][k]) < 1e-14) return -1; /* columns are scaled to max 1 */
        for (j = 0; j <= NC; j++) {
            const double tmp = A[k][j];
            A[k][j] = A[p][j];
            A[p][j] = tmp;
        }
        for (i = k + 1; i < NC; i++) {
            const double l = A[i][k] / A[k][k];
            for (j = k; j <= NC; j++) A[i][j] -= l * A[k][j];
        }
    }
    for (k = NC - 1; k >= 0; k--) {
        double s = A[k][NC];
        for (j = k + 1; j < NC; j++) s -= A[k][j] * u[j];
        u[k] = s / A[k][k];
    }
    return 0;
}

/* Exact solve plus one step of iterative refinement. */
static int solve3_refined(double B[NC][NC], const double t[NC], double u[NC])
{
    double r[NC], du[NC];
    int i;
    if (solve3_gepp(B, t, u) != 0) return -1;
    mat_vec(B, u, r);
    for (i = 0; i < NC; i++) r[i] = t[i] - r[i];
    if (solve3_gepp(B, r, du) != 0) return -1;
    for (i = 0; i < NC; i++) u[i] += du[i];
    return 0;
}

/* Least squares min |B_S u_S - t| over the dampers in `mask` (bit j = damper j free), others 0,
 * by Householder QR on the selected columns. Returns -1 when the columns are rank deficient. */
static int lsq_subset(double B[NC][NC], unsigned mask, const double t[NC], double u[NC])
{
    double R[NC][NC], y[NC];
    int col[NC], n = 0, i, j, k;
    for (j = 0; j < NC; j++) {
        u[j] = 0.0;
        if (mask & (1u << j)) col[n++] = j;
    }
    for (i = 0; i < NC; i++) {
        for (k = 0; k < n; k++) R[i][k] = B[i][col[k]];
        y[i] = t[i];
    }
    for (k = 0; k < n; k++) {
        double v[NC], norm = 0.0, vv = 0.0, alpha;
        for (i = k; i < NC; i++) norm += R[i][k] * R[i][k];
        norm = sqrt(norm);
        if (norm < 1e-12) return -1; /* columns are scaled to max 1 */
        alpha = -copysign(norm, R[k][k]);
        for (i = k; i < NC; i++) v[i] = R[i][k];
        v[k] -= alpha;
        for (i = k; i < NC; i++) vv += v[i] * v[i];
        for (j = k; j < n; j++) { /* R <- H R */
            double s = 0.0;
            for (i = k; i < NC; i++) s += v[i] * R[i][j];
            for (i = k; i < NC; i++) R[i][j] -= 2.0 * s * v[i] / vv;
        }
        {
            double s = 0.0; /* y <- H y */
            for (i = k; i < NC; i++) s += v[i] * y[i];
            for (i = k; i < NC; i++) y[i] -= 2.0 * s * v[i] / vv;
        }
    }
    for (k = n - 1; k >= 0; k--) {
        double s = y[k];
        for (j = k + 1; j < n; j++) s -= R[k][j] * u[col[j]];
        u[col[k]] = s / R[k][k];
    }
    return 0;
}

/* NNLS by enumeration of the free sets; the all-zero set is the starting candidate. */
static void nnls_enumerate(double B[NC][NC], const double t[NC], double u[NC])
{
    double best;
    unsigned mask;
    int j;
    for (j = 0; j < NC; j++) u[j] = 0.0;
    best = residual2(B, u, t);
    for (mask = 1; mask < (1u << NC); mask++) {
        double v[NC], r2;
        if (lsq_subset(B, mask, t, v) != 0) continue;
        if (v[0] < 0.0 || v[1] < 0.0 || v[2] < 0.0) continue;
        r2 = residual2(B, v, t);
        if (r2 < best) {
            best = r2;
            for (j = 0; j < NC; j++) u[j] = v[j];
        }
    }
}

static int validate_zeta(const double zeta[3], double *zeta_max, char *err, size_t errlen)
{
    int i;
    if (!zeta) {
        hg_errorf(err, errlen, "modal dampers: no damping ratios given");
        return HG_MODAL_EINPUT;
    }
    *zeta_max = 0.0;
    for (i = 0; i < NC; i++) {
        if (!(isfinite(zeta[i]) && zeta[i] >= 0.0 && zeta[i] <= 1.0)) {
            hg_errorf(err, errlen, "modal dampers: zeta of mode %d = %g must be finite and in [0, 1]",
                 i + 2, zeta[i]);
            return HG_MODAL_EINPUT;
        }
        if (zeta[i] > *zeta_max) *zeta_max = zeta[i];
    }
    return HG_MODAL_OK;
}

/* Scaled system B u = t: row i divided by w_i (relative residuals), column j by its maximum s_j
 * (unknowns u_j = c_j / s_j of order one). */
static void scale_system(double a[NC][NC], const double zeta[3], double zeta_max,
                         double B[NC][NC], double t[NC], double s[NC])
{
    int i, j;
    for (i = 0; i < NC; i++) {
        const double w = zeta[i] > 0.0 ? zeta[i] : zeta_max;
        for (j = 0; j < NC; j++) B[i][j] = a[i][j] / w;
        t[i] = zeta[i] / w;
    }
    for (j = 0; j < NC; j++) {
        double cmax = 0.0;
        for (i = 0; i < NC; i++) cmax = fmax(cmax, B[i][j]);
        s[j] = cmax > 0.0 ? 1.0 / cmax : 1.0;
        for (i = 0; i < NC; i++) B[i][j] *= s[j];
    }
}

static void store_dampers(double a[NC][NC], const double c[NC], int fallback,
                          hg_dampers *out)
{
    out->c_t1 = c[0];
    out->c = c[1];
    out->c_t2 = c[2];
    mat_vec(a, c, out->zeta_achieved);
    out->used_fallback = fallback;
}

int hg_modal_dampers(const hg_modal_input *in, const double zeta[3], hg_dampers *out, char *err,
                     size_t errlen)
{
    hg_modes m;
    double a[NC][NC], B[NC][NC], t[NC], s[NC], u[NC], c[NC] = {0.0, 0.0, 0.0}, zeta_max;
    int rc, j, fallback = 0;
    if ((rc = hg_modal_analysis(in, &m, err, errlen)) != HG_MODAL_OK) return rc;
    if ((rc = validate_zeta(zeta, &zeta_max, err, errlen)) != HG_MODAL_OK) return rc;
    if (!out) {
        hg_errorf(err, errlen, "modal dampers: no output given");
        return HG_MODAL_EINPUT;
    }
    if (m.omega[1] <= 0.0) {
        hg_errorf(err, errlen, "modal dampers: more than one rigid-body mode");
        return HG_MODAL_ENUM;
    }
    zeta_per_unit_damper(in, &m, a);
    if (zeta_max > 0.0) {
        scale_system(a, zeta, zeta_max, B, t, s);
        if (solve3_refined(B, t, u) != 0 || u[0] < 0.0 || u[1] < 0.0 || u[2] < 0.0) {
            nnls_enumerate(B, t, u);
            fallback = 1;
        }
        for (j = 0; j < NC; j++) c[j] = s[j] * u[j];
    }
    store_dampers(a, c, fallback, out);
    return HG_MODAL_OK;
}
