/* The friction seam: per-pair friction from the per-pair contact state, whatever the model. */
#ifndef HG_FRICTION_H
#define HG_FRICTION_H

#include "tribo/pair_contact.h"
#include "tribo/ehl.h"

typedef struct {
    int model;                /* HG_FRICTION_MODEL_* of hg_vars.h */
    double mu_const;          /* friction coefficient of the coulomb model */
    hg_ehl_params ehl;        /* the EHL models (ehl.thermal set from the model) */
    const hg_lubricant *lub;  /* the EHL models' lubricant */
} hg_friction_config;

/* Fills every field of *out. *T_c_warm is the pair's warm start for thermal models (in/out). */
void hg_friction_pair(const hg_friction_config *cfg, const hg_pair_contact *c, double *T_c_warm,
                      hg_pair_friction *out);

/* For a caller that evaluates one load and geometry at several speeds or temperatures: the
 * Hertz ellipse of c once (hg_friction_hertz; zeroed for models without one), then
 * hg_friction_pair_hertz at each, with hg_friction_pair's result to the last bit. */
void hg_friction_hertz(const hg_friction_config *cfg, const hg_pair_contact *c, hg_hertz *h);
void hg_friction_pair_hertz(const hg_friction_config *cfg, const hg_pair_contact *c,
                            const hg_hertz *h, double *T_c_warm, hg_pair_friction *out);

#endif
