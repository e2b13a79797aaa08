/* Internals of the model object shared by its files: hypoid.c (stepping, events, outputs,
 * snapshots) and setup.c (data, parameters, damping, initial state). */
#ifndef HG_HYPOID_INTERNAL_H
#define HG_HYPOID_INTERNAL_H

#include "model/effmap.h"
#include "model/hypoid.h"
#include "solver/solver.h"

#define TWO_PI 6.283185307179586
#define STEPS_PER_MESH 30     /* CVODE's automatic max_step: 1/30 of a mesh period (physics 8.8) */

struct hg_model {
    char *resource_dir;
    hg_log_fn log;
    void *log_ctx;
    hg_gearset gear;
    hg_lubricant lub;
    hg_effmap map; /* friction_model = map only */
    hg_dyn_params p;
    hg_solver *solver;
    double atol[HG_NY];
    double rtol;
    double max_step;      /* user's max_step, 0 = automatic */
    int steps_per_mesh;   /* per mesh cycle: the fixed step (newmark) or the automatic max_step */
    int fixed_step;       /* the solver takes fixed steps (newmark) */
    double f_max;         /* highest natural frequency of the linearised system [Hz] */
    double window_angle; /* pinion angle of one averaging window [rad] */
    hg_runtime rt;
};

void hg_model_log(hg_model *m, const char *category, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* The FMU inputs of v. */
void hg_model_inputs(const hg_vars *v, hg_dyn_inputs *u);

/* (Re)creates the integrator on the model's right-hand side and roots. */
int hg_model_make_solver(hg_model *m, const hg_vars *v, char *err, size_t errlen);

/* Fills the outputs of v from the current state. */
void hg_model_write_outputs(hg_model *m, hg_vars *v);

#endif
