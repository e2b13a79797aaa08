/* Plausibility warnings at set-up: see plausibility.h. */
#include "model/plausibility.h"

#include <math.h>

static void warn_speed(const hg_logger *lg, const char *name, double w)
{
    if (fabs(w) <= HG_PLAUSIBLE_PINION_SPEED) return;
    hg_logf(lg, "logStatusWarning",
            "%s = %g rad/s (%.0f rpm) is faster than road-vehicle axle pinions turn (above "
            "%.0f rad/s = %.0f rpm); %s is in rad/s: if %g was meant in rpm, set %.4g rad/s",
            name, w, w * HG_RPM_PER_RAD_S, HG_PLAUSIBLE_PINION_SPEED,
            HG_PLAUSIBLE_PINION_SPEED * HG_RPM_PER_RAD_S, name, w, w / HG_RPM_PER_RAD_S);
}

void hg_plausibility_warn(const hg_vars *v, const hg_logger *lg)
{
    double T_w_start = hg_var_table[hg_input_vr[HG_IN_T_W]].start;
    if (v->load_mode == HG_LOAD_MODE_SPEED) {
        if (v->T_w != T_w_start)
            hg_logf(lg, "logStatusWarning",
                    "T_w = %g N.m is ignored: with load_mode = speed the speed governor sets the "
                    "wheel-end torque (output T_w_out); set load_mode = torque to apply T_w",
                    v->T_w);
        warn_speed(lg, "w_set", v->w_set);
    }
    warn_speed(lg, "w_p0", v->w_p0);
}
