/* FMI 2.0 variable access: fmi2Get/Set{Real,Integer,Boolean,String} (adapters over access.c). */
#include "fmi/instance.h"
#include "fmi2Functions.h"

/* Reads nvr variables of one type into values (elements of size bytes). */
static fmi2Status get_values(hg_instance *c, const char *fn, hg_base_type type,
                             const fmi2ValueReference vr[], size_t nvr, void *values, size_t size)
{
    size_t i;
    if (hg_prepare_get(c, fn, vr, nvr, values) != HG_OK) return fmi2Error;
    for (i = 0; i < nvr; i++)
        if (hg_get_value(c, fn, type, vr[i], (char *)values + i * size) != HG_OK)
            return fmi2Error;
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

/* Sets Real (values: fmi2Real[]) or Integer / Boolean (values: fmi2Integer[]) variables. */
static fmi2Status set_numbers(hg_instance *c, const char *fn, hg_base_type type,
                              const fmi2ValueReference vr[], size_t nvr, const void *values)
{
    size_t i;
    if (hg_prepare_set(c, fn, vr, nvr, values) != HG_OK) return fmi2Error;
    for (i = 0; i < nvr; i++) {
        double x = type == HG_REAL ? ((const fmi2Real *)values)[i] : 0.0;
        int k = type == HG_REAL ? 0 : ((const fmi2Integer *)values)[i];
        if (hg_set_number(c, fn, type, vr[i], x, k) != HG_OK) return fmi2Error;
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
    size_t i;
    if (hg_prepare_set(comp, __func__, vr, nvr, value) != HG_OK) return fmi2Error;
    for (i = 0; i < nvr; i++)
        if (hg_set_string(comp, __func__, vr[i], value[i]) != HG_OK) return fmi2Error;
    return fmi2OK;
}
