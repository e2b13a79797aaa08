/* The co-simulation instance shared by the files of the FMI layer. The FMI 2.0 and FMI 3.0
 * functions are thin adapters (fmi2_*.c, fmi3_*.c: their argument types, names and states) over
 * version-neutral files that know no FMI header, as the Modelica Association's Reference-FMUs do:
 *   instance.c       logging, the state machine, the model's set-up and checks on its results
 *   lifecycle.c      instantiation, log categories, experiment set-up, termination, reset
 *   access.c         getting and setting one variable by value reference
 *   step.c           the communication step with its checks
 *   snapshot.c       FMU state snapshots and their serialization
 *   vars.c, uri.c    hg_vars start values and copies; file:// URIs
 * FMI 2.0: fmi2_lifecycle.c, fmi2_access.c, fmi2_step.c (input derivatives, status queries),
 * fmi2_state.c, fmi2_me.c. FMI 3.0: fmi3_lifecycle.c, fmi3_access.c (typed, arrays),
 * fmi3_step.c, fmi3_state.c, fmi3_me.c, fmi3_unsupported.c (the functions of what this FMU does
 * not implement). Model Exchange of both (time, continuous states, derivatives, event
 * indicators, event and continuous-time modes, over model/exchange.h): me.c. */
#ifndef HG_INSTANCE_H
#define HG_INSTANCE_H

#include "hg_vars.h"
#include "io/errmsg.h"
#include "model/hypoid.h"

/* The status of an FMI call: the values of fmi2Status and fmi3Status (fmi2OK = fmi3OK = 0, ...),
 * which the adapters pass on as they are. */
typedef enum { HG_OK, HG_WARNING, HG_DISCARD, HG_ERROR, HG_FATAL } hg_status;

/* A value reference: hg_vr and fmi3ValueReference are both unsigned 32-bit. */
typedef unsigned int hg_vr;

/* The states (bit flags, so a function can name the set it is allowed in): co-simulation steps
 * in ST_STEP_COMPLETE (FMI 2.0's step complete is FMI 3.0's step mode), Model Exchange
 * alternates between ST_EVENT_MODE and ST_CONTINUOUS_TIME; an instance is one or the other from
 * its instantiation on. */
typedef enum {
    ST_INSTANTIATED = 1,
    ST_INITIALIZATION = 2,
    ST_STEP_COMPLETE = 4,
    ST_TERMINATED = 8,
    ST_ERROR = 16,
    ST_EVENT_MODE = 32,
    ST_CONTINUOUS_TIME = 64
} hg_fmi_state;

/* The sets of states the functions are allowed in. */
#define ST_RUNNING (ST_STEP_COMPLETE | ST_EVENT_MODE | ST_CONTINUOUS_TIME) /* after initialization */
#define ST_ANY (ST_INSTANTIATED | ST_INITIALIZATION | ST_RUNNING | ST_TERMINATED | ST_ERROR)
#define ST_READABLE (ST_INITIALIZATION | ST_RUNNING | ST_TERMINATED | ST_ERROR)
#define ST_BEFORE_RUN (ST_INSTANTIATED | ST_INITIALIZATION)
#define ST_STATUS (ST_STEP_COMPLETE | ST_TERMINATED | ST_ERROR) /* status queries, termination */

enum { CAT_EVENTS, CAT_WARNING, CAT_ERROR, CAT_ALL, N_CATEGORIES };
extern const char *const hg_category_names[N_CATEGORIES];

typedef struct hg_instance hg_instance;

/* Passes a message to the host's logger (the adapter of the instance's FMI version). */
typedef void (*hg_emit_fn)(const hg_instance *c, hg_status status, const char *category,
                           const char *message);
/* Any function pointer: the host's logger, cast back to its type by the emit function. */
typedef void (*hg_any_fn)(void);

struct hg_instance {
    char *name;
    hg_emit_fn emit;         /* NULL: no logger */
    hg_any_fn logger;        /* the host's fmi2CallbackLogger / fmi3LogMessageCallback */
    void *env;               /* the host's component / instance environment */
    int log_on[N_CATEGORIES];
    hg_fmi_state state;
    int model_exchange; /* instantiated for Model Exchange (else co-simulation) */
    char *resource_dir;
    hg_vars vars;
    double start_time;
    int stop_defined;        /* a stop time was given: no step may pass it */
    double stop_time;
    hg_inputs input_der;     /* first derivatives for the next step */
    hg_model *model;
    int set_up; /* the model is set up for the current parameters and initial inputs */
    int step_warned; /* a step longer than the coupling holds has been reported */
};

/* Logs to the host when the category is on. status: the status the message accompanies. */
void hg_log(hg_instance *c, hg_status status, int category, const char *fmt, ...) HG_PRINTF_LIKE(4, 5);

/* Logs "fn: message" as an error. */
void hg_error(hg_instance *c, const char *fn, const char *fmt, ...) HG_PRINTF_LIKE(3, 4);

/* An error in the model: logs "fn: why" and leaves the instance in the error state. */
hg_status hg_fail(hg_instance *c, const char *fn, const char *why);

/* Returns 1 when the call is allowed in the current state, else logs and returns 0. */
int hg_allowed(hg_instance *c, const char *fn, int states);

