/* The right-hand side of the 4-DoF torsional model (model/dynamics.h, eqs. 20-25) against states
 * built by hand: the static equilibrium gives zero accelerations; a known shaft twist gives the
 * hand-computed torque; the rigid mesh turns pinion and gear as one body; and the power balance
 * dE_stored/dt = T_s w_s - T_w w_w - P_damp holds for an arbitrary state (the stored energy
 * differentiated numerically along ydot); the housing heat's memo gives each evaluation its
 * own value. Frictionless flanks, the mean and the rigid mesh: no data files. */
#include "model/dynamics.h"

#include <math.h>
#include <string.h>

#include "check.h"

#define N_P 13.0
#define N_G 36.0

/* Only the tooth numbers of the gear set matter off the varying mesh. */
static hg_gearset gear;

static hg_dyn_params params(int mesh)
{
    hg_dyn_params p;
    memset(&p, 0, sizeof p);
    gear.N_p = (int)N_P;
    gear.N_g = (int)N_G;
    p.gear = &gear;
    p.I_s = p.I_p = 1.4e-2; /* kg m^2 */
    p.I_g = p.I_w = 0.29;   /* kg m^2 */
    p.k_t1 = p.k_t2 = 8e5;  /* N m/rad */
    p.mesh = mesh;
    p.k_m0 = 1.711e8;       /* N/m */
    p.R_p0 = 21.01e-3;      /* m */
    p.ratio = N_G / N_P;
    p.friction.model = HG_FRICTION_MODEL_NONE;
    return p;
}

/* The inputs: pinion and wheel torques [N m], governor set-point [rad/s]; the bath at 40 degC
 * and every other input at its start value. */
static hg_inputs inputs(double T_s, double T_w, double w_set)
{
    hg_inputs u;
    int k;
    for (k = 0; k < HG_NUM_INPUTS; k++) *hg_input(&u, k) = hg_var_table[hg_input_vr[k]].start;
    u.T_s = T_s;
    u.T_w = T_w;
    u.T_bath = 313.15;
    u.w_set = w_set;
    return u;
}

static void evaluate(const hg_dyn_params *p, const hg_inputs *u, const double *y, double *ydot,
                     hg_dyn_eval *ev)
{
    double warm[HG_MAX_PAIRS] = {-1.0, -1.0, -1.0};
    hg_dyn_evaluate(p, u, HG_MODE_DRIVE, y, 0, warm, ev);
    hg_dyn_derivatives(p, u, y, ev, ydot);
}

/* Shafts twisted by their torques, mesh deflected by W_t / k_m = T_s / (R_p k_m), all at one
 * speed (docs/physics.md §8.6): nothing accelerates, and the power flows through unchanged. */
static void test_static_equilibrium(void)
{
    hg_dyn_params p = params(HG_MESH_MODEL_MEAN);
    hg_inputs u = inputs(100.0, 100.0 * N_G / N_P, 0.0);
    double y[HG_NY] = {0}, ydot[HG_NY], w = 200.0;
    hg_dyn_eval ev;
    p.c_t1 = 40.0, p.c_m = 2.0e3, p.c_t2 = 300.0; /* dampers see no relative motion */
    y[HG_Y_TWIST1] = u.T_s / p.k_t1;
    y[HG_Y_TWIST2] = u.T_w / p.k_t2;
    y[HG_Y_X] = u.T_s / (p.R_p0 * p.k_m0);
    y[HG_Y_W_S] = y[HG_Y_W_P] = w;
    y[HG_Y_W_G] = y[HG_Y_W_W] = w / p.ratio;
    evaluate(&p, &u, y, ydot, &ev);
    CHECK_CLOSE(ev.W_t, u.T_s / p.R_p0, 1e-12, 0.0);
    CHECK_CLOSE(ev.xdot, 0.0, 0.0, 1e-12);
    CHECK_CLOSE(ydot[HG_Y_W_S], 0.0, 0.0, 1e-8);
    CHECK_CLOSE(ydot[HG_Y_W_P], 0.0, 0.0, 1e-8);
    CHECK_CLOSE(ydot[HG_Y_W_G], 0.0, 0.0, 1e-8);
    CHECK_CLOSE(ydot[HG_Y_W_W], 0.0, 0.0, 1e-8);
    CHECK_CLOSE(ydot[HG_Y_X], 0.0, 0.0, 1e-12);
    CHECK_CLOSE(ydot[HG_Y_E_IN], u.T_s * w, 1e-12, 0.0);
    CHECK_CLOSE(ydot[HG_Y_E_OUT], u.T_s * w, 1e-12, 0.0);
    CHECK(ydot[HG_Y_E_FRIC] == 0.0 && ev.P_loss == 0.0 && ev.eta == 1.0);
    CHECK_CLOSE(ydot[HG_Y_E_DAMP], 0.0, 0.0, 1e-12);
}

