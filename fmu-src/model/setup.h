/* Model set-up from the FMU variables: the data files the parameters name, the dynamics and EHL
 * parameters, the modal damping and the integration settings. Calls only downwards (data
 * readers, modal analysis); the model object (hypoid.c) owns an hg_setup. */
#ifndef HG_SETUP_H
#define HG_SETUP_H

#include <stddef.h>

#include "hg_vars.h"
#include "io/log.h"
#include "model/dynamics.h"

typedef struct {
    hg_gearset gear;
    const hg_phase_tables *phase; /* gear's series tabulated, per flank and torque level (held
                                     from the process's table store, model/table_store.h) */
    hg_lubricant lub;
    const hg_z_table *z_table;    /* the lubricant's Z_exact over T (roelands_z = exact, EHL
                                     friction; held from the store), or NULL */
    hg_effmap map;        /* friction_model = map only */
    hg_heat_memo heat;    /* the housing heat's cache */
    hg_dyn_params p;      /* points into gear, lub, map and heat */
    int solver;           /* HG_SOLVER_* in force (auto resolved) */
    double atol[HG_NY];
    double rtol;
    int n_active;         /* states the integrator holds: the half-shaft's two (the last) only
                             under load_mode = half_shaft */
    double max_step;      /* user's max_step, 0 = automatic */
    int steps_per_mesh;   /* per mesh cycle: the fixed step (newmark) or the automatic max_step */
    int fixed_step;       /* the solver takes fixed steps (newmark) */
    int explicit_rk;      /* arkode_erk: stability-bounded steps, no automatic max_step */
    int max_order;        /* highest order of CVODE's BDF (0: its own, 5); see bdf_max_order */
    long jac_every;       /* most steps between CVODE's Jacobians (0: its own); see jac_every */
    double f_max;         /* highest natural frequency of the linearised system [Hz] */
    double window_angle;  /* pinion angle of one averaging window [rad] */
    double I_vehicle;     /* load_mode = half_shaft: the vehicle's inertia at the wheels, over
                             which the wheel speed is corrected (0: not) [kg m^2] */
} hg_setup;

/* Fills s from the parameters of v (data files relative to resource_dir) and writes the
 * calculated parameters into v; warnings go to lg. s must be zeroed or set up before. */
int hg_setup_load(hg_setup *s, const char *resource_dir, const hg_logger *lg, hg_vars *v,
                  char *err, size_t errlen);

/* 0 if the oil temperature T [K], the value of the variable `name`, lies in the lubricant's
 * valid range (hg_lubricant_T_range); else -1 with a message naming it, its value and unit. */
int hg_setup_oil_in_range(const hg_setup *s, const char *name, double T, char *err, size_t errlen);

/* Frees what hg_setup_load allocated. */
void hg_setup_free(hg_setup *s);

#endif
