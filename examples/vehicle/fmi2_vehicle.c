/* A thin FMI 2.0 co-simulation layer around vehicle_model.c: instance, state machine, variable
 * access, stepping, FMU states (get, set, serialize: iterative masters roll the vehicle back);
 * Model Exchange's functions are in fmi2_vehicle_me.c.
 * No global state: everything lives in the instance. Directional derivatives and input
 * derivatives are not supported (the modelDescription says so) and return fmi2Error. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "vehicle_instance.h"

#define GUID "{6b1f3c52-2d8e-4f0a-9c57-1e0b7a4d9e21}"

static const char *const category_names[N_CATEGORIES] = {"logStatusWarning", "logStatusError",
                                                         "logAll"};

void logf_(vm_instance *c, fmi2Status status, int cat, const char *fmt, ...)
{
    char msg[512], escaped[1024], *o = escaped;
    const char *s;
    va_list ap;
    if (!c->logger || !(c->log_on[cat] || c->log_on[CAT_ALL])) return;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    for (s = msg; *s; s++) { /* the host treats the message as a format string */
        if (*s == '%') *o++ = '%';
        *o++ = *s;
    }
    *o = '\0';
    c->logger(c->env, c->name, status, category_names[cat], escaped);
}

fmi2Status fail(vm_instance *c, const char *fn, const char *why)
{
    c->state = ST_ERROR;
    logf_(c, fmi2Error, CAT_ERROR, "%s: %s", fn, why);
    return fmi2Error;
}

int allowed(vm_instance *c, const char *fn, int states)
{
    static const char *const names[] = {"instantiated", "initialization mode", "step complete",
                                        "terminated", "error", "event mode",
                                        "continuous-time mode"};
    int k = 0;
    if (!c) return 0;
    if ((int)c->state & states) return 1;
    while (k < 6 && !(c->state & (1 << k))) k++;
    logf_(c, fmi2Error, CAT_ERROR, "%s: not allowed in state %s", fn, names[k]);
    return 0;
}

/* ------------------------------------------------------------------ common functions */

const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char *fmi2GetVersion(void) { return fmi2Version; }

fmi2Status fmi2SetDebugLogging(fmi2Component comp, fmi2Boolean on, size_t n,
                               const fmi2String categories[])
{
    vm_instance *c = comp;
    size_t i;
    int k;
    if (!c) return fmi2Error;
    if (n == 0) {
        for (k = 0; k < N_CATEGORIES; k++) c->log_on[k] = on != fmi2False;
        return fmi2OK;
    }
    if (!categories) return fmi2Error;
    for (i = 0; i < n; i++) {
        for (k = 0; k < N_CATEGORIES; k++)
            if (categories[i] && strcmp(categories[i], category_names[k]) == 0) break;
        if (k == N_CATEGORIES) {
            c->log_on[CAT_ERROR] = 1;
            logf_(c, fmi2Error, CAT_ERROR, "fmi2SetDebugLogging: unknown log category %s",
                  categories[i] ? categories[i] : "(null)");
            return fmi2Error;
        }
        c->log_on[k] = on != fmi2False;
    }
    return fmi2OK;
}

fmi2Component fmi2Instantiate(fmi2String name, fmi2Type type, fmi2String guid,
                              fmi2String resource_location, const fmi2CallbackFunctions *cb,
                              fmi2Boolean visible, fmi2Boolean logging_on)
{
    vm_instance *c;
    fmi2CallbackLogger logger = cb ? cb->logger : NULL;
    fmi2ComponentEnvironment env = cb ? cb->componentEnvironment : NULL;
    (void)resource_location;
    (void)visible;
    int known = type == fmi2CoSimulation || type == fmi2ModelExchange;
    if (!name || !*name || !known || !guid || strcmp(guid, GUID) != 0) {
        if (logger)
            logger(env, name ? name : "?", fmi2Error, "logStatusError",
                   !known ? "fmi2Instantiate: fmuType is neither fmi2ModelExchange nor "
                            "fmi2CoSimulation"
                          : "fmi2Instantiate: missing name or wrong GUID");
        return NULL;
    }
    c = calloc(1, sizeof *c);
    if (!c || !(c->name = malloc(strlen(name) + 1))) {
        free(c);
        if (logger)
            logger(env, name, fmi2Error, "logStatusError", "fmi2Instantiate: out of memory");
        return NULL;
    }
    strcpy(c->name, name);
    c->logger = logger;
    c->env = env;
    c->log_on[CAT_WARNING] = c->log_on[CAT_ERROR] = logging_on != fmi2False;
    c->state = ST_INSTANTIATED;
    c->model_exchange = type == fmi2ModelExchange;
    vm_reset(&c->model, 0.0);
    return c;
}

