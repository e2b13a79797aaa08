/* The instance's life cycle, of either FMI version: instantiation, log categories, experiment
 * set-up, initialization, termination, reset and freeing. Physics lives in model/. */
#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fmi/instance.h"
#include "model/table_store.h"

static int set_categories(hg_instance *c, const char *fn, int on, size_t n,
                          const char *const cats[])
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

hg_status hg_set_debug_logging(hg_instance *c, const char *fn, int on, size_t n,
                               const char *const cats[])
{
    if (!hg_allowed(c, fn, ST_ANY)) return HG_ERROR;
    return set_categories(c, fn, on, n, cats) ? HG_ERROR : HG_OK;
}

void hg_free_instance(hg_instance *c)
{
    if (!c) return;
    hg_model_free(c->model);
    hg_store_detach(); /* the instance's own hold (hg_instantiate) */
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

static int check_instantiate_args(hg_instance *c, const char *fn, const char *name,
                                  const char *token, const char *const tokens[])
{
    int k;
    if (blank(name)) {
        hg_error(c, fn, "instanceName '%s' is empty or blank", name ? name : "(null)");
        return -1;
    }
    for (k = 0; token && tokens[k]; k++)
        if (strcmp(token, tokens[k]) == 0) return 0;
    hg_error(c, fn, "GUID '%s' does not match this binary's '%s'", token ? token : "(null)",
             tokens[0]);
    return -1;
}

/* A copy of the resource location: a file:// URI (FMI 2.0) or a path (FMI 3.0), without the
 * trailing separators. NULL (why filled) when it cannot be one. */
static char *resource_dir(const char *resources, int uri, char *why, size_t whylen)
{
    char *path;
    size_t n;
    if (uri) return hg_uri_to_path(resources, why, whylen);
    n = strlen(resources);
    if (!(path = malloc(n + 1))) {
        hg_errorf(why, whylen, "out of memory");
        return NULL;
    }
    strcpy(path, resources);
    while (n > 1 && (path[n - 1] == '/' || path[n - 1] == '\\')) path[--n] = '\0';
    return path;
}

hg_instance *hg_instantiate(const char *fn, const char *name, const char *token,
                            const char *const tokens[], const char *resources, int uri,
                            hg_emit_fn emit, hg_any_fn logger, void *env, int logging_on)
{
    hg_instance *c;
    char why[HG_ERRLEN];
    if (!(c = calloc(1, sizeof *c))) return NULL;
    c->emit = logger ? emit : NULL;
    c->logger = logger;
    c->env = env;
    set_categories(c, fn, logging_on, 0, NULL);
    c->name = malloc(strlen(name ? name : "") + 1);
    if (!c->name) {
        free(c);
        return NULL;
    }
    strcpy(c->name, name ? name : "");
    /* the instance holds the process's shared tables for its whole life: its model is freed and
     * made again at fmi2Reset, and the store would empty if that model were its only holder */
    hg_store_attach();
    if (check_instantiate_args(c, fn, name, token, tokens) || reset_instance(c)) {
        hg_free_instance(c);
        return NULL;
    }
    if (resources && *resources &&
        !(c->resource_dir = resource_dir(resources, uri, why, sizeof why))) {
        hg_error(c, fn, "%s: %s", uri ? "fmuResourceLocation" : "resourcePath", why);
        hg_free_instance(c);
        return NULL;
    }
    return c;
}

hg_status hg_setup_experiment(hg_instance *c, const char *fn, double start, int stop_defined,
                              double stop)
{
    if (!hg_allowed(c, fn, ST_INSTANTIATED)) return HG_ERROR;
    if (!isfinite(start) || (stop_defined && !(stop >= start))) {
        hg_error(c, fn, "startTime = %g, stopTime = %g: need a finite start not after the "
                 "stop", start, stop);
        return HG_ERROR;
    }
    c->start_time = start;
    c->set_up = 0; /* a model set up early (Model Exchange's nominals) starts at start */
    c->stop_defined = stop_defined != 0;
    c->stop_time = c->stop_defined ? stop : 0.0;
    return HG_OK;
}

hg_status hg_enter_initialization(hg_instance *c, const char *fn)
{
    if (!hg_allowed(c, fn, ST_INSTANTIATED)) return HG_ERROR;
    c->state = ST_INITIALIZATION;
    return HG_OK;
}

hg_status hg_exit_initialization(hg_instance *c, const char *fn)
{
    if (!hg_allowed(c, fn, ST_INITIALIZATION)) return HG_ERROR;
    if (hg_ensure_set_up(c, fn) != HG_OK) return HG_ERROR;
    c->state = c->model_exchange ? ST_EVENT_MODE : ST_STEP_COMPLETE;
    return HG_OK;
}

hg_status hg_terminate(hg_instance *c, const char *fn)
{
    if (!hg_allowed(c, fn, ST_RUNNING | ST_ERROR)) return HG_ERROR;
    c->state = ST_TERMINATED;
    return HG_OK;
}

hg_status hg_reset(hg_instance *c, const char *fn)
{
    if (!hg_allowed(c, fn, ST_ANY)) return HG_ERROR;
    if (reset_instance(c)) return hg_fail(c, fn, "out of memory");
    return HG_OK;
}
