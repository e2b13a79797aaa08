/* Model set-up: see setup.h. */
#include "model/setup.h"

#include "model/table_store.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "io/constants.h"
#include "io/datafile.h"
#include "io/errmsg.h"
#include "model/modal.h"
#include "model/plausibility.h"

#define GOVERNOR_ZETA 0.7     /* damping ratio of the speed governor's closed loop */
#define STEPS_PER_MESH 30     /* CVODE's automatic max_step: 1/30 of a mesh period (docs/physics.md §8.8) */

/* A data file named by a parameter: the user's file if set (absolute, or relative to the
 * resources), else a built-in one below the resources. */
typedef struct {
    const char *user_key, *user_file; /* the file parameter and its value, "" when unset */
    const char *builtin_key;          /* what picks the built-in file */
    char builtin[96];                 /* the built-in file below the resources */
    char path[4096];                  /* the file to read, after resolve() */
} data_file;

/* preset = paper: the paper's friction and tooth data together (docs/friction-evidence.md) */
static int paper_friction(const hg_vars *v)
{
    return v->preset == HG_PRESET_PAPER || v->friction_preset == HG_FRICTION_PRESET_PAPER;
}

static int paper_tooth_data(const hg_vars *v)
{
    return v->preset == HG_PRESET_PAPER || v->tooth_data == HG_TOOTH_DATA_PAPER;
}

/* The built-in gear set's tooth data: the paper's calibrated one series, or the loaded
 * two-flank file (docs/data-files.md). */
static data_file gearset_file(const hg_vars *v)
{
    int paper = paper_tooth_data(v);
    data_file f = {"gear_set_file", "", "", "", ""};
    f.user_file = v->gear_set_file;
    f.builtin_key = paper ? "gear_set (tooth_data = paper)" : "gear_set (tooth_data = loaded)";
    snprintf(f.builtin, sizeof f.builtin, "gearsets/%sgearset%d.txt", paper ? "" : "loaded/",
             v->gear_set);
    return f;
}

static data_file lubricant_file(const hg_vars *v)
{
    data_file f = {"lubricant_file", "", "lubricant", "", ""};
    f.user_file = v->lubricant_file;
    snprintf(f.builtin, sizeof f.builtin, "lubricants/%s.txt",
             v->lubricant == 2 ? "OS265963" : "OS265962");
    return f;
}

static data_file map_file(const hg_vars *v)
{
    data_file f = {"efficiency_map_file", "", "the built-in efficiency map", "", ""};
    f.user_file = v->efficiency_map_file;
    snprintf(f.builtin, sizeof f.builtin, "maps/gearset%d_%s.txt", v->gear_set,
             v->lubricant == 2 ? "OS265963" : "OS265962");
    return f;
}

static int resolve(data_file *f, const char *resource_dir, char *err, size_t errlen)
{
    const char *u = f->user_file;
    size_t len = sizeof f->path;
    int n = !*u ? snprintf(f->path, len, "%s/%s", resource_dir, f->builtin)
            : hg_path_is_absolute(u) ? snprintf(f->path, len, "%s", u)
                                     : snprintf(f->path, len, "%s/%s", resource_dir, u);
    if (n < 0 || (size_t)n >= len) {
        hg_errorf(err, errlen, "data file path is too long: '%.80s...'", f->path);
        return -1;
    }
    return 0;
}

/* "gear_set_file = 'x.txt'" or "gear_set (tooth_data = paper) = 'gearsets/gearset1.txt'". */
static void describe(const data_file *f, char *buf, size_t len)
{
    snprintf(buf, len, "%s = '%s'", *f->user_file ? f->user_key : f->builtin_key,
             *f->user_file ? f->user_file : f->builtin);
}

static int load_failed(const data_file *f, const char *why, char *err, size_t errlen)
{
    char name[4200];
    describe(f, name, sizeof name);
    hg_errorf(err, errlen, "%s: %s", name, why);
    return -1;
}

