/* hg_solver on SUNDIALS ARKODE's ERKStep: an explicit embedded Runge-Kutta pair with adaptive
 * steps, dense output and root finding. No Newton iteration, Jacobian or linear solve: each step
 * costs its stages' right-hand sides and a few fused vector operations, which suits the compliant
 * meshes, whose stiffest mode (the input shaft's, ~1.7 kHz) must be resolved anyway. The pair is
 * Kennedy and Carpenter's ARK4(3)6L[2]SA explicit table (6 stages, order 4 with an order-3
 * embedding): of the tables ARKODE ships, the cheapest per mesh cycle at equal accuracy here
 * (bench/bench_fmu.c; Dormand-Prince 5(4) needs 1.4 times the right-hand sides). The operations
 * themselves are sun_common.c's over the table API below. */
#include "solver/sun_common.h"

#include <arkode/arkode_erkstep.h>
#include <stdlib.h>
#include <string.h>

#if SUNDIALS_VERSION_MAJOR >= 7
#define SET_HANDLER NULL
#else
#define SET_HANDLER (hg_sun_set_handler)ERKStepSetErrHandlerFn
#endif

static int configure(hg_sun *b, const hg_solver_options *opt, char *err, size_t errlen)
{
    if (hg_sun_catch_errors(b, SET_HANDLER, err, errlen)) return -1;
    HG_SUN_CALL(b, ERKStepSetUserData, (b->mem, b));
    HG_SUN_CALL(b, ERKStepSVtolerances, (b->mem, opt->rtol, b->atol));
    HG_SUN_CALL(b, ERKStepSetMaxNumSteps, (b->mem, opt->max_steps));
    HG_SUN_CALL(b, ERKStepSetTableNum, (b->mem, ARKODE_ARK436L2SA_ERK_6_3_4));
    if (b->pb.n_roots > 0)
        HG_SUN_CALL(b, ERKStepRootInit, (b->mem, b->pb.n_roots, hg_sun_roots));
    return 0;
}

/* The SUNDIALS objects, each named when it cannot be made (fused vector operations on), then
 * configured. */
static int make(hg_sun *b, const hg_solver_options *opt, char *err, size_t errlen)
{
    if (N_VEnableFusedOps_Serial(b->y, 1) != 0)
        return hg_sun_fail_new("ARKODE", err, errlen, "N_VEnableFusedOps_Serial");
    if (!(b->mem = ERKStepCreate(hg_sun_rhs, 0.0, b->y, b->ctx)))
        return hg_sun_fail_new("ARKODE", err, errlen, "ERKStepCreate");
    return configure(b, opt, err, errlen);
}

static void release(hg_sun *b)
{
    if (b->mem) ERKStepFree(&b->mem);
}

/* ERKStepReInit takes the right-hand side again. */
static int reinit(void *mem, sunrealtype t0, N_Vector y0)
{
    return ERKStepReInit(mem, hg_sun_rhs, t0, y0);
}

static const hg_sun_api API = {
    .who = "ARKODE",
    .size = sizeof(hg_sun),
    .make = make,
    .release = release,
    .flag_name = ERKStepGetReturnFlagName,
    .success = ARK_SUCCESS,
    .tstop_return = ARK_TSTOP_RETURN,
    .root_return = ARK_ROOT_RETURN,
    .normal = ARK_NORMAL,
    .can_pass = 1, /* held inputs: no step cut at t_stop (docs/model.md, "Steps without restarts") */
    .reinit = reinit, /* ERKStepReInit with the right-hand side */
    .reinit_name = "ERKStepReInit",
    HG_SUN_FN(set_max_step, ERKStepSetMaxStep),
    HG_SUN_FN(set_init_step, ERKStepSetInitStep),
    HG_SUN_FN(set_stop_time, ERKStepSetStopTime),
    HG_SUN_FN(evolve, ERKStepEvolve),
    HG_SUN_FN(root_info, ERKStepGetRootInfo),
    .num_steps = ERKStepGetNumSteps,
    .num_rhs_evals = ERKStepGetNumRhsEvals,
};

static void *create(const hg_problem *pb, const hg_solver_options *opt, char *err, size_t errlen)
{
    return hg_sun_create(&API, pb, opt, err, errlen);
}

const hg_solver_ops hg_arkode_erk_ops = {create,          hg_sun_destroy, hg_sun_restart,
                                         hg_sun_set_max_step, hg_sun_advance, hg_sun_stats};