/* Returns 1 when the instance has the interface (model_exchange 1: Model Exchange, 0:
 * co-simulation) that fn belongs to, else logs and returns 0. */
int hg_interface(hg_instance *c, const char *fn, int model_exchange);

/* The instance's model, created on first use with logging through the host. NULL: no memory. */
hg_model *hg_instance_model(hg_instance *c);

/* Sets the model up for the current parameters and initial inputs, once (in Model Exchange also
 * hands it to the host's integrator). */
hg_status hg_ensure_set_up(hg_instance *c, const char *fn);

/* Before output info is read: brings the outputs in c->vars up to date with the model (they
 * are computed when first read after a step); a Real output that is not finite puts the
 * instance in the error state. */
hg_status hg_instance_output(hg_instance *c, const char *fn, const hg_var_info *info);

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
const hg_var_info *hg_lookup(hg_instance *c, const char *fn, hg_vr vr,
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

/* ------------------------------------------------------------------ lifecycle.c */

/* A new instance (NULL: no memory) named name, logging through emit / logger / env with every
 * category on when logging_on (warnings and errors always); checks the name and the token
 * (GUID / instantiation token) against tokens (NULL-terminated), and takes the resource
 * location (may be NULL or empty): a file:// URI when uri (FMI 2.0), else a path (FMI 3.0).
 * NULL after logging when bad. */
hg_instance *hg_instantiate(const char *fn, const char *name, const char *token,
                            const char *const tokens[], const char *resources, int uri,
                            hg_emit_fn emit, hg_any_fn logger, void *env, int logging_on);
void hg_free_instance(hg_instance *c);

/* Switches the categories named (all when n = 0) on or off. */
hg_status hg_set_debug_logging(hg_instance *c, const char *fn, int on, size_t n,
                               const char *const cats[]);

/* The experiment's start and (when stop_defined) stop time, before initialization. */
hg_status hg_setup_experiment(hg_instance *c, const char *fn, double start, int stop_defined,
                              double stop);

hg_status hg_enter_initialization(hg_instance *c, const char *fn);
hg_status hg_exit_initialization(hg_instance *c, const char *fn);
hg_status hg_terminate(hg_instance *c, const char *fn);
hg_status hg_reset(hg_instance *c, const char *fn);

/* ------------------------------------------------------------------ access.c */

/* Checks before reading variables (allowed now, arrays not NULL), setting the model up when
 * read in initialization mode. */
hg_status hg_prepare_get(hg_instance *c, const char *fn, const void *vr, size_t nvr,
                         const void *values);

/* Copies the variable vr of the given type into value (a double, an int or a string pointer). */
hg_status hg_get_value(hg_instance *c, const char *fn, hg_base_type type, hg_vr vr, void *value);

/* Checks before setting variables (allowed now, arrays not NULL). */
hg_status hg_prepare_set(hg_instance *c, const char *fn, const void *vr, size_t nvr,
                         const void *values);

/* Sets a Real (x) or an Integer / Boolean (k) variable after checking that it may be set now
 * and that the value is finite and in range. */
hg_status hg_set_number(hg_instance *c, const char *fn, hg_base_type type, hg_vr vr, double x,
                        int k);

/* Sets a String variable (copied). */
hg_status hg_set_string(hg_instance *c, const char *fn, hg_vr vr, const char *value);

/* ------------------------------------------------------------------ step.c */

/* The communication step from t by h (the input derivatives of c->input_der held over it). */
hg_status hg_do_step(hg_instance *c, const char *fn, double t, double h);

/* ------------------------------------------------------------------ me.c (Model Exchange) */

hg_status hg_me_enter_event_mode(hg_instance *c, const char *fn);
/* The event's discrete update; *states_changed: the host must read the states again. */
hg_status hg_me_update(hg_instance *c, const char *fn, int *states_changed);
hg_status hg_me_enter_continuous_time(hg_instance *c, const char *fn);
/* After the host's integrator step; *enter_event_mode: a step event is due. */
hg_status hg_me_completed_step(hg_instance *c, const char *fn, int *enter_event_mode);
hg_status hg_me_set_time(hg_instance *c, const char *fn, double t);
/* The arrays have the model's sizes: nx = HG_NUM_STATES, nz = HG_NUM_EVENT_INDICATORS. */
hg_status hg_me_set_states(hg_instance *c, const char *fn, const double x[], size_t nx);
hg_status hg_me_states(hg_instance *c, const char *fn, double x[], size_t nx);
hg_status hg_me_nominals(hg_instance *c, const char *fn, double x_nominal[], size_t nx);
hg_status hg_me_derivatives(hg_instance *c, const char *fn, double dx[], size_t nx);
hg_status hg_me_indicators(hg_instance *c, const char *fn, double z[], size_t nz);

/* ------------------------------------------------------------------ snapshot.c */

hg_status hg_get_state(hg_instance *c, const char *fn, void **state);
hg_status hg_set_state(hg_instance *c, const char *fn, const void *state);
hg_status hg_free_state(hg_instance *c, const char *fn, void **state);
hg_status hg_serialized_size(hg_instance *c, const char *fn, const void *state, size_t *size);
hg_status hg_serialize(hg_instance *c, const char *fn, const void *state, void *bytes,
                       size_t size);
hg_status hg_deserialize(hg_instance *c, const char *fn, const void *bytes, size_t size,
                         void **state);

#endif
