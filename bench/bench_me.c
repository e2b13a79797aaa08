/* Real-time factor of the gear and the vehicle FMU as one Model Exchange system in a C host (no
 * Python in the loop): both FMUs dlopened (tests/host/fmu_host.c), their states integrated
 * together by CVODE BDF through the project's solver layer (fmu-src/solver: dense Newton, rtol
 * and rtol x the FMUs' nominals; --method: Adams or an explicit Runge-Kutta pair instead), root finding on the gear's event indicators, an event
 * iteration at every root and wherever a completed step asks for one; the connections at every
 * right-hand side: the gear's w_w (a state of it: read from the state vector) to the vehicle's
 * w_w, the vehicle's T_hs to the gear's T_w, the propeller-shaft torque T_s a function of time.
 *
 *   bench_me GEAR_DIR VEHICLE_DIR [--level full|map|NAME=VALUE,...] [--runs N] [--stop T]
 *            [--rtol R] [--stop-at-outputs 0|1] [--keep-store 0|1] [--method bdf|adams|erk]
 *
 * The scene is tests/cosim's (cosim_driver.Scene): from 100 rpm, T_s ramps to 150 N m in 0.3 s
 * (the launch), holds to 1.2 s, a tip-out to -50 N m (coast) by 1.3 s, held to 1.8 s, a tip-in
 * back to 150 N m by 1.9 s, held to the stop (2.5 s); gear load_mode = torque, the vehicle's
 * half-shaft coupling. Prints per run the wall and CPU time, the real-time factor (simulated /
 * CPU seconds), the integrator's steps, right-hand sides (the host's: including those of its
 * difference-quotient Jacobians), events, and w_p, E_in and the energy residual at the end.
 * Levels: full (the FMU's defaults) or map (mesh_model = rigid, friction_model = map). The
 * integrator stops at the profile's breakpoints (kinks of T_s) and steps past the other outputs,
 * which it interpolates (fmpy's CVode and most hosts stop at none). */
#define _POSIX_C_SOURCE 199309L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "fmu_host.h"
#include "solver/solver.h"

#define RPM 0.10471975511965977
#define RATIO (36.0 / 13.0) /* gear set 1 */
#define OUTPUT_INTERVAL 0.01 /* [s] the host's outputs (every breakpoint of the profile is one) */
#define MAX_X (2 * HOST_MAX_STATES)

/* --stop-at-outputs 1: the integrator stops at every output (a stop time there) instead of
 * stepping past and interpolating, as fmpy's CVode and most hosts do */
static int stop_at_outputs;
/* --keep-store 1: one more gear instance, initialised with the level's parameters, lives
 * through all the runs, so that the process's table store keeps what the first run solved (its
 * node tables) for the next: the cost of a run whose friction tables the process already has (a
 * second instance, a sweep, a rerun while the FMU stays instantiated) */
static int keep_store;
/* --method: the host's integrator through the project's layer: CVODE BDF (the default) or
 * Adams with the dense Newton iteration, or ARKODE's explicit embedded Runge-Kutta pair (the
 * FMU's own choice in co-simulation for the compliant mesh) */
static int method = HG_METHOD_BDF;

typedef struct {
    instance gear, vehicle;
    size_t nx_g, nx_v, nz;
    fmi2ValueReference g_ts_tw[2], g_ww, v_ww, v_ths;
    long k_ww; /* w_w's place in the gear's state vector (the host reads it there), or -1 */
    long rhs_calls, jac_calls; /* jac_calls: in runs of nx or more at one time (a Jacobian) */
    long run;                  /* calls in a row at the time of the last one */
    double t_last;
    int failed;
} me_system;

/* The scene's propeller-shaft torque profile: time [s], T_s [N m] (linear in between). */
static const double pts[][2] = {{0.0, 0.0},   {0.3, 150.0}, {1.2, 150.0}, {1.3, -50.0},
                                {1.8, -50.0}, {1.9, 150.0}, {1e9, 150.0}};

static double torque(double t)
{
    int k = 0;
    while (t > pts[k + 1][0]) k++;
    return pts[k][1] + (pts[k + 1][1] - pts[k][1]) * (t - pts[k][0]) / (pts[k + 1][0] - pts[k][0]);
}

/* Whether t is a breakpoint of the profile (a kink of the input: the integrator stops there). */
static int breakpoint(double t)
{
    int k;
    for (k = 0; pts[k][0] < 1e9; k++)
        if (fabs(t - pts[k][0]) < 1e-9) return 1;
    return 0;
}

