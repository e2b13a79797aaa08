/* The FMI layer's shared services: logging, the state machine, the model's set-up and checks on
 * its results (see instance.h). */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "fmi/instance.h"
#include "model/exchange.h"

const char *const hg_category_names[N_CATEGORIES] = {"logEvents", "logStatusWarning",
                                                     "logStatusError", "logAll"};

/* ------------------------------------------------------------------ logging */

static int logging(const hg_instance *c, int category)
{
    return c && c->emit && (c->log_on[category] || c->log_on[CAT_ALL]);
}

/* Formats "fn: message" (or just the message when fn is NULL) and passes it on. */
static void vlog(hg_instance *c, hg_status status, int category, const char *fn,
                 const char *fmt, va_list ap)
{
    char msg[HG_ERRLEN];
    int n = fn ? snprintf(msg, sizeof msg, "%s: ", fn) : 0;
    if (n < 0 || (size_t)n >= sizeof msg) n = 0;
    vsnprintf(msg + n, sizeof msg - (size_t)n, fmt, ap);
    c->emit(c, status, hg_category_names[category], msg);
}

void hg_log(hg_instance *c, hg_status status, int category, const char *fmt, ...)
{
    va_list ap;
    if (!logging(c, category)) return;
    va_start(ap, fmt);
    vlog(c, status, category, NULL, fmt, ap);
    va_end(ap);
}

void hg_error(hg_instance *c, const char *fn, const char *fmt, ...)
{
    va_list ap;
    if (!logging(c, CAT_ERROR)) return;
    va_start(ap, fmt);
    vlog(c, HG_ERROR, CAT_ERROR, fn, fmt, ap);
    va_end(ap);
}

hg_status hg_fail(hg_instance *c, const char *fn, const char *why)
{
    hg_error(c, fn, "%s", why);
    c->state = ST_ERROR;
    return HG_ERROR;
}

static void model_log(void *ctx, const char *category, const char *message)
{
    hg_instance *c = ctx;
    int k;
    for (k = 0; k < N_CATEGORIES; k++)
        if (strcmp(category, hg_category_names[k]) == 0) break;
    if (k == N_CATEGORIES) k = CAT_ALL;
    hg_log(c, k == CAT_WARNING ? HG_WARNING : k == CAT_ERROR ? HG_ERROR : HG_OK, k, "%s",
           message);
}

/* ------------------------------------------------------------------ state machine */

static const char *state_name(hg_fmi_state s)
{
    switch (s) {
    case ST_INSTANTIATED: return "instantiated";
    case ST_INITIALIZATION: return "initialization mode";
    case ST_STEP_COMPLETE: return "step complete";
    case ST_TERMINATED: return "terminated";
    case ST_EVENT_MODE: return "event mode";
    case ST_CONTINUOUS_TIME: return "continuous-time mode";
    default: return "error";
    }
}

int hg_allowed(hg_instance *c, const char *fn, int states)
{
    if (!c) return 0;
    if (c->state & states) return 1;
    hg_log(c, HG_ERROR, CAT_ERROR, "%s is not allowed in state '%s'", fn, state_name(c->state));
    return 0;
}

int hg_interface(hg_instance *c, const char *fn, int model_exchange)
{
    if (!c) return 0;
    if (c->model_exchange == model_exchange) return 1;
    hg_error(c, fn, "is a %s function, and this instance was instantiated for %s",
             model_exchange ? "Model Exchange" : "co-simulation",
             c->model_exchange ? "Model Exchange" : "co-simulation");
    return 0;
}

/* ------------------------------------------------------------------ variables and results */

double hg_real_value(const hg_instance *c, const hg_var_info *info)
{
    return *(const double *)hg_var_cptr(&c->vars, info);
}

double hg_derivative_of(const hg_instance *c, const hg_var_info *info)
{
    return info->input >= 0 ? hg_input_value(&c->input_der, info->input) : 0.0;
}

void hg_describe_inputs(const hg_instance *c, char *out, size_t len)
{
    size_t used = 0;
    int k;
    out[0] = '\0';
    for (k = 0; k < HG_NUM_INPUTS && used < len; k++) {
        const hg_var_info *info = &hg_var_table[hg_input_vr[k]];
        double du = hg_derivative_of(c, info);
        int n = du != 0.0
                    ? snprintf(out + used, len - used, "%s%s = %g changing at %g /s",
                               used ? ", " : "", info->name, hg_real_value(c, info), du)
                    : snprintf(out + used, len - used, "%s%s = %g", used ? ", " : "", info->name,
                               hg_real_value(c, info));
        if (n < 0) break;
        used += (size_t)n;
    }
}

void hg_quote_value(char *buf, size_t n, const hg_var_info *info, double v)
{
    int len = snprintf(buf, n, "%.10g%s%s", v, *info->unit ? " " : "", info->unit);
    if (info->display_unit && len > 0 && (size_t)len < n)
        snprintf(buf + len, n - (size_t)len, " (%.6g %s)",
                 info->display_factor * v + info->display_offset, info->display_unit);
}

void hg_quote_range(char *buf, size_t n, const hg_var_info *info)
{
    snprintf(buf, n, "[%g, %g]%s%s", info->has_min ? info->min : -HUGE_VAL,
             info->has_max ? info->max : HUGE_VAL, *info->unit ? " " : "", info->unit);
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

/* ------------------------------------------------------------------ the model */

hg_model *hg_instance_model(hg_instance *c)
{
    if (!c->model) c->model = hg_model_new(c->resource_dir, model_log, c);
    return c->model;
}

hg_status hg_instance_output(hg_instance *c, const char *fn, const hg_var_info *info)
{
    if (c->set_up && c->model && !hg_model_outputs_current(c->model, info->outset))
        hg_model_outputs(c->model, &c->vars, info->outset);
    if (info->type != HG_REAL || isfinite(hg_real_value(c, info))) return HG_OK;
    hg_error(c, fn, "output %s became %g at t = %.9g s", info->name, hg_real_value(c, info),
             hg_instance_time(c));
    c->state = ST_ERROR;
    return HG_ERROR;
}

double hg_instance_time(const hg_instance *c)
{
    return c->set_up && c->model ? hg_model_time(c->model) : c->start_time;
}

hg_status hg_ensure_set_up(hg_instance *c, const char *fn)
{
    char err[HG_ERRLEN];
    const hg_var_info *bad;
    hg_vars before;
    if (c->set_up) return HG_OK;
    if (!c->resource_dir) {
        hg_error(c, fn, "no fmuResourceLocation was given at instantiation, so the gear-set and "
                 "lubricant data cannot be found");
        return HG_ERROR;
    }
    if (!hg_instance_model(c)) {
        hg_error(c, fn, "out of memory");
        return HG_ERROR;
    }
    before = c->vars; /* shallow copy: only its results are ever copied back */
    if (hg_model_setup(c->model, &c->vars, c->start_time, err, sizeof err)) {
        hg_vars_copy_results(&c->vars, &before);
        hg_error(c, fn, "%s", err);
        return HG_ERROR;
    }
    if ((bad = hg_first_nonfinite(c, 1)) != NULL) {
        double value = hg_real_value(c, bad);
        hg_vars_copy_results(&c->vars, &before);
        hg_describe_inputs(c, err, sizeof err);
        hg_error(c, fn, "%s = %g at the start: the parameters and inputs (%s) are beyond the "
                 "model's reach", bad->name, value, err);
        return HG_ERROR;
    }
    c->set_up = 1;
    if (c->model_exchange) hg_exchange_begin(c->model, &c->vars);
    return HG_OK;
}
