/* Model set-up: see setup.h. */
#include "model/setup.h"

#include <stdio.h>
#include <string.h>

#include "io/errmsg.h"
#include "model/modal.h"
#include "model/plausibility.h"

#define GOVERNOR_ZETA 0.7     /* damping ratio of the speed governor's closed loop */
#define STEPS_PER_MESH 30     /* CVODE's automatic max_step: 1/30 of a mesh period (docs/physics.md §8.8) */

/* user_file if set (absolute, or relative to the resources), else resources/<builtin>. */
static int resolve_path(const char *resource_dir, const char *user_file, const char *builtin,
                        char *path, size_t len, char *err, size_t errlen)
{
    int n;
    if (user_file && *user_file)
        n = user_file[0] == '/' ? snprintf(path, len, "%s", user_file)
                                : snprintf(path, len, "%s/%s", resource_dir, user_file);
    else
        n = snprintf(path, len, "%s/%s", resource_dir, builtin);
    if (n < 0 || (size_t)n >= len) {
        hg_errorf(err, errlen, "data file path is too long: '%.80s...'", path);
        return -1;
    }
    return 0;
}

static void gearset_builtin(const hg_vars *v, char *builtin, size_t len)
{
    snprintf(builtin, len, "gearsets/gearset%d.txt", v->gear_set);
}

static const char *lubricant_builtin(const hg_vars *v)
{
    static const char *const builtin[] = {"lubricants/OS265962.txt", "lubricants/OS265963.txt"};
    return builtin[v->lubricant == 2];
}

static int load_gearset(hg_setup *s, const char *resource_dir, const hg_vars *v, char *err,
                        size_t errlen)
{
    char path[4096], builtin[64], why[HG_ERRLEN];
    gearset_builtin(v, builtin, sizeof builtin);
    if (resolve_path(resource_dir, v->gear_set_file, builtin, path, sizeof path, err, errlen))
        return -1;
    if (hg_gearset_load(path, &s->gear, why, sizeof why)) {
        hg_errorf(err, errlen, "%s = '%s': %s", v->gear_set_file[0] ? "gear_set_file" : "gear_set",
                  v->gear_set_file[0] ? v->gear_set_file : builtin, why);
        return -1;
    }
    hg_series_scale(&s->gear.k_m, v->k_m_scale);
    hg_series_scale(&s->gear.e_0, v->e_0_scale);
    return 0;
}

static int load_lubricant(hg_setup *s, const char *resource_dir, const hg_vars *v, char *err,
                          size_t errlen)
{
    const char *name = lubricant_builtin(v);
    char path[4096], why[HG_ERRLEN];
    if (resolve_path(resource_dir, v->lubricant_file, name, path, sizeof path, err, errlen))
        return -1;
    if (hg_lubricant_load(path, &s->lub, why, sizeof why)) {
        hg_errorf(err, errlen, "%s = '%s': %s",
                  v->lubricant_file[0] ? "lubricant_file" : "lubricant",
                  v->lubricant_file[0] ? v->lubricant_file : name, why);
        return -1;
    }
    return 0;
}

/* A map applies only to the data file it was made from: its recorded content hash must be the
 * hash of the file in use (`var` = user_file, or the built-in file). */
static int check_map_source(const hg_effmap_source *made, const char *what, const char *var,
                            const char *resource_dir, const char *user_file, const char *builtin,
                            const char *map_name, char *err, size_t errlen)
{
    char path[4096], hash[HG_HASH_HEX], why[HG_ERRLEN];
    if (resolve_path(resource_dir, user_file, builtin, path, sizeof path, err, errlen)) return -1;
    if (hg_datafile_hash(path, hash, why, sizeof why)) {
        hg_errorf(err, errlen, "%s", why);
        return -1;
    }
    if (strcmp(hash, made->hash) == 0) return 0;
    hg_errorf(err, errlen, "%s was made for the %s '%s' (content hash %s), but this run uses %s = "
              "'%s' (content hash %s): make a map for it with hypoid effmap", map_name, what,
              made->source, made->hash, var, user_file[0] ? user_file : builtin, hash);
    return -1;
}

