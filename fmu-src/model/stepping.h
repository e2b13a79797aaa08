/* What evolves in time (hg_runtime) and the stepping helpers of the model object: the initial
 * state, the inputs over a step, the events (contact changes, averaging windows), the angle wrap
 * and the step limit. They work on an hg_runtime and an hg_setup and call only downwards. */
#ifndef HG_STEPPING_H
#define HG_STEPPING_H

#include "hg_vars.h"
#include "io/log.h"
#include "model/setup.h"

/* Everything that evolves in time; plain data, so a snapshot is a copy. */
typedef struct {
    double t;
    double y[HG_NY];
    int mode;                      /* backlash contact mode HG_MODE_* */
    int n_impacts;                 /* contact changes so far */
    double T_c_warm[HG_MAX_PAIRS]; /* warm starts of the thermal solves [K] */
    hg_inputs u0, du;              /* inputs at the step start and their time derivatives */
    double t_u0;                   /* time at which u0 holds */
    hg_inputs u_end;               /* inputs extrapolated to the end of the last step, u0 + du h */
    int restart;                   /* the integrator must restart before the next step */
    int held;                      /* steps in a row with the inputs unchanged (capped) */
    int ahead;                     /* the integrator stepped past t on the last step's inputs */
    double imp_w0;                 /* y[HG_Y_IMP_W] at the step's start t_u0 [N m s] */
    double T_w_mean_last, h_last;  /* mean T_w over the step before, and its length [N m], [s]
                                      (h_last 0: no step before) */
    int wheel_given;               /* w_wheel has been set to something but 0 since the start */
    double w_wheel0;               /* the wheel speed taken until then: w_p0 / i [rad/s] */
    double w_wheel_last;           /* the w_wheel of the step before [rad/s] */
    double T_wheel_given;          /* T_wheel as the host read it before the current step [N m] */
    double imp_given;              /* T_wheel's impulse over the steps so far, held over each:
                                      what a Jacobi host has passed to the wheels [N m s] */
    double h_int;                  /* mean integrator step of the last step [s]: the first step
                                      of the explicit method's restarts */
    double win_phi0, win_t0;       /* start of the averaging window: pinion angle, time */
    double win_eta2_0, win_efric_0, win_eta_axle2_0;
    int windows;                   /* averaging windows completed */
    double eta_cycle, P_loss_cycle, eta_axle_cycle;
    int map_warned;                /* the map level has said once that it left its grid */
    hg_ft_key ft_key;              /* the friction table's operating point, when ft_valid */
    int ft_valid;
    int ft_in_use;                 /* the last step ran on the table of ft_key (else on the
                                      direct solve): the outputs then use it too */
} hg_runtime;

/* Static equilibrium at speed w_p0 at time t0 (docs/physics.md §8.6), inputs of v held. */
void hg_stepping_start(hg_runtime *rt, const hg_setup *s, const hg_vars *v, double t0);

/* The inputs at time t: u0 extrapolated with du. */
/* load_mode = half_shaft, before a step: while the host has passed 0 (or nothing) for w_wheel
 * since the start, the wheel turns at the gear's own start speed w_p0 / i (docs/integration.md,
 * "The start"); unless the host gives w_wheel's derivative, the step runs on w_wheel extrapolated
 * linearly from the last two steps' values (du), so that the wheel's angle the half-shaft sees
 * is second-order in the step instead of lagging by h/2 times the change of speed. */
void hg_stepping_wheel_input(hg_runtime *rt, const hg_setup *s, hg_inputs *u, hg_inputs *du);

/* load_mode = half_shaft, a co-simulation step's start, before hg_stepping_wheel_input: adds the
 * impulse of T_wheel held over the step that ended to what the wheels have been given, takes the
 * T_wheel the host now reads as held over the coming step, and, with I_vehicle set and the wheel
 * speed given, takes from the host's w_wheel the speed that the impulse passed ahead of the
 * half-shaft's own (given minus HG_Y_IMP_W) has added to the vehicle's inertia: the wheel speed
 * the vehicle would have had with the half-shaft's exact impulse (docs/integration.md). */
void hg_stepping_wheel_correct(hg_runtime *rt, const hg_setup *s, hg_inputs *u);

/* The torque to hold at the vehicle's wheels over the next step (output T_wheel): the mean of
 * T_w over the last step extrapolated linearly over one step from the mean of the step before, so
 * that the wheels receive the half-shaft's impulse to second order and all of it in the sum. */
double hg_stepping_wheel_torque(const hg_runtime *rt, double T_w_now);

void hg_stepping_inputs_at(const hg_runtime *rt, double t, hg_inputs *u);

/* How the inputs u (derivatives du) of a step differ from those the last step ended with:
 * not at all, in their derivatives only (a kink: the right-hand side stays continuous), or in
 * their values (a jump of the right-hand side). */
typedef enum { HG_INPUTS_SAME, HG_INPUTS_KINK, HG_INPUTS_JUMP } hg_input_change;
hg_input_change hg_stepping_change(const hg_runtime *rt, const hg_inputs *u,
                                   const hg_inputs *du);

/* Takes the inputs u and derivatives du (changed as said) for a step from the current time and
 * wraps the pinion angle (a restart). */
void hg_stepping_begin(hg_runtime *rt, const hg_setup *s, const hg_inputs *u,
                       const hg_inputs *du, hg_input_change change);

/* Whether the pinion angle is due to be wrapped by whole load-share periods, and the wrap (the
 * window's start moves with it; the integrator must restart). */
int hg_stepping_wrap_due(const hg_runtime *rt, const hg_setup *s);
void hg_stepping_wrap(hg_runtime *rt, const hg_setup *s);

/* Whether a jump of the right-hand side from f_old to f_new at the current state is small
 * against the integrator's tolerances: its effect over one mean integrator step,
 * h_int |f_new - f_old|, has a weighted RMS norm (weights rtol |y| + atol) of at most 1. */
int hg_stepping_jump_small(const hg_runtime *rt, const hg_setup *s, const double *f_old,
                           const double *f_new);

/* Whether the integrator may step past the end of this step (hg_solver_advance's pass): the
 * inputs are held (no derivatives) and have been for a few steps, so that the next step will
 * most likely continue on the same right-hand side. */
int hg_stepping_may_pass(const hg_runtime *rt);

/* The longest integrator step of this communication step of h_comm [s] (0: no limit). */
double hg_stepping_step_limit(const hg_runtime *rt, const hg_setup *s, double h_comm);

/* 1 when contact changes are root events (the exact dead zone of the varying mesh). */
int hg_stepping_contact_events(const hg_dyn_params *p);

/* The root functions: g[0..1] the backlash edges, g[2..3] the window ends. */
#define HG_STEPPING_N_ROOTS 4
void hg_stepping_roots(const hg_runtime *rt, const hg_setup *s, const double *y, double *g);

/* A contact change (dir[0], dir[1] of the roots, +1 upwards, -1 downwards). */
void hg_stepping_contact_event(hg_runtime *rt, const hg_setup *s, const int *dir,
                               const hg_logger *lg);

/* The end of an averaging window: eta_cycle and P_loss_cycle over it. */
void hg_stepping_window_event(hg_runtime *rt, const hg_logger *lg);

/* The end of a step of h at t_end: the final inputs u0 + du h (the very bits a host computes
 * when it continues a ramp: then the next step's inputs do not jump), and a warning once when
 * the map level leaves its grid. */
void hg_stepping_end(hg_runtime *rt, const hg_setup *s, double t_end, double h,
                     const hg_logger *lg);

#endif
