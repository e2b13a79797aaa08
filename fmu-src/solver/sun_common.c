/* The shared parts of the SUNDIALS integrators: see sun_common.h. */
#include "solver/sun_common.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NO_STOP 1e300 /* [s] a stop time never reached */

/* Calls the integrator's function api->fn with the arguments args; on failure returns
 * hg_sun_fail() with the name the table gives it. */
#define API_CALL(b, fn, args) \
    do { \
        int flag_ = (b)->api->fn args; \
        if (flag_ != (b)->api->success) \
            return hg_sun_fail((b), err, errlen, (b)->api->fn##_name, flag_); \
    } while (0)

int hg_sun_rhs(sunrealtype t, N_Vector y, N_Vector ydot, void *data)
{
    hg_sun *b = data;
    return b->pb.f(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot), b->pb.user);
}

int hg_sun_roots(sunrealtype t, N_Vector y, sunrealtype *g, void *data)
{
    hg_sun *b = data;
    return b->pb.g(t, N_VGetArrayPointer(y), g, b->pb.user);
}

int hg_sun_fail_new(const char *who, char *err, size_t errlen, const char *what)
{
    hg_errorf(err, errlen, "%s: %s failed (out of memory)", who, what);
    return -1;
}

int hg_sun_fail(const hg_sun *b, char *err, size_t errlen, const char *what, int flag)
{
    char *flag_name = b->api->flag_name(flag);
    hg_errorf(err, errlen, "%s: %s failed: %s (flag %d)%s%s", b->api->who, what,
              flag_name ? flag_name : "?", flag, b->last_error[0] ? ": " : "", b->last_error);
    free(flag_name);
    return -1;
}

#if SUNDIALS_VERSION_MAJOR >= 7
static void error_handler(int line, const char *function, const char *file, const char *msg,
                          SUNErrCode code, void *data, SUNContext ctx)
{
    hg_sun *b = data;
    (void)line;
    (void)file;
    (void)ctx;
    snprintf(b->last_error, sizeof b->last_error, "%s (%d): %s", function, (int)code, msg);
}

int hg_sun_catch_errors(hg_sun *b, hg_sun_set_handler set, char *err, size_t errlen)
{
    (void)set;
    if (SUNContext_ClearErrHandlers(b->ctx) != SUN_SUCCESS ||
        SUNContext_PushErrHandler(b->ctx, error_handler, b) != SUN_SUCCESS)
        return hg_sun_fail_new(b->api->who, err, errlen, "SUNContext_PushErrHandler");
    return 0;
}
#else
static void error_handler(int code, const char *module, const char *function, char *msg,
                          void *data)
{
    hg_sun *b = data;
    snprintf(b->last_error, sizeof b->last_error, "%s %s (%d): %s", module, function, code, msg);
}

int hg_sun_catch_errors(hg_sun *b, hg_sun_set_handler set, char *err, size_t errlen)
{
    int flag = set(b->mem, error_handler, b);
    if (flag != 0) {
        hg_errorf(err, errlen, "%s: setting the error handler failed (flag %d)", b->api->who,
                  flag);
        return -1;
    }
    return 0;
}
#endif

/* The context, y (zero), atol (from opt) and the root buffer; fails naming what it could not
 * make. */
static int init(hg_sun *b, const hg_problem *pb, const hg_solver_options *opt, char *err,
                size_t errlen)
{
    const char *who = b->api->who;
    int n = pb->n;
    b->pb = *pb;
    if (SUNContext_Create(HG_SUN_COMM, &b->ctx) != 0)
        return hg_sun_fail_new(who, err, errlen, "SUNContext_Create");
    if (!(b->y = N_VNew_Serial(n, b->ctx)) || !(b->atol = N_VNew_Serial(n, b->ctx)))
        return hg_sun_fail_new(who, err, errlen, "N_VNew_Serial");
    if (!(b->root_info = calloc((size_t)(pb->n_roots > 0 ? pb->n_roots : 1), sizeof(int))))
        return hg_sun_fail_new(who, err, errlen, "the root buffer");
    N_VConst(0.0, b->y);
    memcpy(N_VGetArrayPointer(b->atol), opt->atol, (size_t)n * sizeof(double));
    return 0;
}

