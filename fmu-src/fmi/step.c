/* The communication step of either FMI version: its checks against the FMU time, the stop time,
 * the time resolution and the inputs' ranges, and the model's step. */
#include <math.h>
#include <string.h>

#include "fmi/instance.h"

#define MAX_COMM_STEP 1000.0 /* [s] longest communication step (docs/integration.md, limits) */
#define TIME_RESOLUTION 1e-6 /* largest relative rounding error of t + h accepted by a step */

/* Inputs extrapolated with their derivatives must stay finite and in range over the step. */
static int check_extrapolation(hg_instance *c, const char *fn, double h)
{
    int k;
    for (k = 0; k < HG_NUM_INPUTS; k++) {
        const hg_var_info *info = &hg_var_table[hg_input_vr[k]];
        double u = hg_real_value(c, info), du = hg_derivative_of(c, info), end = u + du * h;
        char value[96], range[96];
        if (du == 0.0 || (isfinite(end) && !(info->has_min && end < info->min) &&
                          !(info->has_max && end > info->max)))
            continue;
        hg_quote_value(value, sizeof value, info, end);
        hg_quote_range(range, sizeof range, info);
        hg_error(c, fn, "input %s = %g %s with derivative %g %s/s would reach %s over the step "
                 "of %g s, outside its range %s", info->name, u, info->unit, du, info->unit,
                 value, h, range);
        return -1;
    }
    return 0;
}

/* Checks the step's arguments against the FMU time, the stop time and the time resolution. */
static int check_step(hg_instance *c, const char *fn, double t, double h)
{
    double now = hg_instance_time(c);
    if (!isfinite(h) || h < 0.0 || !isfinite(t) || fabs(t - now) > 1e-9 * (1.0 + fabs(now))) {
        hg_error(c, fn, "communication point %.12g with step %g does not continue the FMU time "
                 "%.12g (or is not finite / negative)", t, h, now);
        return -1;
    }
    if (h > MAX_COMM_STEP) {
        hg_error(c, fn, "communicationStepSize = %g s is longer than the limit of %g s", h,
                 MAX_COMM_STEP);
        return -1;
    }
    if (h > 0.0 && fabs((now + h) - now - h) > TIME_RESOLUTION * h) {
        hg_error(c, fn, "communicationStepSize = %g s is below the resolution of the time t = "
                 "%.17g s (t + h rounds off more than %g of it)", h, now, TIME_RESOLUTION);
        return -1;
    }
    if (check_extrapolation(c, fn, h)) return -1;
    if (c->stop_defined && now + h > c->stop_time + 1e-9 * (1.0 + fabs(c->stop_time))) {
        hg_error(c, fn, "the step from t = %.12g s by %g s passes the stopTime %.12g s given to "
                 "the experiment set-up", now, h, c->stop_time);
        return -1;
    }
    return 0;
}

/* A failed step: the instance goes to the error state; the model stays where the step began,
 * so the last good outputs stay readable. */
static hg_status step_failed(hg_instance *c, const char *fn, const char *why)
{
    char inputs[HG_ERRLEN / 2];
    hg_describe_inputs(c, inputs, sizeof inputs);
    hg_error(c, fn, "%s (inputs %s)", why, inputs);
    c->state = ST_ERROR;
    return HG_ERROR;
}

/* A step longer than the load mode's coupling holds: a warning naming both, once per instance. */
static void warn_long_step(hg_instance *c, const char *fn, double h)
{
    double limit = hg_model_comm_step_limit(c->model);
    if (c->step_warned || !(limit > 0.0) || h <= limit) return;
    c->step_warned = 1;
    hg_log(c, HG_WARNING, CAT_WARNING, "%s: communication step %g s is longer than %g s, the "
           "longest the half-shaft coupling is measured to hold with k_hs = %g N.m/rad (two fifths "
           "of the half-shaft mode's period; docs/integration.md); shorter steps keep its error "
           "bounded", fn, h, limit, c->vars.k_hs);
}

/* The outputs are computed when read (hg_instance_outputs), not after every step. */
hg_status hg_do_step(hg_instance *c, const char *fn, double t, double h)
{
    char err[HG_ERRLEN];
    if (!hg_allowed(c, fn, ST_STEP_COMPLETE)) return HG_ERROR;
    if (!c->set_up || !c->model) return hg_fail(c, fn, "the model is not set up");
    if (check_step(c, fn, t, h)) return HG_ERROR;
    hg_log(c, HG_OK, CAT_ALL, "%s: t = %.9g s, h = %g s", fn, t, h);
    warn_long_step(c, fn, h);
    if (h > 0.0 && hg_model_step(c->model, &c->vars, &c->input_der, h, err, sizeof err))
        return step_failed(c, fn, err);
    memset(&c->input_der, 0, sizeof c->input_der); /* derivatives apply to one step */
    return HG_OK;
}
