/* FMI 2.0 Model Exchange: fmi2EnterEventMode, fmi2NewDiscreteStates, fmi2EnterContinuousTimeMode,
 * fmi2CompletedIntegratorStep, time, continuous states, nominals, derivatives and event
 * indicators (adapters over me.c). */
#include "fmi/instance.h"
#include "fmi2Functions.h"

fmi2Status fmi2EnterEventMode(fmi2Component comp)
{
    return (fmi2Status)hg_me_enter_event_mode(comp, __func__);
}

fmi2Status fmi2NewDiscreteStates(fmi2Component comp, fmi2EventInfo *info)
{
    int changed;
    if (comp && !info) {
        hg_error(comp, __func__, "the fmi2EventInfo pointer is NULL");
        return fmi2Error;
    }
    if (hg_me_update(comp, __func__, &changed) != HG_OK) return fmi2Error;
    info->newDiscreteStatesNeeded = fmi2False;
    info->terminateSimulation = fmi2False;
    info->nominalsOfContinuousStatesChanged = fmi2False;
    info->valuesOfContinuousStatesChanged = changed ? fmi2True : fmi2False;
    info->nextEventTimeDefined = fmi2False;
    info->nextEventTime = 0.0;
    return fmi2OK;
}

fmi2Status fmi2EnterContinuousTimeMode(fmi2Component comp)
{
    return (fmi2Status)hg_me_enter_continuous_time(comp, __func__);
}

fmi2Status fmi2CompletedIntegratorStep(fmi2Component comp, fmi2Boolean no_prior_state,
                                       fmi2Boolean *enter_event_mode,
                                       fmi2Boolean *terminate_simulation)
{
    int event;
    (void)no_prior_state;
    if (comp && (!enter_event_mode || !terminate_simulation)) {
        hg_error(comp, __func__, "enterEventMode or terminateSimulation is a NULL pointer");
        return fmi2Error;
    }
    if (hg_me_completed_step(comp, __func__, &event) != HG_OK) return fmi2Error;
    *enter_event_mode = event ? fmi2True : fmi2False;
    *terminate_simulation = fmi2False;
    return fmi2OK;
}

fmi2Status fmi2SetTime(fmi2Component comp, fmi2Real t)
{
    return (fmi2Status)hg_me_set_time(comp, __func__, t);
}

fmi2Status fmi2SetContinuousStates(fmi2Component comp, const fmi2Real x[], size_t nx)
{
    return (fmi2Status)hg_me_set_states(comp, __func__, x, nx);
}

fmi2Status fmi2GetContinuousStates(fmi2Component comp, fmi2Real x[], size_t nx)
{
    return (fmi2Status)hg_me_states(comp, __func__, x, nx);
}

fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component comp, fmi2Real x_nominal[], size_t nx)
{
    return (fmi2Status)hg_me_nominals(comp, __func__, x_nominal, nx);
}

fmi2Status fmi2GetDerivatives(fmi2Component comp, fmi2Real dx[], size_t nx)
{
    return (fmi2Status)hg_me_derivatives(comp, __func__, dx, nx);
}

fmi2Status fmi2GetEventIndicators(fmi2Component comp, fmi2Real z[], size_t nz)
{
    return (fmi2Status)hg_me_indicators(comp, __func__, z, nz);
}
