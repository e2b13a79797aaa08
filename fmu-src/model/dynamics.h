/* The 4-DoF torsional hypoid pair (paper eqs. 20-25 with correction D3, docs/physics.md §8.1) as a pure
 * right-hand side, with the energy audit and efficiency integrals carried as extra states.
 * With a rigid mesh the pinion and gear turn as one body (x stays 0, w_g = w_p N_p/N_g) and the
 * mesh load follows from the gear's equation of motion. */
#ifndef HG_DYNAMICS_H
#define HG_DYNAMICS_H

#include "hg_vars.h" /* hg_inputs: the FMU inputs at the evaluation time */
#include "mesh/backlash.h"
#include "model/effmap.h"
#include "model/friction.h"
#include "model/friction_table.h"
#include "mesh/phase_table.h"
#include "mesh/gearset.h"
#include "model/ledger.h"
#include "mesh/mesh_law.h"

enum {
    HG_Y_TWIST1, /* phi_s - phi_p [rad] */
    HG_Y_TWIST2, /* phi_g - phi_w [rad] */
    HG_Y_PHI_P,  /* pinion angle, wrapped by whole load-share periods [rad] */
    HG_Y_X,      /* dynamic transmission error x [m] (eq. 25) */
    HG_Y_W_S, HG_Y_W_P, HG_Y_W_G, HG_Y_W_W, /* angular speeds [rad/s] */
    HG_Y_GOV,    /* integral of the governor's wheel-speed error [rad] */
    HG_Y_E_IN, HG_Y_E_OUT, HG_Y_E_FRIC, HG_Y_E_DAMP, HG_Y_E_EXC, /* energy audit [J] */
    HG_Y_ETA2,   /* integral of eta^2 dt [s] */
    HG_Y_T_OIL,  /* oil temperature of the sump [K] (thermal_model = sump; else unused) */
    HG_Y_Q_H,    /* heat given to the air [J] */
    HG_Y_E_CHURN, HG_Y_E_BEAR, HG_Y_E_SEAL, /* the axle's other losses [J] */
    HG_Y_ETA_AXLE2, /* integral of eta_axle^2 dt [s] */
    HG_Y_T_KM,   /* transmitted pinion torque filtered over a few mesh cycles, at which the tooth
                    data are interpolated [N m] (docs/physics.md §10.8; constant for one level) */
    HG_Y_TWIST_HS, /* half-shaft twist phi_w - phi_wheel [rad] (load_mode = half_shaft; else 0) */
    HG_Y_IMP_W,  /* impulse of the wheel-end torque, integral of T_w dt [N m s] (output T_wheel;
                    load_mode = half_shaft; else 0) */
    HG_NY
};

/* The housing heat of the last evaluation and what it was computed from: the oil and air
 * temperatures and the air speed repeat exactly over a communication step unless the sump runs
 * or the inputs are extrapolated, and the convection correlations cost a pow and two cbrt per
 * evaluation. A cache: the same bits with or without it. */
typedef struct {
    int valid;
    double T_oil, T_amb, v_air; /* [K], [K], [m/s] */
    double Q_dot;               /* [W] */
} hg_heat_memo;

typedef struct {
    double I_s, I_p, I_g, I_w;   /* [kg m^2] */
    double k_t1, k_t2;           /* [N m/rad] */
    double c_t1, c_m, c_t2;      /* [N m s/rad], [N s/m], [N m s/rad] */
    int mesh;                    /* HG_MESH_MODEL_RIGID, _MEAN (constant k_m0, R_p0, no e_0, no
                                    backlash) or _VARYING */
    int quasi_static_input;      /* the input shaft quasi-static (input_shaft; rigid mesh only) */
    int quasi_static_output;     /* the output shaft quasi-static (output_shaft; rigid mesh only) */
    hg_backlash backlash;        /* b = 0 unless the mesh varies */
    double k_m0, R_p0;           /* mean mesh stiffness [N/m] and radius [m] */
    double ratio;                /* N_g / N_p */
    const hg_gearset *gear;      /* series already scaled by k_m_scale and e_0_scale */
    const hg_phase_tables *phase; /* gear's series tabulated, for the right-hand side */
    hg_friction_config friction;
    hg_ft_set *tables;           /* tabulated F_f of the pairs for the right-hand side (built
                                    on first use), or NULL: hg_friction_pair at every evaluation */
    const hg_effmap *map;        /* friction_model = map: efficiency of the rigid gear */
    int speed_governor;          /* load_mode = speed */
    int half_shaft;              /* load_mode = half_shaft: T_w from the half-shaft to w_wheel */
    double k_hs, c_hs;           /* half-shaft stiffness [N m/rad] and damping [N m s/rad] */
    double K_p, K_i;             /* governor gains [N m s/rad], [N m/rad] */
    hg_ledger ledger;            /* churning, bearings, seals and the sump (docs/axle.md) */
    hg_heat_memo *heat;          /* the instance's cache of the housing heat, or NULL */
} hg_dyn_params;