void fmi2FreeInstance(fmi2Component comp)
{
    vm_instance *c = comp;
    if (!c) return;
    free(c->name);
    free(c);
}

fmi2Status fmi2SetupExperiment(fmi2Component comp, fmi2Boolean tolerance_defined,
                               fmi2Real tolerance, fmi2Real start, fmi2Boolean stop_defined,
                               fmi2Real stop)
{
    vm_instance *c = comp;
    (void)tolerance_defined;
    (void)tolerance;
    if (!allowed(c, "fmi2SetupExperiment", ST_INSTANTIATED)) return fmi2Error;
    if (!isfinite(start) || (stop_defined && !(stop >= start)))
        return fail(c, "fmi2SetupExperiment", "start time not finite or stop time before it");
    c->start_time = start;
    c->stop_defined = stop_defined != fmi2False;
    c->stop_time = stop;
    c->model.time = start;
    return fmi2OK;
}

fmi2Status fmi2EnterInitializationMode(fmi2Component comp)
{
    vm_instance *c = comp;
    if (!allowed(c, "fmi2EnterInitializationMode", ST_INSTANTIATED)) return fmi2Error;
    c->state = ST_INIT;
    c->model.time = c->start_time;
    vm_initial_state(&c->model);
    return fmi2OK;
}

fmi2Status fmi2ExitInitializationMode(fmi2Component comp)
{
    vm_instance *c = comp;
    const char *why;
    if (!allowed(c, "fmi2ExitInitializationMode", ST_INIT)) return fmi2Error;
    if ((why = vm_check_parameters(&c->model)) != NULL)
        return fail(c, "fmi2ExitInitializationMode", why);
    if (c->model_exchange && c->model.v[VR_COUPLING] == VM_ROAD_LOAD)
        return fail(c, "fmi2ExitInitializationMode", "coupling = 2 (road load) is co-simulation "
                    "only: its acceleration is a difference quotient over the communication step");
    vm_initial_state(&c->model);
    c->state = c->model_exchange ? ST_EVENT : ST_STEP_COMPLETE;
    return fmi2OK;
}

fmi2Status fmi2Terminate(fmi2Component comp)
{
    vm_instance *c = comp;
    if (!allowed(c, "fmi2Terminate", ST_RUNNING)) return fmi2Error;
    c->state = ST_TERMINATED;
    return fmi2OK;
}

fmi2Status fmi2Reset(fmi2Component comp)
{
    vm_instance *c = comp;
    if (!allowed(c, "fmi2Reset", ST_INSTANTIATED | ST_INIT | ST_RUNNING | ST_TERMINATED |
                                     ST_ERROR))
        return fmi2Error;
    vm_reset(&c->model, 0.0);
    c->start_time = 0.0;
    c->stop_defined = 0;
    c->state = ST_INSTANTIATED;
    return fmi2OK;
}

/* ------------------------------------------------------------------ variable access */

static int check_refs(vm_instance *c, const char *fn, const fmi2ValueReference vr[], size_t n,
                      const void *values)
{
    size_t i;
    if (n > 0 && (!vr || !values)) {
        fail(c, fn, "NULL value reference or value array");
        return 0;
    }
    for (i = 0; i < n; i++)
        if (vr[i] >= VM_NUM_VARS) {
            logf_(c, fmi2Error, CAT_ERROR, "%s: unknown value reference %u", fn, (unsigned)vr[i]);
            c->state = ST_ERROR;
            return 0;
        }
    return 1;
}