/* The phase tables of a gear set (after scaling), for the store: each flank's and level's table
 * is an entry of plain bytes of its own, so that the FMU can ship it (hg_store_get_shipped),
 * copied into the set. */
typedef struct {
    const char *resource_dir;
    const hg_gearset *gear;
    hg_store_id id; /* the set's */
    int fl, lv;
} phase_job;

static int build_phase_table(void *table, void *ctx)
{
    const phase_job *j = ctx;
    hg_phase_table_build(table, j->gear, j->fl, j->lv);
    return 0;
}

static int phase_table_of_store(hg_phase_table *t, int fl, int lv, void *ctx)
{
    phase_job *j = ctx;
    const hg_phase_table *held;
    hg_store_id id = hg_store_hash(hg_store_hash(j->id, &fl, sizeof fl), &lv, sizeof lv);
    j->fl = fl, j->lv = lv;
    held = hg_store_get_shipped(j->resource_dir, id, sizeof *held, build_phase_table, j, NULL);
    if (!held) return -1; /* out of memory, or a key collision */
    memcpy(t, held, sizeof *t);
    hg_store_put(held);
    return 0;
}

static int build_phase_tables(void *table, void *ctx)
{
    phase_job *j = ctx;
    return hg_phase_tables_build_with(table, j->gear, phase_table_of_store, j);
}

static void free_phase_tables(void *table)
{
    hg_phase_tables_free(table);
}

/* A gear-set file read and checked, for the store (the path and the error buffer). */
typedef struct {
    const char *path;
    char *why;
    size_t why_len;
} gearset_job;

static int read_gearset(void *gear, void *ctx)
{
    gearset_job *j = ctx;
    return hg_gearset_load(j->path, gear, j->why, j->why_len);
}

/* The gear set of the file at path into *g: read and checked once per file content in the
 * process (the store's entry, named by the file's content hash), copied here. */
static int gearset_of_file(const char *resource_dir, const char *path, hg_gearset *g, char *why,
                           size_t why_len)
{
    char hash[HG_HASH_HEX];
    gearset_job job;
    const hg_gearset *read;
    if (hg_datafile_hash(path, hash, why, why_len)) return -1;
    job.path = path, job.why = why, job.why_len = why_len;
    read = hg_store_get_shipped(resource_dir,
                                hg_store_hash(hg_store_id_of("gear-set file"), hash, sizeof hash),
                                sizeof *read, read_gearset, &job, NULL);
    if (!read) return *why ? -1 : hg_gearset_load(path, g, why, why_len); /* out of memory */
    memcpy(g, read, sizeof *g);
    hg_store_put(read);
    return 0;
}

static int load_gearset(hg_setup *s, const char *resource_dir, const hg_vars *v, char *err,
                        size_t errlen)
{
    data_file f = gearset_file(v);
    char why[HG_ERRLEN] = "";
    const hg_phase_tables *held;
    phase_job job;
    if (resolve(&f, resource_dir, err, errlen)) return -1;
    if (gearset_of_file(resource_dir, f.path, &s->gear, why, sizeof why))
        return load_failed(&f, why, err, errlen);
    hg_gearset_scale(&s->gear, v->k_m_scale, v->e_0_scale);
    held = s->phase;
    job.resource_dir = resource_dir, job.gear = &s->gear, job.fl = job.lv = 0;
    job.id = hg_store_hash(hg_store_id_of("phase tables"), &s->gear, sizeof s->gear);
    s->phase = hg_store_get(job.id, sizeof *s->phase, build_phase_tables, &job,
                            free_phase_tables, NULL);
    hg_store_put(held); /* after: the same gear set finds the tables it held */
    if (!s->phase) {
        hg_errorf(err, errlen, "out of memory for the tables of %s (or a table-store key collision)",
                  s->gear.name);
        return -1;
    }
    return 0;
}

