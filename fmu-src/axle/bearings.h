/* Tapered roller bearings of a hypoid axle: mesh force components, bearing reactions, the
 * axial loads of an adjusted pair, and the friction torque of each bearing.
 *
 * Sources:
 *   mesh force components of spiral bevel and hypoid gears: the Gleason/AGMA form, e.g.
 *   ANSI/AGMA 2005-D03 (Design manual for bevel gears), clause "Bearing loads", and Shigley's
 *   Mechanical Engineering Design, 9th ed., section 13-15 (bevel gear force analysis);
 *   axial loads of two single-row tapered roller bearings adjusted against each other:
 *   ISO 281 / the SKF rolling bearings catalogue (2018), "Determining axial loads for
 *   bearings mounted singly or paired", extended by a preload;
 *   friction torque: Palmgren's load-independent plus load-dependent moments as used in
 *   ISO/TR 14179-2:2001 and in T. A. Harris, M. N. Kotzalas, Rolling Bearing Analysis (2007):
 *     M_0 = 10^-7 f_0 (nu n)^(2/3) d_m^3   for nu n >= 2000
 *     M_0 = 160 10^-7 f_0 d_m^3            for nu n < 2000
 *     M_1 = f_1 P_1 d_m,  tapered roller bearings: f_1 = 0.0004, P_1 = 2 Y F_a
 *   (M [N mm], nu [mm^2/s], n [r/min], d_m [mm], P_1 [N]). The functions below take and give
 *   SI units and convert inside. */
#ifndef HG_AXLE_BEARINGS_H
#define HG_AXLE_BEARINGS_H

/* One member of the gear pair at its mean point. */
typedef struct {
    double r_m;     /* mean pitch radius [m] */
    double delta;   /* pitch angle [rad] */
    double beta;    /* mean spiral angle [rad] */
    double alpha_n; /* normal pressure angle [rad] */
} hg_member_geom;

/* Force components on a member, from its tangential force F_t [N] (positive) on the flank in
 * contact. s = +1 when the pinion drives on its drive flank (drive), -1 on the coast flank;
 * driving = 1 for the pinion, 0 for the driven gear. AGMA 2005 / Shigley 13-15:
 *   F_a = F_t / cos(beta) (tan(alpha_n) sin(delta) + k sin(beta) cos(delta))
 *   F_r = F_t / cos(beta) (tan(alpha_n) cos(delta) - k sin(beta) sin(delta))
 * with k = s for the pinion and k = -s for the gear, so that a spiral bevel pair
 * (no offset, 90 deg shafts) gives pinion thrust = gear separating force and vice versa.
 * F_a > 0 points away from the pitch-cone apex, F_r > 0 pushes the member away from its mate. */
typedef struct {
    double F_t, F_a, F_r;
} hg_mesh_force;

hg_mesh_force hg_mesh_force_components(const hg_member_geom *m, double F_t, double s, int driving);

/* A shaft on two bearings A and B at axial positions x_A, x_B [m] (x = 0 at the mean point,
 * positive away from the apex); the mesh force acts at radius r_m. Radial reactions
 * (magnitudes) from statics in the tangential and separating planes, the axial force's couple
 * F_a r_m included. */
void hg_shaft_reactions(const hg_mesh_force *f, double r_m, double x_A, double x_B, double *Fr_A,
                        double *Fr_B);

/* Axial loads of two single-row tapered roller bearings adjusted against each other. Bearing 1
 * takes an external axial force K_a > 0, bearing 2 takes K_a < 0. Induced thrusts
 * F_i = 0.5 F_r / Y (ISO 281); a preload F_pre shared equally by two bearings of equal axial
 * stiffness (linear approximation):
 *   F_a1 = max(F_i1, F_i2 + K_a, F_pre + K_a/2),  F_a2 = F_a1 - K_a. */
void hg_trb_pair_axial(double Fr_1, double Y_1, double Fr_2, double Y_2, double K_a, double F_pre,
                       double *Fa_1, double *Fa_2);

/* A tapered roller bearing. */
typedef struct {
    double d_m; /* mean diameter (d + D)/2 [m] */
    double Y;   /* axial load factor of the bearing (catalogue) */
    double f_0; /* Palmgren's load-independent factor (lubrication and bearing series) */
    double f_1; /* load-dependent factor, 0.0004 for tapered roller bearings */
} hg_trb;

/* Friction torque magnitude [N m] at the axial load F_a [N], kinematic viscosity nu [m^2/s]
 * and speed omega [rad/s] (either sign). The low-speed branch is taken as
 * max((nu n)^(2/3), 160), which equals Palmgren's two branches except between nu n = 2000 and
 * 2024, where it is continuous and the published form jumps by 0.8 %. */
double hg_trb_torque(const hg_trb *b, double F_a, double nu, double omega);

#endif
