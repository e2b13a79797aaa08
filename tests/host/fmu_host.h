/* The parts of a small FMI 2.0 host in C shared by the test host (tests/host/run_fmu.c) and the
 * benchmark host (bench/bench_fmu.c): dlopen an unzipped FMU, read what the host needs from its
 * modelDescription.xml, instantiate it (co-simulation or Model Exchange) with a logger that
 * counts errors, and set variables by name. */
#ifndef HG_FMU_HOST_H
#define HG_FMU_HOST_H

#include <limits.h>
#include <stddef.h>

#include "fmi2Functions.h"

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif
#define HOST_MAX_REALS 1024
#define HOST_MAX_STATES 64 /* continuous states and event indicators (Model Exchange) */

/* The FMU's functions. */
typedef struct {
    void *so;
    fmi2InstantiateTYPE *instantiate;
    fmi2FreeInstanceTYPE *free_instance;
    fmi2SetupExperimentTYPE *setup;
    fmi2EnterInitializationModeTYPE *enter;
    fmi2ExitInitializationModeTYPE *exit_init;
    fmi2TerminateTYPE *terminate;
    fmi2ResetTYPE *reset;
    fmi2GetRealTYPE *get_real;
    fmi2GetIntegerTYPE *get_integer;
    fmi2SetRealTYPE *set_real;
    fmi2SetIntegerTYPE *set_integer;
    fmi2SetBooleanTYPE *set_boolean;
    fmi2SetStringTYPE *set_string;
    fmi2SetRealInputDerivativesTYPE *set_real_input_derivatives;
    fmi2DoStepTYPE *do_step;
    fmi2GetFMUstateTYPE *get_state;
    fmi2SetFMUstateTYPE *set_state;
    fmi2FreeFMUstateTYPE *free_state;
    fmi2SerializedFMUstateSizeTYPE *state_size;
    fmi2SerializeFMUstateTYPE *serialize;
    fmi2DeSerializeFMUstateTYPE *deserialize;
    /* Model Exchange (NULL when the FMU has none) */
    fmi2EnterEventModeTYPE *enter_event_mode;
    fmi2NewDiscreteStatesTYPE *new_discrete_states;
    fmi2EnterContinuousTimeModeTYPE *enter_continuous_time_mode;
    fmi2CompletedIntegratorStepTYPE *completed_integrator_step;
    fmi2SetTimeTYPE *set_time;
    fmi2SetContinuousStatesTYPE *set_continuous_states;
    fmi2GetContinuousStatesTYPE *get_continuous_states;
    fmi2GetDerivativesTYPE *get_derivatives;
    fmi2GetEventIndicatorsTYPE *get_event_indicators;
    fmi2GetNominalsOfContinuousStatesTYPE *get_nominals;
} fmu_lib;

/* What the host reads from the model description. */
typedef struct {
    char so_path[PATH_MAX];
    char guid[128];
    char *resource_uri;
    fmi2ValueReference reals[HOST_MAX_REALS]; /* every Real variable */
    size_t n_reals;
    size_t nx, nz; /* continuous states and event indicators (Model Exchange) */
    char *xml;
} fmu_info;

typedef struct {
    int errors;
} log_env;

typedef struct {
    const fmu_lib *f;
    const fmu_info *m;
    fmi2CallbackFunctions cb;
    log_env log;
    fmi2Component c;
    int model_exchange; /* instantiated as fmi2ModelExchange */
} instance;

/* Prints "<prog>: FAILED: what" and returns -1. */
int host_fail(const char *what);

int host_load(fmu_lib *f, const char *so_path);
void host_unload(fmu_lib *f);

/* Reads DIR/modelDescription.xml of an unzipped FMU. */
int host_read_info(fmu_info *m, const char *dir);
void host_free_info(fmu_info *m);

/* The value reference of the variable called name, or -1. */
long host_value_reference(const fmu_info *m, const char *name);

/* fmi2Instantiate with a logger that prints errors (everything with RUN_FMU_VERBOSE set) and
 * counts them in in->log.errors. */
int host_open(instance *in, const fmu_lib *f, const fmu_info *m, const char *name);
/* The same for co-simulation (model_exchange 0) or Model Exchange (1). */
int host_open_as(instance *in, const fmu_lib *f, const fmu_info *m, const char *name,
                 int model_exchange);
void host_close(instance *in);

int host_set_int(instance *in, const char *name, int value);
int host_set_real(instance *in, const char *name, double value);
/* Sets a Real, Integer, Boolean or Enumeration variable from text: a number, true/false, or an
 * enumeration item's name ("cvode_adams"). */
int host_set(instance *in, const char *name, const char *text);

#endif
