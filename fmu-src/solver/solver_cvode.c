/* hg_solver on SUNDIALS CVODE (BDF or Adams, dense direct linear solver, Newton iteration); the
 * operations themselves are sun_common.c's over the table API below. */
#include "solver/sun_common.h"

#include "solver/block_dense.h"

#include <cvode/cvode.h>
#include <stdlib.h>
#include <string.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

typedef struct {
    hg_sun b; /* first: the user data of the adapters */
    SUNMatrix A;
    SUNLinearSolver LS;
} cvode_solver;

#if SUNDIALS_VERSION_MAJOR >= 7
#define SET_HANDLER NULL
#else
#define SET_HANDLER (hg_sun_set_handler)CVodeSetErrHandlerFn
#endif

static int configure(hg_sun *b, cvode_solver *s, const hg_solver_options *opt, char *err,
                     size_t errlen)
{
    if (hg_sun_catch_errors(b, SET_HANDLER, err, errlen)) return -1;
    HG_SUN_CALL(b, CVodeInit, (b->mem, hg_sun_rhs, 0.0, b->y));
    HG_SUN_CALL(b, CVodeSetUserData, (b->mem, b));
    HG_SUN_CALL(b, CVodeSVtolerances, (b->mem, opt->rtol, b->atol));
    HG_SUN_CALL(b, CVodeSetMaxNumSteps, (b->mem, opt->max_steps));
    HG_SUN_CALL(b, CVodeSetStabLimDet, (b->mem, opt->method == HG_METHOD_BDF));
    if (opt->max_order > 0) HG_SUN_CALL(b, CVodeSetMaxOrd, (b->mem, opt->max_order));
    HG_SUN_CALL(b, CVodeSetLinearSolver, (b->mem, s->LS, s->A));
    if (opt->jac_every > 0) HG_SUN_CALL(b, CVodeSetJacEvalFrequency, (b->mem, opt->jac_every));
    if (b->pb.n_roots > 0) HG_SUN_CALL(b, CVodeRootInit, (b->mem, b->pb.n_roots, hg_sun_roots));
    return 0;
}

/* The SUNDIALS objects, each named when it cannot be made, then configured. */
static int make(hg_sun *b, const hg_solver_options *opt, char *err, size_t errlen)
{
    cvode_solver *s = (cvode_solver *)b;
    int n = b->pb.n;
    if (!(b->mem = CVodeCreate(opt->method == HG_METHOD_ADAMS ? CV_ADAMS : CV_BDF, b->ctx)))
        return hg_sun_fail_new("CVODE", err, errlen, "CVodeCreate");
    if (!(s->A = SUNDenseMatrix(n, n, b->ctx)))
        return hg_sun_fail_new("CVODE", err, errlen, "SUNDenseMatrix");
    if (!(s->LS = hg_block_dense_new(b->y, s->A, b->ctx)))
        return hg_sun_fail_new("CVODE", err, errlen, "hg_block_dense_new");
    return configure(b, s, opt, err, errlen);
}

/* The frees' return codes are dropped on purpose: nothing can be done about them here, and each
 * only fails for a NULL argument, which the checks exclude. */
static void release(hg_sun *b)
{
    cvode_solver *s = (cvode_solver *)b;
    if (b->mem) CVodeFree(&b->mem);
    if (s->LS) (void)SUNLinSolFree(s->LS);
    if (s->A) SUNMatDestroy(s->A);
}

/* Right-hand-side evaluations including those of the difference-quotient Jacobian. */
static int total_rhs_evals(void *mem, long *n)
{
    long n_f = 0, n_lin = 0;
    int flag = CVodeGetNumRhsEvals(mem, &n_f);
    if (flag == CV_SUCCESS) flag = CVodeGetNumLinRhsEvals(mem, &n_lin);
    *n = n_f + n_lin;
    return flag;
}

static const hg_sun_api API = {
    .who = "CVODE",
    .size = sizeof(cvode_solver),
    .make = make,
    .release = release,
    .flag_name = CVodeGetReturnFlagName,
    .success = CV_SUCCESS,
    .tstop_return = CV_TSTOP_RETURN,
    .root_return = CV_ROOT_RETURN,
    .normal = CV_NORMAL,
    .can_pass = 1,
    HG_SUN_FN(reinit, CVodeReInit),
    HG_SUN_FN(set_max_step, CVodeSetMaxStep),
    HG_SUN_FN(set_init_step, CVodeSetInitStep),
    HG_SUN_FN(set_stop_time, CVodeSetStopTime),
    HG_SUN_FN(evolve, CVode),
    HG_SUN_FN(root_info, CVodeGetRootInfo),
    .num_steps = CVodeGetNumSteps,
    .num_rhs_evals = total_rhs_evals,
};

static void *create(const hg_problem *pb, const hg_solver_options *opt, char *err, size_t errlen)
{
    return hg_sun_create(&API, pb, opt, err, errlen);
}

const hg_solver_ops hg_cvode_ops = {create,          hg_sun_destroy, hg_sun_restart,
                                    hg_sun_set_max_step, hg_sun_advance, hg_sun_stats};
