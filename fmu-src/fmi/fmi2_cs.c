/* FMI 2.0 co-simulation interface: instance life cycle, state machine, logging, variable access
 * and stepping. Physics lives in model/; this file only translates FMI calls. */
#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi/instance.h"

#define ALL_STATES (ST_INSTANTIATED | ST_INITIALIZATION | ST_STEP_COMPLETE | ST_TERMINATED | ST_ERROR)
#define READABLE (ST_INITIALIZATION | ST_STEP_COMPLETE | ST_TERMINATED | ST_ERROR)
#define BEFORE_RUN (ST_INSTANTIATED | ST_INITIALIZATION)
#define MAX_COMM_STEP 1000.0 /* [s] longest communication step (docs/integration.md, limits) */
#define TIME_RESOLUTION 1e-6 /* largest relative rounding error of t + h accepted by fmi2DoStep */

static const char *const category_names[N_CATEGORIES] = {"logEvents", "logStatusWarning",
                                                         "logStatusError", "logAll"};

/* ------------------------------------------------------------------ logging */

void hg_log(hg_instance *c, fmi2Status status, int category, const char *fmt, ...)
{
    char msg[HG_ERRLEN], escaped[2 * HG_ERRLEN];
    const char *s;
    char *o = escaped;
    va_list ap;
    if (!c || !c->logger || !(c->log_on[category] || c->log_on[CAT_ALL])) return;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    for (s = msg; *s; s++) { /* the host treats the message as a format string */
        if (*s == '%') *o++ = '%';
        *o++ = *s;
    }
    *o = '\0';
    c->logger(c->env, c->name, status, category_names[category], escaped);
}

static void model_log(void *ctx, const char *category, const char *message)
{
    hg_instance *c = ctx;
    int k;
    for (k = 0; k < N_CATEGORIES; k++)
        if (strcmp(category, category_names[k]) == 0) break;
    if (k == N_CATEGORIES) k = CAT_ALL;
    hg_log(c, k == CAT_WARNING ? fmi2Warning : k == CAT_ERROR ? fmi2Error : fmi2OK, k, "%s",
           message);
}

hg_model *hg_instance_model(hg_instance *c)
{
    if (!c->model) c->model = hg_model_new(c->resource_dir, model_log, c);
    return c->model;
}

static const char *state_name(hg_fmi_state s)
{
    switch (s) {
    case ST_INSTANTIATED: return "instantiated";
    case ST_INITIALIZATION: return "initialization mode";
    case ST_STEP_COMPLETE: return "step complete";
    case ST_TERMINATED: return "terminated";
    case ST_ERROR: return "error";
    default: return "fatal";
    }
}

int hg_allowed(hg_instance *c, const char *fn, int states)
{
    if (!c) return 0;
    if (c->state & states) return 1;
    hg_log(c, fmi2Error, CAT_ERROR, "%s is not allowed in state '%s'", fn, state_name(c->state));
    return 0;
}

/* An error in the model leaves the instance in the error state (only Get/Reset/Free allowed). */
static fmi2Status fail(hg_instance *c, const char *fn, const char *why)
{
    hg_log(c, fmi2Error, CAT_ERROR, "%s: %s", fn, why);
    c->state = ST_ERROR;
    return fmi2Error;
}

/* ------------------------------------------------------------------ life cycle */

const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char *fmi2GetVersion(void) { return fmi2Version; }

static int set_categories(hg_instance *c, fmi2Boolean on, size_t n, const fmi2String cats[])
{
    size_t i;
    int k;
    if (n == 0) {
        for (k = 0; k < N_CATEGORIES; k++) c->log_on[k] = on;
        c->log_on[CAT_WARNING] = c->log_on[CAT_ERROR] = 1; /* problems are always reported */
        return 0;
    }
    if (!cats) {
        hg_log(c, fmi2Error, CAT_ERROR, "fmi2SetDebugLogging: nCategories = %zu but categories "
               "is NULL", n);
        return -1;
    }
    for (i = 0; i < n; i++) {
        for (k = 0; k < N_CATEGORIES; k++)
            if (cats[i] && strcmp(cats[i], category_names[k]) == 0) break;
        if (k == N_CATEGORIES) {
            hg_log(c, fmi2Error, CAT_ERROR, "fmi2SetDebugLogging: unknown log category '%s'",
                   cats[i] ? cats[i] : "(null)");
            return -1;
        }
        c->log_on[k] = on;
    }
    return 0;
}

