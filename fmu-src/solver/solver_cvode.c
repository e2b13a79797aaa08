/* hg_solver on SUNDIALS CVODE (BDF or Adams, dense direct linear solver, Newton iteration). */
#include "solver/solver_impl.h"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sundials/sundials_config.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

typedef struct {
    hg_problem pb;
    SUNContext ctx;
    void *cvode;
    N_Vector y, atol;
    SUNMatrix A;
    SUNLinearSolver LS;
    int *root_info;
    long steps_before, rhs_before; /* counters of earlier CVODE runs (restarts reset them) */
    char last_error[256];          /* CVODE's own message of the last failure */
} cvode_solver;

static int rhs_adapter(sunrealtype t, N_Vector y, N_Vector ydot, void *data)
{
    cvode_solver *s = data;
    return s->pb.f(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot), s->pb.user);
}

static int root_adapter(sunrealtype t, N_Vector y, sunrealtype *g, void *data)
{
    cvode_solver *s = data;
    return s->pb.g(t, N_VGetArrayPointer(y), g, s->pb.user);
}

/* CVODE's own message of a failure, kept for ours. SUNDIALS 7 reports through the context's
 * error handler, SUNDIALS 6 through the integrator's. */
#if SUNDIALS_VERSION_MAJOR >= 7
static void error_handler(int line, const char *function, const char *file, const char *msg,
                          SUNErrCode code, void *data, SUNContext ctx)
{
    cvode_solver *s = data;
    (void)line;
    (void)file;
    (void)ctx;
    snprintf(s->last_error, sizeof s->last_error, "%s (%d): %s", function, (int)code, msg);
}
#else
static void error_handler(int code, const char *module, const char *function, char *msg,
                          void *data)
{
    cvode_solver *s = data;
    snprintf(s->last_error, sizeof s->last_error, "%s %s (%d): %s", module, function, code, msg);
}
#endif

/* "CVODE: what failed: CV_NAME (flag f): CVODE's message". */
static int fail(char *err, size_t errlen, const char *what, int flag, const cvode_solver *s)
{
    char *name = CVodeGetReturnFlagName(flag);
    hg_errorf(err, errlen, "CVODE: %s failed: %s (flag %d)%s%s", what, name ? name : "?", flag,
              s->last_error[0] ? ": " : "", s->last_error);
    free(name);
    return -1;
}

/* A constructor of SUNDIALS returned NULL or an error. */
static int fail_new(char *err, size_t errlen, const char *what)
{
    hg_errorf(err, errlen, "CVODE: %s failed (out of memory)", what);
    return -1;
}

