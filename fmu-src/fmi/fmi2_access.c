/* FMI 2.0 variable access: fmi2Get/Set{Real,Integer,Boolean,String} through the generated
 * variable table (value reference r = hg_var_table[r]). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fmi/instance.h"

const hg_var_info *hg_lookup(hg_instance *c, const char *fn, fmi2ValueReference vr,
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

static fmi2Status prepare_get(hg_instance *c, const char *fn, const void *vr, size_t nvr,
                              const void *values)
{
    if (!hg_allowed(c, fn, ST_READABLE) || hg_check_array_args(c, fn, vr, nvr, values))
        return fmi2Error;
    if (c->state == ST_INITIALIZATION) return hg_ensure_set_up(c, fn);
    return fmi2OK;
}

/* Copies each variable's field into values[i]: a double, an int or a string pointer, whose
 * sizes the FMI types share (fmi2Real, fmi2Integer / fmi2Boolean, fmi2String). */
static fmi2Status get_values(hg_instance *c, const char *fn, hg_base_type type,
                             const fmi2ValueReference vr[], size_t nvr, void *values, size_t size)
{
    size_t i;
    if (prepare_get(c, fn, vr, nvr, values) != fmi2OK) return fmi2Error;
    for (i = 0; i < nvr; i++) {
        const hg_var_info *info = hg_lookup(c, fn, vr[i], type);
        if (!info || (info->causality == HG_OUTPUT && hg_instance_output(c, fn, info) != fmi2OK))
            return fmi2Error;
        memcpy((char *)values + i * size, hg_var_cptr(&c->vars, info), size);
    }
    return fmi2OK;
}

fmi2Status fmi2GetReal(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                       fmi2Real value[])
{
    return get_values(comp, __func__, HG_REAL, vr, nvr, value, sizeof *value);
}

fmi2Status fmi2GetInteger(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                          fmi2Integer value[])
{
    return get_values(comp, __func__, HG_INTEGER, vr, nvr, value, sizeof *value);
}

fmi2Status fmi2GetBoolean(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                          fmi2Boolean value[])
{
    return get_values(comp, __func__, HG_BOOLEAN, vr, nvr, value, sizeof *value);
}

fmi2Status fmi2GetString(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                         fmi2String value[])
{
    return get_values(comp, __func__, HG_STRING, vr, nvr, value, sizeof *value);
}

/* ------------------------------------------------------------------ set */

static int prepare_set(hg_instance *c, const char *fn, const void *vr, size_t nvr,
                       const void *values)
{
    return hg_allowed(c, fn, ST_BEFORE_RUN | ST_STEP_COMPLETE) &&
           !hg_check_array_args(c, fn, vr, nvr, values);
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

/* Before the run, parameters and initial inputs define the start: set up again when asked. */
static void note_set(hg_instance *c)
{
    if (c->state & ST_BEFORE_RUN) c->set_up = 0;
}

/* Sets Real (values: fmi2Real[]) or Integer / Boolean (values: int[]) variables. */
static fmi2Status set_numbers(hg_instance *c, const char *fn, hg_base_type type,
                              const fmi2ValueReference vr[], size_t nvr, const void *values)
{
    size_t i;
    if (!prepare_set(c, fn, vr, nvr, values)) return fmi2Error;
    for (i = 0; i < nvr; i++) {
        const hg_var_info *info = hg_lookup(c, fn, vr[i], type);
        int k = type == HG_REAL ? 0 : ((const int *)values)[i];
        double x = type == HG_REAL ? ((const double *)values)[i] : k;
        if (!info || !settable(c, fn, info) || check_range(c, fn, info, x)) return fmi2Error;
        if (type == HG_REAL)
            *(double *)hg_var_ptr(&c->vars, info) = x;
        else
            *(int *)hg_var_ptr(&c->vars, info) = type == HG_BOOLEAN ? k != 0 : k;
        note_set(c);
    }
    return fmi2OK;
}

fmi2Status fmi2SetReal(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                       const fmi2Real value[])
{
    return set_numbers(comp, __func__, HG_REAL, vr, nvr, value);
}

fmi2Status fmi2SetInteger(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                          const fmi2Integer value[])
{
    return set_numbers(comp, __func__, HG_INTEGER, vr, nvr, value);
}

fmi2Status fmi2SetBoolean(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                          const fmi2Boolean value[])
{
    return set_numbers(comp, __func__, HG_BOOLEAN, vr, nvr, value);
}

fmi2Status fmi2SetString(fmi2Component comp, const fmi2ValueReference vr[], size_t nvr,
                         const fmi2String value[])
{
    hg_instance *c = comp;
    size_t i;
    if (!prepare_set(c, __func__, vr, nvr, value)) return fmi2Error;
    for (i = 0; i < nvr; i++) {
        const hg_var_info *info = hg_lookup(c, __func__, vr[i], HG_STRING);
        char **slot, *copy;
        if (!info || !settable(c, __func__, info)) return fmi2Error;
        if (!value[i] || strlen(value[i]) > 4095) {
            hg_error(c, __func__, "%s must be a string of at most 4095 characters (got %s)",
                     info->name, value[i] ? "a longer one" : "NULL");
            return fmi2Error;
        }
        if (!(copy = malloc(strlen(value[i]) + 1))) return hg_fail(c, __func__, "out of memory");
        strcpy(copy, value[i]);
        slot = (char **)hg_var_ptr(&c->vars, info);
        free(*slot);
        *slot = copy;
        note_set(c);
    }
    return fmi2OK;
}
