/* Heat given by the axle housing to the air: natural and forced convection plus radiation.
 *
 * Sources:
 *   natural convection, vertical surface of height L in air, laminar range
 *   (1e4 < Ra < 1e9): h_N = 1.42 (dT/L)^(1/4) W/(m^2 K) (the simplified air correlation of
 *   J. P. Holman, Heat Transfer, 10th ed., Table 7-2, after McAdams);
 *   forced convection over a flat plate of length L (F. P. Incropera et al., Fundamentals of
 *   Heat and Mass Transfer, 6th ed., eqs. 7.30 and 7.38):
 *     Nu_L = 0.664 Re_L^(1/2) Pr^(1/3)             laminar, Re_L < 5e5
 *     Nu_L = (0.037 Re_L^(4/5) - 871) Pr^(1/3)     mixed laminar/turbulent, Re_L > 5e5
 *   taken as the larger of the two (they cross at Re_L = 5.0e5: continuous);
 *   combination of the two (Churchill's mixed convection, Incropera eq. 9.64 with n = 3):
 *     h_conv^3 = h_N^3 + h_F^3;
 *   radiation from a grey surface of emissivity eps to surroundings at T_amb:
 *     q = eps sigma (T^4 - T_amb^4).
 * Air properties are those at 300 K and 1 atm (Incropera Table A.4): k = 0.0263 W/(m K),
 * nu = 15.89e-6 m^2/s, Pr = 0.707. */
#ifndef HG_AXLE_SUMP_H
#define HG_AXLE_SUMP_H

typedef struct {
    double A;   /* outer surface of the housing that gives heat to the air [m^2] */
    double L;   /* characteristic length (height for natural, length along the air for forced) [m] */
    double eps; /* emissivity of the housing surface */
} hg_housing;

/* Convective heat-transfer coefficients [W/(m^2 K)]. */
double hg_h_natural(double dT, double L);
double hg_h_forced(double v_air, double L);

/* The combined convective coefficient (h_N^3 + h_F^3)^(1/3) at the wall-to-air difference dT [K]
 * and air speed v_air [m/s]. */
double hg_housing_h_conv(const hg_housing *h, double dT, double v_air);

/* Heat flow from the housing at T_oil to the air at T_amb [W] (negative when the air is hotter)
 * with the convective coefficient h_conv [W/(m^2 K)], radiation included; temperatures in K.
 * The housing wall is taken at the oil temperature (lumped sump: the oil and the housing share
 * one temperature). */
double hg_housing_heat_h(const hg_housing *h, double h_conv, double T_oil, double T_amb);

#endif