fmi2Status fmi2SetDebugLogging(fmi2Component comp, fmi2Boolean on, size_t n,
                               const fmi2String cats[])
{
    hg_instance *c = comp;
    if (!hg_allowed(c, "fmi2SetDebugLogging", ALL_STATES)) return fmi2Error;
    return set_categories(c, on, n, cats) ? fmi2Error : fmi2OK;
}

static void free_instance(hg_instance *c)
{
    if (!c) return;
    hg_model_free(c->model);
    hg_vars_free_strings(&c->vars);
    free(c->resource_dir);
    free(c->name);
    free(c);
}

static int reset_instance(hg_instance *c)
{
    hg_model_free(c->model);
    c->model = NULL;
    c->set_up = 0;
    c->start_time = 0.0;
    c->stop_defined = 0;
    c->stop_time = 0.0;
    memset(&c->input_der, 0, sizeof c->input_der);
    c->state = ST_INSTANTIATED;
    return hg_vars_reset(&c->vars);
}

/* The standard asks for at least one character that is not white space. */
static int blank(const char *s)
{
    if (!s) return 1;
    while (*s && isspace((unsigned char)*s)) s++;
    return *s == '\0';
}

static int check_instantiate_args(hg_instance *c, fmi2Type type, fmi2String guid)
{
    if (type != fmi2CoSimulation) {
        hg_log(c, fmi2Error, CAT_ERROR, "fmi2Instantiate: this FMU supports co-simulation only");
        return -1;
    }
    if (!guid || strcmp(guid, HG_GUID) != 0) {
        hg_log(c, fmi2Error, CAT_ERROR,
               "fmi2Instantiate: GUID '%s' does not match this binary's '%s'",
               guid ? guid : "(null)", HG_GUID);
        return -1;
    }
    return 0;
}

fmi2Component fmi2Instantiate(fmi2String name, fmi2Type type, fmi2String guid,
                              fmi2String resources, const fmi2CallbackFunctions *functions,
                              fmi2Boolean visible, fmi2Boolean logging_on)
{
    hg_instance *c;
    char why[HG_ERRLEN];
    (void)visible;
    if (!functions || !(c = calloc(1, sizeof *c))) return NULL;
    c->logger = functions->logger;
    c->env = functions->componentEnvironment;
    set_categories(c, logging_on, 0, NULL);
    c->name = malloc(strlen(name ? name : "") + 1);
    if (!c->name) {
        free(c);
        return NULL;
    }
    strcpy(c->name, name ? name : "");
    if (blank(name)) {
        hg_log(c, fmi2Error, CAT_ERROR, "fmi2Instantiate: instanceName '%s' is empty or blank",
               name ? name : "(null)");
        free_instance(c);
        return NULL;
    }
    if (check_instantiate_args(c, type, guid) || reset_instance(c)) {
        free_instance(c);
        return NULL;
    }
    if (resources && *resources && !(c->resource_dir = hg_uri_to_path(resources, why, sizeof why))) {
        hg_log(c, fmi2Error, CAT_ERROR, "fmi2Instantiate: fmuResourceLocation: %s", why);
        free_instance(c);
        return NULL;
    }
    return c;
}

void fmi2FreeInstance(fmi2Component comp) { free_instance(comp); }

