/* FMI 2.0 stepping: input derivatives, fmi2DoStep with its checks, the status queries and the
 * derivative functions this FMU does not provide. */
#include <math.h>
#include <string.h>

#include "fmi/instance.h"

#define MAX_COMM_STEP 1000.0 /* [s] longest communication step (docs/integration.md, limits) */
#define TIME_RESOLUTION 1e-6 /* largest relative rounding error of t + h accepted by fmi2DoStep */

fmi2Status fmi2SetRealInputDerivatives(fmi2Component comp, const fmi2ValueReference vr[],
                                       size_t nvr, const fmi2Integer order[],
                                       const fmi2Real value[])
{
    hg_instance *c = comp;
    size_t i;
    if (!hg_allowed(c, __func__, ST_BEFORE_RUN | ST_STEP_COMPLETE) ||
        hg_check_array_args(c, __func__, vr, nvr, value) ||
        hg_check_array_args(c, __func__, vr, nvr, order))
        return fmi2Error;
    for (i = 0; i < nvr; i++) {
        const hg_var_info *info = hg_lookup(c, __func__, vr[i], HG_REAL);
        if (!info) return fmi2Error;
        if (info->input < 0 || order[i] != 1 || !isfinite(value[i])) {
            hg_error(c, __func__, "%s, order %d, value %g: only finite first derivatives of "
                     "inputs are accepted", info->name, (int)order[i], value[i]);
            return fmi2Error;
        }
        *hg_input(&c->input_der, info->input) = value[i];
    }
    return fmi2OK;
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component comp, const fmi2ValueReference vr[],
                                        size_t nvr, const fmi2Integer order[], fmi2Real value[])
{
    hg_instance *c = comp;
    (void)vr;
    (void)nvr;
    (void)order;
    (void)value;
    if (!hg_allowed(c, __func__, ST_READABLE)) return fmi2Error;
    hg_error(c, __func__, "not provided (maxOutputDerivativeOrder = 0)");
    return fmi2Error;
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component comp, const fmi2ValueReference u[],
                                        size_t nu, const fmi2ValueReference z[], size_t nz,
                                        const fmi2Real dv[], fmi2Real dz[])
{
    hg_instance *c = comp;
    (void)u;
    (void)nu;
    (void)z;
    (void)nz;
    (void)dv;
    (void)dz;
    if (!hg_allowed(c, __func__, ST_READABLE)) return fmi2Error;
    hg_error(c, __func__, "not provided");
    return fmi2Error;
}

/* ------------------------------------------------------------------ fmi2DoStep */

/* Inputs extrapolated with their derivatives must stay finite and in range over the step. */
static int check_extrapolation(hg_instance *c, const char *fn, double h)
{
    int k;
    for (k = 0; k < HG_NUM_INPUTS; k++) {
        const hg_var_info *info = &hg_var_table[hg_input_vr[k]];
        double u = hg_real_value(c, info), du = hg_derivative_of(c, info), end = u + du * h;
        char value[96], range[96];
        if (du == 0.0 || (isfinite(end) && !(info->has_min && end < info->min) &&
                          !(info->has_max && end > info->max)))
            continue;
        hg_quote_value(value, sizeof value, info, end);
        hg_quote_range(range, sizeof range, info);
        hg_error(c, fn, "input %s = %g %s with derivative %g %s/s would reach %s over the step "
                 "of %g s, outside its range %s", info->name, u, info->unit, du, info->unit,
                 value, h, range);
        return -1;
    }
    return 0;
}

/* Checks fmi2DoStep's arguments against the FMU time, the stop time and the time resolution. */
static int check_step(hg_instance *c, const char *fn, double t, double h)
{
    double now = hg_instance_time(c);
    if (!isfinite(h) || h < 0.0 || !isfinite(t) || fabs(t - now) > 1e-9 * (1.0 + fabs(now))) {
        hg_error(c, fn, "communication point %.12g with step %g does not continue the FMU time "
                 "%.12g (or is not finite / negative)", t, h, now);
        return -1;
    }
    if (h > MAX_COMM_STEP) {
        hg_error(c, fn, "communicationStepSize = %g s is longer than the limit of %g s", h,
                 MAX_COMM_STEP);
        return -1;
    }
    if (h > 0.0 && fabs((now + h) - now - h) > TIME_RESOLUTION * h) {
        hg_error(c, fn, "communicationStepSize = %g s is below the resolution of the time t = "
                 "%.17g s (t + h rounds off more than %g of it)", h, now, TIME_RESOLUTION);
        return -1;
    }
    if (check_extrapolation(c, fn, h)) return -1;
    if (c->stop_defined && now + h > c->stop_time + 1e-9 * (1.0 + fabs(c->stop_time))) {
        hg_error(c, fn, "the step from t = %.12g s by %g s passes the stopTime %.12g s given to "
                 "fmi2SetupExperiment", now, h, c->stop_time);
        return -1;
    }
    return 0;
}

