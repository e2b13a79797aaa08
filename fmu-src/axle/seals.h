/* Radial lip seals on a rotating shaft.
 *
 * Source: ISO/TR 14179-1:2001, Gears - Thermal capacity - Part 1: Rating gear drives with
 * thermal equilibrium at 95 degC sump temperature, seal losses:
 *   P_seal = 7.69 10^-6 d_sh^2 n   [W], d_sh the shaft diameter [mm], n [r/min].
 * The correlation is for elastomer lip seals in mineral oil at their running temperature; it
 * does not depend on the oil temperature. */
#ifndef HG_AXLE_SEALS_H
#define HG_AXLE_SEALS_H

/* Friction torque magnitude [N m] of one lip seal on a shaft of diameter d_sh [m]; constant
 * in speed (the power above divided by omega). Multiply by |omega| for the loss. */
double hg_seal_torque(double d_sh);

#endif
