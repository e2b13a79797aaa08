/* The shared parts of the SUNDIALS integrators: see sun_common.h. */
#include "solver/sun_common.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

int hg_sun_init(hg_sun *b, const char *who, const hg_problem *pb, const hg_solver_options *opt,
                char *err, size_t errlen)
{
    int n = pb->n;
    b->who = who;
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

void hg_sun_free(hg_sun *b)
{
    if (b->y) N_VDestroy(b->y);
    if (b->atol) N_VDestroy(b->atol);
    if (b->ctx) (void)SUNContext_Free(&b->ctx); /* fails only for NULL, excluded */
    free(b->root_info);
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

int hg_sun_catch_errors(hg_sun *b, void *mem, hg_sun_set_handler set, char *err, size_t errlen)
{
    (void)mem;
    (void)set;
    if (SUNContext_ClearErrHandlers(b->ctx) != SUN_SUCCESS ||
        SUNContext_PushErrHandler(b->ctx, error_handler, b) != SUN_SUCCESS)
        return hg_sun_fail_new(b->who, err, errlen, "SUNContext_PushErrHandler");
    return 0;
}
#else
static void error_handler(int code, const char *module, const char *function, char *msg,
                          void *data)
{
    hg_sun *b = data;
    snprintf(b->last_error, sizeof b->last_error, "%s %s (%d): %s", module, function, code, msg);
}

int hg_sun_catch_errors(hg_sun *b, void *mem, hg_sun_set_handler set, char *err, size_t errlen)
{
    int flag = set(mem, error_handler, b);
    if (flag != 0) {
        hg_errorf(err, errlen, "%s: setting the error handler failed (flag %d)", b->who, flag);
        return -1;
    }
    return 0;
}
#endif

int hg_sun_fail(const hg_sun *b, char *err, size_t errlen, const char *what, char *flag_name,
                int flag)
{
    hg_errorf(err, errlen, "%s: %s failed: %s (flag %d)%s%s", b->who, what,
              flag_name ? flag_name : "?", flag, b->last_error[0] ? ": " : "", b->last_error);
    free(flag_name);
    return -1;
}

void hg_sun_restart(hg_sun *b, const double *y0, long steps, long rhs_evals)
{
    b->steps_before += steps;
    b->rhs_before += rhs_evals;
    memcpy(N_VGetArrayPointer(b->y), y0, (size_t)b->pb.n * sizeof(double));
    b->last_error[0] = '\0';
}

hg_advance_result hg_sun_outcome(const hg_sun *b, int root, double t_stop, double *t, double *y,
                                 int *roots)
{
    memcpy(y, N_VGetArrayPointer(b->y), (size_t)b->pb.n * sizeof(double));
    if (root) {
        if (roots) memcpy(roots, b->root_info, (size_t)b->pb.n_roots * sizeof(int));
        return HG_ADVANCE_ROOT;
    }
    *t = t_stop;
    return HG_ADVANCE_REACHED;
}