/* A twist of 1 mrad of the input shaft at rest: T_1 = k_t1 1e-3 = 800 N m, plus the damper
 * c_t1 (w_s - w_p) = 50 * 2 = 100 N m; nothing else is loaded (x = 0, no wheel torque). */
static void test_known_twist(void)
{
    hg_dyn_params p = params(HG_MESH_MODEL_MEAN);
    hg_inputs u = inputs(0.0, 0.0, 0.0);
    double y[HG_NY] = {0}, ydot[HG_NY];
    hg_dyn_eval ev;
    p.c_t1 = 50.0;
    y[HG_Y_TWIST1] = 1e-3;
    y[HG_Y_W_S] = 2.0;
    evaluate(&p, &u, y, ydot, &ev);
    CHECK_CLOSE(ydot[HG_Y_W_S], -900.0 / 1.4e-2, 1e-13, 0.0);   /* eq. 20 */
    CHECK_CLOSE(ydot[HG_Y_TWIST1], 2.0, 0.0, 0.0);
    CHECK_CLOSE(ev.xdot, 0.0, 0.0, 0.0);                         /* x' = R_p w_p - R_g w_g */
    CHECK_CLOSE(ydot[HG_Y_W_P], 900.0 / 1.4e-2, 1e-13, 0.0);    /* eq. 21 with W_t = 0 */
    CHECK(ydot[HG_Y_W_G] == 0.0 && ydot[HG_Y_W_W] == 0.0);
    CHECK_CLOSE(ydot[HG_Y_E_DAMP], 50.0 * 2.0 * 2.0, 1e-13, 0.0); /* c_t1 (w_s - w_p)^2 */

    /* the same twist on the mesh instead: x = 10 um, k_m x = 1711 N on R_p and R_g = i R_p */
    memset(y, 0, sizeof y);
    y[HG_Y_X] = 1e-5;
    evaluate(&p, &u, y, ydot, &ev);
    CHECK_CLOSE(ev.W_t, 1711.0, 1e-12, 0.0);
    CHECK_CLOSE(ydot[HG_Y_W_P], -1711.0 * 21.01e-3 / 1.4e-2, 1e-12, 0.0);
    CHECK_CLOSE(ydot[HG_Y_W_G], 1711.0 * 21.01e-3 * N_G / N_P / 0.29, 1e-12, 0.0); /* eq. 22 */
}

/* Rigid mesh: pinion and gear as one body of inertia I_p + I_g / i^2 seen at the pinion; the
 * mesh load is what accelerates the gear: W_t = I_g (acc / i) / R_g. */
static void test_rigid_mesh(void)
{
    hg_dyn_params p = params(HG_MESH_MODEL_RIGID);
    hg_inputs u = inputs(0.0, 0.0, 0.0);
    double y[HG_NY] = {0}, ydot[HG_NY], i = N_G / N_P, J = 1.4e-2 + 0.29 / (i * i), acc;
    hg_dyn_eval ev;
    y[HG_Y_TWIST1] = 1e-3;  /* T_1 = 800 N m */
    y[HG_Y_TWIST2] = -2e-4; /* T_2 = -160 N m: the wheel shaft pulls the gear along */
    evaluate(&p, &u, y, ydot, &ev);
    acc = (800.0 + 160.0 / i) / J;
    CHECK_CLOSE(ydot[HG_Y_W_P], acc, 1e-12, 0.0);
    CHECK_CLOSE(ydot[HG_Y_W_G], acc / i, 1e-12, 0.0);
    CHECK_CLOSE(ev.W_t, (0.29 * acc / i - 160.0) / (21.01e-3 * i), 1e-12, 0.0);
    CHECK(ydot[HG_Y_X] == 0.0);
}

