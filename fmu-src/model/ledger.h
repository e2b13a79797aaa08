/* The axle's loss ledger beyond the mesh (axle_losses = full) and its oil sump
 * (thermal_model = sump): the parameters from the FMU variables, and the loss torques and heat
 * flows at a state, from the kernels of fmu-src/axle (docs/axle.md). */
#ifndef HG_LEDGER_H
#define HG_LEDGER_H

#include <stddef.h>

#include "axle/bearings.h"
#include "axle/churning.h"
#include "axle/sump.h"
#include "hg_vars.h"
#include "tribo/lubricant.h"

enum { HG_BRG_P_HEAD, HG_BRG_P_TAIL, HG_BRG_G_NEAR, HG_BRG_G_FAR, HG_N_BRG };

typedef struct {
    int full;                 /* axle_losses = full: churning, bearings and seals */
    int sump;                 /* thermal_model = sump: T_oil is a state */
    hg_churn_geom churn;      /* the ring gear in the sump */
    hg_churn_terms churn_terms; /* its geometry's part of the churning torque, once */
    hg_member_geom pinion, gear;
    hg_trb brg[HG_N_BRG];     /* pinion head and tail, carrier ring side and far side */
    hg_trb_geometry brg_geom[HG_N_BRG]; /* their geometry terms (hg_trb_geometry_of) */
    hg_mesh_force unit_p[2], unit_g[2]; /* mesh force components per newton of F_t on the
                                           coast [0] and drive [1] flank (pinion, gear) */
    double x_brg[HG_N_BRG];   /* axial positions from the member's mean point [m] */
    double Fr_unit[2][HG_N_BRG]; /* the bearings' radial loads per newton of F_t (by the sign
                                  * of the mesh force, as unit_p, unit_g) [N/N] */
    double F_pre_p, F_pre_g;  /* preloads of the pinion and carrier pairs as set at 20 degC [N] */
    double k_ax_p, k_ax_g;    /* axial stiffness of the preloaded pairs [N/m] */
    double d_alpha;           /* thermal expansion of the carrier less that of steel [1/K] */
    double T_seal_p, T_seal_w; /* ISO seal torques: pinion seal, the two axle-shaft seals [N m] */
    int seal_linke;           /* seal_model = linke: the seal torques follow the oil temperature */
    double d_seal_p, d_seal_w; /* seal shaft diameters [m] */
    double nu_40;             /* the oil's kinematic viscosity at 40 degC [m^2/s] (Linke) */
    double linke_oil;         /* hg_seal_linke_oil_term(nu_40), once */
    hg_housing housing;
    double h_housing;         /* > 0: fixed convective coefficient [W/(m^2 K)]; 0: correlations */
    double C_sump;            /* heat capacity of oil, gears and housing [J/K] */
    const hg_lubricant *lub;
    double ln_vogel_a;        /* ln of the lubricant's Vogel a, once */
} hg_ledger;

typedef struct {
    double T_p, T_g;                     /* loss torques on pinion and gear [N m], oppose motion */
    double P_churn, P_bearings, P_seals; /* [W]; P = -(T_p w_p + T_g w_g) split by part */
    double P_bearings_p, P_bearings_g;   /* the pinion's and the carrier's bearing pairs [W] */
    double F_pre_p, F_pre_g;             /* the pairs' preloads at T_oil [N] */
    double nu;                           /* kinematic viscosity of the oil at T_oil [m^2/s] */
    double T_seal_p, T_seal_w;           /* seal torques at T_oil: pinion, both shafts [N m] */
    double Fr[HG_N_BRG], Fa[HG_N_BRG];   /* bearing loads [N] */
} hg_ledger_eval;

/* Fills *a from the parameters of v; gear_set_builtin is the built-in set (1-3) whose geometry
 * stands in for parameters left at 0, or 0 for a user's gear-set file, whose blank (file_blank,
 * HG_N_BLANK values in the order of mesh/gearset.h; NULL when the file has none) stands in for
 * them, else they must be set. Returns 0, or -1 with a message naming the variable, its value
 * and unit. */
int hg_ledger_setup(hg_ledger *a, const hg_vars *v, int gear_set_builtin,
                    const double *file_blank, const hg_lubricant *lub, char *err, size_t errlen);

/* Oil density [kg/m^3] and kinematic viscosity [m^2/s] at T [K]. */
double hg_ledger_rho(const hg_lubricant *lub, double T);
double hg_ledger_nu(const hg_lubricant *lub, double T);

/* Loss torques at pinion and gear speeds w_p, w_g [rad/s], mesh load W_t [N] at the contact
 * radii R_p, R_g [m] (W_t < 0: coast flank) and oil temperature T_oil [K]. All zero unless full. */
void hg_ledger_losses(const hg_ledger *a, double w_p, double w_g, double W_t, double R_p,
                      double R_g, double T_oil, hg_ledger_eval *ev);

/* Heat from the housing to the air [W]. */
double hg_ledger_heat_out(const hg_ledger *a, double T_oil, double T_amb, double v_air);

#endif