fmi2Status fmi2GetReal(fmi2Component comp, const fmi2ValueReference vr[], size_t n,
                       fmi2Real value[])
{
    vm_instance *c = comp;
    size_t i;
    if (!allowed(c, "fmi2GetReal", ST_INIT | ST_RUNNING | ST_TERMINATED | ST_ERROR))
        return fmi2Error;
    if (!check_refs(c, "fmi2GetReal", vr, n, value)) return fmi2Error;
    if (c->state == ST_INIT) vm_initial_state(&c->model); /* outputs follow the parameters */
    else vm_outputs(&c->model);                           /* and the current input */
    for (i = 0; i < n; i++) value[i] = c->model.v[vr[i]];
    return fmi2OK;
}

fmi2Status fmi2SetReal(fmi2Component comp, const fmi2ValueReference vr[], size_t n,
                       const fmi2Real value[])
{
    vm_instance *c = comp;
    size_t i;
    if (!allowed(c, "fmi2SetReal", ST_INSTANTIATED | ST_INIT | ST_RUNNING)) return fmi2Error;
    if (!check_refs(c, "fmi2SetReal", vr, n, value)) return fmi2Error;
    for (i = 0; i < n; i++) {
        if (!vm_settable((int)vr[i])) {
            logf_(c, fmi2Error, CAT_ERROR, "fmi2SetReal: value reference %u is an output or a "
                  "derivative (computed by the FMU)", (unsigned)vr[i]);
            return fmi2Error;
        }
        if (vr[i] >= VM_FIRST_PARAMETER && vr[i] < VM_FIRST_OUTPUT && (c->state & ST_RUNNING)) {
            logf_(c, fmi2Error, CAT_ERROR, "fmi2SetReal: parameter %u is fixed after "
                  "initialization", (unsigned)vr[i]);
            return fmi2Error;
        }
        if (!isfinite(value[i])) {
            logf_(c, fmi2Error, CAT_ERROR, "fmi2SetReal: value reference %u: value %g is not "
                  "finite", (unsigned)vr[i], value[i]);
            return fmi2Error;
        }
        if (vr[i] == VR_T_BRAKE && value[i] < 0.0) {
            logf_(c, fmi2Error, CAT_ERROR, "fmi2SetReal: T_brake = %g N.m is negative: the brakes "
                  "oppose the wheels' rotation whichever way they turn (min 0)", value[i]);
            return fmi2Error;
        }
    }
    for (i = 0; i < n; i++) c->model.v[vr[i]] = value[i];
    return fmi2OK;
}

/* There are no Integer, Boolean or String variables: only n = 0 is accepted. */
static fmi2Status no_variables(fmi2Component comp, const char *fn, size_t n, int states)
{
    vm_instance *c = comp;
    if (!allowed(c, fn, states)) return fmi2Error;
    if (n > 0) {
        logf_(c, fmi2Error, CAT_ERROR, "%s: the FMU has no variable of this type", fn);
        return fmi2Error;
    }
    return fmi2OK;
}

#define GET_STATES (ST_INIT | ST_RUNNING | ST_TERMINATED | ST_ERROR)
#define SET_STATES (ST_INSTANTIATED | ST_INIT | ST_RUNNING)

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                          fmi2Integer value[])
{
    (void)vr;
    (void)value;
    return no_variables(c, "fmi2GetInteger", n, GET_STATES);
}

fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                          fmi2Boolean value[])
{
    (void)vr;
    (void)value;
    return no_variables(c, "fmi2GetBoolean", n, GET_STATES);
}

fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                         fmi2String value[])
{
    (void)vr;
    (void)value;
    return no_variables(c, "fmi2GetString", n, GET_STATES);
}

fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                          const fmi2Integer value[])
{
    (void)vr;
    (void)value;
    return no_variables(c, "fmi2SetInteger", n, SET_STATES);
}

fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                          const fmi2Boolean value[])
{
    (void)vr;
    (void)value;
    return no_variables(c, "fmi2SetBoolean", n, SET_STATES);
}

fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                         const fmi2String value[])
{
    (void)vr;
    (void)value;
    return no_variables(c, "fmi2SetString", n, SET_STATES);
}

