/* The model object's fields, shared by its two faces: hypoid.c (set-up, stepping with the model's
 * own integrator, outputs, snapshots) and exchange.c (the host's integrator). Private to the
 * model layer: nothing above it includes this header. */
#ifndef HG_MODEL_OBJECT_H
#define HG_MODEL_OBJECT_H

#include "model/hypoid.h"
#include "model/setup.h"
#include "solver/solver.h"

struct hg_model {
    char *resource_dir;
    hg_logger log;
    hg_setup s;
    hg_solver *solver;
    hg_ft_set *tables; /* friction_table on with an EHL friction model, else NULL */
    hg_runtime rt;
    int outputs_current[HG_NUM_OUTSETS]; /* each set of outputs written last is that of rt */
};

/* Marks every set of outputs out of date (the state, time or inputs changed). */
void hg_model_outputs_stale(hg_model *m);

#endif
