/* Model Exchange of either FMI version between the host's integrator and the model's ODE face
 * (model/exchange.h). The host sets the time, the continuous states and the inputs, reads the
 * derivatives and the event indicators, and updates the discrete states in event mode
 * (fmi2NewDiscreteStates, fmi3UpdateDiscreteStates), where the model switches its contact mode,
 * closes an averaging window, wraps the pinion angle or keys its friction tables anew. Arrays are
 * checked against the model's sizes (HG_NUM_STATES, HG_NUM_EVENT_INDICATORS of variables.toml).
 * The adapters are fmi2_me.c and fmi3_me.c. */
#include <math.h>

#include "fmi/instance.h"
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

hg_status hg_me_enter_event_mode(hg_instance *c, const char *fn)
{
    if (!me_call(c, fn, ST_CONTINUOUS_TIME)) return HG_ERROR;
    c->state = ST_EVENT_MODE;
    return HG_OK;
}

hg_status hg_me_update(hg_instance *c, const char *fn, int *states_changed)
{
    *states_changed = 0;
    if (!me_call(c, fn, ST_EVENT_MODE)) return HG_ERROR;
    hg_exchange_event(c->model, states_changed); /* one pass settles every event */
    return HG_OK;
}

hg_status hg_me_enter_continuous_time(hg_instance *c, const char *fn)
{
    if (!me_call(c, fn, ST_EVENT_MODE)) return HG_ERROR;
    c->state = ST_CONTINUOUS_TIME;
    return HG_OK;
}

hg_status hg_me_completed_step(hg_instance *c, const char *fn, int *enter_event_mode)
{
    if (!me_call(c, fn, ST_CONTINUOUS_TIME)) return HG_ERROR;
    *enter_event_mode = hg_exchange_step_done(c->model);
    return HG_OK;
}

/* ------------------------------------------------------------------ time and states */

hg_status hg_me_set_time(hg_instance *c, const char *fn, double t)
{
    if (!me_call(c, fn, ST_EVENT_MODE | ST_CONTINUOUS_TIME)) return HG_ERROR;
    if (!isfinite(t) || t < c->start_time) {
        hg_error(c, fn, "time = %.17g s is not finite or before the start time %.17g s",
                 t, c->start_time);
        return HG_ERROR;
    }
    hg_exchange_set_time(c->model, t);
    return HG_OK;
}

hg_status hg_me_set_states(hg_instance *c, const char *fn, const double x[], size_t nx)
{
    size_t k;
    if (!me_array_call(c, fn, ST_CONTINUOUS_TIME, "continuous states", x, nx, HG_NUM_STATES)) return HG_ERROR;
    for (k = 0; k < nx; k++)
        if (!isfinite(x[k])) {
            hg_error(c, fn, "state %zu, %s = %g, is not a finite number", k,
                     hg_var_table[hg_state_vr[k]].name, x[k]);
            return HG_ERROR;
        }
    hg_exchange_set_states(c->model, x);
    return HG_OK;
}

hg_status hg_me_states(hg_instance *c, const char *fn, double x[], size_t nx)
{
    if (!me_array_call(c, fn, ST_READABLE, "continuous states", x, nx, HG_NUM_STATES)) return HG_ERROR;
    hg_exchange_states(c->model, x);
    return HG_OK;
}

hg_status hg_me_nominals(hg_instance *c, const char *fn, double x_nominal[], size_t nx)
{
    if (!me_array_call(c, fn, ST_INSTANTIATED | ST_READABLE,
                       "nominals of continuous states", x_nominal, nx, HG_NUM_STATES))
        return HG_ERROR;
    hg_exchange_nominals(c->model, x_nominal);
    return HG_OK;
}

hg_status hg_me_derivatives(hg_instance *c, const char *fn, double dx[], size_t nx)
{
    char inputs[HG_ERRLEN / 2];
    int bad;
    if (!me_array_call(c, fn, ST_READABLE, "derivatives", dx, nx, HG_NUM_STATES)) return HG_ERROR;
    if ((bad = hg_exchange_derivatives(c->model, dx)) < 0) return HG_OK;
    hg_describe_inputs(c, inputs, sizeof inputs);
    hg_error(c, fn, "%s = %g at t = %.9g s: the state and the inputs (%s) are beyond the "
             "model's reach", hg_var_table[hg_derivative_vr[bad]].name, dx[bad],
             hg_instance_time(c), inputs);
    c->state = ST_ERROR;
    return HG_ERROR;
}

hg_status hg_me_indicators(hg_instance *c, const char *fn, double z[], size_t nz)
{
    if (!me_array_call(c, fn, ST_READABLE, "event indicators", z, nz, HG_NUM_EVENT_INDICATORS)) return HG_ERROR;
    hg_exchange_indicators(c->model, z);
    return HG_OK;
}
