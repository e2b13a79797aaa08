/* The model's outputs: every output variable of hg_vars from the current state, in the sets of
 * variables.toml's [output_sets] (HG_OUTSET_*). */
#ifndef HG_OUTPUTS_H
#define HG_OUTPUTS_H

#include "hg_vars.h"
#include "model/setup.h"
#include "model/stepping.h"

/* Fills the main outputs of v from rt (without disturbing its warm starts) as its right-hand side
 * computes them: with the friction tables s->p.tables when there are, which must be keyed as the
 * state ran. steps and evals are the integrator's counters. */
void hg_outputs_main(const hg_setup *s, const hg_runtime *rt, long steps, long evals, hg_vars *v);

/* Fills the pair outputs of v from rt: every pair's friction model solved directly; the split of
 * P_loss needs the main outputs of v to be current. */
void hg_outputs_pairs(const hg_setup *s, const hg_runtime *rt, hg_vars *v);

/* Fills the continuous states' own (local) variables in v (variables.toml's [[state]],
 * hg_state_vr): the state vector's values, without evaluating the model (the states that are
 * outputs are the main set's). */
void hg_outputs_states(const hg_runtime *rt, hg_vars *v);

/* Fills every state's derivative in v (hg_derivative_vr) as the right-hand side computes it. */
void hg_outputs_derivatives(const hg_setup *s, const hg_runtime *rt, hg_vars *v);

#endif