fmi2Status fmi2SetupExperiment(fmi2Component comp, fmi2Boolean tol_defined, fmi2Real tol,
                               fmi2Real start, fmi2Boolean stop_defined, fmi2Real stop)
{
    hg_instance *c = comp;
    (void)tol_defined;
    (void)tol;
    if (!hg_allowed(c, "fmi2SetupExperiment", ST_INSTANTIATED)) return fmi2Error;
    if (!isfinite(start) || (stop_defined && !(stop >= start))) {
        hg_log(c, fmi2Error, CAT_ERROR, "fmi2SetupExperiment: startTime = %g, stopTime = %g: "
               "need a finite start not after the stop", start, stop);
        return fmi2Error;
    }
    c->start_time = start;
    c->stop_defined = stop_defined != fmi2False;
    c->stop_time = c->stop_defined ? stop : 0.0;
    return fmi2OK;
}

fmi2Status fmi2EnterInitializationMode(fmi2Component comp)
{
    hg_instance *c = comp;
    if (!hg_allowed(c, "fmi2EnterInitializationMode", ST_INSTANTIATED)) return fmi2Error;
    c->state = ST_INITIALIZATION;
    return fmi2OK;
}

/* ------------------------------------------------------------------ checks on the results */

double hg_real_value(const hg_instance *c, const hg_var_info *info)
{
    return *(const double *)((const char *)&c->vars + info->offset);
}

const hg_var_info *hg_first_nonfinite(const hg_instance *c, int calculated_too)
{
    int r;
    for (r = 0; r < HG_NUM_VARS; r++) {
        const hg_var_info *info = &hg_var_table[r];
        int checked = info->causality == HG_OUTPUT ||
                      (calculated_too && info->causality == HG_CALCULATED);
        if (checked && info->type == HG_REAL && !isfinite(hg_real_value(c, info))) return info;
    }
    return NULL;
}

static double *input_slot(hg_inputs *u, const char *name)
{
    if (strcmp(name, "T_s") == 0) return &u->T_s;
    if (strcmp(name, "T_w") == 0) return &u->T_w;
    if (strcmp(name, "T_bath") == 0) return &u->T_bath;
    if (strcmp(name, "w_set") == 0) return &u->w_set;
    return NULL;
}

/* The first time derivative the host gave for an input (0 when none). */
static double derivative_of(const hg_instance *c, const hg_var_info *info)
{
    const double *d = input_slot((hg_inputs *)&c->input_der, info->name);
    return d ? *d : 0.0;
}

/* "T_s = 100, T_w = 276.9, ...": the inputs, for messages about failed set-ups and steps. */
static void describe_inputs(const hg_instance *c, char *out, size_t len)
{
    size_t used = 0;
    int r;
    out[0] = '\0';
    for (r = 0; r < HG_NUM_VARS && used < len; r++) {
        const hg_var_info *info = &hg_var_table[r];
        int n;
        if (info->causality != HG_INPUT || info->type != HG_REAL) continue;
        n = derivative_of(c, info) != 0.0
                ? snprintf(out + used, len - used, "%s%s = %g changing at %g /s", used ? ", " : "",
                           info->name, hg_real_value(c, info), derivative_of(c, info))
                : snprintf(out + used, len - used, "%s%s = %g", used ? ", " : "", info->name,
                           hg_real_value(c, info));
        if (n < 0) break;
        used += (size_t)n;
    }
}

/* Sets the model up for the current parameters and initial inputs, once. */
static fmi2Status ensure_set_up(hg_instance *c, const char *fn)
{
    char err[HG_ERRLEN];
    const hg_var_info *bad;
    hg_vars before;
    if (c->set_up) return fmi2OK;
    if (!c->resource_dir) {
        hg_log(c, fmi2Error, CAT_ERROR, "%s: no fmuResourceLocation was given at instantiation, "
               "so the gear-set and lubricant data cannot be found", fn);
        return fmi2Error;
    }
    if (!hg_instance_model(c)) {
        hg_log(c, fmi2Error, CAT_ERROR, "%s: out of memory", fn);
        return fmi2Error;
    }
    before = c->vars; /* shallow copy: only its results are ever copied back */
    if (hg_model_setup(c->model, &c->vars, c->start_time, err, sizeof err)) {
        hg_vars_copy_results(&c->vars, &before);
        hg_log(c, fmi2Error, CAT_ERROR, "%s: %s", fn, err);
        return fmi2Error;
    }
    if ((bad = hg_first_nonfinite(c, 1)) != NULL) {
        double value = hg_real_value(c, bad);
        hg_vars_copy_results(&c->vars, &before);
        describe_inputs(c, err, sizeof err);
        hg_log(c, fmi2Error, CAT_ERROR, "%s: %s = %g at the start: the parameters and inputs "
               "(%s) are beyond the model's reach", fn, bad->name, value, err);
        return fmi2Error;
    }
    c->set_up = 1;
    return fmi2OK;
}

