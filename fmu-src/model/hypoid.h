/* The HypoidGearPair model: set-up from the FMU variables, time stepping with events, outputs and
 * state snapshots. It knows the variables (hg_vars) but nothing of the FMI calling conventions. */
#ifndef HG_HYPOID_H
#define HG_HYPOID_H

#include <stddef.h>

#include "hg_vars.h"
#include "io/datafile.h"
#include "model/dynamics.h"

/* Messages to the host: category is "logEvents", "logStatusWarning", "logStatusError" or
 * "logAll". */
typedef void (*hg_log_fn)(void *ctx, const char *category, const char *message);

/* Everything that evolves in time; plain data, so a snapshot is a copy. */
typedef struct {
    double t;
    double y[HG_NY];
    int mode;                      /* backlash contact mode HG_MODE_* */
    int n_impacts;                 /* contact changes so far */
    double T_c_warm[HG_MAX_PAIRS]; /* warm starts of the thermal solves [K] */
    hg_dyn_inputs u0, du;          /* inputs at the step start and their time derivatives */
    double t_u0;                   /* time at which u0 holds */
    hg_dyn_inputs u_end;           /* inputs extrapolated to the end of the last step */
    int restart;                   /* the integrator must restart before the next step */
    double win_phi0, win_t0;       /* start of the averaging window: pinion angle, time */
    double win_eta2_0, win_efric_0;
    int windows;                   /* averaging windows completed */
    double eta_cycle, P_loss_cycle;
    int map_warned;                /* the map level has said once that it left its grid */
} hg_runtime;

typedef struct hg_model hg_model;

hg_model *hg_model_new(const char *resource_dir, hg_log_fn log, void *log_ctx);
void hg_model_free(hg_model *m);

/* Loads the data the parameters name, computes the damping and the calculated parameters, and
 * puts the state at static equilibrium at speed w_p0 at time t0. Writes the calculated
 * parameters and the outputs into v. */
int hg_model_setup(hg_model *m, hg_vars *v, double t0, char *err, size_t errlen);

/* Advances from the current time by h with the inputs of v (and their derivatives du, held
 * over the step), handling every contact change and averaging window inside; writes outputs. */
int hg_model_step(hg_model *m, hg_vars *v, const hg_dyn_inputs *du, double h, char *err,
                  size_t errlen);

double hg_model_time(const hg_model *m);

/* State snapshots: copy out, and restore after hg_model_setup with the same parameters. Taking a
 * snapshot makes the next step restart the integrator, so that a restored run and the original
 * continue bit-identically. */
void hg_model_save(hg_model *m, hg_runtime *out);
int hg_model_restore(hg_model *m, hg_vars *v, const hg_runtime *in, char *err, size_t errlen);

#endif
