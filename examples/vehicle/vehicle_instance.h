/* The vehicle FMU's instance, shared by its FMI 2.0 files: fmi2_vehicle.c (life cycle, variable
 * access, co-simulation stepping, FMU states) and fmi2_vehicle_me.c (Model Exchange). */
#ifndef VEHICLE_INSTANCE_H
#define VEHICLE_INSTANCE_H

#include "fmi2Functions.h"
#include "vehicle_model.h"

/* The states of the instance (bit flags): co-simulation steps in ST_STEP_COMPLETE, Model
 * Exchange alternates between ST_EVENT and ST_CONTINUOUS. */
typedef enum {
    ST_INSTANTIATED = 1,
    ST_INIT = 2,
    ST_STEP_COMPLETE = 4,
    ST_TERMINATED = 8,
    ST_ERROR = 16,
    ST_EVENT = 32,
    ST_CONTINUOUS = 64
} vm_state;
#define ST_RUNNING (ST_STEP_COMPLETE | ST_EVENT | ST_CONTINUOUS) /* after initialization */

enum { CAT_WARNING, CAT_ERROR, CAT_ALL, N_CATEGORIES };

typedef struct {
    char *name;
    fmi2CallbackLogger logger;
    fmi2ComponentEnvironment env;
    int log_on[N_CATEGORIES];
    vm_state state;
    int model_exchange; /* instantiated for Model Exchange */
    double start_time;
    int stop_defined;
    double stop_time;
    vm_model model;
} vm_instance;

/* A message to the host when its category is on ('%' escaped: the host formats it). */
void logf_(vm_instance *c, fmi2Status status, int cat, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

/* Logs an error, puts the instance into the error state and returns fmi2Error. */
fmi2Status fail(vm_instance *c, const char *fn, const char *why);

/* 1 when fn may be called in the instance's state; else logs (without changing the state). */
int allowed(vm_instance *c, const char *fn, int states);

#endif
