/* When and for which operating point the friction tables serve: see friction_table_policy.h. */
#include "model/friction_table_policy.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "io/constants.h"
#include "io/errmsg.h"

/* The paper's Newmark scheme, the reference of the comparisons, solves the friction model itself
 * (its Newton iteration with a difference Jacobian also failed to converge on the table in a
 * torque reversal at 10 rpm on the rigid mesh, an extremes case). */
static int wanted(const hg_setup *s, const hg_vars *v)
{
    return v->friction_table && s->solver != HG_SOLVER_NEWMARK &&
           (v->friction_model == HG_FRICTION_MODEL_EHL_THERMAL ||
            v->friction_model == HG_FRICTION_MODEL_EHL_ISOTHERMAL);
}

void hg_ftp_free(hg_ft_set **tables)
{
    if (*tables) hg_ft_set_free(*tables);
    free(*tables);
    *tables = NULL;
}

int hg_ftp_setup(hg_ft_set **tables, hg_setup *s, const char *resource_dir, const hg_vars *v,
                 char *err, size_t errlen)
{
    s->p.tables = NULL;
    if (!wanted(s, v)) {
        hg_ftp_free(tables);
        return 0;
    }
    if (!*tables && !(*tables = calloc(1, sizeof **tables))) {
        hg_errorf(err, errlen, "out of memory for the friction tables");
        return -1;
    }
    hg_ft_set_alloc(*tables, &s->p.friction, &s->gear, s->p.mesh == HG_MESH_MODEL_RIGID);
    (*tables)->resource_dir = resource_dir;
    return 0;
}

static int keyed_for(const hg_ft_set *tables, const hg_ft_key *key)
{
    return tables->keyed && !memcmp(&tables->key, key, sizeof *key);
}

/* The key follows the operating point: speed, oil temperature and a load estimate (input torque
 * over the mean radius, or the mean spring force), its load range on its lattice and, once it
 * has moved, its temperature on its own. */
int hg_ftp_stale(const hg_ft_set *tables, hg_runtime *rt, const hg_dyn_params *p,
                 const hg_inputs *u)
{
    double w_p = rt->y[HG_Y_W_P], T_oil = hg_dyn_oil_temperature(p, u, rt->y), W;
    if (!tables || !hg_ft_speed_tabulated(w_p)) return 0;
    W = fmax(fabs(u->T_s) / p->R_p0,
             p->k_m0 * fabs(hg_backlash_f(&p->backlash, rt->y[HG_Y_X], rt->mode)));
    if (!rt->ft_valid || !hg_ft_key_covers(&rt->ft_key, w_p, T_oil, W)) {
        double T_key = rt->ft_key.T_bath;
        int moved = rt->ft_valid;
        hg_ft_key_next(&rt->ft_key, rt->ft_valid, w_p, p->ratio, T_oil, W);
        moved = moved && rt->ft_key.T_bath != T_key;
        rt->ft_key.W_max = hg_ft_load_range_on_lattice(rt->ft_key.W_max);
        if (moved) rt->ft_key.T_bath = hg_ft_temperature_on_lattice(rt->ft_key.T_bath);
        rt->ft_valid = 1;
    }
    return !keyed_for(tables, &rt->ft_key);
}

/* The tables of the levels the filtered torque picks now are built here, others when the
 * right-hand side first asks. */
static void build(hg_ft_set *tables, const hg_runtime *rt, const hg_setup *s,
                  const hg_logger *log)
{
    hg_level_pick b;
    tables->key = rt->ft_key;
    tables->keyed = 1;
    hg_gearset_level_at(&s->gear, rt->mode == HG_MODE_BACK ? HG_FLANK_COAST : HG_FLANK_DRIVE,
                        rt->y[HG_Y_T_KM], &b);
    hg_ft_set_table(tables, &s->p.friction, &s->gear, b.flank, b.lo);
    if (b.hi != b.lo) hg_ft_set_table(tables, &s->p.friction, &s->gear, b.flank, b.hi);
    hg_logf(log, "logEvents", "t = %.6f s: friction table built for %.1f rpm, T_oil = "
            "%.2f degC, pair loads up to %.0f N (%lu node table columns solved so far)", rt->t,
            rt->ft_key.w_p * HG_RPM_PER_RAD_S, rt->ft_key.T_bath - 273.15, rt->ft_key.W_max,
            tables->solved);
}

int hg_ftp_begin(hg_ft_set *tables, hg_runtime *rt, hg_setup *s, int rebuild,
                 const hg_logger *log)
{
    hg_ft_set *use = tables && hg_ft_speed_tabulated(rt->y[HG_Y_W_P]) ? tables : NULL;
    int switched = use != s->p.tables;
    if (rebuild) build(tables, rt, s, log);
    s->p.tables = use;
    rt->ft_in_use = use != NULL;
    return switched;
}

hg_ft_set *hg_ftp_of_state(hg_ft_set *tables, const hg_runtime *rt, const hg_setup *s,
                           const hg_logger *log)
{
    if (!rt->ft_in_use || !tables) return NULL;
    if (!keyed_for(tables, &rt->ft_key)) build(tables, rt, s, log);
    return tables;
}