/* A failed step: the instance goes to the error state; the model stays where the step began,
 * so the last good outputs stay readable. */
static fmi2Status step_failed(hg_instance *c, const char *fn, const char *why)
{
    char inputs[HG_ERRLEN / 2];
    hg_describe_inputs(c, inputs, sizeof inputs);
    hg_error(c, fn, "%s (inputs %s)", why, inputs);
    c->state = ST_ERROR;
    return fmi2Error;
}

/* The outputs are computed when read (hg_instance_outputs), not after every step. */
fmi2Status fmi2DoStep(fmi2Component comp, fmi2Real t, fmi2Real h, fmi2Boolean no_prior)
{
    hg_instance *c = comp;
    char err[HG_ERRLEN];
    (void)no_prior;
    if (!hg_allowed(c, __func__, ST_STEP_COMPLETE)) return fmi2Error;
    if (!c->set_up || !c->model) return hg_fail(c, __func__, "the model is not set up");
    if (check_step(c, __func__, t, h)) return fmi2Error;
    hg_log(c, fmi2OK, CAT_ALL, "%s: t = %.9g s, h = %g s", __func__, t, h);
    if (h > 0.0 && hg_model_step(c->model, &c->vars, &c->input_der, h, err, sizeof err))
        return step_failed(c, __func__, err);
    memset(&c->input_der, 0, sizeof c->input_der); /* derivatives apply to one step */
    return fmi2OK;
}

fmi2Status fmi2CancelStep(fmi2Component comp)
{
    hg_instance *c = comp;
    if (!hg_allowed(c, __func__, ST_STEP_COMPLETE)) return fmi2Error;
    hg_error(c, __func__, "steps are synchronous, nothing to cancel");
    return fmi2Error;
}

/* ------------------------------------------------------------------ status */

/* A status query is allowed after initialization; its value pointer must not be NULL. */
static int status_query(hg_instance *c, const char *fn, const void *value)
{
    if (!hg_allowed(c, fn, ST_STATUS)) return 0;
    if (value) return 1;
    hg_error(c, fn, "the value pointer is NULL");
    return 0;
}

/* A status kind this FMU does not provide. */
static fmi2Status no_status(hg_instance *c, const char *fn)
{
    return hg_allowed(c, fn, ST_STATUS) ? fmi2Discard : fmi2Error;
}

fmi2Status fmi2GetStatus(fmi2Component comp, const fmi2StatusKind s, fmi2Status *value)
{
    hg_instance *c = comp;
    if (!status_query(c, __func__, value)) return fmi2Error;
    if (s != fmi2DoStepStatus) return fmi2Discard;
    *value = c->state == ST_ERROR ? fmi2Error : fmi2OK;
    return fmi2OK;
}

fmi2Status fmi2GetRealStatus(fmi2Component comp, const fmi2StatusKind s, fmi2Real *value)
{
    hg_instance *c = comp;
    if (!status_query(c, __func__, value)) return fmi2Error;
    if (s != fmi2LastSuccessfulTime) return fmi2Discard;
    *value = hg_instance_time(c);
    return fmi2OK;
}

fmi2Status fmi2GetIntegerStatus(fmi2Component comp, const fmi2StatusKind s, fmi2Integer *value)
{
    (void)s;
    (void)value;
    return no_status(comp, __func__);
}

fmi2Status fmi2GetBooleanStatus(fmi2Component comp, const fmi2StatusKind s, fmi2Boolean *value)
{
    hg_instance *c = comp;
    if (!status_query(c, __func__, value)) return fmi2Error;
    if (s != fmi2Terminated) return fmi2Discard;
    *value = fmi2False; /* the model never asks to end the simulation */
    return fmi2OK;
}

fmi2Status fmi2GetStringStatus(fmi2Component comp, const fmi2StatusKind s, fmi2String *value)
{
    (void)s;
    (void)value;
    return no_status(comp, __func__);
}
