/* hg_solver on SUNDIALS CVODE (BDF or Adams, dense direct linear solver, Newton iteration). */
#include "solver/sun_common.h"

#include <cvode/cvode.h>
#include <stdlib.h>
#include <string.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

typedef struct {
    hg_sun b; /* first: the user data of the adapters */
    void *cvode;
    SUNMatrix A;
    SUNLinearSolver LS;
} cvode_solver;

/* "CVODE: what failed: CV_NAME (flag f): CVODE's message". */
static int fail(char *err, size_t errlen, const char *what, int flag, const cvode_solver *s)
{
    return hg_sun_fail(&s->b, err, errlen, what, CVodeGetReturnFlagName(flag), flag);
}

/* Calls a CVODE function fn with the arguments args; on failure returns fail() naming it. */
#define CV_CALL(fn, args) \
    do { \
        int flag_ = fn args; \
        if (flag_ != CV_SUCCESS) return fail(err, errlen, #fn, flag_, s); \
    } while (0)

#if SUNDIALS_VERSION_MAJOR >= 7
#define SET_HANDLER NULL
#else
#define SET_HANDLER (hg_sun_set_handler)CVodeSetErrHandlerFn
#endif

static int configure(cvode_solver *s, const hg_solver_options *opt, char *err, size_t errlen)
{
    if (hg_sun_catch_errors(&s->b, s->cvode, SET_HANDLER, err, errlen)) return -1;
    CV_CALL(CVodeInit, (s->cvode, hg_sun_rhs, 0.0, s->b.y));
    CV_CALL(CVodeSetUserData, (s->cvode, &s->b));
    CV_CALL(CVodeSVtolerances, (s->cvode, opt->rtol, s->b.atol));
    CV_CALL(CVodeSetMaxNumSteps, (s->cvode, opt->max_steps));
    CV_CALL(CVodeSetStabLimDet, (s->cvode, opt->method == HG_METHOD_BDF));
    CV_CALL(CVodeSetLinearSolver, (s->cvode, s->LS, s->A));
    if (s->b.pb.n_roots > 0) CV_CALL(CVodeRootInit, (s->cvode, s->b.pb.n_roots, hg_sun_roots));
    return 0;
}

/* The SUNDIALS objects, each named when it cannot be made. */
static int build(cvode_solver *s, const hg_problem *pb, const hg_solver_options *opt, char *err,
                 size_t errlen)
{
    int n = pb->n;
    if (hg_sun_init(&s->b, "CVODE", pb, opt, err, errlen)) return -1;
    if (!(s->cvode = CVodeCreate(opt->method == HG_METHOD_ADAMS ? CV_ADAMS : CV_BDF, s->b.ctx)))
        return hg_sun_fail_new("CVODE", err, errlen, "CVodeCreate");
    if (!(s->A = SUNDenseMatrix(n, n, s->b.ctx)))
        return hg_sun_fail_new("CVODE", err, errlen, "SUNDenseMatrix");
    if (!(s->LS = SUNLinSol_Dense(s->b.y, s->A, s->b.ctx)))
        return hg_sun_fail_new("CVODE", err, errlen, "SUNLinSol_Dense");
    return 0;
}

static void destroy(void *impl);

static void *create(const hg_problem *pb, const hg_solver_options *opt, char *err, size_t errlen)
{
    cvode_solver *s = calloc(1, sizeof *s);
    if (!s) {
        hg_errorf(err, errlen, "out of memory creating the solver");
        return NULL;
    }
    if (build(s, pb, opt, err, errlen) || configure(s, opt, err, errlen)) {
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
    hg_sun_free(&s->b);
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

static int restart(void *impl, double t0, const double *y0, char *err, size_t errlen)
{
    cvode_solver *s = impl;
    hg_sun_restart(&s->b, y0, counter(CVodeGetNumSteps, s->cvode), total_rhs_evals(s));
    CV_CALL(CVodeReInit, (s->cvode, t0, s->b.y));
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
    *flag = CVode(s->cvode, t_stop, s->b.y, &t_ret, CV_NORMAL);
    *t = t_ret;
    if (*flag == CV_ROOT_RETURN) CV_CALL(CVodeGetRootInfo, (s->cvode, s->b.root_info));
    return 0;
}

static hg_advance_result advance(void *impl, double t_stop, double *t, double *y, int *roots,
                                 char *err, size_t errlen)
{
    cvode_solver *s = impl;
    int flag = CV_SUCCESS;
    if (integrate(s, t_stop, t, &flag, err, errlen)) return HG_ADVANCE_FAILED;
    if (flag == CV_ROOT_RETURN || flag == CV_SUCCESS || flag == CV_TSTOP_RETURN)
        return hg_sun_outcome(&s->b, flag == CV_ROOT_RETURN, t_stop, t, y, roots);
    fail(err, errlen, "CVode", flag, s);
    return HG_ADVANCE_FAILED;
}

static void stats(const void *impl, long *steps, long *rhs_evals)
{
    const cvode_solver *s = impl;
    *steps = s->b.steps_before + counter(CVodeGetNumSteps, s->cvode);
    *rhs_evals = s->b.rhs_before + total_rhs_evals(s);
}

const hg_solver_ops hg_cvode_ops = {create, destroy, restart, set_max_step, advance, stats};
