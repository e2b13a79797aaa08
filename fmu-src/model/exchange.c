/* The model for a host's integrator: see exchange.h. */
#include "model/exchange.h"

#include <math.h>
#include <string.h>

#include "model/friction_table_policy.h"
#include "model/model_object.h"

/* variables.toml's [[state]] list is the model's state vector, in its order (generate.py) */
typedef char hg_state_order_check[HG_STATE_ORDER_OK && HG_NUM_STATES == HG_NY &&
                                          HG_NUM_EVENT_INDICATORS == HG_STEPPING_N_ROOTS
                                      ? 1
                                      : -1];

/* Keys the friction tables on the operating point of the current state (built again when the
 * key moves) and puts the right-hand side on them, or on the direct solve near standstill. */
static void key_tables(hg_model *m)
{
    int rebuild = hg_ftp_stale(m->tables, &m->rt, &m->s.p, &m->rt.u0);
    hg_ftp_begin(m->tables, &m->rt, &m->s, rebuild, &m->log);
}

/* Whether key_tables would change the right-hand side: a new key or a switch to or from the
 * direct solve (tried on a copy of the runtime, whose key it may move). */
static int tables_due(const hg_model *m)
{
    hg_runtime probe = m->rt;
    int use = m->tables && hg_ft_speed_tabulated(probe.y[HG_Y_W_P]);
    return hg_ftp_stale(m->tables, &probe, &m->s.p, &probe.u0) ||
           use != (m->s.p.tables != NULL);
}

void hg_exchange_begin(hg_model *m, const hg_vars *v)
{
    hg_exchange_inputs(m, v);
    key_tables(m);
}

void hg_exchange_inputs(hg_model *m, const hg_vars *v)
{
    hg_runtime *rt = &m->rt;
    hg_vars_inputs(v, &rt->u0);
    memset(&rt->du, 0, sizeof rt->du);
    rt->t_u0 = rt->t; /* no step: nothing is extrapolated, T_wheel is T_w_out */
    hg_stepping_wheel_input(rt, &m->s, &rt->u0, &rt->du);
    rt->u_end = rt->u0;
    hg_model_outputs_stale(m);
}

void hg_exchange_set_time(hg_model *m, double t)
{
    m->rt.t = m->rt.t_u0 = t; /* the inputs are held: u0 applies at any time */
    hg_model_outputs_stale(m);
}

void hg_exchange_set_states(hg_model *m, const double *x)
{
    memcpy(m->rt.y, x, sizeof m->rt.y);
    hg_model_outputs_stale(m);
}

void hg_exchange_states(const hg_model *m, double *x) { memcpy(x, m->rt.y, sizeof m->rt.y); }

int hg_exchange_derivatives(hg_model *m, double *dx)
{
    hg_runtime *rt = &m->rt;
    hg_dyn_eval ev;
    int k;
    hg_dyn_evaluate(&m->s.p, &rt->u0, rt->mode, rt->y, 0, rt->T_c_warm, &ev);
    hg_dyn_derivatives(&m->s.p, &rt->u0, rt->y, &ev, dx);
    for (k = 0; k < HG_NY; k++)
        if (!isfinite(dx[k])) return k;
    return -1;
}

void hg_exchange_indicators(const hg_model *m, double *z)
{
    hg_stepping_roots(&m->rt, &m->s, m->rt.y, z);
}

void hg_exchange_nominals(const hg_model *m, double *nominal)
{
    int k;
    for (k = 0; k < HG_NY; k++) nominal[k] = m->s.atol[k] / m->s.rtol;
}

int hg_exchange_step_done(hg_model *m)
{
    hg_stepping_end(&m->rt, &m->s, m->rt.t, 0.0, &m->log); /* the map's range warning */
    return hg_stepping_wrap_due(&m->rt, &m->s) || tables_due(m);
}

/* The contact mode the deflection x has reached: the flank it lies beyond, or on an edge the one
 * it moves towards (xdot), the current one when it rests there. */
static int contact_mode(double x, double xdot, double b, int mode)
{
    if (x > b || (x == b && (xdot > 0.0 || (xdot == 0.0 && mode == HG_MODE_DRIVE))))
        return HG_MODE_DRIVE;
    if (x < -b || (x == -b && (xdot < 0.0 || (xdot == 0.0 && mode == HG_MODE_BACK))))
        return HG_MODE_BACK;
    return HG_MODE_FREE;
}

/* A contact change as the model's own integrator reports it: the roots of x - b (dir[0]) and of
 * x + b (dir[1]) crossed between the old and the new mode, +1 upwards, -1 downwards. The host's
 * state stays as it is (no snap of x to the edge). */
static void contact_event(hg_model *m)
{
    hg_runtime *rt = &m->rt;
    double dx[HG_NY], x = rt->y[HG_Y_X];
    int mode, dir[HG_STEPPING_N_ROOTS] = {0, 0, 0, 0};
    if (!hg_stepping_contact_events(&m->s.p)) return;
    hg_exchange_derivatives(m, dx);
    mode = contact_mode(x, dx[HG_Y_X], m->s.p.backlash.b, rt->mode);
    if (mode == rt->mode) return;
    dir[0] = (mode == HG_MODE_DRIVE) - (rt->mode == HG_MODE_DRIVE);
    dir[1] = (rt->mode == HG_MODE_BACK) - (mode == HG_MODE_BACK);
    hg_stepping_contact_event(rt, &m->s, dir, &m->log);
    rt->y[HG_Y_X] = x;
}

void hg_exchange_event(hg_model *m, int *states_changed)
{
    hg_runtime *rt = &m->rt;
    double z[HG_STEPPING_N_ROOTS];
    double phi_p = rt->y[HG_Y_PHI_P];
    contact_event(m);
    hg_stepping_roots(rt, &m->s, rt->y, z);
    if (z[2] >= 0.0 || z[3] <= 0.0) hg_stepping_window_event(rt, &m->log);
    hg_stepping_wrap(rt, &m->s);
    *states_changed = rt->y[HG_Y_PHI_P] != phi_p;
    key_tables(m);
    hg_model_outputs_stale(m);
}