/* ------------------------------------------------------------------ unsupported features */

static fmi2Status unsupported(fmi2Component comp, const char *fn)
{
    vm_instance *c = comp;
    if (c) logf_(c, fmi2Error, CAT_ERROR, "%s: not supported by this FMU", fn);
    return fmi2Error;
}

/* ------------------------------------------------------------------ FMU states
 * A state is a copy of everything that evolves (the model: variables, states, time) and of the
 * instance's mode; the model is plain data, so get and set are copies and the serialized form is
 * a tagged copy of its bytes (for the same build of this FMU). */

typedef struct {
    vm_model model;
    vm_state state;
    int model_exchange; /* of the instance it was taken from */
    double start_time, stop_time;
    int stop_defined;
} vm_snapshot;

#define SNAPSHOT_TAG "LongitudinalVehicle-state-1"

/* A refused state call: logged, fmi2Error, the instance as it was (nothing was changed). */
static fmi2Status refuse(vm_instance *c, const char *fn, const char *why)
{
    logf_(c, fmi2Error, CAT_ERROR, "%s: %s", fn, why);
    return fmi2Error;
}

static void snapshot_take(const vm_instance *c, vm_snapshot *s)
{
    s->model = c->model;
    s->state = c->state;
    s->model_exchange = c->model_exchange;
    s->start_time = c->start_time;
    s->stop_time = c->stop_time;
    s->stop_defined = c->stop_defined;
}

fmi2Status fmi2GetFMUstate(fmi2Component comp, fmi2FMUstate *out)
{
    vm_instance *c = comp;
    vm_snapshot *s;
    if (!allowed(c, "fmi2GetFMUstate", ST_INIT | ST_RUNNING | ST_TERMINATED)) return fmi2Error;
    if (!out) return refuse(c, "fmi2GetFMUstate", "NULL state pointer");
    s = *out ? (vm_snapshot *)*out : malloc(sizeof *s); /* a given state is overwritten */
    if (!s) return refuse(c, "fmi2GetFMUstate", "out of memory");
    snapshot_take(c, s);
    *out = s;
    return fmi2OK;
}

fmi2Status fmi2SetFMUstate(fmi2Component comp, fmi2FMUstate in)
{
    vm_instance *c = comp;
    const vm_snapshot *s = in;
    if (!allowed(c, "fmi2SetFMUstate", ST_INSTANTIATED | ST_INIT | ST_RUNNING | ST_TERMINATED))
        return fmi2Error;
    if (!s) return refuse(c, "fmi2SetFMUstate", "NULL state");
    if (s->model_exchange != c->model_exchange)
        return refuse(c, "fmi2SetFMUstate", "the state was taken from an instance of the other "
                      "interface (Model Exchange / co-simulation)");
    c->model = s->model;
    c->state = s->state;
    c->start_time = s->start_time;
    c->stop_time = s->stop_time;
    c->stop_defined = s->stop_defined;
    return fmi2OK;
}

fmi2Status fmi2FreeFMUstate(fmi2Component comp, fmi2FMUstate *s)
{
    (void)comp;
    if (s) {
        free(*s);
        *s = NULL;
    }
    return fmi2OK;
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component comp, fmi2FMUstate s, size_t *size)
{
    vm_instance *c = comp;
    if (!c) return fmi2Error;
    if (!s || !size) return refuse(c, "fmi2SerializedFMUstateSize", "NULL state or size");
    *size = sizeof SNAPSHOT_TAG + sizeof(vm_snapshot);
    return fmi2OK;
}

