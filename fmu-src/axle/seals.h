/* Radial lip seals on a rotating shaft.
 *
 * Source: ISO/TR 14179-2:2001, Gears - Thermal capacity - Part 2: Thermal load-carrying
 * capacity, seal losses (the FZG/Niemann form):
 *   P_seal = 7.69 10^-6 d_sh^2 n   [W], d_sh the shaft diameter [mm], n [r/min].
 * (docs/axle.md: the constant and its part of the report were checked against two public
 * gearbox-loss implementations that cite it; the standard itself was not at hand.)
 * The correlation is for elastomer lip seals in mineral oil at their running temperature; it
 * does not depend on the oil temperature. */
#ifndef HG_AXLE_SEALS_H
#define HG_AXLE_SEALS_H

/* Friction torque magnitude [N m] of one lip seal on a shaft of diameter d_sh [m]; constant
 * in speed (the power above divided by omega). Multiply by |omega| for the loss. */
double hg_seal_torque(double d_sh);

#endif
