/* Variable access of either FMI version, one variable at a time, through the generated variable
 * table (value reference r = hg_var_table[r]); the adapters loop over the host's arrays. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fmi/instance.h"
#include "model/exchange.h"

const hg_var_info *hg_lookup(hg_instance *c, const char *fn, hg_vr vr,
                             hg_base_type type)
{
    static const char *const type_names[] = {"Real", "Integer", "Boolean", "String"};
    if (vr >= HG_NUM_VARS) {
        hg_error(c, fn, "unknown value reference %u", (unsigned)vr);
        return NULL;
    }
    if (hg_var_table[vr].type != type) {
        hg_error(c, fn, "value reference %u is '%s', of type %s", (unsigned)vr,
                 hg_var_table[vr].name, type_names[hg_var_table[vr].type]);
        return NULL;
    }
    return &hg_var_table[vr];
}

int hg_check_array_args(hg_instance *c, const char *fn, const void *vr, size_t nvr,
                        const void *values)
{
    if (nvr > 0 && (!vr || !values)) {
        hg_error(c, fn, "NULL value-reference or value array");
        return -1;
    }
    return 0;
}

/* ------------------------------------------------------------------ get */

hg_status hg_prepare_get(hg_instance *c, const char *fn, const void *vr, size_t nvr,
                         const void *values)
{
    if (!hg_allowed(c, fn, ST_READABLE) || hg_check_array_args(c, fn, vr, nvr, values))
        return HG_ERROR;
    if (c->state == ST_INITIALIZATION) return hg_ensure_set_up(c, fn);
    return HG_OK;
}

/* The variable's field has the size of the FMI type (fmi2Real / fmi3Float64, fmi2Integer /
 * fmi3Int32, fmi2String / fmi3String); Booleans are converted by the FMI 3.0 adapter. */
hg_status hg_get_value(hg_instance *c, const char *fn, hg_base_type type, hg_vr vr, void *value)
{
    const hg_var_info *info = hg_lookup(c, fn, vr, type);
    const void *field;
    int computed = info && (info->causality == HG_OUTPUT || info->causality == HG_LOCAL);
    if (!info || (computed && hg_instance_output(c, fn, info) != HG_OK)) return HG_ERROR;
    field = hg_var_cptr(&c->vars, info);
    if (type == HG_REAL) /* by type, not a memcpy of its size: a host reads many at a time */
        *(double *)value = *(const double *)field;
    else if (type == HG_STRING)
        *(char **)value = *(char *const *)field;
    else
        *(int *)value = *(const int *)field;
    return HG_OK;
}

/* ------------------------------------------------------------------ set */

hg_status hg_prepare_set(hg_instance *c, const char *fn, const void *vr, size_t nvr,
                         const void *values)
{
    return hg_allowed(c, fn, ST_BEFORE_RUN | ST_RUNNING) &&
                   !hg_check_array_args(c, fn, vr, nvr, values)
               ? HG_OK
               : HG_ERROR;
}

/* May this variable be set now? Parameters before the run, inputs always. */
static int settable(hg_instance *c, const char *fn, const hg_var_info *info)
{
    if (info->causality == HG_INPUT) return 1;
    if (info->causality == HG_PARAMETER && (c->state & ST_BEFORE_RUN)) return 1;
    hg_error(c, fn, "'%s' cannot be set %s", info->name,
             info->causality == HG_PARAMETER ? "after initialization (it is a fixed parameter)"
                                             : "(it is computed by the FMU)");
    return 0;
}

static int check_range(hg_instance *c, const char *fn, const hg_var_info *info, double v)
{
    char value[96], range[96];
    if (!isfinite(v)) {
        hg_error(c, fn, "%s = %g is not a finite number", info->name, v);
        return -1;
    }
    if ((info->has_min && v < info->min) || (info->has_max && v > info->max)) {
        hg_quote_value(value, sizeof value, info, v);
        hg_quote_range(range, sizeof range, info);
        hg_error(c, fn, "%s = %s is outside its range %s", info->name, value, range);
        return -1;
    }
    return 0;
}

/* Before the run, parameters and initial inputs define the start: set up again when asked. In
 * Model Exchange the model's right-hand side takes a new input at once. */
static void note_set(hg_instance *c, const hg_var_info *info)
{
    if (c->state & ST_BEFORE_RUN)
        c->set_up = 0;
    else if (c->model_exchange && c->set_up && info->causality == HG_INPUT)
        hg_exchange_inputs(c->model, &c->vars);
}

hg_status hg_set_number(hg_instance *c, const char *fn, hg_base_type type, hg_vr vr, double x,
                        int k)
{
    const hg_var_info *info = hg_lookup(c, fn, vr, type);
    if (type != HG_REAL) x = k;
    if (!info || !settable(c, fn, info) || check_range(c, fn, info, x)) return HG_ERROR;
    if (type == HG_REAL)
        *(double *)hg_var_ptr(&c->vars, info) = x;
    else
        *(int *)hg_var_ptr(&c->vars, info) = type == HG_BOOLEAN ? k != 0 : k;
    note_set(c, info);
    return HG_OK;
}

hg_status hg_set_string(hg_instance *c, const char *fn, hg_vr vr, const char *value)
{
    const hg_var_info *info = hg_lookup(c, fn, vr, HG_STRING);
    char **slot, *copy;
    if (!info || !settable(c, fn, info)) return HG_ERROR;
    if (!value || strlen(value) > 4095) {
        hg_error(c, fn, "%s must be a string of at most 4095 characters (got %s)", info->name,
                 value ? "a longer one" : "NULL");
        return HG_ERROR;
    }
    if (!(copy = malloc(strlen(value) + 1))) return hg_fail(c, fn, "out of memory");
    strcpy(copy, value);
    slot = (char **)hg_var_ptr(&c->vars, info);
    free(*slot);
    *slot = copy;
    note_set(c, info);
    return HG_OK;
}
