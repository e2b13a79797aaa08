/* When the right-hand side reads the pairs' friction from tables (friction_table.h), and for
 * which operating point: the policy between the model object and the tables. The tables are
 * wanted with friction_table on, an EHL friction model and a solver other than Newmark; at each
 * step's start their key follows the operating point (pinion speed, oil temperature, a load
 * estimate) and they are built again when it moves; near standstill the direct solve runs
 * instead. The model object owns the tables (hg_ft_set), the runtime their key, so a restored
 * state rebuilds the very tables it was run with. */
#ifndef HG_FRICTION_TABLE_POLICY_H
#define HG_FRICTION_TABLE_POLICY_H

#include <stddef.h>

#include "hg_vars.h"
#include "io/log.h"
#include "model/friction_table.h"
#include "model/stepping.h"

/* *tables for the set-up s and the variables v: allocated (unbuilt) when wanted, else freed and
 * NULL; s->p.tables is cleared (the first step picks). Node tables shipped in
 * resource_dir/tables/ are read rather than solved (hg_store_get_shipped); resource_dir must
 * outlive *tables. -1 with a message when out of memory. */
int hg_ftp_setup(hg_ft_set **tables, hg_setup *s, const char *resource_dir, const hg_vars *v,
                 char *err, size_t errlen);
void hg_ftp_free(hg_ft_set **tables);

/* At a step's start with inputs u, before the step begins: moves rt's key onto the operating
 * point when it no longer covers it, its load range on hg_ft_load_range_on_lattice's lattice
 * and its temperature, when that moves, on hg_ft_temperature_on_lattice's (the first key keeps
 * the temperature itself: a run at a constant oil temperature keeps the drift terms at 0), for
 * the model's own integrator and a host's alike. 1 when the tables must be built again, else 0
 * (also without tables and near standstill). A new key changes the right-hand side within the
 * tables' error: like a jump of the inputs it restarts the integrator, whose history saw the
 * old one. */
int hg_ftp_stale(const hg_ft_set *tables, hg_runtime *rt, const hg_dyn_params *p,
                 const hg_inputs *u);

/* Then, once the old right-hand side is no longer needed: builds the tables for rt's key when
 * `rebuild`, and points s->p.tables at the tables this step uses (NULL, the direct solve: none
 * wanted, or near standstill; a table that is not usable falls back per table). 1 when that
 * switched to or from the direct solve (a full restart of the integrator). */
int hg_ftp_begin(hg_ft_set *tables, hg_runtime *rt, hg_setup *s, int rebuild,
                 const hg_logger *log);

/* The tables the state rt ran on (NULL: the direct solve), keyed again for its key when a
 * restored state or a failed step left them keyed for another, for the outputs of that state. */
hg_ft_set *hg_ftp_of_state(hg_ft_set *tables, const hg_runtime *rt, const hg_setup *s,
                           const hg_logger *log);

#endif
