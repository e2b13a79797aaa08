/* What the two SUNDIALS integrators behind hg_solver (solver_cvode.c, solver_arkode.c) share: the
 * problem and its N_Vectors, the right-hand-side and root adapters, the restart counters, and
 * SUNDIALS's own message of a failure routed into ours (SUNDIALS 6: the integrator's error
 * handler, 7: the context's). */
#ifndef HG_SUN_COMMON_H
#define HG_SUN_COMMON_H

#include <nvector/nvector_serial.h>
#include <sundials/sundials_config.h>
#include <sundials/sundials_context.h>

#include "solver/solver_impl.h"

#if SUNDIALS_VERSION_MAJOR >= 7
#define HG_SUN_COMM SUN_COMM_NULL
#else
#define HG_SUN_COMM NULL
#endif

typedef struct {
    const char *who; /* "CVODE", "ARKODE" */
    hg_problem pb;
    SUNContext ctx;
    N_Vector y, atol;
    int *root_info;
    long steps_before, rhs_before; /* counters of earlier runs (restarts reset them) */
    char last_error[256];          /* SUNDIALS's own message of the last failure */
} hg_sun;

/* y' = f and the roots, with user data the hg_sun itself. */
int hg_sun_rhs(sunrealtype t, N_Vector y, N_Vector ydot, void *data);
int hg_sun_roots(sunrealtype t, N_Vector y, sunrealtype *g, void *data);

/* The context, y (zero), atol (from opt) and the root buffer; fails naming what it could not
 * make. */
int hg_sun_init(hg_sun *b, const char *who, const hg_problem *pb, const hg_solver_options *opt,
                char *err, size_t errlen);
void hg_sun_free(hg_sun *b);

/* SUNDIALS 6's integrator error-handler setter (CVodeSetErrHandlerFn, ERKStepSetErrHandlerFn):
 * both take a handler of this shape. */
typedef void (*hg_sun_handler)(int code, const char *module, const char *function, char *msg,
                               void *data);
typedef int (*hg_sun_set_handler)(void *mem, hg_sun_handler fn, void *data);

/* Routes the messages of integrator mem into b->last_error instead of stderr. */
int hg_sun_catch_errors(hg_sun *b, void *mem, hg_sun_set_handler set, char *err, size_t errlen);

/* "WHO: what failed: NAME (flag f): SUNDIALS's message"; frees flag_name (from
 * ...GetReturnFlagName). Returns -1. */
int hg_sun_fail(const hg_sun *b, char *err, size_t errlen, const char *what, char *flag_name,
                int flag);

/* A constructor returned NULL or an error. Returns -1. */
int hg_sun_fail_new(const char *who, char *err, size_t errlen, const char *what);

/* After an integration towards t_stop: y from b->y, and ROOT (root set; roots from b->root_info)
 * or REACHED with *t = t_stop. */
hg_advance_result hg_sun_outcome(const hg_sun *b, int root, double t_stop, double *t, double *y,
                                 int *roots);

/* Copies y0 into b->y and adds the run's counters to the earlier ones before a re-init. */
void hg_sun_restart(hg_sun *b, const double *y0, long steps, long rhs_evals);

#endif
