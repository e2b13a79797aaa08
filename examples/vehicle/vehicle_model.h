/* A longitudinal vehicle seen from the driveline's wheel-side flange, loaded by rolling
 * resistance, aerodynamic drag, grade and the wheel brakes. Two couplings (parameter coupling):
 *
 * 1, half-shaft: a compliant half-shaft (spring-damper) between the flange, whose speed is the
 *    input, and the wheels plus the vehicle mass reflected at the wheel (rolling without slip);
 *    the output is the half-shaft torque, which resists the flange:
 *      twist'   = w_w - w_wheel
 *      T_hs     = k_hs twist + c_hs (w_w - w_wheel)
 *      J_v w_wheel' = T_hs - r_dyn (F_roll + F_aero + F_grade) - T_b,  J_v = m r_dyn^2 + J_wheels
 * 2, road load: the vehicle's inertia J_v and the half-shaft compliance live in the driveline
 *    model (the gear FMU's I_w and k_t2), the input is the wheel speed and the output the load
 *    torque at the wheel, T_hs = r_dyn (F_roll + F_aero + F_grade) + T_b. Nothing stiff crosses
 *    the coupling, so a host can take long communication steps (a drive cycle).
 * 3, wheel torque: the half-shaft lives in the driveline model (the gear FMU's load_mode =
 *    half_shaft), the input T_wheel is the torque it delivers to the wheels and the output the
 *    wheel speed w_wheel, a state of the vehicle's large inertia:
 *      J_v w_wheel' = T_wheel - r_dyn (F_roll + F_aero + F_grade) - T_b
 *    The variable that crosses at the stiff side is the slow wheel speed, so a host holding its
 *    inputs over 10 ms steps stays stable (docs/integration.md).
 * In all
 *   F_roll = c_rr m g cos(grade) tanh(v / v_eps),  F_aero = rho/2 CdA v |v|,
 *   F_grade = m g sin(grade),  T_b = T_brake tanh(v / v_eps),  v = r_dyn w_wheel
 * with the energy integrals as extra states, so that
 *   E_in = (E_kin - E_kin0) + (E_spring - E_spring0) + E_road + E_grade + E_damper + E_brake
 * closes to the integrator's error (fixed-step RK4, the inputs held over a communication step;
 * with coupling 2, E_kin and E_spring are the driveline model's and read 0 here). */
#ifndef VEHICLE_MODEL_H
#define VEHICLE_MODEL_H

/* Value references: the index into vm_vars.v. Keep in step with modelDescription.xml. */
enum {
    /* inputs */
    VR_W_W, VR_T_BRAKE,
    /* parameters */
    VR_M, VR_R_DYN, VR_J_WHEELS, VR_C_RR, VR_CDA, VR_RHO_AIR, VR_G, VR_GRADE, VR_K_HS, VR_C_HS,
    VR_V_EPS, VR_V0, VR_T_HS0, VR_H_MAX, VR_COUPLING,
    /* outputs */
    VR_T_HS, VR_V, VR_W_WHEEL, VR_A, VR_X, VR_TWIST, VR_F_ROAD, VR_P_IN, VR_E_IN, VR_E_KIN,
    VR_E_SPRING, VR_E_ROAD, VR_E_GRADE, VR_E_DAMPER, VR_E_BRAKE,
    /* input of coupling 3, after the others so that their value references stay */
    VR_T_WHEEL,
    /* Model Exchange: the time derivatives of the states (locals), in the order of the states */
    VR_DER_TWIST, VR_DER_W_WHEEL, VR_DER_X, VR_DER_E_IN, VR_DER_E_ROAD, VR_DER_E_DAMPER,
    VR_DER_E_BRAKE,
    VM_NUM_VARS
};
#define VM_FIRST_PARAMETER VR_M
#define VM_FIRST_OUTPUT VR_T_HS

/* States of the integrator; in Model Exchange the continuous states, each the output
 * vm_state_vr[k] (half-shaft and wheel-torque couplings; road load is co-simulation only). */
enum { S_TWIST, S_W_WHEEL, S_X, S_E_IN, S_E_ROAD, S_E_DAMPER, S_E_BRAKE, VM_NUM_STATES };
extern const int vm_state_vr[VM_NUM_STATES];

/* values of the parameter coupling */
enum { VM_HALF_SHAFT = 1, VM_ROAD_LOAD = 2, VM_WHEEL_TORQUE = 3 };

/* 1 when value reference vr is an input or a parameter (settable), 0 for an output */
int vm_settable(int vr);

typedef struct {
    double v[VM_NUM_VARS];      /* every variable, by value reference */
    double s[VM_NUM_STATES];    /* the states */
    double time;
    double w_w_prev;            /* road load: the input at the previous step (acceleration) */
} vm_model;

/* Sets every input and parameter to its start value, time to t0 and the states from them. */
void vm_reset(vm_model *m, double t0);

/* NULL when the parameters are usable, else a message naming the first bad one. */
const char *vm_check_parameters(const vm_model *m);

/* The states at the start: speed v0, twist from T_hs0, energy integrals zero. */
void vm_initial_state(vm_model *m);

/* Advances the states by h with the input held; updates time and the outputs. */
void vm_step(vm_model *m, double h);

/* Recomputes the outputs (and the states' derivatives) from the states and the current input. */
void vm_outputs(vm_model *m);

/* The states' time derivatives at the current states and inputs (Model Exchange). */
void vm_derivatives(const vm_model *m, double *ds);

#endif
