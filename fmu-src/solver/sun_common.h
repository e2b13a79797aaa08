/* What the two SUNDIALS integrators behind hg_solver (solver_cvode.c, solver_arkode.c) share: the
 * problem and its N_Vectors, the right-hand-side and root adapters, SUNDIALS's own message of a
 * failure routed into ours (SUNDIALS 6: the integrator's error handler, 7: the context's), and the
 * operations restart, set_max_step, advance and stats, written once over a table of each
 * integrator's functions (hg_sun_api). Every SUNDIALS call's return code is checked and named. */
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

typedef struct hg_sun hg_sun;

/* An integrator's own functions behind the shared operations, with the names the messages give
 * them. CVODE's and ERKStep's have the same signatures (an adapter wraps the one that differs)
 * and their return codes the same meanings. */
typedef struct {
    const char *who; /* "CVODE", "ARKODE": the first word of every message */
    size_t size;     /* of the adapter's struct, which begins with its hg_sun */
    /* b->mem and the integrator's other objects, configured; fails naming what it could not do */
    int (*make)(hg_sun *b, const hg_solver_options *opt, char *err, size_t errlen);
    void (*release)(hg_sun *b); /* what make made (NULL members skipped) */
    char *(*flag_name)(long flag);
    int success, tstop_return, root_return, normal; /* CV_SUCCESS ... / ARK_SUCCESS ... */
    /* 1: steps past t_stop and interpolates when asked (hg_solver_advance's pass): CVODE, whose
     * Nordsieck interpolant has the method's order; ARKODE's dense output for the ERK pair is of
     * lower degree than the method, so it always stops at t_stop */
    int can_pass;
    int (*reinit)(void *mem, sunrealtype t0, N_Vector y0);
    int (*set_max_step)(void *mem, sunrealtype h_max);
    int (*set_init_step)(void *mem, sunrealtype h0);
    int (*set_stop_time)(void *mem, sunrealtype t_stop);
    int (*evolve)(void *mem, sunrealtype t_out, N_Vector y, sunrealtype *t_ret, int task);
    int (*root_info)(void *mem, int *found);
    int (*num_steps)(void *mem, long *n);
    int (*num_rhs_evals)(void *mem, long *n);
    const char *reinit_name, *set_max_step_name, *set_init_step_name, *set_stop_time_name,
        *evolve_name, *root_info_name;
} hg_sun_api;

/* One integrator function and the name its failures give: .op = fn, .op_name = "fn" */
#define HG_SUN_FN(op, fn) .op = fn, .op##_name = #fn

struct hg_sun {
    const hg_sun_api *api;
    void *mem; /* the integrator's memory */
    hg_problem pb;
    SUNContext ctx;
    N_Vector y, atol;
    int *root_info;
    long steps_before, rhs_before; /* counters of earlier runs (restarts reset them) */
    char last_error[256];          /* SUNDIALS's own message of the last failure */
};

/* y' = f and the roots, with user data the hg_sun itself. */
int hg_sun_rhs(sunrealtype t, N_Vector y, N_Vector ydot, void *data);
int hg_sun_roots(sunrealtype t, N_Vector y, sunrealtype *g, void *data);

/* SUNDIALS 6's integrator error-handler setter (CVodeSetErrHandlerFn, ERKStepSetErrHandlerFn):
 * both take a handler of this shape. */
typedef void (*hg_sun_handler)(int code, const char *module, const char *function, char *msg,
                               void *data);
typedef int (*hg_sun_set_handler)(void *mem, hg_sun_handler fn, void *data);

/* Routes the messages of b->mem into b->last_error instead of stderr. */
int hg_sun_catch_errors(hg_sun *b, hg_sun_set_handler set, char *err, size_t errlen);

/* "WHO: what failed: NAME (flag f): SUNDIALS's message". Returns -1. */
int hg_sun_fail(const hg_sun *b, char *err, size_t errlen, const char *what, int flag);

/* A constructor returned NULL or an error. Returns -1. */
int hg_sun_fail_new(const char *who, char *err, size_t errlen, const char *what);

/* Calls fn with the arguments args; on failure returns hg_sun_fail() naming fn (in a function
 * with err and errlen). */
#define HG_SUN_CALL(b, fn, args) \
    do { \
        int flag_ = fn args; \
        if (flag_ != (b)->api->success) return hg_sun_fail((b), err, errlen, #fn, flag_); \
    } while (0)

/* The hg_solver_ops of an integrator described by api (create wraps hg_sun_create). */
void *hg_sun_create(const hg_sun_api *api, const hg_problem *pb, const hg_solver_options *opt,
                    char *err, size_t errlen);
void hg_sun_destroy(void *impl);
int hg_sun_restart(void *impl, double t0, const double *y0, double h0, char *err,
                   size_t errlen);
int hg_sun_set_max_step(void *impl, double h_max, char *err, size_t errlen);
hg_advance_result hg_sun_advance(void *impl, double t_stop, int pass, double *t, double *y,
                                 int *roots, char *err, size_t errlen);
void hg_sun_stats(const void *impl, long *steps, long *rhs_evals);

#endif
