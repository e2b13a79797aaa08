/* FMI 3.0 co-simulation stepping: fmi3DoStep (step.c), and output derivatives, which this FMU
 * does not provide. */
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

fmi3Status fmi3GetOutputDerivatives(fmi3Instance instance, const fmi3ValueReference vr[],
                                    size_t nvr, const fmi3Int32 orders[], fmi3Float64 values[],
                                    size_t n_values)
{
    hg_instance *c = instance;
    (void)vr;
    (void)nvr;
    (void)orders;
    (void)values;
    (void)n_values;
    if (!hg_allowed(c, __func__, ST_READABLE) || !hg_interface(c, __func__, 0)) return fmi3Error;
    hg_error(c, __func__, "not provided (maxOutputDerivativeOrder = 0)");
    return fmi3Error;
}