/* Calls a CVODE function fn with the arguments args; on failure returns fail() naming it. */
#define CV_CALL(fn, args) \
    do { \
        int flag_ = fn args; \
        if (flag_ != CV_SUCCESS) return fail(err, errlen, #fn, flag_, s); \
    } while (0)

/* Routes CVODE's messages into last_error instead of stderr. */
static int catch_errors(cvode_solver *s, char *err, size_t errlen)
{
#if SUNDIALS_VERSION_MAJOR >= 7
    if (SUNContext_ClearErrHandlers(s->ctx) != SUN_SUCCESS ||
        SUNContext_PushErrHandler(s->ctx, error_handler, s) != SUN_SUCCESS)
        return fail_new(err, errlen, "SUNContext_PushErrHandler");
    return 0;
#else
    CV_CALL(CVodeSetErrHandlerFn, (s->cvode, error_handler, s));
    return 0;
#endif
}

static int configure(cvode_solver *s, const hg_solver_options *opt, char *err, size_t errlen)
{
    memcpy(N_VGetArrayPointer(s->atol), opt->atol, (size_t)s->pb.n * sizeof(double));
    if (catch_errors(s, err, errlen)) return -1;
    CV_CALL(CVodeInit, (s->cvode, rhs_adapter, 0.0, s->y));
    CV_CALL(CVodeSetUserData, (s->cvode, s));
    CV_CALL(CVodeSVtolerances, (s->cvode, opt->rtol, s->atol));
    CV_CALL(CVodeSetMaxNumSteps, (s->cvode, opt->max_steps));
    CV_CALL(CVodeSetStabLimDet, (s->cvode, opt->method == HG_METHOD_BDF));
    CV_CALL(CVodeSetLinearSolver, (s->cvode, s->LS, s->A));
    if (s->pb.n_roots > 0) CV_CALL(CVodeRootInit, (s->cvode, s->pb.n_roots, root_adapter));
    return 0;
}

#if SUNDIALS_VERSION_MAJOR >= 7
#define HG_SUN_COMM SUN_COMM_NULL
#else
#define HG_SUN_COMM NULL
#endif

/* The SUNDIALS objects, each named when it cannot be made. */
static int build(cvode_solver *s, int method, char *err, size_t errlen)
{
    int n = s->pb.n;
    if (SUNContext_Create(HG_SUN_COMM, &s->ctx) != 0)
        return fail_new(err, errlen, "SUNContext_Create");
    if (!(s->cvode = CVodeCreate(method == HG_METHOD_ADAMS ? CV_ADAMS : CV_BDF, s->ctx)))
        return fail_new(err, errlen, "CVodeCreate");
    if (!(s->y = N_VNew_Serial(n, s->ctx)) || !(s->atol = N_VNew_Serial(n, s->ctx)))
        return fail_new(err, errlen, "N_VNew_Serial");
    if (!(s->A = SUNDenseMatrix(n, n, s->ctx))) return fail_new(err, errlen, "SUNDenseMatrix");
    if (!(s->LS = SUNLinSol_Dense(s->y, s->A, s->ctx)))
        return fail_new(err, errlen, "SUNLinSol_Dense");
    if (!(s->root_info = calloc((size_t)(s->pb.n_roots > 0 ? s->pb.n_roots : 1), sizeof(int))))
        return fail_new(err, errlen, "the root buffer");
    N_VConst(0.0, s->y);
    return 0;
}

static void destroy(void *impl);

static void *create(const hg_problem *pb, const hg_solver_options *opt, char *err,
                    size_t errlen)
{
    cvode_solver *s = calloc(1, sizeof *s);
    if (!s) {
        hg_errorf(err, errlen, "out of memory creating the solver");
        return NULL;
    }
    s->pb = *pb;
    if (build(s, opt->method, err, errlen) || configure(s, opt, err, errlen)) {
        destroy(s);
        return NULL;
    }
    return s;
}

/* The frees' return codes are dropped on purpose: nothing can be done about them here, and each
 * only fails for a NULL argument, which the checks exclude. */
static void destroy(void *impl)
{
    cvode_solver *s = impl;
    if (!s) return;
    if (s->cvode) CVodeFree(&s->cvode);
    if (s->LS) (void)SUNLinSolFree(s->LS);
    if (s->A) SUNMatDestroy(s->A);
    if (s->y) N_VDestroy(s->y);
    if (s->atol) N_VDestroy(s->atol);
    if (s->ctx) (void)SUNContext_Free(&s->ctx);
    free(s->root_info);
    free(s);
}

/* A counter of CVODE's (0 if it cannot say, which it can whenever the solver exists). */
static long counter(int (*get)(void *, long *), void *cvode)
{
    long n = 0;
    return get(cvode, &n) == CV_SUCCESS ? n : 0;
}

/* Right-hand-side evaluations including those of the difference-quotient Jacobian. */
static long total_rhs_evals(const cvode_solver *s)
{
    return counter(CVodeGetNumRhsEvals, s->cvode) + counter(CVodeGetNumLinRhsEvals, s->cvode);
}

static void accumulate_stats(cvode_solver *s)
{
    s->steps_before += counter(CVodeGetNumSteps, s->cvode);
    s->rhs_before += total_rhs_evals(s);
}

static int restart(void *impl, double t0, const double *y0, char *err, size_t errlen)
{
    cvode_solver *s = impl;
    accumulate_stats(s);
    memcpy(N_VGetArrayPointer(s->y), y0, (size_t)s->pb.n * sizeof(double));
    s->last_error[0] = '\0';
    CV_CALL(CVodeReInit, (s->cvode, t0, s->y));
    return 0;
}

static int set_max_step(void *impl, double h_max, char *err, size_t errlen)
{
    cvode_solver *s = impl;
    CV_CALL(CVodeSetMaxStep, (s->cvode, h_max));
    return 0;
}

static int integrate(cvode_solver *s, double t_stop, double *t, int *flag, char *err,
                     size_t errlen)
{
    sunrealtype t_ret = *t;
    CV_CALL(CVodeSetStopTime, (s->cvode, t_stop));
    *flag = CVode(s->cvode, t_stop, s->y, &t_ret, CV_NORMAL);
    *t = t_ret;
    if (*flag == CV_ROOT_RETURN) CV_CALL(CVodeGetRootInfo, (s->cvode, s->root_info));
    return 0;
}

static hg_advance_result advance(void *impl, double t_stop, double *t, double *y, int *roots,
                                 char *err, size_t errlen)
{
    cvode_solver *s = impl;
    int flag = CV_SUCCESS;
    if (integrate(s, t_stop, t, &flag, err, errlen)) return HG_ADVANCE_FAILED;
    memcpy(y, N_VGetArrayPointer(s->y), (size_t)s->pb.n * sizeof(double));
    if (flag == CV_ROOT_RETURN) {
        if (roots) memcpy(roots, s->root_info, (size_t)s->pb.n_roots * sizeof(int));
        return HG_ADVANCE_ROOT;
    }
    if (flag == CV_SUCCESS || flag == CV_TSTOP_RETURN) {
        *t = t_stop;
        return HG_ADVANCE_REACHED;
    }
    fail(err, errlen, "CVode", flag, s);
    return HG_ADVANCE_FAILED;
}

static void stats(const void *impl, long *steps, long *rhs_evals)
{
    const cvode_solver *s = impl;
    *steps = s->steps_before + counter(CVodeGetNumSteps, s->cvode);
    *rhs_evals = s->rhs_before + total_rhs_evals(s);
}

const hg_solver_ops hg_cvode_ops = {create, destroy, restart, set_max_step, advance, stats};