/* The map level: the input shaft's end joins the body (I_s + I_p + I_g / i^2), driven by T_s; the
 * shaft is quasi-static, carrying T_1 = T_s - I_s acc, and its twist and speed states stay put.
 * A map of eta = 0.9 everywhere: the pinion loses 0.1 T_1 of the frictionless pass's T_1 (w_p far
 * above the spin regularisation). */
static void test_map_level_quasi_static_input(void)
{
    static double eta[16], D[8 * 16]; /* D[0]: the table; the second derivatives: none */
    static const double axis[3][2] = {{0.0, 600.0}, {0.0, 500.0}, {250.0, 450.0}};
    hg_dyn_params p = params(HG_MESH_MODEL_RIGID);
    hg_effmap map;
    hg_inputs u = inputs(800.0, 0.0, 0.0);
    double y[HG_NY] = {0}, ydot[HG_NY], i = N_G / N_P, J = 2.8e-2 + 0.29 / (i * i), acc0, T_fp,
           acc;
    hg_dyn_eval ev;
    int k;
    memset(&map, 0, sizeof map);
    for (k = 0; k < 16; k++) eta[k] = D[k] = 0.9;
    map.n_w = map.n_T = map.n_K = 2;
    memcpy(map.w, axis[0], sizeof axis[0]);
    memcpy(map.T, axis[1], sizeof axis[1]);
    memcpy(map.K, axis[2], sizeof axis[2]);
    map.eta = eta;
    map.D = D; /* two nodes: no curvature */
    p.friction.model = HG_FRICTION_MODEL_MAP;
    p.quasi_static_input = 1; /* input_shaft = auto at the map level */
    p.map = &map;
    y[HG_Y_TWIST1] = 1e-3;  /* not a state here: no torque of its own */
    y[HG_Y_TWIST2] = -2e-4; /* T_2 = -160 N m */
    y[HG_Y_W_S] = 5.0;      /* nor this: the input end turns with the pinion */
    y[HG_Y_W_P] = 300.0;
    y[HG_Y_W_G] = 300.0 / i;
    evaluate(&p, &u, y, ydot, &ev);
    acc0 = (800.0 + 160.0 / i) / J;
    T_fp = -0.1 * (800.0 - 1.4e-2 * acc0) * 300.0 / sqrt(300.0 * 300.0 + 1e-6);
    acc = (800.0 + 160.0 / i + T_fp) / J;
    CHECK_CLOSE(ev.T_fp, T_fp, 1e-12, 0.0);
    CHECK_CLOSE(ydot[HG_Y_W_P], acc, 1e-12, 0.0);
    CHECK_CLOSE(ydot[HG_Y_W_G], acc / i, 1e-12, 0.0);
    CHECK_CLOSE(ev.T_1, 800.0 - 1.4e-2 * acc, 1e-12, 0.0);
    CHECK_CLOSE(ev.W_t, (0.29 * acc / i - 160.0) / (21.01e-3 * i), 1e-12, 0.0);
    CHECK(ydot[HG_Y_TWIST1] == 0.0 && ydot[HG_Y_W_S] == 0.0 && ydot[HG_Y_E_DAMP] == 0.0);
    CHECK(ev.w_s == 300.0 && ydot[HG_Y_E_IN] == 800.0 * 300.0);
}

/* The output shaft quasi-static (output_shaft: the map level's by default): the wheel end joins
 * the body (I_p + (I_g + I_w) / i^2), resisted by the wheel-end torque T_w; the shaft carries
 * T_2 = T_w + I_w acc / i from the gear, its twist and damper act no more and the wheel end's
 * speed follows the gear's. */