fmi2Status fmi2ExitInitializationMode(fmi2Component comp)
{
    hg_instance *c = comp;
    if (!hg_allowed(c, "fmi2ExitInitializationMode", ST_INITIALIZATION)) return fmi2Error;
    if (ensure_set_up(c, "fmi2ExitInitializationMode") != fmi2OK) return fmi2Error;
    c->state = ST_STEP_COMPLETE;
    return fmi2OK;
}

fmi2Status fmi2Terminate(fmi2Component comp)
{
    hg_instance *c = comp;
    if (!hg_allowed(c, "fmi2Terminate", ST_STEP_COMPLETE | ST_ERROR)) return fmi2Error;
    c->state = ST_TERMINATED;
    return fmi2OK;
}

fmi2Status fmi2Reset(fmi2Component comp)
{
    hg_instance *c = comp;
    if (!hg_allowed(c, "fmi2Reset", ALL_STATES)) return fmi2Error;
    if (reset_instance(c)) return fail(c, "fmi2Reset", "out of memory");
    return fmi2OK;
}

/* ------------------------------------------------------------------ variable access */

static const hg_var_info *lookup(hg_instance *c, const char *fn, fmi2ValueReference vr,
                                 hg_base_type type)
{
    static const char *const type_names[] = {"Real", "Integer", "Boolean", "String"};
    if (vr >= HG_NUM_VARS) {
        hg_log(c, fmi2Error, CAT_ERROR, "%s: unknown value reference %u", fn, (unsigned)vr);
        return NULL;
    }
    if (hg_var_table[vr].type != type) {
        hg_log(c, fmi2Error, CAT_ERROR, "%s: value reference %u is '%s', of type %s", fn,
               (unsigned)vr, hg_var_table[vr].name, type_names[hg_var_table[vr].type]);
        return NULL;
    }
    return &hg_var_table[vr];
}

static void *field(hg_instance *c, const hg_var_info *info)
{
    return (char *)&c->vars + info->offset;
}

static int check_array_args(hg_instance *c, const char *fn, const void *vr, size_t nvr,
                            const void *values)
{
    if (nvr > 0 && (!vr || !values)) {
        hg_log(c, fmi2Error, CAT_ERROR, "%s: NULL value-reference or value array", fn);
        return -1;
    }
    return 0;
}

static fmi2Status prepare_get(hg_instance *c, const char *fn, const void *vr, size_t nvr,
                              const void *values)
{
    if (!hg_allowed(c, fn, READABLE) || check_array_args(c, fn, vr, nvr, values)) return fmi2Error;
    if (c->state == ST_INITIALIZATION) return ensure_set_up(c, fn);
    return fmi2OK;
}

fmi2Status fmi2GetReal(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                       fmi2Real value[])
{
    hg_instance *c = comp;
    size_t i;
    if (prepare_get(c, "fmi2GetReal", vr, nvr, value) != fmi2OK) return fmi2Error;
    for (i = 0; i < nvr; i++) {
        const hg_var_info *info = lookup(c, "fmi2GetReal", vr[i], HG_REAL);
        if (!info) return fmi2Error;
        value[i] = *(double *)field(c, info);
    }
    return fmi2OK;
}

