/* The longitudinal vehicle: see vehicle_model.h for the equations. */
#include "vehicle_model.h"

#include <math.h>
#include <string.h>

/* Start values of the inputs and parameters, by value reference (outputs: 0). */
static const double start_values[VM_NUM_VARS] = {
    [VR_W_W] = 0.0,
    [VR_T_BRAKE] = 0.0,  /* N.m, brake torque of all wheels */
    [VR_M] = 1500.0,     /* kg, passenger car with driver */
    [VR_R_DYN] = 0.3,    /* m, dynamic rolling radius */
    [VR_J_WHEELS] = 3.0, /* kg.m2, four wheels, tyres, discs and half-shafts at the wheel */
    [VR_C_RR] = 0.012,   /* rolling resistance coefficient */
    [VR_CDA] = 0.7,      /* m2, drag coefficient times frontal area */
    [VR_RHO_AIR] = 1.2,  /* kg/m3 */
    [VR_G] = 9.81,       /* m/s2 */
    [VR_GRADE] = 0.0,    /* rad, road slope, positive uphill */
    [VR_K_HS] = 1.2e4,   /* N.m/rad, both half-shafts and the tyres' torsional compliance */
    [VR_C_HS] = 40.0,    /* N.m.s/rad */
    [VR_V_EPS] = 0.01,   /* m/s, speed over which rolling resistance builds up (tanh) */
    [VR_V0] = 0.0,       /* m/s */
    [VR_T_HS0] = 0.0,    /* N.m, half-shaft torque (twist) at the start */
    [VR_H_MAX] = 1e-4,   /* s, largest internal RK4 step */
    [VR_COUPLING] = VM_HALF_SHAFT,
    [VR_T_WHEEL] = 0.0,  /* N.m, torque the driveline delivers to the wheels (coupling 3) */
};

int vm_settable(int vr) { return vr < VM_FIRST_OUTPUT || vr == VR_T_WHEEL; }

const int vm_state_vr[VM_NUM_STATES] = {VR_TWIST, VR_W_WHEEL, VR_X, VR_E_IN, VR_E_ROAD,
                                        VR_E_DAMPER, VR_E_BRAKE};

void vm_reset(vm_model *m, double t0)
{
    memcpy(m->v, start_values, sizeof m->v);
    m->time = t0;
    vm_initial_state(m);
}

const char *vm_check_parameters(const vm_model *m)
{
    const double *v = m->v;
    int k;
    for (k = 0; k < VM_NUM_VARS; k++)
        if (vm_settable(k) && !isfinite(v[k])) return "a parameter or input is not finite";
    if (!(v[VR_M] > 0.0)) return "m must be > 0";
    if (!(v[VR_R_DYN] > 0.0)) return "r_dyn must be > 0";
    if (!(v[VR_J_WHEELS] >= 0.0)) return "J_wheels must be >= 0";
    if (!(v[VR_C_RR] >= 0.0)) return "c_rr must be >= 0";
    if (!(v[VR_CDA] >= 0.0)) return "CdA must be >= 0";
    if (!(v[VR_RHO_AIR] >= 0.0)) return "rho_air must be >= 0";
    if (!(v[VR_G] >= 0.0)) return "g must be >= 0";
    if (!(fabs(v[VR_GRADE]) < 1.5)) return "grade must be within (-1.5, 1.5) rad";
    if (!(v[VR_K_HS] > 0.0)) return "k_hs must be > 0";
    if (!(v[VR_C_HS] >= 0.0)) return "c_hs must be >= 0";
    if (!(v[VR_V_EPS] > 0.0)) return "v_eps must be > 0";
    if (!(v[VR_H_MAX] > 0.0)) return "h_max must be > 0";
    if (v[VR_COUPLING] != VM_HALF_SHAFT && v[VR_COUPLING] != VM_ROAD_LOAD &&
        v[VR_COUPLING] != VM_WHEEL_TORQUE)
        return "coupling must be 1 (half-shaft), 2 (road load) or 3 (wheel torque)";
    if (!(v[VR_T_BRAKE] >= 0.0)) return "T_brake must be >= 0";
    return NULL;
}

void vm_initial_state(vm_model *m)
{
    memset(m->s, 0, sizeof m->s);
    if (m->v[VR_K_HS] > 0.0 && m->v[VR_COUPLING] != VM_WHEEL_TORQUE) /* else not its shaft */
        m->s[S_TWIST] = m->v[VR_T_HS0] / m->v[VR_K_HS];
    if (m->v[VR_R_DYN] > 0.0) m->s[S_W_WHEEL] = m->v[VR_V0] / m->v[VR_R_DYN];
    m->w_w_prev = m->v[VR_W_W];
    if (m->v[VR_COUPLING] == VM_ROAD_LOAD) m->v[VR_A] = 0.0;
    vm_outputs(m);
}

/* Road load forces at speed v (N): rolling plus aerodynamic, and grade. */
static void road_load(const double *p, double v, double *f_resist, double *f_grade)
{
    double normal = p[VR_M] * p[VR_G] * cos(p[VR_GRADE]);
    *f_resist = p[VR_C_RR] * normal * tanh(v / p[VR_V_EPS])
                + 0.5 * p[VR_RHO_AIR] * p[VR_CDA] * v * fabs(v);
    *f_grade = p[VR_M] * p[VR_G] * sin(p[VR_GRADE]);
}

static double inertia(const double *p)
{
    return p[VR_M] * p[VR_R_DYN] * p[VR_R_DYN] + p[VR_J_WHEELS];
}

static int road_load_coupling(const double *p) { return p[VR_COUPLING] == VM_ROAD_LOAD; }

