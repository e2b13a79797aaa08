/* FMU state snapshots of either FMI version: get, set, free, serialize and deserialize (deep
 * copies throughout). */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi/instance.h"

#define SNAPSHOT_MAGIC 0x48475331u /* "HGS1" */

typedef struct {
    hg_fmi_state state;
    int model_exchange; /* of the instance it was taken from */
    int set_up;
    double start_time;
    int stop_defined;
    double stop_time;
    hg_inputs input_der;
    hg_vars vars;  /* strings owned by the snapshot */
    hg_runtime rt; /* meaningful when set_up */
} hg_snapshot;

hg_status hg_get_state(hg_instance *c, const char *fn, void **out)
{
    hg_snapshot *s;
    if (!hg_allowed(c, fn, ST_ANY)) return HG_ERROR;
    if (!out) {
        hg_error(c, fn, "FMUstate pointer is NULL");
        return HG_ERROR;
    }
    s = *out ? (hg_snapshot *)*out : calloc(1, sizeof *s);
    if (!s || hg_vars_copy(&s->vars, &c->vars)) {
        hg_error(c, fn, "out of memory");
        if (s && !*out) {
            hg_vars_free_strings(&s->vars);
            free(s);
        }
        return HG_ERROR;
    }
    s->state = c->state;
    s->model_exchange = c->model_exchange;
    s->set_up = c->set_up;
    s->start_time = c->start_time;
    s->stop_defined = c->stop_defined;
    s->stop_time = c->stop_time;
    s->input_der = c->input_der;
    if (c->set_up) hg_model_save(c->model, &s->rt);
    *out = s;
    return HG_OK;
}

/* A failed restore: the error state, with the results the instance had before. */
static hg_status restore_failed(hg_instance *c, const char *fn, const hg_vars *before,
                                 const char *why)
{
    hg_vars_copy_results(&c->vars, before);
    return hg_fail(c, fn, why);
}

static hg_status restore(hg_instance *c, const char *fn, const hg_snapshot *s)
{
    char err[HG_ERRLEN];
    const hg_var_info *bad;
    hg_vars before;
    int same = c->set_up && hg_vars_same_parameters(&c->vars, &s->vars);
    before = c->vars; /* shallow copy: only its results are ever copied back */
    if (hg_vars_copy(&c->vars, &s->vars)) {
        hg_error(c, fn, "out of memory");
        return HG_ERROR;
    }
    c->state = s->state;
    c->start_time = s->start_time;
    c->stop_defined = s->stop_defined;
    c->stop_time = s->stop_time;
    c->input_der = s->input_der;
    c->set_up = 0;
    if (!s->set_up) return HG_OK;
    if (!hg_instance_model(c)) {
        hg_error(c, fn, "out of memory");
        return HG_ERROR;
    }
    if ((!same && hg_model_setup(c->model, &c->vars, c->start_time, err, sizeof err)) ||
        hg_model_restore(c->model, &c->vars, &s->rt, err, sizeof err))
        return restore_failed(c, fn, &before, err);
    if ((bad = hg_first_nonfinite(c, 1)) != NULL) {
        hg_errorf(err, sizeof err, "the state gives %s = %g", bad->name, hg_real_value(c, bad));
        return restore_failed(c, fn, &before, err);
    }
    c->set_up = 1;
    return HG_OK;
}

hg_status hg_set_state(hg_instance *c, const char *fn, const void *state)
{
    if (!hg_allowed(c, fn, ST_ANY)) return HG_ERROR;
    if (!state) {
        hg_error(c, fn, "FMUstate is NULL");
        return HG_ERROR;
    }
    if (!c->resource_dir && ((const hg_snapshot *)state)->set_up) {
        hg_error(c, fn, "this instance has no resource location");
        return HG_ERROR;
    }
    if (((const hg_snapshot *)state)->model_exchange != c->model_exchange) {
        hg_error(c, fn, "the state was taken from a %s instance, this one is %s",
                 c->model_exchange ? "co-simulation" : "Model Exchange",
                 c->model_exchange ? "Model Exchange" : "co-simulation");
        return HG_ERROR;
    }
    return restore(c, fn, state);
}