/* The map level: a rigid gear whose efficiency comes from a map of the full model. */
static int load_map(hg_setup *s, const char *resource_dir, const hg_vars *v, char *err,
                    size_t errlen)
{
    char path[4096], builtin[96], gear[64], name[4200], why[HG_ERRLEN];
    hg_effmap_free(&s->map);
    s->p.map = NULL;
    if (v->friction_model != HG_FRICTION_MODEL_MAP) return 0;
    if (v->mesh_model != HG_MESH_MODEL_RIGID) {
        hg_errorf(err, errlen, "friction_model = map describes the whole gear's losses: it needs "
                  "mesh_model = rigid (mesh_model is %d)", v->mesh_model);
        return -1;
    }
    if (!v->efficiency_map_file[0] && v->lubricant_file[0]) {
        hg_errorf(err, errlen, "friction_model = map with lubricant_file = '%s' needs an "
                  "efficiency_map_file made for that lubricant (hypoid effmap)", v->lubricant_file);
        return -1;
    }
    snprintf(builtin, sizeof builtin, "maps/gearset%d_%s.txt", v->gear_set,
             v->lubricant == 2 ? "OS265963" : "OS265962");
    if (resolve_path(resource_dir, v->efficiency_map_file, builtin, path, sizeof path, err,
                     errlen))
        return -1;
    snprintf(name, sizeof name, "%s = '%s'",
             v->efficiency_map_file[0] ? "efficiency_map_file" : "the built-in efficiency map",
             v->efficiency_map_file[0] ? v->efficiency_map_file : builtin);
    if (hg_effmap_load(path, &s->map, why, sizeof why)) {
        hg_errorf(err, errlen, "%s: %s", name, why);
        return -1;
    }
    gearset_builtin(v, gear, sizeof gear);
    if (check_map_source(&s->map.gear_set, "gear set", v->gear_set_file[0] ? "gear_set_file"
                         : "gear_set", resource_dir, v->gear_set_file, gear, name, err, errlen) ||
        check_map_source(&s->map.lubricant, "lubricant", v->lubricant_file[0] ? "lubricant_file"
                         : "lubricant", resource_dir, v->lubricant_file, lubricant_builtin(v),
                         name, err, errlen)) {
        hg_effmap_free(&s->map);
        return -1;
    }
    s->p.map = &s->map;
    return 0;
}

static void ehl_params(hg_setup *s, const hg_vars *v)
{
    hg_ehl_params *e = &s->p.friction.ehl;
    hg_ehl_params_default(e);
    e->E = v->E;
    e->nu = v->nu;
    e->k_s = v->k_s;
    e->rho_s = v->rho_s;
    e->c_s = v->c_s;
    e->tau_0 = v->tau_0;
    e->varsigma_a = v->varsigma_a;
    e->sigma_s = v->sigma_s;
    e->eta_beta_sigma = v->eta_beta_sigma;
    e->sigma_over_beta = v->sigma_over_beta;
    e->T_inlet_rise = v->T_inlet_rise;
    e->Lambda_cap = v->Lambda_cap;
    e->k_f_override = v->k_f;
    e->hertz = v->hertz_model == HG_HERTZ_MODEL_APPROX ? HG_HERTZ_APPROX : HG_HERTZ_EXACT;
    e->roelands_Z = v->roelands_z == HG_ROELANDS_Z_EXACT ? HG_Z_EXACT : HG_Z_SIMPLE;
    e->shear_pressure = v->shear_pressure == HG_SHEAR_PRESSURE_MAX ? HG_SHEAR_P_MAX : HG_SHEAR_P_MEAN;
    e->thermal = v->friction_model == HG_FRICTION_MODEL_EHL_THERMAL;
    s->p.friction.lub = &s->lub;
}

static int damping(hg_setup *s, const hg_logger *lg, hg_vars *v, char *err, size_t errlen)
{
    hg_modal_input in;
    hg_modes modes;
    hg_dampers d;
    double zeta[3];
    char why[HG_ERRLEN];
    in.I_s = v->I_s;
    in.I_p = v->I_p;
    in.I_g = v->I_g;
    in.I_w = v->I_w;
    in.k_t1 = v->k_t1;
    in.k_t2 = v->k_t2;
    in.k_m = s->p.k_m0;
    in.R_p = s->p.R_p0;
    in.R_g = s->p.R_p0 * s->p.ratio;
    zeta[0] = v->zeta_2;
    zeta[1] = v->zeta_3;
    zeta[2] = v->zeta_4;
    if (hg_modal_analysis(&in, &modes, why, sizeof why) ||
        hg_modal_dampers(&in, zeta, &d, why, sizeof why)) {
        hg_errorf(err, errlen, "modal damping: %s", why);
        return -1;
    }
    if (d.used_fallback)
        hg_logf(lg, "logStatusWarning",
              "modal damping ratios (%g, %g, %g) cannot all be met with non-negative dampers; "
              "least-squares fallback achieves (%.4f, %.4f, %.4f)",
              zeta[0], zeta[1], zeta[2], d.zeta_achieved[0], d.zeta_achieved[1],
              d.zeta_achieved[2]);
    s->p.c_t1 = v->c_t1 = d.c_t1;
    s->p.c_m = v->c_m = d.c;
    s->p.c_t2 = v->c_t2 = d.c_t2;
    v->f_2 = modes.f_hz[1];
    v->f_3 = modes.f_hz[2];
    v->f_4 = modes.f_hz[3];
    return 0;
}