/* Time, states and the connections at t: the state vector is the gear's, then the vehicle's. */
static int load(me_system *s, double t, const double *x)
{
    const fmu_lib *g = s->gear.f, *v = s->vehicle.f;
    double w_w, T_hs, in[2];
    if (g->set_time(s->gear.c, t) != fmi2OK || v->set_time(s->vehicle.c, t) != fmi2OK ||
        g->set_continuous_states(s->gear.c, x, s->nx_g) != fmi2OK ||
        v->set_continuous_states(s->vehicle.c, x + s->nx_g, s->nx_v) != fmi2OK ||
        (s->k_ww >= 0 ? (w_w = x[s->k_ww], 0)
                      : g->get_real(s->gear.c, &s->g_ww, 1, &w_w) != fmi2OK) ||
        v->set_real(s->vehicle.c, &s->v_ww, 1, &w_w) != fmi2OK ||
        v->get_real(s->vehicle.c, &s->v_ths, 1, &T_hs) != fmi2OK)
        return -1;
    in[0] = torque(t);
    in[1] = T_hs;
    return g->set_real(s->gear.c, s->g_ts_tw, 2, in) != fmi2OK ? -1 : 0;
}

static int rhs(double t, const double *x, double *dx, void *user)
{
    me_system *s = user;
    size_t n = s->nx_g + s->nx_v;
    s->rhs_calls++;
    s->run = t == s->t_last ? s->run + 1 : 1;
    s->t_last = t;
    if (s->run == (long)n + 1) s->jac_calls += (long)n; /* a difference-quotient Jacobian */
    if (s->run > (long)n + 1) s->jac_calls++;
    if (load(s, t, x) || s->gear.f->get_derivatives(s->gear.c, dx, s->nx_g) != fmi2OK ||
        s->vehicle.f->get_derivatives(s->vehicle.c, dx + s->nx_g, s->nx_v) != fmi2OK) {
        s->failed = 1;
        return -1;
    }
    return 0;
}

static int roots(double t, const double *x, double *z, void *user)
{
    me_system *s = user;
    if (load(s, t, x) || s->gear.f->get_event_indicators(s->gear.c, z, s->nz) != fmi2OK) {
        s->failed = 1;
        return -1;
    }
    return 0;
}

/* The discrete states' iteration of one instance in event mode, then continuous-time mode. */
static int iterate(instance *in)
{
    fmi2EventInfo info;
    do {
        if (in->f->new_discrete_states(in->c, &info) != fmi2OK) return -1;
    } while (info.newDiscreteStatesNeeded && !info.terminateSimulation);
    return in->f->enter_continuous_time_mode(in->c) != fmi2OK ? -1 : 0;
}

static int states(me_system *s, double *x)
{
    return s->gear.f->get_continuous_states(s->gear.c, x, s->nx_g) != fmi2OK ||
                   s->vehicle.f->get_continuous_states(s->vehicle.c, x + s->nx_g, s->nx_v) !=
                       fmi2OK
               ? -1
               : 0;
}

static int set_params(instance *in, const char *list)
{
    char buf[512], *tok, *save = NULL;
    snprintf(buf, sizeof buf, "%s", list);
    for (tok = strtok_r(buf, ",", &save); tok; tok = strtok_r(NULL, ",", &save)) {
        char *eq = strchr(tok, '=');
        if (!eq) return host_fail(tok);
        *eq = '\0';
        if (host_set(in, tok, eq + 1)) return -1;
    }
    return 0;
}

/* Both instances initialised at t = 0 (the gear first: its w_w is the vehicle's start input). */
static int start(me_system *s, const char *level_params)
{
    double w_p0 = 100.0 * RPM, w_w;
    instance *g = &s->gear, *v = &s->vehicle;
    if (g->f->setup(g->c, fmi2False, 0.0, 0.0, fmi2False, 0.0) != fmi2OK ||
        host_set_int(g, "load_mode", 1) || host_set_real(g, "w_p0", w_p0) ||
        host_set_real(g, "T_s", torque(0.0)) || host_set_real(g, "T_w", 0.0) ||
        set_params(g, level_params) || g->f->enter(g->c) != fmi2OK ||
        g->f->exit_init(g->c) != fmi2OK || iterate(g) ||
        g->f->get_real(g->c, &s->g_ww, 1, &w_w) != fmi2OK)
        return host_fail("the gear's initialization");
    if (v->f->setup(v->c, fmi2False, 0.0, 0.0, fmi2False, 0.0) != fmi2OK ||
        host_set_real(v, "v0", 0.3 * w_p0 / RATIO) || host_set_real(v, "T_hs0", 0.0) ||
        host_set_real(v, "w_w", w_w) || v->f->enter(v->c) != fmi2OK ||
        v->f->exit_init(v->c) != fmi2OK || iterate(v))
        return host_fail("the vehicle's initialization");
    return 0;
}

