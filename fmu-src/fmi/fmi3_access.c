/* FMI 3.0 variable access: fmi3Get/Set{Float64,Int32,Int64,Boolean,String} (adapters over
 * access.c). A value reference names a scalar or an array (the per-pair outputs, whose
 * elements are consecutive in the variable table, hg_fmi3_vars), the independent variable
 * time or an event indicator (Model Exchange); nValues must be the number of elements the value
 * references name. Enumerations are read and set as Int64, as FMI 3.0 has it. */
#include <limits.h>
#include <string.h>

#include "fmi/instance.h"
#include "fmi3Functions.h"

/* The FMI 3.0 types this FMU has (the table's base type, plus Enumeration as Int64). */
typedef enum { F64, I32, ENUM64, BOOL, STR } kind;

static const char *const kind_names[] = {"Float64", "Int32", "Enumeration (Int64)", "Boolean",
                                         "String"};
static const hg_base_type kind_base[] = {HG_REAL, HG_INTEGER, HG_INTEGER, HG_BOOLEAN, HG_STRING};

static int is_indicator(hg_vr vr)
{
    return vr >= HG_FMI3_VR_INDICATOR && vr < HG_FMI3_VR_INDICATOR + HG_NUM_EVENT_INDICATORS;
}

/* Time or an event indicator (the variables beyond the table) into *x. */
static hg_status beyond_table(hg_instance *c, const char *fn, hg_vr vr, double *x)
{
    double z[HG_NUM_EVENT_INDICATORS + 1];
    if (vr == HG_FMI3_VR_TIME) {
        *x = hg_instance_time(c);
        return HG_OK;
    }
    if (hg_me_indicators(c, fn, z, HG_NUM_EVENT_INDICATORS) != HG_OK) return HG_ERROR;
    *x = z[vr - HG_FMI3_VR_INDICATOR];
    return HG_OK;
}

static kind kind_of(hg_vr vr)
{
    static const kind of_base[] = {F64, I32, BOOL, STR};
    return hg_fmi3_vars[vr].enumeration ? ENUM64 : of_base[hg_var_table[vr].type];
}

/* "pair.W" for an array (its first element is "pair[1].W"), the name for a scalar. */
static void fmi3_name(char *buf, size_t n, hg_vr vr)
{
    const char *name = hg_var_table[vr].name, *at = strstr(name, "[1]");
    size_t head = at && hg_fmi3_vars[vr].count > 1 ? (size_t)(at - name) : strlen(name);
    if (head >= n) head = n - 1;
    memcpy(buf, name, head);
    buf[head] = '\0';
    if (head < strlen(name) && head + strlen(name + head + 3) < n) strcat(buf, name + head + 3);
}

/* The number of values vr names (0 after logging when it is not an FMI 3.0 variable of kind k). */
static size_t count_of(hg_instance *c, const char *fn, hg_vr vr, kind k)
{
    char name[128];
    if (k == F64 && (vr == HG_FMI3_VR_TIME || is_indicator(vr))) return 1;
    if (vr >= HG_NUM_VARS || hg_fmi3_vars[vr].count == 0) {
        hg_error(c, fn, "unknown value reference %u", (unsigned)vr);
        return 0;
    }
    if (kind_of(vr) != k) {
        fmi3_name(name, sizeof name, vr);
        hg_error(c, fn, "value reference %u is '%s', of type %s", (unsigned)vr, name,
                 kind_names[kind_of(vr)]);
        return 0;
    }
    return hg_fmi3_vars[vr].count;
}

/* Checks that the value references name variables of kind k with n_values elements in all. */
static int check_refs(hg_instance *c, const char *fn, const fmi3ValueReference vr[], size_t nvr,
                      size_t n_values, kind k)
{
    size_t i, total = 0, n;
    for (i = 0; i < nvr; i++) {
        if ((n = count_of(c, fn, vr[i], k)) == 0) return -1;
        total += n;
    }
    if (total == n_values) return 0;
    hg_error(c, fn, "nValues = %zu, but the %zu value references name %zu values", n_values, nvr,
             total);
    return -1;
}

/* Stores one element read as a double / int / string pointer into values[j] of kind k. */
static void store(kind k, void *values, size_t j, const void *v)
{
    switch (k) {
    case F64: ((fmi3Float64 *)values)[j] = *(const double *)v; break;
    case I32: ((fmi3Int32 *)values)[j] = *(const int *)v; break;
    case ENUM64: ((fmi3Int64 *)values)[j] = *(const int *)v; break;
    case BOOL: ((fmi3Boolean *)values)[j] = *(const int *)v != 0; break;
    case STR: ((fmi3String *)values)[j] = *(const char *const *)v; break;
    }
}

