/* The FMI 3.0 functions of what this FMU does not implement: Scheduled Execution, event mode in
 * co-simulation (fmi3EnterStepMode; fmi3_me.c refuses fmi3EnterEventMode and
 * fmi3UpdateDiscreteStates to a co-simulation instance), clocks, configuration mode,
 * derivatives and dependencies, and the variable types it has none of. Each is present (hosts resolve every symbol) and returns
 * fmi3Error with a message naming itself; the typed getters and setters accept empty calls. */
#include "fmi/instance.h"
#include "fmi3Functions.h"

#define UNUSED(x) (void)(x)

static fmi3Status unsupported(fmi3Instance instance, const char *fn, const char *why)
{
    hg_instance *c = instance;
    if (!hg_allowed(c, fn, ST_ANY)) return fmi3Error;
    hg_error(c, fn, "not supported: %s", why);
    return fmi3Error;
}

/* A getter or setter of a type this FMU has no variables of: only an empty call succeeds. */
static fmi3Status no_such_type(fmi3Instance instance, const char *fn,
                               const fmi3ValueReference vr[], size_t nvr, const char *type)
{
    hg_instance *c = instance;
    if (!hg_allowed(c, fn, ST_ANY)) return fmi3Error;
    if (nvr == 0) return fmi3OK;
    if (!vr)
        hg_error(c, fn, "nValueReferences = %zu but valueReferences is NULL", nvr);
    else
        hg_error(c, fn, "unknown value reference %u: this FMU has no %s variables",
                 (unsigned)vr[0], type);
    return fmi3Error;
}

/* An instance cannot be made: the host's logger hears why. */
static fmi3Instance no_instance(const char *fn, fmi3String name, fmi3InstanceEnvironment env,
                                fmi3LogMessageCallback log_message, const char *why)
{
    char msg[HG_ERRLEN];
    hg_errorf(msg, sizeof msg, "%s: %s (instance '%s')", fn, why, name ? name : "(null)");
    if (log_message) log_message(env, fmi3Error, "logStatusError", msg);
    return NULL;
}

fmi3Instance fmi3InstantiateScheduledExecution(
    fmi3String name, fmi3String token, fmi3String resource_path, fmi3Boolean visible,
    fmi3Boolean logging_on, fmi3InstanceEnvironment env, fmi3LogMessageCallback log_message,
    fmi3ClockUpdateCallback clock_update, fmi3LockPreemptionCallback lock,
    fmi3UnlockPreemptionCallback unlock)
{
    UNUSED(token);
    UNUSED(resource_path);
    UNUSED(visible);
    UNUSED(logging_on);
    UNUSED(clock_update);
    UNUSED(lock);
    UNUSED(unlock);
    return no_instance(__func__, name, env, log_message,
                       "this FMU implements co-simulation and Model Exchange, no Scheduled "
                       "Execution");
}

/* ------------------------------------------------------------------ types without variables */

#define NO_TYPE_GET(NAME, CTYPE, TYPE)                                                         \
    fmi3Status NAME(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,          \
                    CTYPE values[], size_t n_values)                                           \
    {                                                                                          \
        UNUSED(values);                                                                        \
        UNUSED(n_values);                                                                      \
        return no_such_type(instance, __func__, vr, nvr, TYPE);                                \
    }
#define NO_TYPE_SET(NAME, CTYPE, TYPE) NO_TYPE_GET(NAME, const CTYPE, TYPE)

NO_TYPE_GET(fmi3GetFloat32, fmi3Float32, "Float32")
NO_TYPE_GET(fmi3GetInt8, fmi3Int8, "Int8")
NO_TYPE_GET(fmi3GetUInt8, fmi3UInt8, "UInt8")
NO_TYPE_GET(fmi3GetInt16, fmi3Int16, "Int16")
NO_TYPE_GET(fmi3GetUInt16, fmi3UInt16, "UInt16")
NO_TYPE_GET(fmi3GetUInt32, fmi3UInt32, "UInt32")
NO_TYPE_GET(fmi3GetUInt64, fmi3UInt64, "UInt64")
NO_TYPE_SET(fmi3SetFloat32, fmi3Float32, "Float32")
NO_TYPE_SET(fmi3SetInt8, fmi3Int8, "Int8")
NO_TYPE_SET(fmi3SetUInt8, fmi3UInt8, "UInt8")
NO_TYPE_SET(fmi3SetInt16, fmi3Int16, "Int16")
NO_TYPE_SET(fmi3SetUInt16, fmi3UInt16, "UInt16")
NO_TYPE_SET(fmi3SetUInt32, fmi3UInt32, "UInt32")
NO_TYPE_SET(fmi3SetUInt64, fmi3UInt64, "UInt64")

fmi3Status fmi3GetBinary(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                         size_t sizes[], fmi3Binary values[], size_t n_values)
{
    UNUSED(sizes);
    UNUSED(values);
    UNUSED(n_values);
    return no_such_type(instance, __func__, vr, nvr, "Binary");
}

fmi3Status fmi3SetBinary(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                         const size_t sizes[], const fmi3Binary values[], size_t n_values)
{
    UNUSED(sizes);
    UNUSED(values);
    UNUSED(n_values);
    return no_such_type(instance, __func__, vr, nvr, "Binary");
}

fmi3Status fmi3GetClock(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                        fmi3Clock values[])
{
    UNUSED(values);
    return no_such_type(instance, __func__, vr, nvr, "Clock");
}

fmi3Status fmi3SetClock(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                        const fmi3Clock values[])
{
    UNUSED(values);
    return no_such_type(instance, __func__, vr, nvr, "Clock");
}

/* ------------------------------------------------------------------ clocks */

