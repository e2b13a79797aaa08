/* hg_solver on SUNDIALS CVODE (BDF or Adams, dense direct linear solver, Newton iteration). */
#include "solver/solver_impl.h"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

typedef struct {
    int n, n_roots;
    hg_rhs_fn f;
    hg_root_fn g;
    void *user;
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
    return s->f(t, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot), s->user);
}

static int root_adapter(sunrealtype t, N_Vector y, sunrealtype *g, void *data)
{
    cvode_solver *s = data;
    return s->g(t, N_VGetArrayPointer(y), g, s->user);
}

static void error_handler(int code, const char *module, const char *function, char *msg,
                          void *data)
{
    cvode_solver *s = data;
    snprintf(s->last_error, sizeof s->last_error, "%s %s (%d): %s", module, function, code, msg);
}

static int fail(char *err, size_t errlen, const char *what, int flag, const cvode_solver *s)
{
    snprintf(err, errlen, "CVODE: %s failed (flag %d)%s%s", what, flag,
             s && s->last_error[0] ? ": " : "", s ? s->last_error : "");
    return -1;
}

static int configure(cvode_solver *s, const hg_solver_options *opt, char *err, size_t errlen)
{
    int flag;
    memcpy(N_VGetArrayPointer(s->atol), opt->atol, (size_t)s->n * sizeof(double));
    if ((flag = CVodeInit(s->cvode, rhs_adapter, 0.0, s->y)) != CV_SUCCESS)
        return fail(err, errlen, "CVodeInit", flag, s);
    if ((flag = CVodeSetUserData(s->cvode, s)) != CV_SUCCESS ||
        (flag = CVodeSetErrHandlerFn(s->cvode, error_handler, s)) != CV_SUCCESS ||
        (flag = CVodeSVtolerances(s->cvode, opt->rtol, s->atol)) != CV_SUCCESS ||
        (flag = CVodeSetMaxNumSteps(s->cvode, opt->max_steps)) != CV_SUCCESS ||
        (flag = CVodeSetStabLimDet(s->cvode, opt->method == HG_METHOD_BDF)) != CV_SUCCESS ||
        (flag = CVodeSetLinearSolver(s->cvode, s->LS, s->A)) != CV_SUCCESS)
        return fail(err, errlen, "CVODE set-up", flag, s);
    if (s->n_roots > 0 && (flag = CVodeRootInit(s->cvode, s->n_roots, root_adapter)) != CV_SUCCESS)
        return fail(err, errlen, "CVodeRootInit", flag, s);
    return 0;
}

static void destroy(void *impl);

static void *create(int n, int n_roots, hg_rhs_fn f, hg_root_fn g, void *user,
                    const hg_solver_options *opt, char *err, size_t errlen)
{
    cvode_solver *s = calloc(1, sizeof *s);
    if (!s) {
        snprintf(err, errlen, "out of memory creating the solver");
        return NULL;
    }
    s->n = n;
    s->n_roots = n_roots;
    s->f = f;
    s->g = g;
    s->user = user;
    if (SUNContext_Create(NULL, &s->ctx) != 0 ||
        !(s->cvode = CVodeCreate(opt->method == HG_METHOD_ADAMS ? CV_ADAMS : CV_BDF, s->ctx)) ||
        !(s->y = N_VNew_Serial(n, s->ctx)) || !(s->atol = N_VNew_Serial(n, s->ctx)) ||
        !(s->A = SUNDenseMatrix(n, n, s->ctx)) ||
        !(s->LS = SUNLinSol_Dense(s->y, s->A, s->ctx)) ||
        !(s->root_info = calloc((size_t)(n_roots > 0 ? n_roots : 1), sizeof(int)))) {
        snprintf(err, errlen, "out of memory creating the CVODE solver");
        destroy(s);
        return NULL;
    }
    N_VConst(0.0, s->y);
    if (configure(s, opt, err, errlen)) {
        destroy(s);
        return NULL;
    }
    return s;
}

static void destroy(void *impl)
{
    cvode_solver *s = impl;
    if (!s) return;
    if (s->cvode) CVodeFree(&s->cvode);
    if (s->LS) SUNLinSolFree(s->LS);
    if (s->A) SUNMatDestroy(s->A);
    if (s->y) N_VDestroy(s->y);
    if (s->atol) N_VDestroy(s->atol);
    if (s->ctx) SUNContext_Free(&s->ctx);
    free(s->root_info);
    free(s);
}

/* Right-hand-side evaluations including those of the difference-quotient Jacobian. */
static long total_rhs_evals(const cvode_solver *s)
{
    long evals = 0, jac_evals = 0;
    CVodeGetNumRhsEvals(s->cvode, &evals);
    CVodeGetNumLinRhsEvals(s->cvode, &jac_evals);
    return evals + jac_evals;
}

static void accumulate_stats(cvode_solver *s)
{
    long steps = 0;
    CVodeGetNumSteps(s->cvode, &steps);
    s->steps_before += steps;
    s->rhs_before += total_rhs_evals(s);
}

static int restart(void *impl, double t0, const double *y0, char *err, size_t errlen)
{
    cvode_solver *s = impl;
    int flag;
    accumulate_stats(s);
    memcpy(N_VGetArrayPointer(s->y), y0, (size_t)s->n * sizeof(double));
    s->last_error[0] = '\0';
    if ((flag = CVodeReInit(s->cvode, t0, s->y)) != CV_SUCCESS)
        return fail(err, errlen, "CVodeReInit", flag, s);
    return 0;
}

static int set_max_step(void *impl, double h_max, char *err, size_t errlen)
{
    cvode_solver *s = impl;
    int flag = CVodeSetMaxStep(s->cvode, h_max);
    return flag == CV_SUCCESS ? 0 : fail(err, errlen, "CVodeSetMaxStep", flag, s);
}

static hg_advance_result advance(void *impl, double t_stop, double *t, double *y, int *roots,
                                 char *err, size_t errlen)
{
    cvode_solver *s = impl;
    sunrealtype t_ret = 0.0;
    int flag = CVodeSetStopTime(s->cvode, t_stop);
    if (flag != CV_SUCCESS) {
        fail(err, errlen, "CVodeSetStopTime", flag, s);
        return HG_ADVANCE_FAILED;
    }
    flag = CVode(s->cvode, t_stop, s->y, &t_ret, CV_NORMAL);
    *t = t_ret;
    memcpy(y, N_VGetArrayPointer(s->y), (size_t)s->n * sizeof(double));
    if (flag == CV_ROOT_RETURN) {
        CVodeGetRootInfo(s->cvode, roots ? roots : s->root_info);
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
    long st = 0;
    CVodeGetNumSteps(s->cvode, &st);
    *steps = s->steps_before + st;
    *rhs_evals = s->rhs_before + total_rhs_evals(s);
}

const hg_solver_ops hg_cvode_ops = {create, destroy, restart, set_max_step, advance, stats};
