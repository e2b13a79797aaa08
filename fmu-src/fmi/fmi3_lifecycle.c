/* FMI 3.0 instance life cycle: co-simulation and Model Exchange instantiation, logging categories,
 * initialization (with the experiment's times), termination, reset and freeing (adapters over
 * lifecycle.c). */
#include "fmi/instance.h"
#include "fmi3Functions.h"

const char *fmi3GetVersion(void) { return fmi3Version; }

static void emit(const hg_instance *c, hg_status status, const char *category, const char *msg)
{
    ((fmi3LogMessageCallback)c->logger)(c->env, (fmi3Status)status, category, msg);
}

fmi3Status fmi3SetDebugLogging(fmi3Instance instance, fmi3Boolean on, size_t n,
                               const fmi3String cats[])
{
    return (fmi3Status)hg_set_debug_logging(instance, __func__, on, n, cats);
}

/* Event mode, early return and intermediate update are not provided (hasEventMode,
 * mightReturnEarlyFromDoStep and providesIntermediateUpdate are false): the host's wishes for
 * them change nothing. */
fmi3Instance fmi3InstantiateCoSimulation(fmi3String name, fmi3String token,
                                         fmi3String resource_path, fmi3Boolean visible,
                                         fmi3Boolean logging_on, fmi3Boolean event_mode_used,
                                         fmi3Boolean early_return_allowed,
                                         const fmi3ValueReference required_intermediate[],
                                         size_t n_required_intermediate,
                                         fmi3InstanceEnvironment env,
                                         fmi3LogMessageCallback log_message,
                                         fmi3IntermediateUpdateCallback intermediate_update)
{
    static const char *const tokens[] = {HG_TOKEN_FMI3, NULL};
    (void)visible;
    (void)event_mode_used;
    (void)early_return_allowed;
    (void)required_intermediate;
    (void)n_required_intermediate;
    (void)intermediate_update;
    return hg_instantiate(__func__, name, token, tokens, resource_path, 0, emit,
                          (hg_any_fn)log_message, env, logging_on);
}

fmi3Instance fmi3InstantiateModelExchange(fmi3String name, fmi3String token,
                                          fmi3String resource_path, fmi3Boolean visible,
                                          fmi3Boolean logging_on, fmi3InstanceEnvironment env,
                                          fmi3LogMessageCallback log_message)
{
    static const char *const tokens[] = {HG_TOKEN_FMI3, NULL};
    hg_instance *c;
    (void)visible;
    c = hg_instantiate(__func__, name, token, tokens, resource_path, 0, emit,
                       (hg_any_fn)log_message, env, logging_on);
    if (c) c->model_exchange = 1;
    return c;
}

void fmi3FreeInstance(fmi3Instance instance) { hg_free_instance(instance); }

fmi3Status fmi3EnterInitializationMode(fmi3Instance instance, fmi3Boolean tol_defined,
                                       fmi3Float64 tol, fmi3Float64 start,
                                       fmi3Boolean stop_defined, fmi3Float64 stop)
{
    (void)tol_defined;
    (void)tol;
    if (hg_setup_experiment(instance, __func__, start, stop_defined, stop) != HG_OK)
        return fmi3Error;
    return (fmi3Status)hg_enter_initialization(instance, __func__);
}

fmi3Status fmi3ExitInitializationMode(fmi3Instance instance)
{
    return (fmi3Status)hg_exit_initialization(instance, __func__);
}

fmi3Status fmi3Terminate(fmi3Instance instance)
{
    return (fmi3Status)hg_terminate(instance, __func__);
}

fmi3Status fmi3Reset(fmi3Instance instance) { return (fmi3Status)hg_reset(instance, __func__); }