fmi2Status fmi2SerializeFMUstate(fmi2Component comp, fmi2FMUstate s, fmi2Byte b[], size_t size)
{
    vm_instance *c = comp;
    if (!c) return fmi2Error;
    if (!s || !b || size < sizeof SNAPSHOT_TAG + sizeof(vm_snapshot))
        return refuse(c, "fmi2SerializeFMUstate", "NULL state or buffer, or the buffer too small "
                    "(see fmi2SerializedFMUstateSize)");
    memcpy(b, SNAPSHOT_TAG, sizeof SNAPSHOT_TAG);
    memcpy(b + sizeof SNAPSHOT_TAG, s, sizeof(vm_snapshot));
    return fmi2OK;
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component comp, const fmi2Byte b[], size_t size,
                                   fmi2FMUstate *out)
{
    vm_instance *c = comp;
    vm_snapshot *s;
    if (!c) return fmi2Error;
    if (!b || !out || size != sizeof SNAPSHOT_TAG + sizeof(vm_snapshot) ||
        memcmp(b, SNAPSHOT_TAG, sizeof SNAPSHOT_TAG) != 0)
        return refuse(c, "fmi2DeSerializeFMUstate", "not a state serialized by this build of the "
                    "FMU (tag or size differs)");
    if (!(s = malloc(sizeof *s))) return refuse(c, "fmi2DeSerializeFMUstate", "out of memory");
    memcpy(s, b + sizeof SNAPSHOT_TAG, sizeof *s);
    *out = s;
    return fmi2OK;
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference u[], size_t nu,
                                        const fmi2ValueReference z[], size_t nz,
                                        const fmi2Real du[], fmi2Real dz[])
{
    (void)u;
    (void)nu;
    (void)z;
    (void)nz;
    (void)du;
    (void)dz;
    return unsupported(c, "fmi2GetDirectionalDerivative");
}

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                                       const fmi2Integer order[], const fmi2Real value[])
{
    (void)vr;
    (void)n;
    (void)order;
    (void)value;
    return unsupported(c, "fmi2SetRealInputDerivatives");
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                                        const fmi2Integer order[], fmi2Real value[])
{
    (void)vr;
    (void)n;
    (void)order;
    (void)value;
    return unsupported(c, "fmi2GetRealOutputDerivatives");
}

fmi2Status fmi2CancelStep(fmi2Component c) { return unsupported(c, "fmi2CancelStep"); }

/* ------------------------------------------------------------------ stepping and status */

fmi2Status fmi2DoStep(fmi2Component comp, fmi2Real t, fmi2Real h, fmi2Boolean no_prior_state)
{
    vm_instance *c = comp;
    double now;
    (void)no_prior_state;
    if (!allowed(c, "fmi2DoStep", ST_STEP_COMPLETE)) return fmi2Error;
    now = c->model.time;
    if (!isfinite(t) || !isfinite(h) || h < 0.0 || fabs(t - now) > 1e-9 * (1.0 + fabs(now))) {
        logf_(c, fmi2Error, CAT_ERROR, "fmi2DoStep: communication point %.12g with step %g does "
              "not continue the FMU time %.12g", t, h, now);
        return fmi2Error;
    }
    if (c->stop_defined && t + h > c->stop_time + 1e-9 * (1.0 + fabs(c->stop_time))) {
        logf_(c, fmi2Error, CAT_ERROR, "fmi2DoStep: the step to %.12g s passes the stop time "
              "%.12g s", t + h, c->stop_time);
        return fmi2Error;
    }
    if (h > 0.0) vm_step(&c->model, h);
    c->model.time = t + h; /* the host's time, without accumulated round-off */
    if (!isfinite(c->model.v[VR_T_HS]) || !isfinite(c->model.v[VR_E_IN]))
        return fail(c, "fmi2DoStep", "the solution is no longer finite");
    return fmi2OK;
}

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status *value)
{
    (void)s;
    (void)value;
    return unsupported(c, "fmi2GetStatus");
}

fmi2Status fmi2GetRealStatus(fmi2Component comp, const fmi2StatusKind s, fmi2Real *value)
{
    vm_instance *c = comp;
    if (c && s == fmi2LastSuccessfulTime && value) {
        *value = c->model.time;
        return fmi2OK;
    }
    return unsupported(c, "fmi2GetRealStatus");
}

fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer *value)
{
    (void)s;
    (void)value;
    return unsupported(c, "fmi2GetIntegerStatus");
}

fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean *value)
{
    (void)s;
    (void)value;
    return unsupported(c, "fmi2GetBooleanStatus");
}

fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String *value)
{
    (void)s;
    (void)value;
    return unsupported(c, "fmi2GetStringStatus");
}