static int wheel_torque_coupling(const double *p) { return p[VR_COUPLING] == VM_WHEEL_TORQUE; }

/* the speed at which the input power enters: the flange's (input w_w) or the wheels' */
static double input_speed(const double *p, const double *s)
{
    return wheel_torque_coupling(p) ? s[S_W_WHEEL] : p[VR_W_W];
}

/* the wheel speed: a state (half-shaft) or the input (road load) */
static double wheel_speed(const double *p, const double *s)
{
    return road_load_coupling(p) ? p[VR_W_W] : s[S_W_WHEEL];
}

/* brake torque at the wheels, opposing their rotation */
static double brake_torque(const double *p, double v)
{
    return p[VR_T_BRAKE] * tanh(v / p[VR_V_EPS]);
}

/* the torque exchanged: half-shaft torque, road load, or the input wheel torque */
static double flange_torque(const double *p, const double *s)
{
    double v = p[VR_R_DYN] * wheel_speed(p, s), f_resist, f_grade;
    if (wheel_torque_coupling(p)) return p[VR_T_WHEEL];
    if (!road_load_coupling(p))
        return p[VR_K_HS] * s[S_TWIST] + p[VR_C_HS] * (p[VR_W_W] - s[S_W_WHEEL]);
    road_load(p, v, &f_resist, &f_grade);
    return p[VR_R_DYN] * (f_resist + f_grade) + brake_torque(p, v);
}

static void rhs(const double *p, const double *s, double *ds)
{
    double w = wheel_speed(p, s), own = !road_load_coupling(p);
    double slip = wheel_torque_coupling(p) ? 0.0 : p[VR_W_W] - w; /* across the half-shaft */
    double t_hs = flange_torque(p, s), v = p[VR_R_DYN] * w, f_resist, f_grade;
    double t_b = brake_torque(p, v);
    road_load(p, v, &f_resist, &f_grade);
    ds[S_TWIST] = own * slip;
    ds[S_W_WHEEL] = own * (t_hs - p[VR_R_DYN] * (f_resist + f_grade) - t_b) / inertia(p);
    ds[S_X] = v;
    ds[S_E_IN] = t_hs * input_speed(p, s);
    ds[S_E_ROAD] = f_resist * v;
    ds[S_E_DAMPER] = own * p[VR_C_HS] * slip * slip;
    ds[S_E_BRAKE] = t_b * w;
}

void vm_derivatives(const vm_model *m, double *ds) { rhs(m->v, m->s, ds); }

void vm_step(vm_model *m, double h)
{
    const double *p = m->v;
    double k1[VM_NUM_STATES], k2[VM_NUM_STATES], k3[VM_NUM_STATES], k4[VM_NUM_STATES],
           y[VM_NUM_STATES];
    int n = (int)ceil(h / p[VR_H_MAX] - 1e-9), i, j;
    double dt;
    /* road load: the right-hand side depends on the inputs alone, held over the step, so one
       step integrates it exactly (sub-steps only added round-off and 95 us per 50 ms step) */
    if (n < 1 || road_load_coupling(p)) n = 1;
    dt = h / n;
    for (i = 0; i < n; i++) { /* classical RK4; the input is held over the step */
        rhs(p, m->s, k1);
        for (j = 0; j < VM_NUM_STATES; j++) y[j] = m->s[j] + 0.5 * dt * k1[j];
        rhs(p, y, k2);
        for (j = 0; j < VM_NUM_STATES; j++) y[j] = m->s[j] + 0.5 * dt * k2[j];
        rhs(p, y, k3);
        for (j = 0; j < VM_NUM_STATES; j++) y[j] = m->s[j] + dt * k3[j];
        rhs(p, y, k4);
        for (j = 0; j < VM_NUM_STATES; j++)
            m->s[j] += dt / 6.0 * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
    }
    m->time += h;
    vm_outputs(m);
    if (road_load_coupling(p) && h > 0.0) { /* the acceleration over the last step */
        m->v[VR_A] = p[VR_R_DYN] * (p[VR_W_W] - m->w_w_prev) / h;
        m->w_w_prev = p[VR_W_W];
    }
}

void vm_outputs(vm_model *m)
{
    double *v = m->v, ds[VM_NUM_STATES], f_resist, f_grade;
    const double *s = m->s;
    double w = wheel_speed(v, s);
    int own_inertia = !road_load_coupling(v);
    rhs(v, s, ds);
    road_load(v, v[VR_R_DYN] * w, &f_resist, &f_grade);
    v[VR_T_HS] = flange_torque(v, s);
    v[VR_W_WHEEL] = w;
    v[VR_V] = v[VR_R_DYN] * w;
    if (own_inertia) v[VR_A] = v[VR_R_DYN] * ds[S_W_WHEEL];
    v[VR_X] = s[S_X];
    v[VR_TWIST] = s[S_TWIST];
    v[VR_F_ROAD] = f_resist + f_grade;
    v[VR_P_IN] = v[VR_T_HS] * input_speed(v, s);
    v[VR_E_IN] = s[S_E_IN];
    v[VR_E_KIN] = own_inertia ? 0.5 * inertia(v) * w * w : 0.0;
    v[VR_E_SPRING] = 0.5 * v[VR_K_HS] * s[S_TWIST] * s[S_TWIST];
    v[VR_E_ROAD] = s[S_E_ROAD];
    v[VR_E_GRADE] = f_grade * s[S_X];
    v[VR_E_DAMPER] = s[S_E_DAMPER];
    v[VR_E_BRAKE] = s[S_E_BRAKE];
    memcpy(&v[VR_DER_TWIST], ds, sizeof ds); /* the derivatives, in the states' order */
}
