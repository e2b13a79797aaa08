/* Warnings at set-up for values that are accepted but ignored or implausible: the run goes on,
 * the host is told (category logStatusWarning). */
#ifndef HG_PLAUSIBILITY_H
#define HG_PLAUSIBILITY_H

#include "hg_vars.h"
#include "io/constants.h"
#include "io/log.h"

/* Pinion speeds above this [rad/s] (8000 rpm) are beyond road-vehicle axles: likely rpm typed
 * where rad/s is meant (the declared range, +-2000 rad/s, is the model's numerical limit). */
#define HG_PLAUSIBLE_PINION_SPEED (8000.0 * HG_PI / 30.0)

/* Warns about T_w set under load_mode = speed (the governor replaces it) and about w_set
 * (load_mode = speed) and w_p0 faster than HG_PLAUSIBLE_PINION_SPEED. */
void hg_plausibility_warn(const hg_vars *v, const hg_logger *lg);

#endif