fmi3Status fmi3GetIntervalDecimal(fmi3Instance instance, const fmi3ValueReference vr[],
                                  size_t nvr, fmi3Float64 intervals[],
                                  fmi3IntervalQualifier qualifiers[])
{
    UNUSED(intervals);
    UNUSED(qualifiers);
    return no_such_type(instance, __func__, vr, nvr, "Clock");
}

fmi3Status fmi3GetIntervalFraction(fmi3Instance instance, const fmi3ValueReference vr[],
                                   size_t nvr, fmi3UInt64 counters[], fmi3UInt64 resolutions[],
                                   fmi3IntervalQualifier qualifiers[])
{
    UNUSED(counters);
    UNUSED(resolutions);
    UNUSED(qualifiers);
    return no_such_type(instance, __func__, vr, nvr, "Clock");
}

fmi3Status fmi3GetShiftDecimal(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                               fmi3Float64 shifts[])
{
    UNUSED(shifts);
    return no_such_type(instance, __func__, vr, nvr, "Clock");
}

fmi3Status fmi3GetShiftFraction(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                                fmi3UInt64 counters[], fmi3UInt64 resolutions[])
{
    UNUSED(counters);
    UNUSED(resolutions);
    return no_such_type(instance, __func__, vr, nvr, "Clock");
}

fmi3Status fmi3SetIntervalDecimal(fmi3Instance instance, const fmi3ValueReference vr[],
                                  size_t nvr, const fmi3Float64 intervals[])
{
    UNUSED(intervals);
    return no_such_type(instance, __func__, vr, nvr, "Clock");
}

fmi3Status fmi3SetIntervalFraction(fmi3Instance instance, const fmi3ValueReference vr[],
                                   size_t nvr, const fmi3UInt64 counters[],
                                   const fmi3UInt64 resolutions[])
{
    UNUSED(counters);
    UNUSED(resolutions);
    return no_such_type(instance, __func__, vr, nvr, "Clock");
}

fmi3Status fmi3SetShiftDecimal(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                               const fmi3Float64 shifts[])
{
    UNUSED(shifts);
    return no_such_type(instance, __func__, vr, nvr, "Clock");
}

fmi3Status fmi3SetShiftFraction(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                                const fmi3UInt64 counters[], const fmi3UInt64 resolutions[])
{
    UNUSED(counters);
    UNUSED(resolutions);
    return no_such_type(instance, __func__, vr, nvr, "Clock");
}

fmi3Status fmi3ActivateModelPartition(fmi3Instance instance, fmi3ValueReference clock,
                                      fmi3Float64 time)
{
    UNUSED(clock);
    UNUSED(time);
    return unsupported(instance, __func__, "no Scheduled Execution");
}

/* ------------------------------------------------------------------ modes */

fmi3Status fmi3EnterStepMode(fmi3Instance instance)
{
    return unsupported(instance, __func__, "no event mode (hasEventMode = false)");
}

fmi3Status fmi3EnterConfigurationMode(fmi3Instance instance)
{
    return unsupported(instance, __func__, "no structural parameters");
}

fmi3Status fmi3ExitConfigurationMode(fmi3Instance instance)
{
    return unsupported(instance, __func__, "no structural parameters");
}

fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance instance)
{
    return unsupported(instance, __func__, "providesEvaluateDiscreteStates = false");
}

/* ------------------------------------------------------------------ derivatives, dependencies */

fmi3Status fmi3GetNumberOfVariableDependencies(fmi3Instance instance, fmi3ValueReference vr,
                                               size_t *n)
{
    UNUSED(vr);
    UNUSED(n);
    return unsupported(instance, __func__, "the dependencies are in modelDescription.xml");
}

fmi3Status fmi3GetVariableDependencies(fmi3Instance instance, fmi3ValueReference dependent,
                                       size_t element_dependent[],
                                       fmi3ValueReference independents[],
                                       size_t element_independents[],
                                       fmi3DependencyKind kinds[], size_t n)
{
    UNUSED(dependent);
    UNUSED(element_dependent);
    UNUSED(independents);
    UNUSED(element_independents);
    UNUSED(kinds);
    UNUSED(n);
    return unsupported(instance, __func__, "the dependencies are in modelDescription.xml");
}

fmi3Status fmi3GetDirectionalDerivative(fmi3Instance instance,
                                        const fmi3ValueReference unknowns[], size_t n_unknowns,
                                        const fmi3ValueReference knowns[], size_t n_knowns,
                                        const fmi3Float64 seed[], size_t n_seed,
                                        fmi3Float64 sensitivity[], size_t n_sensitivity)
{
    UNUSED(unknowns);
    UNUSED(n_unknowns);
    UNUSED(knowns);
    UNUSED(n_knowns);
    UNUSED(seed);
    UNUSED(n_seed);
    UNUSED(sensitivity);
    UNUSED(n_sensitivity);
    return unsupported(instance, __func__, "providesDirectionalDerivative = false");
}

fmi3Status fmi3GetAdjointDerivative(fmi3Instance instance, const fmi3ValueReference unknowns[],
                                    size_t n_unknowns, const fmi3ValueReference knowns[],
                                    size_t n_knowns, const fmi3Float64 seed[], size_t n_seed,
                                    fmi3Float64 sensitivity[], size_t n_sensitivity)
{
    UNUSED(unknowns);
    UNUSED(n_unknowns);
    UNUSED(knowns);
    UNUSED(n_knowns);
    UNUSED(seed);
    UNUSED(n_seed);
    UNUSED(sensitivity);
    UNUSED(n_sensitivity);
    return unsupported(instance, __func__, "providesAdjointDerivatives = false");
}
