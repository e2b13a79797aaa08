/* FMI 2.0 stepping: input derivatives, fmi2DoStep (step.c), the status queries and the
 * derivative functions this FMU does not provide. */
#include <math.h>
#include <string.h>

#include "fmi/instance.h"
#include "fmi2Functions.h"

fmi2Status fmi2SetRealInputDerivatives(fmi2Component comp, const fmi2ValueReference vr[],
                                       size_t nvr, const fmi2Integer order[],
                                       const fmi2Real value[])
{
    hg_instance *c = comp;
    size_t i;
    if (!hg_interface(c, __func__, 0) ||
        !hg_allowed(c, __func__, ST_BEFORE_RUN | ST_STEP_COMPLETE) ||
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
    if (!hg_interface(c, __func__, 0) || !hg_allowed(c, __func__, ST_READABLE)) return fmi2Error;
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

fmi2Status fmi2DoStep(fmi2Component comp, fmi2Real t, fmi2Real h, fmi2Boolean no_prior)
{
    (void)no_prior;
    return (fmi2Status)hg_do_step(comp, __func__, t, h);
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
    if (!hg_allowed(c, fn, ST_STATUS) || !hg_interface(c, fn, 0)) return 0;
    if (value) return 1;
    hg_error(c, fn, "the value pointer is NULL");
    return 0;
}

/* A status kind this FMU does not provide. */
static fmi2Status no_status(hg_instance *c, const char *fn)
{
    return hg_allowed(c, fn, ST_STATUS) && hg_interface(c, fn, 0) ? fmi2Discard : fmi2Error;
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