static fmi3Status get(hg_instance *c, const char *fn, kind k, const fmi3ValueReference vr[],
                      size_t nvr, void *values, size_t n_values)
{
    size_t i, j = 0, e;
    union { double x; int n; const char *s; } v;
    if (hg_prepare_get(c, fn, vr, nvr, values) != HG_OK || check_refs(c, fn, vr, nvr, n_values, k))
        return fmi3Error;
    for (i = 0; i < nvr; i++) {
        if (vr[i] >= HG_NUM_VARS) { /* time or an event indicator */
            if (beyond_table(c, fn, vr[i], &v.x) != HG_OK) return fmi3Error;
            store(k, values, j++, &v);
            continue;
        }
        for (e = 0; e < hg_fmi3_vars[vr[i]].count; e++) {
            if (hg_get_value(c, fn, kind_base[k], vr[i] + (hg_vr)e, &v) != HG_OK) return fmi3Error;
            store(k, values, j++, &v);
        }
    }
    return fmi3OK;
}

/* values[j] of kind k as the number hg_set_number takes (x for Float64, n otherwise). */
static void load(kind k, const void *values, size_t j, double *x, int *n)
{
    fmi3Int64 wide;
    *x = 0.0;
    *n = 0;
    switch (k) {
    case F64: *x = ((const fmi3Float64 *)values)[j]; break;
    case I32: *n = ((const fmi3Int32 *)values)[j]; break;
    case ENUM64: /* beyond int: clamped, so that the range check reports it */
        wide = ((const fmi3Int64 *)values)[j];
        *n = wide > INT_MAX ? INT_MAX : wide < INT_MIN ? INT_MIN : (int)wide;
        break;
    case BOOL: *n = ((const fmi3Boolean *)values)[j] ? 1 : 0; break;
    case STR: break;
    }
}

static fmi3Status set(hg_instance *c, const char *fn, kind k, const fmi3ValueReference vr[],
                      size_t nvr, const void *values, size_t n_values)
{
    size_t i, j = 0, e;
    if (hg_prepare_set(c, fn, vr, nvr, values) != HG_OK || check_refs(c, fn, vr, nvr, n_values, k))
        return fmi3Error;
    for (i = 0; i < nvr; i++) {
        if (vr[i] >= HG_NUM_VARS) {
            hg_error(c, fn, "'%s' cannot be set (it is computed by the FMU)",
                     vr[i] == HG_FMI3_VR_TIME ? "time" : "event_indicator");
            return fmi3Error;
        }
        for (e = 0; e < hg_fmi3_vars[vr[i]].count; e++, j++) {
            hg_status status;
            double x;
            int n;
            if (k == STR) {
                status = hg_set_string(c, fn, vr[i] + (hg_vr)e, ((const fmi3String *)values)[j]);
            } else {
                load(k, values, j, &x, &n);
                status = hg_set_number(c, fn, kind_base[k], vr[i] + (hg_vr)e, x, n);
            }
            if (status != HG_OK) return fmi3Error;
        }
    }
    return fmi3OK;
}

fmi3Status fmi3GetFloat64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                          fmi3Float64 values[], size_t n_values)
{
    return get(instance, __func__, F64, vr, nvr, values, n_values);
}

fmi3Status fmi3GetInt32(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                        fmi3Int32 values[], size_t n_values)
{
    return get(instance, __func__, I32, vr, nvr, values, n_values);
}

fmi3Status fmi3GetInt64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                        fmi3Int64 values[], size_t n_values)
{
    return get(instance, __func__, ENUM64, vr, nvr, values, n_values);
}

fmi3Status fmi3GetBoolean(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                          fmi3Boolean values[], size_t n_values)
{
    return get(instance, __func__, BOOL, vr, nvr, values, n_values);
}

fmi3Status fmi3GetString(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                         fmi3String values[], size_t n_values)
{
    return get(instance, __func__, STR, vr, nvr, values, n_values);
}

fmi3Status fmi3SetFloat64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                          const fmi3Float64 values[], size_t n_values)
{
    return set(instance, __func__, F64, vr, nvr, values, n_values);
}

fmi3Status fmi3SetInt32(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                        const fmi3Int32 values[], size_t n_values)
{
    return set(instance, __func__, I32, vr, nvr, values, n_values);
}

fmi3Status fmi3SetInt64(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                        const fmi3Int64 values[], size_t n_values)
{
    return set(instance, __func__, ENUM64, vr, nvr, values, n_values);
}

fmi3Status fmi3SetBoolean(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                          const fmi3Boolean values[], size_t n_values)
{
    return set(instance, __func__, BOOL, vr, nvr, values, n_values);
}

fmi3Status fmi3SetString(fmi3Instance instance, const fmi3ValueReference vr[], size_t nvr,
                         const fmi3String values[], size_t n_values)
{
    return set(instance, __func__, STR, vr, nvr, values, n_values);
}