static int load_lubricant(hg_setup *s, const char *resource_dir, const hg_vars *v, char *err,
                          size_t errlen)
{
    data_file f = lubricant_file(v);
    char why[HG_ERRLEN];
    if (resolve(&f, resource_dir, err, errlen)) return -1;
    if (hg_lubricant_load(f.path, &s->lub, why, sizeof why))
        return load_failed(&f, why, err, errlen);
    /* the override has the file's lower bound: below it the film's thermal resistance
     * h_c / (2 k_f A) (eq. 18) overflows (a denormal k_f stalls the integrator) */
    if (v->k_f > 0.0 && v->k_f < HG_LUBRICANT_K_F_MIN) {
        hg_errorf(err, errlen,
                  "k_f = %g W/(m.K) is below %g W/(m.K), the lowest a lubricant file may give "
                  "(0 uses the file's value)",
                  v->k_f, HG_LUBRICANT_K_F_MIN);
        return -1;
    }
    return 0;
}

/* A map applies only to the data file it was made from: its recorded content hash must be the
 * hash of the file in use. */
static int check_map_source(const hg_effmap_source *made, const char *what, data_file f,
                            const char *resource_dir, const char *map_name, char *err,
                            size_t errlen)
{
    char hash[HG_HASH_HEX], why[HG_ERRLEN], used[4200];
    if (resolve(&f, resource_dir, err, errlen)) return -1;
    if (hg_datafile_hash(f.path, hash, why, sizeof why)) {
        hg_errorf(err, errlen, "%s", why);
        return -1;
    }
    if (strcmp(hash, made->hash) == 0) return 0;
    describe(&f, used, sizeof used);
    hg_errorf(err, errlen, "%s was made for the %s '%s' (content hash %s), but this run uses %s "
              "(content hash %s): make a map for it with hypoid effmap", map_name, what,
              made->source, made->hash, used, hash);
    return -1;
}

/* The map level: a rigid gear whose efficiency comes from a map of the full model. */
static int load_map(hg_setup *s, const char *resource_dir, const hg_vars *v, char *err,
                    size_t errlen)
{
    data_file f = map_file(v);
    char name[4200], why[HG_ERRLEN];
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
    if (resolve(&f, resource_dir, err, errlen)) return -1;
    if (hg_effmap_load(f.path, &s->map, why, sizeof why))
        return load_failed(&f, why, err, errlen);
    describe(&f, name, sizeof name);
    if (check_map_source(&s->map.gear_set, "gear set", gearset_file(v), resource_dir, name, err,
                         errlen) ||
        check_map_source(&s->map.lubricant, "lubricant", lubricant_file(v), resource_dir, name,
                         err, errlen)) {
        hg_effmap_free(&s->map);
        return -1;
    }
    s->p.map = &s->map;
    return 0;
}

static int build_z_table(void *table, void *lub)
{
    hg_z_table_build(table, lub);
    return 0;
}

