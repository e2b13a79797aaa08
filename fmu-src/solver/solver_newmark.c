/* The paper's fixed-step Newmark-beta scheme behind hg_solver.
 *
 * Newmark with beta = 1/4, gamma = 1/2 (constant average acceleration) applied to M q'' = F(q, q')
 * is, step for step, the trapezoidal rule on the first-order form y = (q, q'):
 *     y_{n+1} = y_n + h/2 [f(t_n, y_n) + f(t_{n+1}, y_{n+1})],
 * which also covers the model's first-order states (the DTE x and the energy integrals). The
 * implicit equation is solved by Newton's method with a finite-difference Jacobian, refreshed when
 * the step changes or Newton converges slowly. Root functions are watched over every step; a sign
 * change shortens the step onto the root (Illinois iteration), so no step crosses an event. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "solver/solver_impl.h"

#define NEWTON_MAX_ITER 8
#define NEWTON_TOL 1e-3   /* weighted RMS norm of the last Newton correction */
#define ROOT_MAX_ITER 60
#define ROOT_TIME_TOL 1e-13 /* [s] */

typedef struct {
    hg_problem pb;
    double rtol, *atol;
    double h;             /* the fixed step [s] */
    double t, *y;         /* current point */
    double *f0;           /* f(t, y), valid when have_f0 */
    int have_f0;
    double *z, *fz, *r, *g0, *g1, *y_trial;
    double *A;            /* LU factors of I - h_lu/2 J (row-major) */
    int *piv;
    double h_lu;          /* step of the factorisation, 0 when none */
    long steps, evals, max_steps;
} newmark;

static void destroy(void *impl)
{
    newmark *s = impl;
    if (!s) return;
    free(s->atol);
    free(s->y);
    free(s->A);
    free(s->piv);
    free(s);
}

static void *create(const hg_problem *pb, const hg_solver_options *opt, char *err,
                    size_t errlen)
{
    newmark *s = calloc(1, sizeof *s);
    int n = pb->n, nr = pb->n_roots > 0 ? pb->n_roots : 1;
    if (!s || !(s->atol = malloc((size_t)n * sizeof(double))) ||
        !(s->y = malloc((size_t)(7 * n + 2 * nr) * sizeof(double))) ||
        !(s->A = malloc((size_t)n * (size_t)n * sizeof(double))) ||
        !(s->piv = malloc((size_t)n * sizeof(int)))) {
        hg_errorf(err, errlen, "out of memory creating the Newmark solver");
        destroy(s);
        return NULL;
    }
    s->pb = *pb;
    s->rtol = opt->rtol;
    memcpy(s->atol, opt->atol, (size_t)n * sizeof(double));
    s->max_steps = opt->max_steps;
    s->f0 = s->y + n;
    s->z = s->f0 + n;
    s->fz = s->z + n;
    s->r = s->fz + n;
    s->y_trial = s->r + n;
    s->g0 = s->y_trial + 2 * n; /* one spare vector of n for the Jacobian column */
    s->g1 = s->g0 + nr;
    return s;
}

static int restart(void *impl, double t0, const double *y0, double h0, char *err,
                   size_t errlen)
{
    newmark *s = impl;
    (void)h0;
    (void)err;
    (void)errlen;
    s->t = t0;
    memcpy(s->y, y0, (size_t)s->pb.n * sizeof(double));
    s->have_f0 = 0;
    return 0;
}

static int set_max_step(void *impl, double h, char *err, size_t errlen)
{
    newmark *s = impl;
    if (!(h > 0.0) || !isfinite(h)) {
        hg_errorf(err, errlen, "Newmark: the fixed step must be positive and finite, got %g", h);
        return -1;
    }
    s->h = h;
    return 0;
}

static int rhs(newmark *s, double t, const double *y, double *ydot)
{
    s->evals++;
    return s->pb.f(t, y, ydot, s->pb.user);
}

