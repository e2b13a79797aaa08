/* The FMI 2.0 co-simulation instance shared by the files of the FMI layer. */
#ifndef HG_INSTANCE_H
#define HG_INSTANCE_H

#include "fmi2Functions.h"
#include "hg_vars.h"
#include "model/hypoid.h"

/* FMI 2.0 co-simulation states (bit flags, so a function can name the set it is allowed in). */
typedef enum {
    ST_INSTANTIATED = 1,
    ST_INITIALIZATION = 2,
    ST_STEP_COMPLETE = 4,
    ST_TERMINATED = 8,
    ST_ERROR = 16,
    ST_FATAL = 32
} hg_fmi_state;

enum { CAT_EVENTS, CAT_WARNING, CAT_ERROR, CAT_ALL, N_CATEGORIES };

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
    hg_inputs input_der; /* first derivatives for the next step */
    hg_model *model;
    int set_up; /* the model is set up for the current parameters and initial inputs */
} hg_instance;

/* Logs to the host when the category is on. status: the fmi2Status the message accompanies. */
void hg_log(hg_instance *c, fmi2Status status, int category, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

/* The instance's model, created on first use with logging through the host. NULL: no memory. */
hg_model *hg_instance_model(hg_instance *c);

/* Returns 1 when the call is allowed in the current state, else logs and returns 0. */
int hg_allowed(hg_instance *c, const char *fn, int states);

/* The value of a Real variable of the instance. */
double hg_real_value(const hg_instance *c, const hg_var_info *info);

/* The first Real output (and calculated parameter when asked) that is not finite, or NULL. */
const hg_var_info *hg_first_nonfinite(const hg_instance *c, int calculated_too);

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
