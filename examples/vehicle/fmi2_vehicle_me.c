/* The vehicle FMU's Model Exchange (FMI 2.0): the host integrates the seven states of
 * vehicle_model.h (half-shaft twist, wheel speed, distance and the energy integrals) from their
 * derivatives. The vehicle has no events (no event indicators, no time events, no step events):
 * event mode only passes the host's iteration through. Road load (coupling 2) is co-simulation
 * only (fmi2ExitInitializationMode refuses it). Bad arguments: fmi2Error naming the function. */
#include <math.h>
#include <stddef.h>

#include "vehicle_instance.h"

/* An ME call allowed in states, on a Model Exchange instance. */
static int me_call(vm_instance *c, const char *fn, int states)
{
    if (!allowed(c, fn, states)) return 0;
    if (c->model_exchange) return 1;
    logf_(c, fmi2Error, CAT_ERROR, "%s: a Model Exchange function, and this instance was "
          "instantiated for co-simulation", fn);
    return 0;
}

/* An array of n values where the model has n_model: not NULL and as long. */
static int array_ok(vm_instance *c, const char *fn, const void *a, size_t n, size_t n_model)
{
    if (a && n == n_model) return 1;
    logf_(c, fmi2Error, CAT_ERROR, "%s: %s (%lu values given, this FMU has %lu)", fn,
          a ? "wrong array size" : "NULL array", (unsigned long)n, (unsigned long)n_model);
    return 0;
}

#define READABLE (ST_INIT | ST_EVENT | ST_CONTINUOUS | ST_TERMINATED | ST_ERROR)

fmi2Status fmi2EnterEventMode(fmi2Component comp)
{
    vm_instance *c = comp;
    if (!me_call(c, "fmi2EnterEventMode", ST_CONTINUOUS)) return fmi2Error;
    c->state = ST_EVENT;
    return fmi2OK;
}

fmi2Status fmi2NewDiscreteStates(fmi2Component comp, fmi2EventInfo *info)
{
    vm_instance *c = comp;
    if (!me_call(c, "fmi2NewDiscreteStates", ST_EVENT)) return fmi2Error;
    if (!info) return fail(c, "fmi2NewDiscreteStates", "NULL fmi2EventInfo");
    info->newDiscreteStatesNeeded = fmi2False;
    info->terminateSimulation = fmi2False;
    info->nominalsOfContinuousStatesChanged = fmi2False;
    info->valuesOfContinuousStatesChanged = fmi2False;
    info->nextEventTimeDefined = fmi2False;
    info->nextEventTime = 0.0;
    return fmi2OK;
}

fmi2Status fmi2EnterContinuousTimeMode(fmi2Component comp)
{
    vm_instance *c = comp;
    if (!me_call(c, "fmi2EnterContinuousTimeMode", ST_EVENT)) return fmi2Error;
    c->state = ST_CONTINUOUS;
    return fmi2OK;
}

fmi2Status fmi2CompletedIntegratorStep(fmi2Component comp, fmi2Boolean no_prior_state,
                                       fmi2Boolean *enter_event_mode,
                                       fmi2Boolean *terminate_simulation)
{
    vm_instance *c = comp;
    (void)no_prior_state;
    if (!me_call(c, "fmi2CompletedIntegratorStep", ST_CONTINUOUS)) return fmi2Error;
    if (!enter_event_mode || !terminate_simulation)
        return fail(c, "fmi2CompletedIntegratorStep", "NULL result pointer");
    *enter_event_mode = *terminate_simulation = fmi2False;
    return fmi2OK;
}

fmi2Status fmi2SetTime(fmi2Component comp, fmi2Real t)
{
    vm_instance *c = comp;
    if (!me_call(c, "fmi2SetTime", ST_EVENT | ST_CONTINUOUS)) return fmi2Error;
    if (!isfinite(t)) {
        logf_(c, fmi2Error, CAT_ERROR, "fmi2SetTime: time = %g is not finite", t);
        return fmi2Error;
    }
    c->model.time = t;
    return fmi2OK;
}

fmi2Status fmi2SetContinuousStates(fmi2Component comp, const fmi2Real x[], size_t nx)
{
    vm_instance *c = comp;
    size_t k;
    if (!me_call(c, "fmi2SetContinuousStates", ST_CONTINUOUS) ||
        !array_ok(c, "fmi2SetContinuousStates", x, nx, VM_NUM_STATES))
        return fmi2Error;
    for (k = 0; k < nx; k++)
        if (!isfinite(x[k])) {
            logf_(c, fmi2Error, CAT_ERROR, "fmi2SetContinuousStates: state %lu = %g is not "
                  "finite", (unsigned long)k, x[k]);
            return fmi2Error;
        }
    for (k = 0; k < nx; k++) c->model.s[k] = x[k];
    return fmi2OK;
}

fmi2Status fmi2GetContinuousStates(fmi2Component comp, fmi2Real x[], size_t nx)
{
    vm_instance *c = comp;
    size_t k;
    if (!me_call(c, "fmi2GetContinuousStates", READABLE) ||
        !array_ok(c, "fmi2GetContinuousStates", x, nx, VM_NUM_STATES))
        return fmi2Error;
    for (k = 0; k < nx; k++) x[k] = c->model.s[k];
    return fmi2OK;
}

fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component comp, fmi2Real x_nominal[], size_t nx)
{
    vm_instance *c = comp;
    size_t k;
    if (!me_call(c, "fmi2GetNominalsOfContinuousStates", ST_INSTANTIATED | READABLE) ||
        !array_ok(c, "fmi2GetNominalsOfContinuousStates", x_nominal, nx, VM_NUM_STATES))
        return fmi2Error;
    for (k = 0; k < nx; k++) x_nominal[k] = 1.0;
    return fmi2OK;
}

fmi2Status fmi2GetDerivatives(fmi2Component comp, fmi2Real dx[], size_t nx)
{
    vm_instance *c = comp;
    size_t k;
    if (!me_call(c, "fmi2GetDerivatives", READABLE) ||
        !array_ok(c, "fmi2GetDerivatives", dx, nx, VM_NUM_STATES))
        return fmi2Error;
    vm_derivatives(&c->model, dx);
    for (k = 0; k < nx; k++)
        if (!isfinite(dx[k])) return fail(c, "fmi2GetDerivatives", "a derivative is not finite");
    return fmi2OK;
}

fmi2Status fmi2GetEventIndicators(fmi2Component comp, fmi2Real z[], size_t nz)
{
    vm_instance *c = comp;
    (void)z;
    if (!me_call(c, "fmi2GetEventIndicators", READABLE)) return fmi2Error;
    if (nz == 0) return fmi2OK;
    logf_(c, fmi2Error, CAT_ERROR, "fmi2GetEventIndicators: %lu asked for, this FMU has none",
          (unsigned long)nz);
    return fmi2Error;
}
