/* The integrator seen by the model: an ODE y' = f(t, y) with root functions g(t, y). The model
 * never sees which method runs underneath. */
#ifndef HG_SOLVER_H
#define HG_SOLVER_H

#include <stddef.h>

typedef int (*hg_rhs_fn)(double t, const double *y, double *ydot, void *user);
typedef int (*hg_root_fn)(double t, const double *y, double *g, void *user);

typedef enum {
    HG_METHOD_BDF,    /* CVODE variable-order BDF */
    HG_METHOD_ADAMS,  /* CVODE variable-order Adams-Moulton */
    HG_METHOD_NEWMARK, /* fixed-step Newmark-beta, beta = 1/4, gamma = 1/2 (the paper's scheme) */
    HG_METHOD_ERK      /* ARKODE explicit embedded Runge-Kutta, ARK4(3)6L[2]SA */
} hg_method;

typedef struct {
    hg_method method;
    double rtol;
    const double *atol; /* one per state */
    long max_steps;     /* internal steps allowed per hg_solver_advance call */
    int max_order;      /* highest order of the multistep methods (0: the method's own) */
    long jac_every;     /* most steps between Jacobian evaluations of CVODE's Newton iteration
                           (0: CVODE's own, 51); it also evaluates one when Newton fails */
} hg_solver_options;

typedef struct hg_solver hg_solver;

hg_solver *hg_solver_new(int n, int n_roots, hg_rhs_fn f, hg_root_fn g, void *user,
                         const hg_solver_options *opt, char *err, size_t errlen);
void hg_solver_free(hg_solver *s);

/* Starts (or restarts, discarding the history) the integration from (t0, y0); h0 is the first
 * step to try (0: the integrator's own estimate; the fixed-step method keeps its step). */
int hg_solver_restart(hg_solver *s, double t0, const double *y0, double h0, char *err,
                      size_t errlen);

/* Largest internal step (0 = unlimited); for the fixed-step method, the step itself. */
int hg_solver_set_max_step(hg_solver *s, double h_max, char *err, size_t errlen);

typedef enum { HG_ADVANCE_REACHED, HG_ADVANCE_ROOT, HG_ADVANCE_FAILED } hg_advance_result;

/* Integrates towards t_stop. Returns REACHED with *t = t_stop, or ROOT with *t at the first
 * root and roots[i] = +1/-1 for each root function that crossed upwards/downwards (0 otherwise);
 * y receives the solution at *t. FAILED fills err. With pass = 0 the integrator stops exactly at
 * t_stop; with pass = 1 it may step beyond t_stop (the right-hand side must hold there as it is)
 * and give the solution at t_stop from its interpolant, so that held inputs cost no steps cut
 * short at every t_stop. CVODE (its Nordsieck interpolant) and ARKODE (its cubic Hermite
 * interpolant) pass; Newmark stops at t_stop all the same. */
hg_advance_result hg_solver_advance(hg_solver *s, double t_stop, int pass, double *t, double *y,
                                    int *roots, char *err, size_t errlen);

/* Cumulative count of internal steps and right-hand-side evaluations. */
void hg_solver_stats(const hg_solver *s, long *steps, long *rhs_evals);

#endif