hg_status hg_free_state(hg_instance *c, const char *fn, void **state)
{
    if (!hg_allowed(c, fn, ST_ANY)) return HG_ERROR;
    if (state && *state) {
        hg_vars_free_strings(&((hg_snapshot *)*state)->vars);
        free(*state);
        *state = NULL;
    }
    return HG_OK;
}

/* ------------------------------------------------------------------ serialization
 * Layout: uint32 magic, uint64 sizeof(hg_snapshot), the snapshot with string pointers zeroed,
 * then for each String variable in table order: uint64 length, the bytes (no terminator). */

static char **string_slot(hg_vars *v, const hg_var_info *info)
{
    return (char **)hg_var_ptr(v, info);
}

static size_t serialized_size(const hg_snapshot *s)
{
    size_t n = sizeof(uint32_t) + sizeof(uint64_t) + sizeof *s;
    int r;
    for (r = 0; r < HG_NUM_VARS; r++)
        if (hg_var_table[r].type == HG_STRING)
            n += sizeof(uint64_t) + strlen(*string_slot((hg_vars *)&s->vars, &hg_var_table[r]));
    return n;
}

hg_status hg_serialized_size(hg_instance *c, const char *fn, const void *state, size_t *size)
{
    if (!hg_allowed(c, fn, ST_ANY)) return HG_ERROR;
    if (!state || !size) {
        hg_error(c, fn, "NULL argument");
        return HG_ERROR;
    }
    *size = serialized_size(state);
    return HG_OK;
}

hg_status hg_serialize(hg_instance *c, const char *fn, const void *state, void *bytes,
                       size_t size)
{
    const hg_snapshot *s = state;
    hg_snapshot flat;
    uint32_t magic = SNAPSHOT_MAGIC;
    uint64_t n = sizeof flat;
    char *o = bytes;
    int r;
    if (!hg_allowed(c, fn, ST_ANY)) return HG_ERROR;
    if (!s || !bytes || size < serialized_size(s)) {
        hg_error(c, fn, "NULL state or buffer, or buffer "
               "of %zu bytes is smaller than the %zu needed", size, s ? serialized_size(s) : 0);
        return HG_ERROR;
    }
    memcpy(&flat, s, sizeof flat); /* bytes, padding included: the blob is deterministic */
    memcpy(o, &magic, sizeof magic), o += sizeof magic;
    memcpy(o, &n, sizeof n), o += sizeof n;
    for (r = 0; r < HG_NUM_VARS; r++)
        if (hg_var_table[r].type == HG_STRING) *string_slot(&flat.vars, &hg_var_table[r]) = NULL;
    memcpy(o, &flat, sizeof flat), o += sizeof flat;
    for (r = 0; r < HG_NUM_VARS; r++) {
        const char *str;
        if (hg_var_table[r].type != HG_STRING) continue;
        str = *string_slot((hg_vars *)&s->vars, &hg_var_table[r]);
        n = strlen(str);
        memcpy(o, &n, sizeof n), o += sizeof n;
        memcpy(o, str, (size_t)n), o += n;
    }
    return HG_OK;
}

/* The states an instance of either interface can be in. */
static int state_valid(hg_fmi_state state, int model_exchange)
{
    int own = model_exchange ? ST_EVENT_MODE | ST_CONTINUOUS_TIME : ST_STEP_COMPLETE;
    return state == ST_INSTANTIATED || state == ST_INITIALIZATION || state == ST_TERMINATED ||
           state == ST_ERROR || ((state & own) && !(state & (state - 1))); /* one flag */
}