static double cpu_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static double wall_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

/* An event at t: both FMUs' iterations; the solver restarts from their states. */
static int event(me_system *s, hg_solver *solver, double t, double *x, char *err, size_t len)
{
    if (s->gear.f->enter_event_mode(s->gear.c) != fmi2OK || iterate(&s->gear) ||
        s->vehicle.f->enter_event_mode(s->vehicle.c) != fmi2OK || iterate(&s->vehicle) ||
        states(s, x))
        return host_fail("an event");
    return hg_solver_restart(solver, t, x, 0.0, err, len);
}

/* Integrates to t_end; counts steps and events. */
static int integrate(me_system *s, hg_solver *solver, double t_end, long *events)
{
    double x[MAX_X], t = 0.0;
    int dir[HOST_MAX_STATES], k, n_out = (int)(t_end / OUTPUT_INTERVAL + 0.5);
    char err[512];
    if (states(s, x) || hg_solver_restart(solver, 0.0, x, 0.0, err, sizeof err))
        return host_fail("the start of the integration");
    for (k = 1; k <= n_out; k++) {
        double t_out = k * OUTPUT_INTERVAL;
        int pass = !stop_at_outputs && !breakpoint(t_out);
        while (t < t_out) {
            fmi2Boolean ev_g = fmi2False, ev_v = fmi2False, stop;
            hg_advance_result r =
                hg_solver_advance(solver, t_out, pass, &t, x, dir, err, sizeof err);
            if (r == HG_ADVANCE_FAILED || s->failed || load(s, t, x)) {
                fprintf(stderr, "bench_me: t = %g: %s\n", t, err);
                return -1;
            }
            if (s->gear.f->completed_integrator_step(s->gear.c, fmi2True, &ev_g, &stop) != fmi2OK ||
                s->vehicle.f->completed_integrator_step(s->vehicle.c, fmi2True, &ev_v, &stop) !=
                    fmi2OK)
                return host_fail("fmi2CompletedIntegratorStep");
            if (r == HG_ADVANCE_ROOT || ev_g || ev_v) {
                (*events)++;
                if (event(s, solver, t, x, err, sizeof err)) return -1;
            }
        }
    }
    return 0;
}

static int run(const fmu_lib *f_g, const fmu_info *m_g, const fmu_lib *f_v, const fmu_info *m_v,
               const char *level_params, double t_end, double rtol)
{
    me_system s;
    hg_solver *solver = NULL;
    hg_solver_options opt;
    double atol[MAX_X], out[3], wall, cpu;
    long steps = 0, nfe = 0, events = 0;
    char err[512];
    int rc = -1;
    const char *names[3] = {"w_p", "E_in", "E_out"};
    memset(&s, 0, sizeof s);
    memset(&opt, 0, sizeof opt); /* max_order, jac_every: the integrator's own */
    s.nx_g = m_g->nx, s.nx_v = m_v->nx, s.nz = m_g->nz;
    s.g_ts_tw[0] = (fmi2ValueReference)host_value_reference(m_g, "T_s");
    s.g_ts_tw[1] = (fmi2ValueReference)host_value_reference(m_g, "T_w");
    s.g_ww = (fmi2ValueReference)host_value_reference(m_g, "w_w");
    s.v_ww = (fmi2ValueReference)host_value_reference(m_v, "w_w");
    s.v_ths = (fmi2ValueReference)host_value_reference(m_v, "T_hs");
    /* w_w is a continuous state: its derivative's place among the derivatives (their value
     * references follow the state vector's order from der of the first state) */
    s.k_ww = host_value_reference(m_g, "der(w_w)") - host_value_reference(m_g, "der(twist_1)");
    if (s.k_ww < 0 || s.k_ww >= (long)s.nx_g || host_value_reference(m_g, "der(w_w)") < 0)
        s.k_ww = -1;
    if (host_open_as(&s.gear, f_g, m_g, "gear", 1) ||
        host_open_as(&s.vehicle, f_v, m_v, "vehicle", 1) || start(&s, level_params))
        goto done;
    wall = wall_now();
    cpu = cpu_now();
    if (f_g->get_nominals(s.gear.c, atol, s.nx_g) != fmi2OK ||
        f_v->get_nominals(s.vehicle.c, atol + s.nx_g, s.nx_v) != fmi2OK) {
        host_fail("fmi2GetNominalsOfContinuousStates");
        goto done;
    }
    for (size_t i = 0; i < s.nx_g + s.nx_v; i++) atol[i] *= rtol;
    opt.method = method;
    opt.rtol = rtol;
    opt.atol = atol;
    opt.max_steps = 1000000;
    if (!(solver = hg_solver_new((int)(s.nx_g + s.nx_v), (int)s.nz, rhs, roots, &s, &opt, err,
                                 sizeof err))) {
        fprintf(stderr, "bench_me: %s\n", err);
        goto done;
    }
    if (integrate(&s, solver, t_end, &events)) goto done;
    cpu = cpu_now() - cpu;
    wall = wall_now() - wall;
    hg_solver_stats(solver, &steps, &nfe);
    for (int k = 0; k < 3; k++) {
        fmi2ValueReference vr = (fmi2ValueReference)host_value_reference(m_g, names[k]);
        f_g->get_real(s.gear.c, &vr, 1, &out[k]);
    }
    printf("bench_me: %.2f s simulated in %.3f s CPU (%.3f s wall): %.1fx real time; %ld steps, "
           "%ld right-hand sides (about %ld of them for difference-quotient Jacobians), "
           "%ld events; w_p = %.6f rad/s, E_in = %.6f J, E_out = %.6f J\n",
           t_end, cpu, wall, t_end / cpu, steps, s.rhs_calls, s.jac_calls, events,
           out[0], out[1], out[2]);
    rc = s.gear.log.errors + s.vehicle.log.errors ? host_fail("errors were logged") : 0;
done:
    hg_solver_free(solver);
    host_close(&s.gear);
    host_close(&s.vehicle);
    return rc;
}

