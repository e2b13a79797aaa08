/* The FMI 2.0 co-simulation instance shared by the files of the FMI layer:
 *   instance.c       logging, the state machine, the model's set-up and checks on its results
 *   fmi2_lifecycle.c instantiation, experiment set-up, initialization, termination, reset
 *   fmi2_access.c    fmi2Get/Set{Real,Integer,Boolean,String}
 *   fmi2_step.c      input derivatives, fmi2DoStep, the status queries
 *   fmi2_state.c     FMU state snapshots and their serialization
 *   vars.c, uri.c    hg_vars start values and copies; file:// URIs */
#ifndef HG_INSTANCE_H
#define HG_INSTANCE_H

#include "fmi2Functions.h"
#include "hg_vars.h"
#include "io/errmsg.h"
#include "model/hypoid.h"

/* FMI 2.0 co-simulation states (bit flags, so a function can name the set it is allowed in). */
typedef enum {
    ST_INSTANTIATED = 1,
    ST_INITIALIZATION = 2,
    ST_STEP_COMPLETE = 4,
    ST_TERMINATED = 8,
    ST_ERROR = 16
} hg_fmi_state;

/* The sets of states the functions are allowed in. */
#define ST_ANY (ST_INSTANTIATED | ST_INITIALIZATION | ST_STEP_COMPLETE | ST_TERMINATED | ST_ERROR)
#define ST_READABLE (ST_INITIALIZATION | ST_STEP_COMPLETE | ST_TERMINATED | ST_ERROR)
#define ST_BEFORE_RUN (ST_INSTANTIATED | ST_INITIALIZATION)
#define ST_STATUS (ST_STEP_COMPLETE | ST_TERMINATED | ST_ERROR) /* status queries, termination */

enum { CAT_EVENTS, CAT_WARNING, CAT_ERROR, CAT_ALL, N_CATEGORIES };
extern const char *const hg_category_names[N_CATEGORIES];

typedef struct {
    char *name;
    fmi2CallbackLogger logger;
    fmi2ComponentEnvironment env;
    int log_on[N_CATEGORIES];
    hg_fmi_state state;
    char *resource_dir;
    hg_vars vars;
    double start_time;
    int stop_defined;        /* fmi2SetupExperiment gave a stop time: no step may pass it */
    double stop_time;
    hg_inputs input_der;     /* first derivatives for the next step */
    hg_model *model;
    int set_up; /* the model is set up for the current parameters and initial inputs */
} hg_instance;

/* Logs to the host when the category is on. status: the fmi2Status the message accompanies. */
void hg_log(hg_instance *c, fmi2Status status, int category, const char *fmt, ...) HG_PRINTF_LIKE(4, 5);

/* Logs "fn: message" as an error. */
void hg_error(hg_instance *c, const char *fn, const char *fmt, ...) HG_PRINTF_LIKE(3, 4);

/* An error in the model: logs "fn: why" and leaves the instance in the error state. */
fmi2Status hg_fail(hg_instance *c, const char *fn, const char *why);

/* Returns 1 when the call is allowed in the current state, else logs and returns 0. */
int hg_allowed(hg_instance *c, const char *fn, int states);

/* The instance's model, created on first use with logging through the host. NULL: no memory. */
hg_model *hg_instance_model(hg_instance *c);

/* Sets the model up for the current parameters and initial inputs, once. */
fmi2Status hg_ensure_set_up(hg_instance *c, const char *fn);

/* Before output info is read: brings the outputs in c->vars up to date with the model (they
 * are computed when first read after a step); a Real output that is not finite puts the
 * instance in the error state. */
fmi2Status hg_instance_output(hg_instance *c, const char *fn, const hg_var_info *info);

/* The model time; the start time while no model is set up. */
double hg_instance_time(const hg_instance *c);

/* The value of a Real variable of the instance. */
double hg_real_value(const hg_instance *c, const hg_var_info *info);

/* The first time derivative the host gave for a variable (0 when none or not an input). */
double hg_derivative_of(const hg_instance *c, const hg_var_info *info);

/* "T_s = 100, T_w = 276.9, ...": the inputs, for messages about failed set-ups and steps. */
void hg_describe_inputs(const hg_instance *c, char *out, size_t len);

/* "40 K (-233.15 degC)": a value with its unit and, when it has one, its display unit. */
void hg_quote_value(char *buf, size_t n, const hg_var_info *info, double v);

/* "[200, 500] K": the declared range with its unit. */
void hg_quote_range(char *buf, size_t n, const hg_var_info *info);

/* The first Real output (and calculated parameter when asked) that is not finite, or NULL. */
const hg_var_info *hg_first_nonfinite(const hg_instance *c, int calculated_too);

/* The table entry of value reference vr when it has the type asked for; else logs, NULL. */
const hg_var_info *hg_lookup(hg_instance *c, const char *fn, fmi2ValueReference vr,
                             hg_base_type type);

/* Logs and returns -1 when nvr > 0 and an array is NULL. */
int hg_check_array_args(hg_instance *c, const char *fn, const void *vr, size_t nvr,
                        const void *values);

/* Sets every variable to its start value (strings duplicated); frees previous strings. */
int hg_vars_reset(hg_vars *v);
void hg_vars_free_strings(hg_vars *v);
int hg_vars_copy(hg_vars *dst, const hg_vars *src); /* deep copy, dst strings freed first */
int hg_vars_same_parameters(const hg_vars *a, const hg_vars *b);
/* Copies the outputs and calculated parameters only: failures put back the last good ones. */
void hg_vars_copy_results(hg_vars *dst, const hg_vars *src);

/* Percent-decoded local path of a file:// URI; NULL (with why filled) when it is not one. */
char *hg_uri_to_path(const char *uri, char *why, size_t whylen);

#endif