/* A deserialized snapshot comes from outside: check what would make it unsafe or meaningless. */
static int header_valid(const hg_snapshot *s)
{
    int k;
    if ((s->model_exchange != 0 && s->model_exchange != 1) ||
        !state_valid(s->state, s->model_exchange))
        return 0;
    if ((s->set_up != 0 && s->set_up != 1) || (s->stop_defined != 0 && s->stop_defined != 1))
        return 0;
    if ((s->state & ST_RUNNING) && !s->set_up) return 0; /* running needs a set-up model */
    if (!isfinite(s->start_time) || (s->stop_defined && !(s->stop_time >= s->start_time)))
        return 0;
    for (k = 0; k < HG_NUM_INPUTS; k++)
        if (!isfinite(hg_input_value(&s->input_der, k))) return 0;
    return !s->set_up || (s->rt.mode >= -1 && s->rt.mode <= 1 && isfinite(s->rt.t));
}

/* Every variable must be one the FMU could hold: finite, parameters and inputs in range. */
static int vars_valid(const hg_vars *v)
{
    int r;
    for (r = 0; r < HG_NUM_VARS; r++) {
        const hg_var_info *info = &hg_var_table[r];
        const void *p = hg_var_cptr(v, info);
        int ranged = info->causality == HG_PARAMETER || info->causality == HG_INPUT;
        double x;
        if (info->type == HG_STRING) continue;
        x = info->type == HG_REAL ? *(const double *)p : *(const int *)p;
        if (!isfinite(x)) return 0;
        if (ranged && ((info->has_min && x < info->min) || (info->has_max && x > info->max)))
            return 0;
    }
    return 1;
}

static int snapshot_valid(const hg_snapshot *s)
{
    return header_valid(s) && vars_valid(&s->vars);
}

static int read_strings(hg_snapshot *s, const char *in, const char *end)
{
    int r;
    for (r = 0; r < HG_NUM_VARS; r++) {
        uint64_t n;
        char **slot;
        if (hg_var_table[r].type != HG_STRING) continue;
        slot = string_slot(&s->vars, &hg_var_table[r]);
        if ((size_t)(end - in) < sizeof n) return -1;
        memcpy(&n, in, sizeof n), in += sizeof n;
        if (n > 4095 || (uint64_t)(end - in) < n || !(*slot = malloc((size_t)n + 1))) return -1;
        memcpy(*slot, in, (size_t)n), in += n;
        (*slot)[n] = '\0';
        if (strlen(*slot) != n) return -1;
    }
    return in == end ? 0 : -1;
}

hg_status hg_deserialize(hg_instance *c, const char *fn, const void *bytes, size_t size,
                         void **state)
{
    const char *in = bytes, *end = in + size;
    hg_snapshot *s;
    uint32_t magic;
    uint64_t n;
    int r;
    if (!hg_allowed(c, fn, ST_ANY)) return HG_ERROR;
    if (!bytes || !state || size < sizeof magic + sizeof n + sizeof *s) goto bad;
    memcpy(&magic, in, sizeof magic), in += sizeof magic;
    memcpy(&n, in, sizeof n), in += sizeof n;
    if (magic != SNAPSHOT_MAGIC || n != sizeof *s || !(s = calloc(1, sizeof *s))) goto bad;
    memcpy(s, in, sizeof *s), in += sizeof *s;
    for (r = 0; r < HG_NUM_VARS; r++)
        if (hg_var_table[r].type == HG_STRING) *string_slot(&s->vars, &hg_var_table[r]) = NULL;
    if (read_strings(s, in, end) || !snapshot_valid(s)) {
        hg_vars_free_strings(&s->vars);
        free(s);
        goto bad;
    }
    if (*state) hg_free_state(c, fn, state);
    *state = s;
    return HG_OK;
bad:
    hg_error(c, fn, "%zu bytes are not a state "
           "serialized by this FMU build", size);
    return HG_ERROR;
}
