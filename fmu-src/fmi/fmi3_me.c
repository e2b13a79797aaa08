/* FMI 3.0 Model Exchange: event and continuous-time modes, fmi3UpdateDiscreteStates,
 * fmi3CompletedIntegratorStep, time, continuous states, nominals, derivatives, event indicators
 * and their numbers (adapters over me.c; instantiation in fmi3_lifecycle.c). */
#include "fmi/instance.h"
#include "fmi3Functions.h"

fmi3Status fmi3EnterEventMode(fmi3Instance instance)
{
    return (fmi3Status)hg_me_enter_event_mode(instance, __func__);
}

fmi3Status fmi3UpdateDiscreteStates(fmi3Instance instance, fmi3Boolean *need_update,
                                    fmi3Boolean *terminate, fmi3Boolean *nominals_changed,
                                    fmi3Boolean *values_changed, fmi3Boolean *next_time_defined,
                                    fmi3Float64 *next_time)
{
    int changed;
    if (instance && (!need_update || !terminate || !nominals_changed || !values_changed ||
                     !next_time_defined || !next_time)) {
        hg_error(instance, __func__, "NULL discreteStatesNeedUpdate, terminateSimulation, "
                 "nominalsOfContinuousStatesChanged, valuesOfContinuousStatesChanged, "
                 "nextEventTimeDefined or nextEventTime");
        return fmi3Error;
    }
    if (hg_me_update(instance, __func__, &changed) != HG_OK) return fmi3Error;
    *need_update = fmi3False; /* one pass settles every event */
    *terminate = fmi3False;
    *nominals_changed = fmi3False;
    *values_changed = changed ? fmi3True : fmi3False;
    *next_time_defined = fmi3False; /* no time events */
    *next_time = 0.0;
    return fmi3OK;
}

fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance instance)
{
    return (fmi3Status)hg_me_enter_continuous_time(instance, __func__);
}

fmi3Status fmi3CompletedIntegratorStep(fmi3Instance instance, fmi3Boolean no_prior,
                                       fmi3Boolean *enter_event_mode, fmi3Boolean *terminate)
{
    int event;
    (void)no_prior;
    if (instance && (!enter_event_mode || !terminate)) {
        hg_error(instance, __func__, "enterEventMode or terminateSimulation is a NULL pointer");
        return fmi3Error;
    }
    if (hg_me_completed_step(instance, __func__, &event) != HG_OK) return fmi3Error;
    *enter_event_mode = event ? fmi3True : fmi3False;
    *terminate = fmi3False;
    return fmi3OK;
}

fmi3Status fmi3SetTime(fmi3Instance instance, fmi3Float64 time)
{
    return (fmi3Status)hg_me_set_time(instance, __func__, time);
}

fmi3Status fmi3SetContinuousStates(fmi3Instance instance, const fmi3Float64 x[], size_t nx)
{
    return (fmi3Status)hg_me_set_states(instance, __func__, x, nx);
}

fmi3Status fmi3GetContinuousStates(fmi3Instance instance, fmi3Float64 x[], size_t nx)
{
    return (fmi3Status)hg_me_states(instance, __func__, x, nx);
}

fmi3Status fmi3GetNominalsOfContinuousStates(fmi3Instance instance, fmi3Float64 nominal[],
                                             size_t nx)
{
    return (fmi3Status)hg_me_nominals(instance, __func__, nominal, nx);
}

fmi3Status fmi3GetContinuousStateDerivatives(fmi3Instance instance, fmi3Float64 dx[], size_t nx)
{
    return (fmi3Status)hg_me_derivatives(instance, __func__, dx, nx);
}

fmi3Status fmi3GetEventIndicators(fmi3Instance instance, fmi3Float64 z[], size_t nz)
{
    return (fmi3Status)hg_me_indicators(instance, __func__, z, nz);
}

/* The model's sizes, known from instantiation on. */
static fmi3Status number(fmi3Instance instance, const char *fn, size_t *n, size_t value)
{
    if (!hg_allowed(instance, fn, ST_ANY)) return fmi3Error;
    if (!n) {
        hg_error(instance, fn, "the pointer for the number is NULL");
        return fmi3Error;
    }
    *n = value;
    return fmi3OK;
}

fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance instance, size_t *n)
{
    return number(instance, __func__, n, HG_NUM_EVENT_INDICATORS);
}

fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance instance, size_t *n)
{
    return number(instance, __func__, n, HG_NUM_STATES);
}
