/* FMI 2.0 instance life cycle: instantiation, logging categories, experiment set-up,
 * initialization, termination, reset and freeing (adapters over lifecycle.c). */
#include <string.h>

#include "fmi/instance.h"
#include "fmi2Functions.h"

const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char *fmi2GetVersion(void) { return fmi2Version; }

/* FMI 2.0's logger takes the message as a format string: '%' is doubled. */
static void emit(const hg_instance *c, hg_status status, const char *category, const char *msg)
{
    char escaped[2 * HG_ERRLEN];
    const char *s;
    char *o = escaped;
    for (s = msg; *s; s++) {
        if (*s == '%') *o++ = '%';
        *o++ = *s;
    }
    *o = '\0';
    ((fmi2CallbackLogger)c->logger)(c->env, c->name, (fmi2Status)status, category, escaped);
}

fmi2Status fmi2SetDebugLogging(fmi2Component comp, fmi2Boolean on, size_t n,
                               const fmi2String cats[])
{
    return (fmi2Status)hg_set_debug_logging(comp, __func__, on, n, cats);
}

fmi2Component fmi2Instantiate(fmi2String name, fmi2Type type, fmi2String guid,
                              fmi2String resources, const fmi2CallbackFunctions *functions,
                              fmi2Boolean visible, fmi2Boolean logging_on)
{
    static const char *const guids[] = {HG_GUID, HG_GUID_INTENUM, NULL};
    hg_instance *c;
    (void)visible;
    if (!functions) return NULL;
    c = hg_instantiate(__func__, name, guid, guids, resources, 1, emit,
                       (hg_any_fn)functions->logger, functions->componentEnvironment,
                       logging_on);
    if (c && type != fmi2CoSimulation && type != fmi2ModelExchange) {
        hg_error(c, __func__, "fmuType = %d is neither fmi2ModelExchange (%d) nor "
                 "fmi2CoSimulation (%d)", (int)type, (int)fmi2ModelExchange,
                 (int)fmi2CoSimulation);
        hg_free_instance(c);
        return NULL;
    }
    if (c) c->model_exchange = type == fmi2ModelExchange;
    return c;
}

void fmi2FreeInstance(fmi2Component comp) { hg_free_instance(comp); }

fmi2Status fmi2SetupExperiment(fmi2Component comp, fmi2Boolean tol_defined, fmi2Real tol,
                               fmi2Real start, fmi2Boolean stop_defined, fmi2Real stop)
{
    (void)tol_defined;
    (void)tol;
    return (fmi2Status)hg_setup_experiment(comp, __func__, start, stop_defined, stop);
}

fmi2Status fmi2EnterInitializationMode(fmi2Component comp)
{
    return (fmi2Status)hg_enter_initialization(comp, __func__);
}

fmi2Status fmi2ExitInitializationMode(fmi2Component comp)
{
    return (fmi2Status)hg_exit_initialization(comp, __func__);
}

fmi2Status fmi2Terminate(fmi2Component comp) { return (fmi2Status)hg_terminate(comp, __func__); }

fmi2Status fmi2Reset(fmi2Component comp) { return (fmi2Status)hg_reset(comp, __func__); }