static void ehl_params(hg_setup *s, const char *resource_dir, const hg_vars *v)
{
    hg_ehl_params *e = &s->p.friction.ehl;
    const hg_z_table *held;
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
    e->shear_pressure = v->shear_pressure == HG_SHEAR_PRESSURE_MAX     ? HG_SHEAR_P_MAX
                        : v->shear_pressure == HG_SHEAR_PRESSURE_HERTZ ? HG_SHEAR_P_HERTZ
                                                                       : HG_SHEAR_P_MEAN;
    e->relaxation = v->relaxation == HG_RELAXATION_TTPS ? HG_RELAX_TTS : HG_RELAX_CONSTANT;
    e->inlet_heating = v->inlet_heating == HG_INLET_HEATING_GUPTA;
    if (paper_friction(v)) { /* the paper's choices together */
        e->roelands_Z = HG_Z_SIMPLE;
        e->shear_pressure = HG_SHEAR_P_MEAN;
        e->relaxation = HG_RELAX_CONSTANT;
        e->Lambda_cap = 0.0;
        e->inlet_heating = 0;
    }
    e->thermal = v->friction_model == HG_FRICTION_MODEL_EHL_THERMAL;
    held = s->z_table;
    s->z_table = NULL;
    if (e->roelands_Z == HG_Z_EXACT && (e->thermal || v->friction_model ==
                                         HG_FRICTION_MODEL_EHL_ISOTHERMAL))
        s->z_table = hg_store_get_shipped(resource_dir,
                                          hg_store_hash(hg_store_id_of("Z_exact over T"),
                                                        &s->lub, sizeof s->lub),
                                          sizeof *s->z_table, build_z_table, &s->lub, NULL);
    hg_store_put(held); /* after: the same lubricant finds the table it held */
    e->z_table = s->z_table; /* NULL (out of memory): Z_exact solved at each temperature */
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

/* output_shaft = auto takes the output shaft quasi-static at the map level only when its own
 * mode lies above this [Hz]: a shaft between the gear and the wheel end (the paper's, about
 * 330 Hz), not a half-shaft given as k_t2 (hypoid drive-cycle's, about 40 Hz), whose mode with the
 * vehicle is a driveline's concern. */
#define OUTPUT_SHAFT_QS_HZ 100.0

/* The output shaft's own mode [Hz]: the wheel end I_w against the pinion-gear body
 * I_g + i^2 (I_p + I_s) on k_t2. */
static double output_shaft_hz(const hg_vars *v, double ratio)
{
    double J_g = v->I_g + ratio * ratio * (v->I_p + v->I_s);
    return sqrt(v->k_t2 * (1.0 / v->I_w + 1.0 / J_g)) / HG_TWO_PI;
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
    p->quasi_static_input = v->input_shaft == HG_INPUT_SHAFT_QUASI_STATIC ||
                            (v->input_shaft == HG_INPUT_SHAFT_AUTO &&
                             v->mesh_model == HG_MESH_MODEL_RIGID &&
                             v->friction_model == HG_FRICTION_MODEL_MAP);
    p->backlash.b = p->mesh == HG_MESH_MODEL_VARYING ? v->b : 0.0;
    p->backlash.eps = p->mesh == HG_MESH_MODEL_VARYING && v->backlash_model == HG_BACKLASH_MODEL_SMOOTHED
                          ? v->backlash_smoothing
                          : 0.0;
    hg_gearset_means(&s->gear, v->T_s < 0.0 ? HG_FLANK_COAST : HG_FLANK_DRIVE, fabs(v->T_s),
                     &p->k_m0, &p->R_p0);
    if (s->gear.n_levels > 1) /* the stiffness a vibration about the start sees: the law's tangent */
        p->k_m0 = hg_mesh_law_tangent_mean(&s->gear, v->T_s < 0.0 ? HG_FLANK_COAST : HG_FLANK_DRIVE,
                                           fabs(v->T_s));
    p->ratio = (double)s->gear.N_g / s->gear.N_p;
    p->quasi_static_output = v->output_shaft == HG_OUTPUT_SHAFT_QUASI_STATIC ||
                             (v->output_shaft == HG_OUTPUT_SHAFT_AUTO &&
                              v->mesh_model == HG_MESH_MODEL_RIGID &&
                              v->friction_model == HG_FRICTION_MODEL_MAP &&
                              output_shaft_hz(v, p->ratio) > OUTPUT_SHAFT_QS_HZ);
    p->gear = &s->gear;
    p->phase = s->phase;
    s->heat.valid = 0; /* emptied: the ledger is set up anew below */
    p->heat = &s->heat;
    p->friction.model = v->friction_model;
    p->friction.mu_const = v->mu_const;
    p->speed_governor = v->load_mode == HG_LOAD_MODE_SPEED;
    p->half_shaft = v->load_mode == HG_LOAD_MODE_HALF_SHAFT;
    p->k_hs = p->half_shaft ? v->k_hs : 0.0; /* no spring energy unless it acts */
    p->c_hs = p->half_shaft ? v->c_hs : 0.0;
    s->I_vehicle = p->half_shaft ? v->I_vehicle : 0.0;
    /* PI governor on the wheel speed, tuned on the rigid-body inertia seen at the wheel */
    J = (v->I_s + v->I_p) * p->ratio * p->ratio + v->I_g + v->I_w;
    w_n = HG_TWO_PI * v->governor_bandwidth;
    p->K_p = 2.0 * GOVERNOR_ZETA * w_n * J;
    p->K_i = w_n * w_n * J;
}

/* The integrator of solver = auto, per fidelity level, chosen from the work-precision
 * measurements (docs/records/work-precision.md): the explicit Runge-Kutta pair for the compliant meshes,
 * whose steps the 1.7 kHz input-shaft mode bounds whatever the tolerance (BDF takes as many,
 * each with a Newton iteration), BDF for the rigid one, whose long steps the explicit pair
 * cannot take (its stability bound is that same mode). */
static int solver_in_force(const hg_vars *v)
{
    if (v->solver != HG_SOLVER_AUTO) return v->solver;
    return v->mesh_model == HG_MESH_MODEL_RIGID ? HG_SOLVER_CVODE_BDF : HG_SOLVER_ARKODE_ERK;
}

/* The highest BDF order: 2 for the rigid mesh with a dynamic input shaft. Its steps are long
 * against that shaft's lightly damped mode (1.7 kHz, zeta_4: eigenvalues close to the imaginary
 * axis), where BDF is A-stable up to order 2 only: with orders up to 5 the order and step
 * controller kept switching between orders 2 and 3 at about 8 steps per period of the mode,
 * chasing its ringing (94 solver steps per mesh cycle at 500 rpm, 100 N m; 31 at order 2, 3.7
 * and 1.25 at 6000 rpm). Elsewhere the method's own (0). */
static int bdf_max_order(const hg_dyn_params *p, int solver)
{
    return solver == HG_SOLVER_CVODE_BDF && p->mesh == HG_MESH_MODEL_RIGID &&
                   !p->quasi_static_input
               ? 2
               : 0;
}

/* Most steps between Jacobian evaluations: 1000 for the rigid mesh, whose Jacobian is the shafts'
 * and the governor's constant one but for the friction's slow drift, so that one serves Newton
 * for many steps (CVODE evaluates a new one whenever Newton fails to converge; the error test is
 * the same). CVODE's own 51 steps spent a fifth of the right-hand sides on finite-difference
 * Jacobians at 500 rpm. Elsewhere CVODE's own (0): the mesh stiffness varies along the cycle. */
static long jac_every(const hg_dyn_params *p)
{
    return p->mesh == HG_MESH_MODEL_RIGID ? 1000 : 0;
}

/* Absolute tolerances: atol is on the DTE [m]; angles scale by 1/R, speeds by omega_4/R. */
static void tolerances(hg_setup *s, const hg_vars *v)
{
    double a = v->atol, R_p = s->p.R_p0, R_g = R_p * s->p.ratio, w4 = HG_TWO_PI * v->f_4;
    double E = a * s->p.k_m0 * 1e-4; /* energy: a force of k_m * 0.1 mm through a */
    double *t = s->atol;
    t[HG_Y_TWIST1] = t[HG_Y_PHI_P] = a / R_p;
    t[HG_Y_TWIST2] = t[HG_Y_GOV] = t[HG_Y_TWIST_HS] = a / R_g;
    t[HG_Y_X] = a;
    t[HG_Y_W_S] = t[HG_Y_W_P] = a * w4 / R_p;
    t[HG_Y_W_G] = t[HG_Y_W_W] = a * w4 / R_g;
    t[HG_Y_E_IN] = t[HG_Y_E_OUT] = t[HG_Y_E_FRIC] = t[HG_Y_E_DAMP] = t[HG_Y_E_EXC] = E;
    t[HG_Y_ETA2] = t[HG_Y_ETA_AXLE2] = 1e-9;
    t[HG_Y_E_CHURN] = t[HG_Y_E_BEAR] = t[HG_Y_E_SEAL] = t[HG_Y_Q_H] = E;
    t[HG_Y_T_OIL] = 1e-6; /* K */
    t[HG_Y_T_KM] = 1e-3;  /* N m */
    t[HG_Y_IMP_W] = 1e-6; /* N m s */
    s->n_active = s->p.half_shaft ? HG_NY : HG_Y_TWIST_HS; /* the half-shaft's states last */
    s->rtol = v->rtol;
    s->solver = solver_in_force(v);
    s->fixed_step = s->solver == HG_SOLVER_NEWMARK;
    s->explicit_rk = s->solver == HG_SOLVER_ARKODE_ERK;
    s->max_order = bdf_max_order(&s->p, s->solver);
    s->jac_every = jac_every(&s->p);
    s->max_step = v->max_step;
    s->f_max = v->f_4;
    s->steps_per_mesh = s->fixed_step ? v->steps_per_mesh_cycle : STEPS_PER_MESH;
}

int hg_setup_oil_in_range(const hg_setup *s, const char *name, double T, char *err, size_t errlen)
{
    double lo, hi;
    hg_lubricant_T_range(&s->lub, &lo, &hi);
    if (T >= lo && T <= hi) return 0;
    hg_errorf(err, errlen, "%s = %g K (%.1f degC) is outside the valid range of the lubricant %s, "
              "%.1f-%.1f K (%.1f to %.1f degC): colder, its viscosity exceeds SAE J306's %g Pa s; "
              "hotter, it lies %g K beyond its pressure-viscosity data", name, T, T - 273.15,
              s->lub.name, lo, hi, lo - 273.15, hi - 273.15, HG_LUBRICANT_ETA_COLD,
              HG_LUBRICANT_T_BEYOND);
    return -1;
}

int hg_setup_load(hg_setup *s, const char *resource_dir, const hg_logger *lg, hg_vars *v,
                  char *err, size_t errlen)
{
    if (load_gearset(s, resource_dir, v, err, errlen) ||
        load_lubricant(s, resource_dir, v, err, errlen))
        return -1;
    if (v->thermal_model == HG_THERMAL_MODEL_SUMP
            ? hg_setup_oil_in_range(s, "T_oil0", v->T_oil0, err, errlen)
            : hg_setup_oil_in_range(s, "T_bath", v->T_bath, err, errlen))
        return -1;
    dynamics_params(s, v);
    if (v->input_shaft == HG_INPUT_SHAFT_QUASI_STATIC && v->mesh_model != HG_MESH_MODEL_RIGID) {
        hg_errorf(err, errlen, "input_shaft = quasi_static joins the input shaft's end to the "
                  "pinion-gear body of the rigid mesh: it needs mesh_model = rigid (mesh_model "
                  "is %d)", v->mesh_model);
        return -1;
    }
    if (v->output_shaft == HG_OUTPUT_SHAFT_QUASI_STATIC && v->mesh_model != HG_MESH_MODEL_RIGID) {
        hg_errorf(err, errlen, "output_shaft = quasi_static joins the wheel end to the "
                  "pinion-gear body of the rigid mesh: it needs mesh_model = rigid (mesh_model "
                  "is %d)", v->mesh_model);
        return -1;
    }
    ehl_params(s, resource_dir, v);
    if (load_map(s, resource_dir, v, err, errlen)) return -1;
    if (damping(s, lg, v, err, errlen)) return -1;
    hg_plausibility_warn(v, lg);
    if (hg_ledger_setup(&s->p.ledger, v, v->gear_set_file[0] ? 0 : v->gear_set,
                        s->gear.has_blank ? s->gear.blank : NULL, &s->lub, err, errlen))
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

void hg_setup_free(hg_setup *s)
{
    hg_effmap_free(&s->map);
    hg_store_put(s->phase);
    hg_store_put(s->z_table);
    s->phase = NULL;
    s->z_table = NULL;
}