static fmi2Status get_ints(hg_instance *c, const char *fn, hg_base_type type,
                           const fmi2ValueReference vr[], size_t nvr, int value[])
{
    size_t i;
    if (prepare_get(c, fn, vr, nvr, value) != fmi2OK) return fmi2Error;
    for (i = 0; i < nvr; i++) {
        const hg_var_info *info = lookup(c, fn, vr[i], type);
        if (!info) return fmi2Error;
        value[i] = *(int *)field(c, info);
    }
    return fmi2OK;
}

fmi2Status fmi2GetInteger(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                          fmi2Integer value[])
{
    return get_ints(comp, "fmi2GetInteger", HG_INTEGER, vr, nvr, value);
}

fmi2Status fmi2GetBoolean(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                          fmi2Boolean value[])
{
    return get_ints(comp, "fmi2GetBoolean", HG_BOOLEAN, vr, nvr, value);
}

fmi2Status fmi2GetString(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                         fmi2String value[])
{
    hg_instance *c = comp;
    size_t i;
    if (prepare_get(c, "fmi2GetString", vr, nvr, value) != fmi2OK) return fmi2Error;
    for (i = 0; i < nvr; i++) {
        const hg_var_info *info = lookup(c, "fmi2GetString", vr[i], HG_STRING);
        if (!info) return fmi2Error;
        value[i] = *(char **)field(c, info);
    }
    return fmi2OK;
}

/* May this variable be set now? Parameters before the run, inputs always. */
static int settable(hg_instance *c, const char *fn, const hg_var_info *info)
{
    if (info->causality == HG_INPUT) return 1;
    if (info->causality == HG_PARAMETER && (c->state & BEFORE_RUN)) return 1;
    hg_log(c, fmi2Error, CAT_ERROR, "%s: '%s' cannot be set %s", fn, info->name,
           info->causality == HG_PARAMETER ? "after initialization (it is a fixed parameter)"
                                           : "(it is computed by the FMU)");
    return 0;
}

/* "40 K (-233.15 degC)": a value with its unit and, when it has one, its display unit. */
static void quote_value(char *buf, size_t n, const hg_var_info *info, double v)
{
    int len = snprintf(buf, n, "%.10g%s%s", v, *info->unit ? " " : "", info->unit);
    if (info->display_unit && len > 0 && (size_t)len < n)
        snprintf(buf + len, n - (size_t)len, " (%.6g %s)",
                 info->display_factor * v + info->display_offset, info->display_unit);
}

/* "[200, 500] K": the declared range with its unit. */
static void quote_range(char *buf, size_t n, const hg_var_info *info)
{
    snprintf(buf, n, "[%g, %g]%s%s", info->has_min ? info->min : -HUGE_VAL,
             info->has_max ? info->max : HUGE_VAL, *info->unit ? " " : "", info->unit);
}

static int check_range(hg_instance *c, const char *fn, const hg_var_info *info, double v)
{
    char value[96], range[96];
    if (!isfinite(v)) {
        hg_log(c, fmi2Error, CAT_ERROR, "%s: %s = %g is not a finite number", fn, info->name, v);
        return -1;
    }
    if ((info->has_min && v < info->min) || (info->has_max && v > info->max)) {
        quote_value(value, sizeof value, info, v);
        quote_range(range, sizeof range, info);
        hg_log(c, fmi2Error, CAT_ERROR, "%s: %s = %s is outside its range %s", fn, info->name,
               value, range);
        return -1;
    }
    return 0;
}

/* Before the run, parameters and initial inputs define the start: set up again when asked. */
static void note_set(hg_instance *c)
{
    if (c->state & BEFORE_RUN) c->set_up = 0;
}

fmi2Status fmi2SetReal(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                       const fmi2Real value[])
{
    hg_instance *c = comp;
    size_t i;
    if (!hg_allowed(c, "fmi2SetReal", BEFORE_RUN | ST_STEP_COMPLETE) ||
        check_array_args(c, "fmi2SetReal", vr, nvr, value))
        return fmi2Error;
    for (i = 0; i < nvr; i++) {
        const hg_var_info *info = lookup(c, "fmi2SetReal", vr[i], HG_REAL);
        if (!info || !settable(c, "fmi2SetReal", info) ||
            check_range(c, "fmi2SetReal", info, value[i]))
            return fmi2Error;
        *(double *)field(c, info) = value[i];
        note_set(c);
    }
    return fmi2OK;
}