/* LU with partial pivoting of the n x n row-major matrix A, in place. */
static int lu_factor(double *A, int *piv, int n)
{
    int i, j, k;
    for (k = 0; k < n; k++) {
        int p = k;
        for (i = k + 1; i < n; i++)
            if (fabs(A[i * n + k]) > fabs(A[p * n + k])) p = i;
        if (A[p * n + k] == 0.0) return -1;
        piv[k] = p;
        if (p != k)
            for (j = 0; j < n; j++) {
                double tmp = A[k * n + j];
                A[k * n + j] = A[p * n + j];
                A[p * n + j] = tmp;
            }
        for (i = k + 1; i < n; i++) {
            double m = A[i * n + k] /= A[k * n + k];
            for (j = k + 1; j < n; j++) A[i * n + j] -= m * A[k * n + j];
        }
    }
    return 0;
}

static void lu_solve(const double *A, const int *piv, int n, double *b)
{
    int i, j;
    for (i = 0; i < n; i++) {
        double tmp = b[piv[i]];
        b[piv[i]] = b[i];
        b[i] = tmp;
        for (j = 0; j < i; j++) b[i] -= A[i * n + j] * b[j];
    }
    for (i = n - 1; i >= 0; i--) {
        for (j = i + 1; j < n; j++) b[i] -= A[i * n + j] * b[j];
        b[i] /= A[i * n + i];
    }
}

/* A = I - h/2 J(t, y), J by forward differences, then factorised. */
static int newton_matrix(newmark *s, double t, const double *y, const double *fy, double h)
{
    int i, j, n = s->pb.n;
    double *col = s->y_trial + n;
    memcpy(s->y_trial, y, (size_t)n * sizeof(double));
    for (j = 0; j < n; j++) {
        double d = sqrt(2.2e-16) * fmax(fabs(y[j]), s->atol[j] / s->rtol);
        if (d == 0.0) d = 1e-8;
        s->y_trial[j] = y[j] + d;
        if (rhs(s, t, s->y_trial, col)) return -1;
        s->y_trial[j] = y[j];
        for (i = 0; i < n; i++) s->A[i * n + j] = -0.5 * h * (col[i] - fy[i]) / d;
        s->A[j * n + j] += 1.0;
    }
    s->h_lu = h;
    return lu_factor(s->A, s->piv, n);
}

static double wrms(const newmark *s, const double *v, const double *ref)
{
    double sum = 0.0;
    int i;
    for (i = 0; i < s->pb.n; i++) {
        double q = v[i] / (s->rtol * fabs(ref[i]) + s->atol[i]);
        sum += q * q;
    }
    return sqrt(sum / s->pb.n);
}

/* One trapezoidal step of length h from (s->t, s->y) into s->z (and s->fz). */
static int trapezoid(newmark *s, double h)
{
    int i, it, attempt, n = s->pb.n;
    for (attempt = 0; attempt < 2; attempt++) {
        if ((s->h_lu != h || attempt > 0) && newton_matrix(s, s->t, s->y, s->f0, h)) return -1;
        for (i = 0; i < n; i++) s->z[i] = s->y[i] + h * s->f0[i]; /* predictor */
        for (it = 0; it < NEWTON_MAX_ITER; it++) {
            if (rhs(s, s->t + h, s->z, s->fz)) return -1;
            for (i = 0; i < n; i++) s->r[i] = -(s->z[i] - s->y[i] - 0.5 * h * (s->f0[i] + s->fz[i]));
            lu_solve(s->A, s->piv, n, s->r);
            for (i = 0; i < n; i++) s->z[i] += s->r[i];
            if (wrms(s, s->r, s->z) < NEWTON_TOL) return rhs(s, s->t + h, s->z, s->fz);
        }
    }
    return -1;
}

/* Index of the root function that changes sign between g0 and g1 first, with its fraction. */
static int first_crossing(const newmark *s, double *frac)
{
    int i, best = -1;
    for (i = 0; i < s->pb.n_roots; i++) {
        double a = s->g0[i], b = s->g1[i], f;
        if (a == 0.0 || !((a < 0.0 && b >= 0.0) || (a > 0.0 && b <= 0.0))) continue;
        f = a / (a - b);
        if (best < 0 || f < *frac) {
            best = i;
            *frac = f;
        }
    }
    return best;
}

/* Shortens the step h onto the first root (Illinois on the step length). On return s->z, s->g1
 * hold the end of the shortened step, which lies on or just past the root. */
