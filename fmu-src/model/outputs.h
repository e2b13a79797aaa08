/* The model's outputs: every output variable of hg_vars from the current state. */
#ifndef HG_OUTPUTS_H
#define HG_OUTPUTS_H

#include "hg_vars.h"
#include "model/setup.h"
#include "model/stepping.h"

/* Fills the outputs of v from rt (without disturbing its warm starts); steps and evals are the
 * integrator's counters. */
void hg_outputs_write(const hg_setup *s, const hg_runtime *rt, long steps, long evals,
                      hg_vars *v);

#endif
