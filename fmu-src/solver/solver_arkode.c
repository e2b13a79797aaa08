/* hg_solver on SUNDIALS ARKODE's ERKStep: an explicit embedded Runge-Kutta pair with adaptive
 * steps, dense output and root finding. No Newton iteration, Jacobian or linear solve: each step
 * costs its stages' right-hand sides and a few fused vector operations, which suits the compliant
 * meshes, whose stiffest mode (the input shaft's, ~1.7 kHz) must be resolved anyway. The pair is
 * Kennedy and Carpenter's ARK4(3)6L[2]SA explicit table (6 stages, order 4 with an order-3
 * embedding): of the tables ARKODE ships, the cheapest per mesh cycle at equal accuracy here
 * (bench/bench_fmu.c; Dormand-Prince 5(4) needs 1.4 times the right-hand sides). */
#include "solver/sun_common.h"

#include <arkode/arkode_erkstep.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    hg_sun b; /* first: the user data of the adapters */
    void *ark;
} erk_solver;

/* "ARKODE: what failed: ARK_NAME (flag f): ARKODE's message". */
static int fail(char *err, size_t errlen, const char *what, int flag, const erk_solver *s)
{
    return hg_sun_fail(&s->b, err, errlen, what, ERKStepGetReturnFlagName(flag), flag);
}

/* Calls an ARKODE function fn with the arguments args; on failure returns fail() naming it. */
#define ARK_CALL(fn, args) \
    do { \
        int flag_ = fn args; \
        if (flag_ != ARK_SUCCESS) return fail(err, errlen, #fn, flag_, s); \
    } while (0)

#if SUNDIALS_VERSION_MAJOR >= 7
#define SET_HANDLER NULL
#else
#define SET_HANDLER (hg_sun_set_handler)ERKStepSetErrHandlerFn
#endif

static int configure(erk_solver *s, const hg_solver_options *opt, char *err, size_t errlen)
{
    if (hg_sun_catch_errors(&s->b, s->ark, SET_HANDLER, err, errlen)) return -1;
    ARK_CALL(ERKStepSetUserData, (s->ark, &s->b));
    ARK_CALL(ERKStepSVtolerances, (s->ark, opt->rtol, s->b.atol));
    ARK_CALL(ERKStepSetMaxNumSteps, (s->ark, opt->max_steps));
    ARK_CALL(ERKStepSetTableNum, (s->ark, ARKODE_ARK436L2SA_ERK_6_3_4));
    if (s->b.pb.n_roots > 0)
        ARK_CALL(ERKStepRootInit, (s->ark, s->b.pb.n_roots, hg_sun_roots));
    return 0;
}

/* The SUNDIALS objects, each named when it cannot be made; fused vector operations on. */
static int build(erk_solver *s, const hg_problem *pb, const hg_solver_options *opt, char *err,
                 size_t errlen)
{
    if (hg_sun_init(&s->b, "ARKODE", pb, opt, err, errlen)) return -1;
    if (N_VEnableFusedOps_Serial(s->b.y, 1) != 0)
        return hg_sun_fail_new("ARKODE", err, errlen, "N_VEnableFusedOps_Serial");
    if (!(s->ark = ERKStepCreate(hg_sun_rhs, 0.0, s->b.y, s->b.ctx)))
        return hg_sun_fail_new("ARKODE", err, errlen, "ERKStepCreate");
    return 0;
}

static void destroy(void *impl);

static void *create(const hg_problem *pb, const hg_solver_options *opt, char *err, size_t errlen)
{
    erk_solver *s = calloc(1, sizeof *s);
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

static void destroy(void *impl)
{
    erk_solver *s = impl;
    if (!s) return;
    if (s->ark) ERKStepFree(&s->ark);
    hg_sun_free(&s->b);
    free(s);
}

/* A counter of ARKODE's (0 if it cannot say, which it can whenever the solver exists). */
static long counter(int (*get)(void *, long *), void *ark)
{
    long n = 0;
    return get(ark, &n) == ARK_SUCCESS ? n : 0;
}

static int restart(void *impl, double t0, const double *y0, char *err, size_t errlen)
{
    erk_solver *s = impl;
    hg_sun_restart(&s->b, y0, counter(ERKStepGetNumSteps, s->ark),
                   counter(ERKStepGetNumRhsEvals, s->ark));
    ARK_CALL(ERKStepReInit, (s->ark, hg_sun_rhs, t0, s->b.y));
    return 0;
}

static int set_max_step(void *impl, double h_max, char *err, size_t errlen)
{
    erk_solver *s = impl;
    ARK_CALL(ERKStepSetMaxStep, (s->ark, h_max));
    return 0;
}

static int integrate(erk_solver *s, double t_stop, double *t, int *flag, char *err,
                     size_t errlen)
{
    sunrealtype t_ret = *t;
    ARK_CALL(ERKStepSetStopTime, (s->ark, t_stop));
    *flag = ERKStepEvolve(s->ark, t_stop, s->b.y, &t_ret, ARK_NORMAL);
    *t = t_ret;
    if (*flag == ARK_ROOT_RETURN) ARK_CALL(ERKStepGetRootInfo, (s->ark, s->b.root_info));
    return 0;
}

static hg_advance_result advance(void *impl, double t_stop, double *t, double *y, int *roots,
                                 char *err, size_t errlen)
{
    erk_solver *s = impl;
    int flag = ARK_SUCCESS;
    if (integrate(s, t_stop, t, &flag, err, errlen)) return HG_ADVANCE_FAILED;
    if (flag == ARK_ROOT_RETURN || flag == ARK_SUCCESS || flag == ARK_TSTOP_RETURN)
        return hg_sun_outcome(&s->b, flag == ARK_ROOT_RETURN, t_stop, t, y, roots);
    fail(err, errlen, "ERKStepEvolve", flag, s);
    return HG_ADVANCE_FAILED;
}

static void stats(const void *impl, long *steps, long *rhs_evals)
{
    const erk_solver *s = impl;
    *steps = s->b.steps_before + counter(ERKStepGetNumSteps, s->ark);
    *rhs_evals = s->b.rhs_before + counter(ERKStepGetNumRhsEvals, s->ark);
}

const hg_solver_ops hg_arkode_erk_ops = {create, destroy, restart, set_max_step, advance, stats};
