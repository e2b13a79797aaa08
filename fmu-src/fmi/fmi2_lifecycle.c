/* FMI 2.0 instance life cycle: instantiation, logging categories, experiment set-up,
 * initialization, termination, reset and freeing. Physics lives in model/. */
#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fmi/instance.h"

const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char *fmi2GetVersion(void) { return fmi2Version; }

static int set_categories(hg_instance *c, const char *fn, fmi2Boolean on, size_t n,
                          const fmi2String cats[])
{
    size_t i;
    int k;
    if (n == 0) {
        for (k = 0; k < N_CATEGORIES; k++) c->log_on[k] = on;
        c->log_on[CAT_WARNING] = c->log_on[CAT_ERROR] = 1; /* problems are always reported */
        return 0;
    }
    if (!cats) {
        hg_error(c, fn, "nCategories = %zu but categories is NULL", n);
        return -1;
    }
    for (i = 0; i < n; i++) {
        for (k = 0; k < N_CATEGORIES; k++)
            if (cats[i] && strcmp(cats[i], hg_category_names[k]) == 0) break;
        if (k == N_CATEGORIES) {
            hg_error(c, fn, "unknown log category '%s'", cats[i] ? cats[i] : "(null)");
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
    if (!hg_allowed(c, __func__, ST_ANY)) return fmi2Error;
    return set_categories(c, __func__, on, n, cats) ? fmi2Error : fmi2OK;
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

static int check_instantiate_args(hg_instance *c, const char *fn, fmi2String name,
                                  fmi2Type type, fmi2String guid)
{
    if (blank(name)) {
        hg_error(c, fn, "instanceName '%s' is empty or blank", name ? name : "(null)");
        return -1;
    }
    if (type != fmi2CoSimulation) {
        hg_error(c, fn, "this FMU supports co-simulation only");
        return -1;
    }
    if (!guid || (strcmp(guid, HG_GUID) != 0 && strcmp(guid, HG_GUID_INTENUM) != 0)) {
        hg_error(c, fn, "GUID '%s' does not match this binary's '%s'", guid ? guid : "(null)",
                 HG_GUID);
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
    set_categories(c, __func__, logging_on, 0, NULL);
    c->name = malloc(strlen(name ? name : "") + 1);
    if (!c->name) {
        free(c);
        return NULL;
    }
    strcpy(c->name, name ? name : "");
    if (check_instantiate_args(c, __func__, name, type, guid) || reset_instance(c)) {
        free_instance(c);
        return NULL;
    }
    if (resources && *resources &&
        !(c->resource_dir = hg_uri_to_path(resources, why, sizeof why))) {
        hg_error(c, __func__, "fmuResourceLocation: %s", why);
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
    if (!hg_allowed(c, __func__, ST_INSTANTIATED)) return fmi2Error;
    if (!isfinite(start) || (stop_defined && !(stop >= start))) {
        hg_error(c, __func__, "startTime = %g, stopTime = %g: need a finite start not after the "
                 "stop", start, stop);
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
    if (!hg_allowed(c, __func__, ST_INSTANTIATED)) return fmi2Error;
    c->state = ST_INITIALIZATION;
    return fmi2OK;
}

fmi2Status fmi2ExitInitializationMode(fmi2Component comp)
{
    hg_instance *c = comp;
    if (!hg_allowed(c, __func__, ST_INITIALIZATION)) return fmi2Error;
    if (hg_ensure_set_up(c, __func__) != fmi2OK) return fmi2Error;
    c->state = ST_STEP_COMPLETE;
    return fmi2OK;
}

fmi2Status fmi2Terminate(fmi2Component comp)
{
    hg_instance *c = comp;
    if (!hg_allowed(c, __func__, ST_STEP_COMPLETE | ST_ERROR)) return fmi2Error;
    c->state = ST_TERMINATED;
    return fmi2OK;
}

fmi2Status fmi2Reset(fmi2Component comp)
{
    hg_instance *c = comp;
    if (!hg_allowed(c, __func__, ST_ANY)) return fmi2Error;
    if (reset_instance(c)) return hg_fail(c, __func__, "out of memory");
    return fmi2OK;
}