static int locate_root(newmark *s, double *h, int i)
{
    double lo = 0.0, hi = *h, g_lo = s->g0[i], g_hi = s->g1[i], step = *h;
    int it, side = 0;
    for (it = 0; it < ROOT_MAX_ITER && hi - lo > ROOT_TIME_TOL; it++) {
        double mid = hi - g_hi * (hi - lo) / (g_hi - g_lo), g_mid;
        if (!(mid > lo && mid < hi)) mid = 0.5 * (lo + hi);
        if (trapezoid(s, mid) || s->pb.g(s->t + mid, s->z, s->g1, s->pb.user)) return -1;
        g_mid = s->g1[i];
        if ((g_mid < 0.0) == (g_lo < 0.0) && g_mid != 0.0) {
            lo = mid, g_lo = g_mid;
            if (side == -1) g_hi *= 0.5;
            side = -1;
        } else {
            hi = mid, g_hi = g_mid;
            if (side == 1) g_lo *= 0.5;
            side = 1;
            step = mid;
            if (g_mid == 0.0) break;
        }
    }
    if (trapezoid(s, step) || s->pb.g(s->t + step, s->z, s->g1, s->pb.user)) return -1;
    *h = step;
    return 0;
}

static void root_directions(const newmark *s, int *roots)
{
    int i;
    for (i = 0; i < s->pb.n_roots; i++) {
        double a = s->g0[i], b = s->g1[i];
        roots[i] = (a < 0.0 && b >= 0.0) ? 1 : (a > 0.0 && b <= 0.0) ? -1 : 0;
    }
}

/* Fixed steps that end exactly at t_stop (pass is ignored). */
static hg_advance_result advance(void *impl, double t_stop, int pass, double *t, double *y,
                                 int *roots, char *err, size_t errlen)
{
    newmark *s = impl;
    long taken = 0;
    (void)pass;
    if (!s->have_f0) {
        if (rhs(s, s->t, s->y, s->f0)) goto failed;
        s->have_f0 = 1;
    }
    if (s->pb.n_roots && s->pb.g(s->t, s->y, s->g0, s->pb.user)) goto failed;
    while (s->t < t_stop) {
        double h = fmin(s->h, t_stop - s->t), frac = 1.0;
        int hit;
        if (h < 1e-9 * s->h) h = t_stop - s->t; /* no sliver steps before t_stop */
        if (++taken > s->max_steps || trapezoid(s, h)) goto failed;
        hit = -1;
        if (s->pb.n_roots) {
            if (s->pb.g(s->t + h, s->z, s->g1, s->pb.user)) goto failed;
            hit = first_crossing(s, &frac);
            if (hit >= 0 && locate_root(s, &h, hit)) goto failed;
        }
        s->steps++;
        s->t = (h == t_stop - s->t) ? t_stop : s->t + h;
        memcpy(s->y, s->z, (size_t)s->pb.n * sizeof(double));
        memcpy(s->f0, s->fz, (size_t)s->pb.n * sizeof(double));
        if (hit >= 0) {
            root_directions(s, roots);
            *t = s->t;
            memcpy(y, s->y, (size_t)s->pb.n * sizeof(double));
            return HG_ADVANCE_ROOT;
        }
        if (s->pb.n_roots) memcpy(s->g0, s->g1, (size_t)s->pb.n_roots * sizeof(double));
    }
    *t = t_stop;
    memcpy(y, s->y, (size_t)s->pb.n * sizeof(double));
    return HG_ADVANCE_REACHED;
failed:
    hg_errorf(err, errlen, "Newmark: %s at t = %.9g s (step %g s); use a shorter step "
              "(steps_per_mesh_cycle, max_step) or a CVODE solver",
              taken > s->max_steps ? "too many steps" : "Newton iteration failed to converge",
              s->t, s->h);
    return HG_ADVANCE_FAILED;
}

static void stats(const void *impl, long *steps, long *rhs_evals)
{
    const newmark *s = impl;
    *steps = s->steps;
    *rhs_evals = s->evals;
}

const hg_solver_ops hg_newmark_ops = {create, destroy, restart, set_max_step, advance, stats};