static void dynamics_params(hg_setup *s, const hg_vars *v)
{
    hg_dyn_params *p = &s->p;
    double J, w_n;
    p->I_s = v->I_s;
    p->I_p = v->I_p;
    p->I_g = v->I_g;
    p->I_w = v->I_w;
    p->k_t1 = v->k_t1;
    p->k_t2 = v->k_t2;
    p->mesh = v->mesh_model;
    p->backlash.b = p->mesh == HG_MESH_MODEL_VARYING ? v->b : 0.0;
    p->backlash.eps = p->mesh == HG_MESH_MODEL_VARYING && v->backlash_model == HG_BACKLASH_MODEL_SMOOTHED
                          ? v->backlash_smoothing
                          : 0.0;
    p->k_m0 = s->gear.k_m.mean;
    p->R_p0 = s->gear.R_p.mean;
    p->ratio = (double)s->gear.N_g / s->gear.N_p;
    p->gear = &s->gear;
    p->friction.model = v->friction_model;
    p->friction.mu_const = v->mu_const;
    p->speed_governor = v->load_mode == HG_LOAD_MODE_SPEED;
    /* PI governor on the wheel speed, tuned on the rigid-body inertia seen at the wheel */
    J = (v->I_s + v->I_p) * p->ratio * p->ratio + v->I_g + v->I_w;
    w_n = HG_TWO_PI * v->governor_bandwidth;
    p->K_p = 2.0 * GOVERNOR_ZETA * w_n * J;
    p->K_i = w_n * w_n * J;
}

/* Absolute tolerances: atol is on the DTE [m]; angles scale by 1/R, speeds by omega_4/R. */
static void tolerances(hg_setup *s, const hg_vars *v)
{
    double a = v->atol, R_p = s->p.R_p0, R_g = R_p * s->p.ratio, w4 = HG_TWO_PI * v->f_4;
    double E = a * s->p.k_m0 * 1e-4; /* energy: a force of k_m * 0.1 mm through a */
    double *t = s->atol;
    t[HG_Y_TWIST1] = t[HG_Y_PHI_P] = a / R_p;
    t[HG_Y_TWIST2] = t[HG_Y_GOV] = a / R_g;
    t[HG_Y_X] = a;
    t[HG_Y_W_S] = t[HG_Y_W_P] = a * w4 / R_p;
    t[HG_Y_W_G] = t[HG_Y_W_W] = a * w4 / R_g;
    t[HG_Y_E_IN] = t[HG_Y_E_OUT] = t[HG_Y_E_FRIC] = t[HG_Y_E_DAMP] = t[HG_Y_E_EXC] = E;
    t[HG_Y_ETA2] = t[HG_Y_ETA_AXLE2] = 1e-9;
    t[HG_Y_E_CHURN] = t[HG_Y_E_BEAR] = t[HG_Y_E_SEAL] = t[HG_Y_Q_H] = E;
    t[HG_Y_T_OIL] = 1e-6; /* K */
    s->rtol = v->rtol;
    s->fixed_step = v->solver == HG_SOLVER_NEWMARK;
    s->max_step = v->max_step;
    s->f_max = v->f_4;
    s->steps_per_mesh = s->fixed_step ? v->steps_per_mesh_cycle : STEPS_PER_MESH;
}

int hg_setup_load(hg_setup *s, const char *resource_dir, const hg_logger *lg, hg_vars *v,
                  char *err, size_t errlen)
{
    if (load_gearset(s, resource_dir, v, err, errlen) ||
        load_lubricant(s, resource_dir, v, err, errlen))
        return -1;
    dynamics_params(s, v);
    ehl_params(s, v);
    if (load_map(s, resource_dir, v, err, errlen)) return -1;
    if (damping(s, lg, v, err, errlen)) return -1;
    hg_plausibility_warn(v, lg);
    if (hg_ledger_setup(&s->p.ledger, v, v->gear_set_file[0] ? 0 : v->gear_set, &s->lub, err,
                        errlen))
        return -1;
    v->R_p0 = s->p.R_p0;
    v->k_m0 = s->p.k_m0;
    v->ratio = s->p.ratio;
    v->N_p = s->gear.N_p;
    v->N_g = s->gear.N_g;
    tolerances(s, v);
    s->window_angle = v->n_avg_cycles * HG_TWO_PI / s->gear.N_p;
    return 0;
}

void hg_setup_free(hg_setup *s) { hg_effmap_free(&s->map); }
