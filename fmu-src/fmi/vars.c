/* Start values, deep copies and comparisons of hg_vars, driven by the generated table. */
#include <stdlib.h>
#include <string.h>

#include "fmi/instance.h"

#define FIELD(v, info, type) ((type *)hg_var_ptr(v, info))
#define CFIELD(v, info, type) ((const type *)hg_var_cptr(v, info))

static char *dup_string(const char *s)
{
    char *d = malloc(strlen(s) + 1);
    if (d) strcpy(d, s);
    return d;
}

void hg_vars_free_strings(hg_vars *v)
{
    int r;
    for (r = 0; r < HG_NUM_VARS; r++) {
        const hg_var_info *info = &hg_var_table[r];
        if (info->type != HG_STRING) continue;
        free(*FIELD(v, info, char *));
        *FIELD(v, info, char *) = NULL;
    }
}

int hg_vars_reset(hg_vars *v)
{
    int r, ok = 1;
    hg_vars_free_strings(v);
    memset(v, 0, sizeof *v);
    for (r = 0; r < HG_NUM_VARS; r++) {
        const hg_var_info *info = &hg_var_table[r];
        if (info->type == HG_REAL)
            *FIELD(v, info, double) = info->start;
        else if (info->type == HG_STRING)
            ok &= (*FIELD(v, info, char *) = dup_string(info->start_string)) != NULL;
        else
            *FIELD(v, info, int) = (int)info->start;
    }
    return ok ? 0 : -1;
}

int hg_vars_copy(hg_vars *dst, const hg_vars *src)
{
    int r, ok = 1;
    hg_vars_free_strings(dst);
    *dst = *src;
    for (r = 0; r < HG_NUM_VARS; r++) {
        const hg_var_info *info = &hg_var_table[r];
        const char *s;
        if (info->type != HG_STRING) continue;
        s = *CFIELD(src, info, char *);
        ok &= (*FIELD(dst, info, char *) = dup_string(s ? s : "")) != NULL;
    }
    return ok ? 0 : -1;
}

int hg_vars_same_parameters(const hg_vars *a, const hg_vars *b)
{
    int r;
    for (r = 0; r < HG_NUM_VARS; r++) {
        const hg_var_info *info = &hg_var_table[r];
        if (info->causality != HG_PARAMETER) continue;
        if (info->type == HG_REAL) {
            if (*CFIELD(a, info, double) != *CFIELD(b, info, double)) return 0;
        } else if (info->type == HG_STRING) {
            if (strcmp(*CFIELD(a, info, char *), *CFIELD(b, info, char *)) != 0) return 0;
        } else if (*CFIELD(a, info, int) != *CFIELD(b, info, int)) {
            return 0;
        }
    }
    return 1;
}

void hg_vars_copy_results(hg_vars *dst, const hg_vars *src)
{
    int r;
    for (r = 0; r < HG_NUM_VARS; r++) {
        const hg_var_info *info = &hg_var_table[r];
        if (info->causality != HG_OUTPUT && info->causality != HG_CALCULATED) continue;
        if (info->type == HG_REAL)
            *FIELD(dst, info, double) = *CFIELD(src, info, double);
        else if (info->type != HG_STRING)
            *FIELD(dst, info, int) = *CFIELD(src, info, int);
    }
}
