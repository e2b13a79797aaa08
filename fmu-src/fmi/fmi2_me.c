/* FMI 2.0 Model Exchange: a thin adapter between the host's integrator and the model's ODE face
 * (model/exchange.h). The host sets the time, the continuous states and the inputs, reads the
 * derivatives and the event indicators, and calls fmi2NewDiscreteStates in event mode, where the
 * model switches its contact mode, closes an averaging window, wraps the pinion angle or keys its
 * friction tables anew. Arrays are checked against the model's sizes (HG_NUM_STATES,
 * HG_NUM_EVENT_INDICATORS of variables.toml). */
#include <math.h>

#include "fmi/instance.h"
#include "fmi2Functions.h"
#include "model/exchange.h"

/* A Model Exchange call allowed in states; in initialization the model is set up first. */
static int me_call(hg_instance *c, const char *fn, int states)
{
    if (!hg_allowed(c, fn, states) || !hg_interface(c, fn, 1)) return 0;
    if ((c->state & ST_BEFORE_RUN) && hg_ensure_set_up(c, fn) != HG_OK) return 0;
    if (c->set_up && c->model) return 1;
    hg_error(c, fn, "the model is not set up (its initialization failed)");
    return 0;
}

/* A Model Exchange call with an array of the model's size n_model: allowed in states, the
 * array not NULL and n as long. */
static int me_array_call(hg_instance *c, const char *fn, int states, const char *what,
                         const void *a, size_t n, size_t n_model)
{
    if (!me_call(c, fn, states)) return 0;
    if (!a) {
        hg_error(c, fn, "the array of %s is NULL", what);
        return 0;
    }
    if (n == n_model) return 1;
    hg_error(c, fn, "%zu %s asked for, this FMU has %zu", n, what, n_model);
    return 0;
}

/* ------------------------------------------------------------------ modes */

fmi2Status fmi2EnterEventMode(fmi2Component comp)
{
    hg_instance *c = comp;
    if (!me_call(c, __func__, ST_CONTINUOUS_TIME)) return fmi2Error;
    c->state = ST_EVENT_MODE;
    return fmi2OK;
}

fmi2Status fmi2NewDiscreteStates(fmi2Component comp, fmi2EventInfo *info)
{
    hg_instance *c = comp;
    int changed = 0;
    if (!me_call(c, __func__, ST_EVENT_MODE)) return fmi2Error;
    if (!info) {
        hg_error(c, __func__, "the fmi2EventInfo pointer is NULL");
        return fmi2Error;
    }
    hg_exchange_event(c->model, &changed);
    info->newDiscreteStatesNeeded = fmi2False; /* one pass settles every event */
    info->terminateSimulation = fmi2False;
    info->nominalsOfContinuousStatesChanged = fmi2False;
    info->valuesOfContinuousStatesChanged = changed ? fmi2True : fmi2False;
    info->nextEventTimeDefined = fmi2False;
    info->nextEventTime = 0.0;
    return fmi2OK;
}

fmi2Status fmi2EnterContinuousTimeMode(fmi2Component comp)
{
    hg_instance *c = comp;
    if (!me_call(c, __func__, ST_EVENT_MODE)) return fmi2Error;
    c->state = ST_CONTINUOUS_TIME;
    return fmi2OK;
}

fmi2Status fmi2CompletedIntegratorStep(fmi2Component comp, fmi2Boolean no_prior_state,
                                       fmi2Boolean *enter_event_mode,
                                       fmi2Boolean *terminate_simulation)
{
    hg_instance *c = comp;
    (void)no_prior_state;
    if (!me_call(c, __func__, ST_CONTINUOUS_TIME)) return fmi2Error;
    if (!enter_event_mode || !terminate_simulation) {
        hg_error(c, __func__, "enterEventMode or terminateSimulation is a NULL pointer");
        return fmi2Error;
    }
    *enter_event_mode = hg_exchange_step_done(c->model) ? fmi2True : fmi2False;
    *terminate_simulation = fmi2False;
    return fmi2OK;
}

/* ------------------------------------------------------------------ time and states */

fmi2Status fmi2SetTime(fmi2Component comp, fmi2Real t)
{
    hg_instance *c = comp;
    if (!me_call(c, __func__, ST_EVENT_MODE | ST_CONTINUOUS_TIME)) return fmi2Error;
    if (!isfinite(t) || t < c->start_time) {
        hg_error(c, __func__, "time = %.17g s is not finite or before the start time %.17g s",
                 t, c->start_time);
        return fmi2Error;
    }
    hg_exchange_set_time(c->model, t);
    return fmi2OK;
}

fmi2Status fmi2SetContinuousStates(fmi2Component comp, const fmi2Real x[], size_t nx)
{
    hg_instance *c = comp;
    size_t k;
    if (!me_array_call(c, __func__, ST_CONTINUOUS_TIME, "continuous states", x, nx, HG_NUM_STATES)) return fmi2Error;
    for (k = 0; k < nx; k++)
        if (!isfinite(x[k])) {
            hg_error(c, __func__, "state %zu, %s = %g, is not a finite number", k,
                     hg_var_table[hg_state_vr[k]].name, x[k]);
            return fmi2Error;
        }
    hg_exchange_set_states(c->model, x);
    return fmi2OK;
}

fmi2Status fmi2GetContinuousStates(fmi2Component comp, fmi2Real x[], size_t nx)
{
    hg_instance *c = comp;
    if (!me_array_call(c, __func__, ST_READABLE, "continuous states", x, nx, HG_NUM_STATES)) return fmi2Error;
    hg_exchange_states(c->model, x);
    return fmi2OK;
}

fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component comp, fmi2Real x_nominal[], size_t nx)
{
    hg_instance *c = comp;
    if (!me_array_call(c, __func__, ST_INSTANTIATED | ST_READABLE,
                       "nominals of continuous states", x_nominal, nx, HG_NUM_STATES))
        return fmi2Error;
    hg_exchange_nominals(c->model, x_nominal);
    return fmi2OK;
}

fmi2Status fmi2GetDerivatives(fmi2Component comp, fmi2Real dx[], size_t nx)
{
    hg_instance *c = comp;
    char inputs[HG_ERRLEN / 2];
    int bad;
    if (!me_array_call(c, __func__, ST_READABLE, "derivatives", dx, nx, HG_NUM_STATES)) return fmi2Error;
    if ((bad = hg_exchange_derivatives(c->model, dx)) < 0) return fmi2OK;
    hg_describe_inputs(c, inputs, sizeof inputs);
    hg_error(c, __func__, "%s = %g at t = %.9g s: the state and the inputs (%s) are beyond the "
             "model's reach", hg_var_table[hg_derivative_vr[bad]].name, dx[bad],
             hg_instance_time(c), inputs);
    c->state = ST_ERROR;
    return fmi2Error;
}

fmi2Status fmi2GetEventIndicators(fmi2Component comp, fmi2Real z[], size_t nz)
{
    hg_instance *c = comp;
    if (!me_array_call(c, __func__, ST_READABLE, "event indicators", z, nz, HG_NUM_EVENT_INDICATORS)) return fmi2Error;
    hg_exchange_indicators(c->model, z);
    return fmi2OK;
}