void *hg_sun_create(const hg_sun_api *api, const hg_problem *pb, const hg_solver_options *opt,
                    char *err, size_t errlen)
{
    hg_sun *b = calloc(1, api->size);
    if (!b) {
        hg_errorf(err, errlen, "out of memory creating the solver");
        return NULL;
    }
    b->api = api;
    if (init(b, pb, opt, err, errlen) || api->make(b, opt, err, errlen)) {
        hg_sun_destroy(b);
        return NULL;
    }
    return b;
}

void hg_sun_destroy(void *impl)
{
    hg_sun *b = impl;
    if (!b) return;
    b->api->release(b);
    if (b->y) N_VDestroy(b->y);
    if (b->atol) N_VDestroy(b->atol);
    if (b->ctx) (void)SUNContext_Free(&b->ctx); /* fails only for NULL, excluded */
    free(b->root_info);
    free(b);
}

/* A counter of the integrator's (0 if it cannot say, which it can whenever the solver exists). */
static long counter(const hg_sun *b, int (*get)(void *, long *))
{
    long n = 0;
    return get(b->mem, &n) == b->api->success ? n : 0;
}

/* Adds the run's counters to the earlier ones (a re-init resets them) and starts again at y0
 * with the first step h0 (0: the integrator's estimate). */
int hg_sun_restart(void *impl, double t0, const double *y0, double h0, char *err,
                   size_t errlen)
{
    hg_sun *b = impl;
    b->steps_before += counter(b, b->api->num_steps);
    b->rhs_before += counter(b, b->api->num_rhs_evals);
    memcpy(N_VGetArrayPointer(b->y), y0, (size_t)b->pb.n * sizeof(double));
    b->last_error[0] = '\0';
    API_CALL(b, set_init_step, (b->mem, h0));
    API_CALL(b, reinit, (b->mem, t0, b->y));
    return 0;
}

int hg_sun_set_max_step(void *impl, double h_max, char *err, size_t errlen)
{
    hg_sun *b = impl;
    API_CALL(b, set_max_step, (b->mem, h_max));
    return 0;
}

/* Integrates towards t_stop; *flag is the integrator's return. Without pass it stops there
 * exactly; with it (where the integrator can) it steps on and interpolates, under a stop time out
 * of reach: an earlier one would still be in force after a step that returned at t_stop by
 * interpolation, and CVODE 6.4 would return there at the next call. */
static int integrate(hg_sun *b, double t_stop, int pass, double *t, int *flag, char *err,
                     size_t errlen)
{
    sunrealtype t_ret = *t;
    API_CALL(b, set_stop_time, (b->mem, pass && b->api->can_pass ? NO_STOP : t_stop));
    *flag = b->api->evolve(b->mem, t_stop, b->y, &t_ret, b->api->normal);
    *t = t_ret;
    if (*flag == b->api->root_return) API_CALL(b, root_info, (b->mem, b->root_info));
    return 0;
}

/* y from b->y, and ROOT (roots from b->root_info) or REACHED with *t = t_stop. */
hg_advance_result hg_sun_advance(void *impl, double t_stop, int pass, double *t, double *y,
                                 int *roots, char *err, size_t errlen)
{
    hg_sun *b = impl;
    const hg_sun_api *api = b->api;
    int flag = api->success;
    if (integrate(b, t_stop, pass, t, &flag, err, errlen)) return HG_ADVANCE_FAILED;
    if (flag != api->root_return && flag != api->success && flag != api->tstop_return) {
        hg_sun_fail(b, err, errlen, api->evolve_name, flag);
        return HG_ADVANCE_FAILED;
    }
    memcpy(y, N_VGetArrayPointer(b->y), (size_t)b->pb.n * sizeof(double));
    if (flag == api->root_return) {
        if (roots) memcpy(roots, b->root_info, (size_t)b->pb.n_roots * sizeof(int));
        return HG_ADVANCE_ROOT;
    }
    *t = t_stop;
    return HG_ADVANCE_REACHED;
}

void hg_sun_stats(const void *impl, long *steps, long *rhs_evals)
{
    const hg_sun *b = impl;
    *steps = b->steps_before + counter(b, b->api->num_steps);
    *rhs_evals = b->rhs_before + counter(b, b->api->num_rhs_evals);
}