static fmi2Status set_ints(hg_instance *c, const char *fn, hg_base_type type,
                           const fmi2ValueReference vr[], size_t nvr, const int value[])
{
    size_t i;
    if (!hg_allowed(c, fn, BEFORE_RUN | ST_STEP_COMPLETE) ||
        check_array_args(c, fn, vr, nvr, value))
        return fmi2Error;
    for (i = 0; i < nvr; i++) {
        const hg_var_info *info = lookup(c, fn, vr[i], type);
        if (!info || !settable(c, fn, info) || check_range(c, fn, info, value[i]))
            return fmi2Error;
        *(int *)field(c, info) = type == HG_BOOLEAN ? value[i] != 0 : value[i];
        note_set(c);
    }
    return fmi2OK;
}

fmi2Status fmi2SetInteger(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                          const fmi2Integer value[])
{
    return set_ints(comp, "fmi2SetInteger", HG_INTEGER, vr, nvr, value);
}

fmi2Status fmi2SetBoolean(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                          const fmi2Boolean value[])
{
    return set_ints(comp, "fmi2SetBoolean", HG_BOOLEAN, vr, nvr, value);
}

fmi2Status fmi2SetString(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                         const fmi2String value[])
{
    hg_instance *c = comp;
    size_t i;
    if (!hg_allowed(c, "fmi2SetString", BEFORE_RUN | ST_STEP_COMPLETE) ||
        check_array_args(c, "fmi2SetString", vr, nvr, value))
        return fmi2Error;
    for (i = 0; i < nvr; i++) {
        const hg_var_info *info = lookup(c, "fmi2SetString", vr[i], HG_STRING);
        char **slot, *copy;
        if (!info || !settable(c, "fmi2SetString", info)) return fmi2Error;
        if (!value[i] || strlen(value[i]) > 4095) {
            hg_log(c, fmi2Error, CAT_ERROR, "fmi2SetString: %s must be a string of at most 4095 "
                   "characters (got %s)", info->name, value[i] ? "a longer one" : "NULL");
            return fmi2Error;
        }
        if (!(copy = malloc(strlen(value[i]) + 1))) return fail(c, "fmi2SetString", "out of memory");
        strcpy(copy, value[i]);
        slot = (char **)field(c, info);
        free(*slot);
        *slot = copy;
        note_set(c);
    }
    return fmi2OK;
}

/* ------------------------------------------------------------------ stepping */

