/* Radial lip seals on a rotating shaft, two published correlations of their power loss:
 *
 * ISO/TR 14179-2:2001, Gears - Thermal capacity - Part 2, seal losses (the FZG/Niemann form):
 *   P_seal = 7.69 10^-6 d_sh^2 n   [W], d_sh the shaft diameter [mm], n [r/min];
 * no oil, no temperature. (docs/axle.md: the constant and its part of the report were checked
 * against two public gearbox-loss implementations that cite it; the standard was not at hand.)
 *
 * Linke (H. Linke, Stirnradverzahnung, Hanser 1996; an empirical law for elastomer lip seals in
 * oil, as public gearbox-loss code and the FVA-Workbench's list of seal-loss methods cite it; the
 * book was not at hand):
 *   P_VD = [145 - 1.6 theta_oil + 350 lg lg(nu_40 + 0.8)] d_sh^2 n 10^-7   [W],
 * theta_oil the oil sump temperature [degC], nu_40 the oil's kinematic viscosity at 40 degC
 * [mm^2/s], d_sh [mm], n [r/min]. The bracket equals ISO's 76.9 at 108.6 degC for a 100 mm^2/s
 * oil; it falls 1.6 per K as the oil warms and reaches zero near 157 degC (held there).
 *
 * Both are a torque independent of speed: P / omega. */
#ifndef HG_AXLE_SEALS_H
#define HG_AXLE_SEALS_H

/* Friction torque magnitude [N m] of one lip seal on a shaft of diameter d_sh [m] by
 * ISO/TR 14179-2. Multiply by |omega| for the loss. */
double hg_seal_torque(double d_sh);

/* Linke's bracket 145 - 1.6 theta + 350 lg lg(nu_40 + 0.8) [-] at the oil temperature T [K] for
 * an oil of nu_40 [m^2/s]; not below 0. */
double hg_seal_linke_factor(double T, double nu_40);
/* its oil's term 350 lg lg(nu_40 + 0.8), once per oil, and the factor from it (the same bits) */
double hg_seal_linke_oil_term(double nu_40);
double hg_seal_linke_factor_at(double T, double oil_term);

/* Friction torque magnitude [N m] of one lip seal on a shaft of diameter d_sh [m] by Linke,
 * given his bracket (hg_seal_linke_factor). */
double hg_seal_torque_linke(double d_sh, double factor);

#endif