static void test_quasi_static_output(void)
{
    hg_dyn_params p = params(HG_MESH_MODEL_RIGID);
    hg_inputs u = inputs(0.0, 160.0, 0.0);
    double y[HG_NY] = {0}, ydot[HG_NY], i = N_G / N_P, J = 1.4e-2 + (0.29 + 0.29) / (i * i);
    double acc = (800.0 - 160.0 / i) / J, T_2 = 160.0 + 0.29 * acc / i;
    hg_dyn_eval ev;
    p.quasi_static_output = 1;
    p.c_t2 = 50.0;
    y[HG_Y_TWIST1] = 1e-3;  /* T_1 = 800 N m */
    y[HG_Y_TWIST2] = 5e-3;  /* not a state here: no torque of its own */
    y[HG_Y_W_G] = 100.0 / i;
    y[HG_Y_W_W] = 3.0;      /* nor does the speed difference drive a damper */
    evaluate(&p, &u, y, ydot, &ev);
    CHECK_CLOSE(ydot[HG_Y_W_P], acc, 1e-12, 0.0);
    CHECK_CLOSE(ydot[HG_Y_W_G], acc / i, 1e-12, 0.0);
    CHECK(ydot[HG_Y_W_W] == ydot[HG_Y_W_G] && ydot[HG_Y_TWIST2] == 0.0);
    CHECK_CLOSE(ev.T_2, T_2, 1e-12, 0.0);
    CHECK_CLOSE(ev.W_t, (0.29 * acc / i + T_2) / (21.01e-3 * i), 1e-12, 0.0);
    CHECK(ydot[HG_Y_E_DAMP] == 0.0);
    p.mesh = HG_MESH_MODEL_MEAN; /* the compliant mesh: the shaft's spring whatever the flag */
    evaluate(&p, &u, y, ydot, &ev);
    CHECK_CLOSE(ev.T_2, 8e5 * 5e-3 + 50.0 * (100.0 / i - 3.0), 1e-12, 0.0);
}

/* The speed governor's wheel torque: T_s i + K_p (w_w - w_set / i) + K_i * integral. */
static void test_governor(void)
{
    hg_dyn_params p = params(HG_MESH_MODEL_MEAN);
    hg_inputs u = inputs(120.0, 0.0, 210.0);
    double y[HG_NY] = {0}, ydot[HG_NY], i = N_G / N_P;
    hg_dyn_eval ev;
    p.speed_governor = 1, p.K_p = 30.0, p.K_i = 900.0;
    y[HG_Y_W_W] = 80.0;
    y[HG_Y_GOV] = 0.01;
    evaluate(&p, &u, y, ydot, &ev);
    CHECK_CLOSE(ev.T_w, 120.0 * i + 30.0 * (80.0 - 210.0 / i) + 900.0 * 0.01, 1e-13, 0.0);
    CHECK_CLOSE(ydot[HG_Y_GOV], 80.0 - 210.0 / i, 1e-13, 0.0);
    CHECK_CLOSE(ydot[HG_Y_W_W], -ev.T_w / 0.29, 1e-13, 0.0); /* eq. 23 with T_2 = 0 */
}

static double stored(const hg_dyn_params *p, const hg_inputs *u, const double *y)
{
    double ydot[HG_NY];
    hg_dyn_eval ev;
    evaluate(p, u, y, ydot, &ev);
    return hg_dyn_stored_energy(p, y, &ev);
}

/* d/dt of the kinetic plus elastic energy along the motion equals the power in minus out minus
 * the damper losses; the energy-audit states integrate exactly these terms. */
