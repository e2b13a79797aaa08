/* The HypoidGearPair model object: set-up from the FMU variables, time stepping with events,
 * outputs and state snapshots. It knows the variables (hg_vars) but nothing of the FMI calling
 * conventions. hypoid.c holds the object and calls down into setup.c, stepping.c, outputs.c,
 * dynamics.c and the solver; none of them calls back. */
#ifndef HG_HYPOID_H
#define HG_HYPOID_H

#include <stddef.h>

#include "hg_vars.h"
#include "io/errmsg.h"
#include "io/log.h"
#include "model/stepping.h"

typedef struct hg_model hg_model;

/* v at the start values of modelDescription/variables.toml (strings point at the table's own
 * start strings; the FMI layer copies its strings instead): for C programs that use the model
 * without the FMI layer (tools/table_files.c, the C tests). */
void hg_model_start_values(hg_vars *v);

/* log: messages to the host (category "logEvents", "logStatusWarning", ...); may be NULL. */
hg_model *hg_model_new(const char *resource_dir, hg_log_fn log, void *log_ctx);
void hg_model_free(hg_model *m);

/* Loads the data the parameters name, computes the damping and the calculated parameters, and
 * puts the state at static equilibrium at speed w_p0 at time t0. Writes the calculated
 * parameters and every output into v. */
int hg_model_setup(hg_model *m, hg_vars *v, double t0, char *err, size_t errlen);

/* Advances from the current time by h with the inputs of v (and their derivatives du, held
 * over the step), handling every contact change and averaging window inside. The outputs of v
 * are then out of date until hg_model_outputs writes them (computed when read). A failed step
 * (err filled, or a state that is not finite) leaves the model where the step began, whose
 * outputs it then writes again when asked (the same values). */
int hg_model_step(hg_model *m, hg_vars *v, const hg_inputs *du, double h, char *err,
                  size_t errlen);

/* Whether the outputs of set `set` (HG_OUTSET_*, variables.toml's [output_sets]) in v are those
 * of the model's current state. */
int hg_model_outputs_current(const hg_model *m, int set);

/* Writes the outputs of set `set` of the current state into v (when they are out of date), each
 * set on its own: what one set costs is not paid for reading another. */
void hg_model_outputs(hg_model *m, hg_vars *v, int set);

double hg_model_time(const hg_model *m);

/* The longest communication step the load mode's coupling is measured to hold [s], or 0 when it
 * sets none (docs/integration.md): under load_mode = half_shaft two fifths of the period of the
 * half-shaft mode against the held wheel, f_hs = sqrt(k_hs / J) / (2 pi) with J the gear's
 * inertia at the wheel end. */
double hg_model_comm_step_limit(const hg_model *m);

/* State snapshots: copy out, and restore after hg_model_setup with the same parameters. Taking a
 * snapshot makes the next step restart the integrator, so that a restored run and the original
 * continue bit-identically. */
void hg_model_save(hg_model *m, hg_runtime *out);
int hg_model_restore(hg_model *m, hg_vars *v, const hg_runtime *in, char *err, size_t errlen);

#endif