typedef struct {
    hg_mesh_point mesh;
    double R_g;        /* gear contact radius R_p N_g/N_p [m] (D4 of docs/physics.md §0) */
    double f;          /* backlash function f(x) [m] */
    double Phi;        /* its potential [m^2]: the mesh spring stores k_m Phi */
    double xdot;       /* dx/dt [m/s] */
    double g;          /* flank engagement df/dx in [0, 1]: the mesh damper acts through it */
    double W_t;        /* net mesh force k_m f + c g xdot, positive pushing the drive flank [N] */
    double W_drive;    /* compressive load on the drive flank, max(k_m f_d + c g_d xdot, 0) [N] */
    double W_coast;    /* compressive load on the back flank, max(-(k_m f_b + c g_b xdot), 0) [N] */
    double T_w;        /* wheel-end torque: input, governor or half-shaft [N m] */
    double T_1;        /* input shaft torque on the pinion [N m]: its spring's, or T_s - I_s acc
                          when the shaft is quasi-static */
    double T_2;        /* output shaft torque on the gear [N m]: its spring's, or T_w + I_w acc_g
                          when the shaft is quasi-static */
    double w_s;        /* speed of the input shaft's end [rad/s] (hg_dyn_input_speed) */
    double slip_hs;    /* w_w - w_wheel across the half-shaft [rad/s] (0 unless half_shaft) */
    double T_fp, T_fg; /* friction torques on pinion and gear [N m] */
    double acc_p;      /* pinion acceleration of the rigid mesh [rad/s^2] */
    double P_loss, P_in, eta;
    double P_visc;     /* viscous part of P_loss [W] */
    double T_oil;      /* oil temperature used by every loss [K] */
    hg_ledger_eval axle; /* the other losses of the axle */
    double P_axle, P_in_axle, eta_axle;
    double Q_dot;      /* heat from the housing to the air [W] */
    double P_damp, P_exc; /* damper dissipation and parametric excitation power [W] */
    double T_km_dot;   /* dT_km/dt [N m/s] */
    double U_mesh;     /* elastic energy of the mesh of a layered file's force law [J] */
    double dU_mesh;    /* its dU/dtheta at fixed x [J/rad] (the law's parametric excitation) */
    int flank;         /* HG_FLANK_DRIVE or _COAST: whose tooth data apply (the drive flank's
                          off the varying mesh) */
    hg_level_pick pick; /* the levels around the filtered torque T_km on that flank */
    int located;      /* cell holds the mesh angle's cell of the phase table */
    double W_pair[HG_MAX_PAIRS];
    /* Every field the friction model's (hg_friction_pair), F_f alone and F_v = 0 from the
     * friction tables, zero without pair friction (the map level, none). */
    hg_pair_friction pair[HG_MAX_PAIRS];
    hg_pt_cell cell;  /* set when located */
} hg_dyn_eval;

/* Evaluates everything at state y in contact mode `mode`. Pair quantities are computed when the
 * friction model needs them or `all_pairs` is set (for outputs). T_c_warm: per-pair warm start. */
void hg_dyn_evaluate(const hg_dyn_params *p, const hg_inputs *u, int mode, const double *y,
                     int all_pairs, double T_c_warm[HG_MAX_PAIRS], hg_dyn_eval *ev);

/* The oil temperature every loss sees [K]: the sump's state, or the input T_bath. */
double hg_dyn_oil_temperature(const hg_dyn_params *p, const hg_inputs *u, const double *y);

/* dy/dt from an evaluation at y. */
void hg_dyn_derivatives(const hg_dyn_params *p, const hg_inputs *u, const double *y,
                        const hg_dyn_eval *ev, double *ydot);

/* Whether the mesh force follows the layered file's force law (mesh/mesh_law.h) instead of
 * k_m f(x): the varying mesh with tooth data of several torque levels. */
int hg_dyn_loaded_law(const hg_dyn_params *p);

/* Whether the input shaft is quasi-static (docs/model.md, "Fidelity levels"; input_shaft: by
 * default at the map level, whose loss from the efficiency map has nothing on the mesh's time
 * scale): its mode with the pinion, above a kilohertz, is not resolved; the shaft is a massless
 * spring and its end turns with the pinion (its twist and speed states stay constant). The rigid
 * mesh only. */
int hg_dyn_quasi_static_input(const hg_dyn_params *p);

/* Whether the output shaft is quasi-static (output_shaft: by default at the map level, as the
 * input shaft): its mode between the gear and the wheel end (a few hundred hertz) is not resolved;
 * the shaft is a massless spring carrying T_w + I_w acc_g, the wheel end turns with the gear (its
 * speed state follows the gear's, its twist state stays constant). The rigid mesh only. */
int hg_dyn_quasi_static_output(const hg_dyn_params *p);

/* The speed of the input shaft's end [rad/s]: its state, or the pinion's when the shaft is
 * quasi-static. */
double hg_dyn_input_speed(const hg_dyn_params *p, const double *y);

/* Kinetic plus elastic energy at y [J]. */
double hg_dyn_stored_energy(const hg_dyn_params *p, const double *y, const hg_dyn_eval *ev);

#endif
