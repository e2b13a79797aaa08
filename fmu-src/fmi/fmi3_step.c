/* FMI 3.0 co-simulation stepping: fmi3DoStep (step.c) and the output derivatives. */
#include "fmi/instance.h"
#include "fmi3Functions.h"

fmi3Status fmi3DoStep(fmi3Instance instance, fmi3Float64 t, fmi3Float64 h,
                      fmi3Boolean no_prior, fmi3Boolean *event_handling_needed,
                      fmi3Boolean *terminate_simulation, fmi3Boolean *early_return,
                      fmi3Float64 *last_successful_time)
{
    hg_instance *c = instance;
    hg_status status;
    (void)no_prior;
    if (!hg_interface(c, __func__, 0) || !hg_allowed(c, __func__, ST_STEP_COMPLETE))
        return fmi3Error;
    if (!event_handling_needed || !terminate_simulation || !early_return ||
        !last_successful_time) {
        hg_error(c, __func__, "NULL eventHandlingNeeded, terminateSimulation, earlyReturn or "
                 "lastSuccessfulTime");
        return fmi3Error;
    }
    status = hg_do_step(c, __func__, t, h);
    *event_handling_needed = fmi3False;
    *terminate_simulation = fmi3False;
    *early_return = fmi3False;
    *last_successful_time = hg_instance_time(c);
    return (fmi3Status)status;
}

/* The value reference of der(vr) when output vr gives a continuous state (hg_state_output_vr),
 * else -1 (after logging). */
static long derivative_of(hg_instance *c, const char *fn, fmi3ValueReference vr, fmi3Int32 order)
{
    int k;
    for (k = 0; k < HG_NUM_STATES && vr < HG_NUM_VARS; k++)
        if (hg_state_output_vr[k] == vr) break;
    if (vr >= HG_NUM_VARS || k == HG_NUM_STATES) {
        hg_error(c, fn, "value reference %u%s%s%s is not an output with a derivative (those "
                 "that are continuous states: the speeds, DTE, the energies)", (unsigned)vr,
                 vr < HG_NUM_VARS ? " ('" : "", vr < HG_NUM_VARS ? hg_var_table[vr].name : "",
                 vr < HG_NUM_VARS ? "')" : "");
        return -1;
    }
    if (order != 1) {
        hg_error(c, fn, "%s: order %d asked for, only the first derivative is provided "
                 "(maxOutputDerivativeOrder = 1)", hg_var_table[vr].name, (int)order);
        return -1;
    }
    return (long)hg_derivative_vr[k];
}

/* The first derivatives of the outputs that are continuous states: their der(x), the model's
 * right-hand side at the end of the step (what a host extrapolating w_s or w_w needs). */
fmi3Status fmi3GetOutputDerivatives(fmi3Instance instance, const fmi3ValueReference vr[],
                                    size_t nvr, const fmi3Int32 orders[], fmi3Float64 values[],
                                    size_t n_values)
{
    hg_instance *c = instance;
    size_t i;
    long der;
    if (!hg_interface(c, __func__, 0) ||
        hg_prepare_get(c, __func__, vr, nvr, values) != HG_OK ||
        hg_check_array_args(c, __func__, vr, nvr, orders))
        return fmi3Error;
    if (n_values != nvr) {
        hg_error(c, __func__, "nValues = %zu, but the %zu value references name %zu values",
                 n_values, nvr, nvr);
        return fmi3Error;
    }
    for (i = 0; i < nvr; i++)
        if ((der = derivative_of(c, __func__, vr[i], orders[i])) < 0 ||
            hg_get_value(c, __func__, HG_REAL, (hg_vr)der, &values[i]) != HG_OK)
            return fmi3Error;
    return fmi3OK;
}
