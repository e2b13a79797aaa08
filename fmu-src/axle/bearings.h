/* Tapered roller bearings of a hypoid axle: mesh force components, bearing reactions, the
 * axial loads of an adjusted pair, its preload at the oil temperature, and the frictional
 * moment of each bearing.
 *
 * Sources:
 *   mesh force components of spiral bevel and hypoid gears: the Gleason/AGMA form, e.g.
 *   ANSI/AGMA 2005-D03 (Design manual for bevel gears), clause "Bearing loads", and Shigley's
 *   Mechanical Engineering Design, 9th ed., section 13-15 (bevel gear force analysis);
 *   axial loads of two single-row tapered roller bearings adjusted against each other:
 *   ISO 281 / the SKF rolling bearings catalogue (2018), "Determining axial loads for
 *   bearings mounted singly or paired", extended by a preload;
 *   frictional moment: the SKF model (SKF rolling bearings catalogue, "The SKF model for
 *   calculating the frictional moment"), rolling and sliding parts for tapered roller bearings:
 *     M_rr = phi_ish phi_rs G_rr (nu n)^0.6,  G_rr = R_1 d_m^2.38 (F_r + R_2 Y F_a)^0.31
 *     M_sl = mu_sl G_sl,                    G_sl = S_1 d_m^0.82 (F_r + S_2 Y F_a)
 *     phi_ish = 1 / (1 + 1.84e-9 (n d_m)^1.28 nu^0.64)                  inlet shear heating
 *     phi_rs = exp(-K_rs nu n (d + D) sqrt(K_z / (2 (D - d))))          kinematic replenishment
 *     mu_sl = phi_bl mu_bl + (1 - phi_bl) mu_EHL,  phi_bl = exp(-2.6e-8 (n nu)^1.4 d_m)
 *   with R_2 = 10.9, S_2 = 2 (every tapered series of the catalogue's Table 2b), K_rs = 3e-8
 *   (oil bath, low level, or oil jet) or 0 (a flooded bearing: no kinematic starvation, the
 *   axle's default, docs/axle.md), K_z = 6 (tapered roller bearings), mu_bl = 0.15,
 *   mu_EHL = 0.002 (tapered roller bearings); M [N mm], d, D, d_m [mm], F [N], n [r/min],
 *   nu [mm^2/s]. No seal moment (open bearings) and no drag moment (the bearings are fed by the
 *   oil the ring gear throws; the bath stays below them, docs/axle.md). The functions below
 *   take and give SI units and convert inside. */
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

/* A tapered roller bearing of the SKF model. */
typedef struct {
    double d, D;   /* bore and outside diameter [m] */
    double Y;      /* axial load factor of the bearing (catalogue) */
    double R_1;    /* SKF geometry constant of the rolling moment of the series [N mm units] */
    double S_1;    /* ... of the sliding moment */
    double K_rs;   /* SKF replenishment/starvation constant [s min / mm^2.5]: 0 for a flooded
                      bearing (no kinematic starvation), HG_TRB_K_RS_LOW_LEVEL otherwise */
} hg_trb;

/* SKF's K_rs for a low-level oil bath or an oil jet (3e-8; grease and oil-air 6e-8) */
#define HG_TRB_K_RS_LOW_LEVEL 3e-8

/* Kinematic replenishment/starvation reduction factor (SKF catalogue, "The SKF model for
 * calculating the frictional moment", rolling moment):
 *   phi_rs = exp(-K_rs nu n (d + D) sqrt(K_z / (2 (D - d))))
 * from K_rs, vn = nu n [mm^2/s r/min] and rs = (d + D) sqrt(K_z / (2 (D - d))) [mm^0.5].
 * The catalogue gives K_rs for the feeds that starve the raceways (a low-level oil bath, whose
 * level is below the centre of the lowest roller, an oil jet, oil-air, grease); a flooded
 * bearing takes K_rs = 0, phi_rs = 1 (docs/axle.md, "Replenishment"). */
double hg_trb_phi_rs(double K_rs, double vn, double rs);

/* The bearing's frictional moment by part [N m], magnitudes. */
typedef struct {
    double M_rr; /* rolling: EHL rolling resistance, with inlet shear heating and replenishment */
    double M_sl; /* sliding: roller ends on the rib and the raceways, boundary and full film */
} hg_trb_moment;

/* Frictional moment at the radial load F_r [N], axial load F_a [N], kinematic viscosity
 * nu [m^2/s] and speed omega [rad/s] (either sign). Both parts vanish with the load; at rest
 * only the boundary sliding (mu_bl) remains. */
hg_trb_moment hg_trb_friction(const hg_trb *b, double F_r, double F_a, double nu, double omega);

/* The same in parts, for a right-hand side that evaluates it often: the bearing's geometry terms
 * (once per bearing), the oil's viscosity terms (once per evaluation: every shaft shares them),
 * the speed terms (once per shaft and evaluation: the bearings of a shaft share them), then the
 * moment at the loads. Powers as exponentials of logarithms, so an evaluation of a shaft's two
 * bearings takes one logarithm (and the oil's one) and four exponentials, and for each bearing's
 * load power (^0.31) a logarithm and an exponential more. */
typedef struct {
    double dm;     /* mean diameter [mm] */
    double G_rr0;  /* R_1 d_m^2.38 */
    double G_sl0;  /* S_1 d_m^0.82 */
    double dm128;  /* d_m^1.28 */
    double rs;     /* (d + D) sqrt(K_z / (2 (D - d))) [mm^0.5] */
} hg_trb_geometry;

typedef struct {
    double v;       /* nu [mm^2/s] */
    double ln_v;    /* ln(nu [mm^2/s]) */
} hg_trb_oil;

typedef struct {
    double ln_n;    /* ln(n [r/min]) */
    double vn;      /* nu n [mm^2/s r/min] */
    double n128v064; /* n^1.28 nu^0.64 */
    double vn14, vn06; /* (nu n)^1.4, (nu n)^0.6 */
} hg_trb_speed;

void hg_trb_geometry_of(const hg_trb *b, hg_trb_geometry *g);
void hg_trb_oil_of(double nu, hg_trb_oil *o);
void hg_trb_speed_at(const hg_trb_oil *o, double omega, hg_trb_speed *s);
void hg_trb_speed_of(double nu, double omega, hg_trb_speed *s); /* the two above */
hg_trb_moment hg_trb_friction_at(const hg_trb *b, const hg_trb_geometry *g,
                                 const hg_trb_speed *s, double F_r, double F_a);

/* Preload [N] of a pair adjusted to F_pre0 and then warmed by dT [K]: a carrier that expands
 * by alpha_c and a steel shaft by alpha_s per kelvin move the cups apart from the cones by
 * d_alpha L dT (d_alpha = alpha_c - alpha_s [1/K]) over the pair's spread L [m], which the
 * pair's axial stiffness k_ax [N/m] turns into force:
 *   F_pre = max(0, F_pre0 - k_ax d_alpha L dT)
 * (linear stiffness, one temperature for carrier, shaft and bearings; docs/axle.md). */
double hg_trb_preload(double F_pre0, double k_ax, double d_alpha, double L, double dT);

#endif