fmi2Status fmi2SetRealInputDerivatives(fmi2Component comp, const fmi2ValueReference vr[],
                                       size_t nvr, const fmi2Integer order[],
                                       const fmi2Real value[])
{
    hg_instance *c = comp;
    size_t i;
    if (!hg_allowed(c, "fmi2SetRealInputDerivatives", BEFORE_RUN | ST_STEP_COMPLETE) ||
        check_array_args(c, "fmi2SetRealInputDerivatives", vr, nvr, value) ||
        check_array_args(c, "fmi2SetRealInputDerivatives", vr, nvr, order))
        return fmi2Error;
    for (i = 0; i < nvr; i++) {
        const hg_var_info *info = lookup(c, "fmi2SetRealInputDerivatives", vr[i], HG_REAL);
        if (!info) return fmi2Error;
        double *der = input_slot(&c->input_der, info->name);
        if (!der || order[i] != 1 || !isfinite(value[i])) {
            hg_log(c, fmi2Error, CAT_ERROR, "fmi2SetRealInputDerivatives: %s, order %d, value %g:"
                   " only finite first derivatives of inputs are accepted", info->name,
                   (int)order[i], value[i]);
            return fmi2Error;
        }
        *der = value[i];
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
    if (!hg_allowed(c, "fmi2GetRealOutputDerivatives", READABLE)) return fmi2Error;
    hg_log(c, fmi2Error, CAT_ERROR, "fmi2GetRealOutputDerivatives: not provided "
           "(maxOutputDerivativeOrder = 0)");
    return fmi2Error;
}

/* The model time; the start time while no model is set up. */
static double model_time(const hg_instance *c)
{
    return c->set_up && c->model ? hg_model_time(c->model) : c->start_time;
}

/* Inputs extrapolated with their derivatives must stay finite and in range over the step. */
static int check_extrapolation(hg_instance *c, double h)
{
    int r;
    for (r = 0; r < HG_NUM_VARS; r++) {
        const hg_var_info *info = &hg_var_table[r];
        double u, du, end;
        char value[96], range[96];
        if (info->causality != HG_INPUT || info->type != HG_REAL) continue;
        u = hg_real_value(c, info);
        du = derivative_of(c, info);
        end = u + du * h;
        if (du == 0.0 || (isfinite(end) && !(info->has_min && end < info->min) &&
                          !(info->has_max && end > info->max)))
            continue;
        quote_value(value, sizeof value, info, end);
        quote_range(range, sizeof range, info);
        hg_log(c, fmi2Error, CAT_ERROR, "fmi2DoStep: input %s = %g %s with derivative %g %s/s "
               "would reach %s over the step of %g s, outside its range %s", info->name, u,
               info->unit, du, info->unit, value, h, range);
        return -1;
    }
    return 0;
}

/* Checks fmi2DoStep's arguments against the FMU time, the stop time and the time resolution. */
static int check_step(hg_instance *c, double t, double h)
{
    double now = model_time(c);
    if (!isfinite(h) || h < 0.0 || !isfinite(t) || fabs(t - now) > 1e-9 * (1.0 + fabs(now))) {
        hg_log(c, fmi2Error, CAT_ERROR, "fmi2DoStep: communication point %.12g with step %g does "
               "not continue the FMU time %.12g (or is not finite / negative)", t, h, now);
        return -1;
    }
    if (h > MAX_COMM_STEP) {
        hg_log(c, fmi2Error, CAT_ERROR, "fmi2DoStep: communicationStepSize = %g s is longer than "
               "the limit of %g s", h, MAX_COMM_STEP);
        return -1;
    }
    if (h > 0.0 && fabs((now + h) - now - h) > TIME_RESOLUTION * h) {
        hg_log(c, fmi2Error, CAT_ERROR, "fmi2DoStep: communicationStepSize = %g s is below the "
               "resolution of the time t = %.17g s (t + h rounds off more than %g of it)", h, now,
               TIME_RESOLUTION);
        return -1;
    }
    if (check_extrapolation(c, h)) return -1;
    if (c->stop_defined && now + h > c->stop_time + 1e-9 * (1.0 + fabs(c->stop_time))) {
        hg_log(c, fmi2Error, CAT_ERROR, "fmi2DoStep: the step from t = %.12g s by %g s passes the "
               "stopTime %.12g s given to fmi2SetupExperiment", now, h, c->stop_time);
        return -1;
    }
    return 0;
}

/* A failed step: the instance goes to the error state with the last good outputs readable. */
static fmi2Status step_failed(hg_instance *c, const hg_vars *good, const char *why)
{
    char inputs[HG_ERRLEN / 2];
    describe_inputs(c, inputs, sizeof inputs);
    hg_vars_copy_results(&c->vars, good);
    hg_log(c, fmi2Error, CAT_ERROR, "fmi2DoStep: %s (inputs %s)", why, inputs);
    c->state = ST_ERROR;
    return fmi2Error;
}

fmi2Status fmi2DoStep(fmi2Component comp, fmi2Real t, fmi2Real h, fmi2Boolean no_prior)
{
    hg_instance *c = comp;
    char err[HG_ERRLEN];
    hg_vars good;
    const hg_var_info *bad;
    (void)no_prior;
    if (!hg_allowed(c, "fmi2DoStep", ST_STEP_COMPLETE)) return fmi2Error;
    if (!c->set_up || !c->model) return fail(c, "fmi2DoStep", "the model is not set up");
    if (check_step(c, t, h)) return fmi2Error;
    hg_log(c, fmi2OK, CAT_ALL, "fmi2DoStep: t = %.9g s, h = %g s", t, h);
    good = c->vars; /* shallow copy: only its results are ever copied back */
    if (h > 0.0 && hg_model_step(c->model, &c->vars, &c->input_der, h, err, sizeof err))
        return step_failed(c, &good, err);
    memset(&c->input_der, 0, sizeof c->input_der); /* derivatives apply to one step */
    if ((bad = hg_first_nonfinite(c, 0)) != NULL) {
        snprintf(err, sizeof err, "output %s became %g at t = %.9g s", bad->name,
                 hg_real_value(c, bad), hg_model_time(c->model));
        return step_failed(c, &good, err);
    }
    return fmi2OK;
}

fmi2Status fmi2CancelStep(fmi2Component comp)
{
    hg_instance *c = comp;
    if (!hg_allowed(c, "fmi2CancelStep", ST_STEP_COMPLETE)) return fmi2Error;
    hg_log(c, fmi2Error, CAT_ERROR, "fmi2CancelStep: steps are synchronous, nothing to cancel");
    return fmi2Error;
}

/* ------------------------------------------------------------------ status */

static fmi2Status status_query(hg_instance *c, const char *fn)
{
    if (!hg_allowed(c, fn, ST_STEP_COMPLETE | ST_TERMINATED | ST_ERROR)) return fmi2Error;
    return fmi2OK;
}

/* A status query's value pointer must not be NULL. */
static int value_given(hg_instance *c, const char *fn, const void *value)
{
    if (value) return 1;
    hg_log(c, fmi2Error, CAT_ERROR, "%s: the value pointer is NULL", fn);
    return 0;
}

fmi2Status fmi2GetStatus(fmi2Component comp, const fmi2StatusKind s, fmi2Status *value)
{
    hg_instance *c = comp;
    if (status_query(c, "fmi2GetStatus") != fmi2OK || !value_given(c, "fmi2GetStatus", value))
        return fmi2Error;
    if (s != fmi2DoStepStatus) return fmi2Discard;
    *value = c->state == ST_ERROR ? fmi2Error : fmi2OK;
    return fmi2OK;
}

fmi2Status fmi2GetRealStatus(fmi2Component comp, const fmi2StatusKind s, fmi2Real *value)
{
    hg_instance *c = comp;
    if (status_query(c, "fmi2GetRealStatus") != fmi2OK ||
        !value_given(c, "fmi2GetRealStatus", value))
        return fmi2Error;
    if (s != fmi2LastSuccessfulTime) return fmi2Discard;
    *value = model_time(c);
    return fmi2OK;
}

fmi2Status fmi2GetIntegerStatus(fmi2Component comp, const fmi2StatusKind s, fmi2Integer *value)
{
    (void)s;
    (void)value;
    return status_query(comp, "fmi2GetIntegerStatus") == fmi2OK ? fmi2Discard : fmi2Error;
}

fmi2Status fmi2GetBooleanStatus(fmi2Component comp, const fmi2StatusKind s, fmi2Boolean *value)
{
    hg_instance *c = comp;
    if (status_query(c, "fmi2GetBooleanStatus") != fmi2OK ||
        !value_given(c, "fmi2GetBooleanStatus", value))
        return fmi2Error;
    if (s != fmi2Terminated) return fmi2Discard;
    *value = fmi2False; /* the model never asks to end the simulation */
    return fmi2OK;
}

fmi2Status fmi2GetStringStatus(fmi2Component comp, const fmi2StatusKind s, fmi2String *value)
{
    (void)s;
    (void)value;
    return status_query(comp, "fmi2GetStringStatus") == fmi2OK ? fmi2Discard : fmi2Error;
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
    if (!hg_allowed(c, "fmi2GetDirectionalDerivative", READABLE)) return fmi2Error;
    hg_log(c, fmi2Error, CAT_ERROR, "fmi2GetDirectionalDerivative: not provided");
    return fmi2Error;
}