static void test_power_balance(int mesh)
{
    hg_dyn_params p = params(mesh);
    hg_inputs u = inputs(150.0, 300.0, 0.0);
    double y[HG_NY] = {0}, ydot[HG_NY], yp[HG_NY], ym[HG_NY], dt = 1e-7, dE, P;
    hg_dyn_eval ev;
    int k;
    p.c_t1 = 40.0, p.c_m = 2.0e3, p.c_t2 = 300.0;
    y[HG_Y_TWIST1] = 3e-4, y[HG_Y_TWIST2] = -1e-4, y[HG_Y_X] = 2e-5;
    y[HG_Y_W_S] = 210.0, y[HG_Y_W_P] = 205.0, y[HG_Y_W_G] = 75.0, y[HG_Y_W_W] = 72.0;
    if (mesh == HG_MESH_MODEL_RIGID) { /* one body: no deflection, w_g = w_p / i */
        y[HG_Y_X] = 0.0;
        y[HG_Y_W_G] = y[HG_Y_W_P] / p.ratio;
    }
    evaluate(&p, &u, y, ydot, &ev);
    for (k = 0; k < HG_NY; k++) {
        yp[k] = y[k] + dt * ydot[k];
        ym[k] = y[k] - dt * ydot[k];
    }
    dE = (stored(&p, &u, yp) - stored(&p, &u, ym)) / (2.0 * dt);
    P = u.T_s * y[HG_Y_W_S] - u.T_w * y[HG_Y_W_W] - ev.P_damp;
    CHECK_CLOSE(dE, P, 1e-6, 1e-6 * u.T_s * y[HG_Y_W_S]);
    CHECK_CLOSE(ydot[HG_Y_E_IN] - ydot[HG_Y_E_OUT] - ydot[HG_Y_E_FRIC] - ydot[HG_Y_E_DAMP] +
                    ydot[HG_Y_E_EXC],
                P, 1e-12, 1e-9);
}

/* The housing heat through the instance's memo: each evaluation's Q_dot is that of its own oil
 * and air temperatures and air speed, also when they change between evaluations and come back.
 * The first against the hand formula Q = A (h dT + eps sigma (T_oil^4 - T_amb^4)) with the
 * natural-convection h = 1.42 (dT / L)^(1/4) (still air). */
static void test_heat_memo(void)
{
    hg_dyn_params p = params(HG_MESH_MODEL_MEAN);
    hg_heat_memo memo = {0};
    hg_inputs u = inputs(100.0, 0.0, 0.0);
    double y[HG_NY] = {0}, ydot[HG_NY], dT = 40.0, hand;
    static const double T_bath[] = {333.15, 353.15, 353.15, 333.15, 333.15};
    static const double v_air[] = {0.0, 0.0, 8.0, 8.0, 0.0};
    hg_dyn_eval ev;
    int k;
    p.ledger.housing.A = 0.6, p.ledger.housing.L = 0.25, p.ledger.housing.eps = 0.9;
    p.heat = &memo;
    u.T_amb = 293.15;
    y[HG_Y_W_S] = y[HG_Y_W_P] = 200.0, y[HG_Y_W_G] = y[HG_Y_W_W] = 200.0 / p.ratio;
    for (k = 0; k < 5; k++) {
        u.T_bath = T_bath[k], u.v_air = v_air[k];
        evaluate(&p, &u, y, ydot, &ev);
        CHECK(ev.Q_dot == hg_ledger_heat_out(&p.ledger, T_bath[k], u.T_amb, v_air[k]));
        CHECK(ydot[HG_Y_Q_H] == ev.Q_dot);
    }
    hand = 0.6 * (1.42 * pow(dT / 0.25, 0.25) * dT +
                  0.9 * 5.670374419e-8 * (pow(333.15, 4) - pow(293.15, 4)));
    u.T_bath = 333.15, u.v_air = 0.0;
    evaluate(&p, &u, y, ydot, &ev);
    CHECK_CLOSE(ev.Q_dot, hand, 1e-12, 0.0);
}

int main(void)
{
    test_static_equilibrium();
    test_known_twist();
    test_rigid_mesh();
    test_map_level_quasi_static_input();
    test_quasi_static_output();
    test_governor();
    test_power_balance(HG_MESH_MODEL_MEAN);
    test_power_balance(HG_MESH_MODEL_RIGID);
    test_heat_memo();
    CHECK_DONE();
}