int main(int argc, char **argv)
{
    fmu_info m_g, m_v;
    fmu_lib f_g, f_v;
    instance keeper;
    const char *level = "";
    double t_end = 2.5, rtol = 1e-6;
    int runs = 3, k, rc = 0;
    if (argc < 3) {
        fprintf(stderr, "usage: bench_me GEAR_DIR VEHICLE_DIR [--level full|map|NAME=VALUE,...] "
                "[--runs N] [--stop T] [--rtol R] [--stop-at-outputs 0|1] [--keep-store 0|1] "
                "[--method bdf|adams|erk]\n");
        return 2;
    }
    for (k = 3; k + 1 < argc; k += 2) {
        if (!strcmp(argv[k], "--level"))
            level = !strcmp(argv[k + 1], "map")    ? "mesh_model=rigid,friction_model=map"
                    : !strcmp(argv[k + 1], "full") ? ""
                                                   : argv[k + 1];
        else if (!strcmp(argv[k], "--runs"))
            runs = atoi(argv[k + 1]);
        else if (!strcmp(argv[k], "--stop"))
            t_end = atof(argv[k + 1]);
        else if (!strcmp(argv[k], "--rtol"))
            rtol = atof(argv[k + 1]);
        else if (!strcmp(argv[k], "--stop-at-outputs"))
            stop_at_outputs = atoi(argv[k + 1]);
        else if (!strcmp(argv[k], "--keep-store"))
            keep_store = atoi(argv[k + 1]);
        else if (!strcmp(argv[k], "--method"))
            method = !strcmp(argv[k + 1], "erk")     ? HG_METHOD_ERK
                     : !strcmp(argv[k + 1], "adams") ? HG_METHOD_ADAMS
                                                     : HG_METHOD_BDF;
        else
            return host_fail(argv[k]) ? 2 : 2;
    }
    if (host_read_info(&m_g, argv[1]) || host_read_info(&m_v, argv[2]) ||
        host_load(&f_g, m_g.so_path) || host_load(&f_v, m_v.so_path))
        return 1;
    if (!f_g.get_nominals || !m_g.nx || !m_v.nx) return host_fail("no Model Exchange") ? 1 : 1;
    if (keep_store && (host_open_as(&keeper, &f_g, &m_g, "keeper", 1) ||
                       f_g.setup(keeper.c, fmi2False, 0.0, 0.0, fmi2False, 0.0) != fmi2OK ||
                       set_params(&keeper, level) || f_g.enter(keeper.c) != fmi2OK ||
                       f_g.exit_init(keeper.c) != fmi2OK))
        return host_fail("the keeper's initialization") ? 1 : 1;
    for (k = 0; k < runs && !rc; k++) rc = run(&f_g, &m_g, &f_v, &m_v, level, t_end, rtol);
    if (keep_store) host_close(&keeper);
    host_unload(&f_g);
    host_unload(&f_v);
    host_free_info(&m_g);
    host_free_info(&m_v);
    return rc ? 1 : 0;
}
