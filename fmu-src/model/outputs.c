/* The model's outputs: see outputs.h. */
#include "model/outputs.h"

#include <string.h>

static void write_pairs(hg_vars *v, const hg_dyn_eval *ev)
{
    int k;
    for (k = 0; k < HG_MAX_PAIRS; k++) {
        const hg_pair_friction *f = &ev->pair[k];
        v->pair_W[k] = ev->W_pair[k];
        v->pair_mu[k] = f->mu;
        v->pair_F_v[k] = f->F_v;
        v->pair_F_b[k] = f->F_b;
        v->pair_h_c[k] = f->h_c;
        v->pair_lambda[k] = f->lambda;
        v->pair_T_c[k] = f->T_c;
        v->pair_u_e[k] = f->u_e;
        v->pair_V_s[k] = f->V_s;
        v->pair_R_e[k] = f->R_e;
        v->pair_R_s[k] = f->R_s;
        v->pair_p_h[k] = f->p_h;
        v->pair_g_V[k] = f->g_V;
        v->pair_g_E[k] = f->g_E;
    }
}

static int clamp_int(long n) { return n > 2147483647L ? 2147483647 : (int)n; }

/* The contact output: the event-tracked mode, or the one the deflection says. */
static int contact(const hg_dyn_params *p, const hg_runtime *rt, const hg_dyn_eval *ev)
{
    if (hg_stepping_contact_events(p)) return rt->mode;
    if (p->mesh == HG_MESH_MODEL_VARYING) return hg_backlash_mode(rt->y[HG_Y_X], p->backlash.b);
    return ev->W_t >= 0.0 ? HG_MODE_DRIVE : HG_MODE_BACK;
}

/* Speeds, deflection, mesh load and torques, contact and the integrator's counters. */
static void write_motion(const hg_setup *s, const hg_runtime *rt, const hg_dyn_eval *ev,
                         long steps, long evals, hg_vars *v)
{
    const double *y = rt->y;
    v->w_s = hg_dyn_input_speed(&s->p, y);
    v->w_p = y[HG_Y_W_P];
    v->w_g = y[HG_Y_W_G];
    v->w_w = y[HG_Y_W_W];
    v->DTE = y[HG_Y_X];
    v->DTE_elastic = s->p.mesh == HG_MESH_MODEL_RIGID ? 0.0 : ev->f; /* eq. 24: f(x) */
    v->W_t = ev->W_t;
    v->T_fp = ev->T_fp;
    v->T_fg = ev->T_fg;
    v->T_w_out = ev->T_w;
    v->T_wheel = s->p.half_shaft ? hg_stepping_wheel_torque(rt, ev->T_w) : ev->T_w;
    v->k_m = ev->mesh.k_m;
    v->contact = contact(&s->p, rt, ev);
    v->n_impacts = rt->n_impacts;
    v->solver_steps = clamp_int(steps);
    v->rhs_evals = clamp_int(evals);
}

/* Power, losses and efficiency of the flanks and of the axle, and the oil's heat balance (the
 * split of P_loss is hg_outputs_pairs'). */
static void write_losses(const hg_runtime *rt, const hg_dyn_eval *ev, hg_vars *v)
{
    v->P_loss = ev->P_loss;
    v->P_in = ev->P_in;
    v->eta = ev->eta;
    v->eta_cycle = rt->eta_cycle;
    v->P_loss_cycle = rt->P_loss_cycle;
    v->P_churn = ev->axle.P_churn;
    v->P_bearings = ev->axle.P_bearings;
    v->P_bearings_p = ev->axle.P_bearings_p;
    v->P_bearings_g = ev->axle.P_bearings_g;
    v->F_pre_p_T = ev->axle.F_pre_p;
    v->F_pre_g_T = ev->axle.F_pre_g;
    v->nu_oil = ev->axle.nu;
    v->P_seals = ev->axle.P_seals;
    v->P_axle = ev->P_axle;
    v->P_in_axle = ev->P_in_axle;
    v->eta_axle = ev->eta_axle;
    v->eta_axle_cycle = rt->eta_axle_cycle;
    v->T_oil = ev->T_oil;
    v->Q_dot_housing = ev->Q_dot;
}

/* The energy audit: the integrals carried as states and the stored energy. */
static void write_energy(const hg_setup *s, const double *y, const hg_dyn_eval *ev, hg_vars *v)
{
    v->E_in = y[HG_Y_E_IN];
    v->E_out = y[HG_Y_E_OUT];
    v->E_friction = y[HG_Y_E_FRIC];
    v->E_damping = y[HG_Y_E_DAMP];
    v->E_excitation = y[HG_Y_E_EXC];
    v->E_stored = hg_dyn_stored_energy(&s->p, y, ev);
    v->Q_housing = y[HG_Y_Q_H];
    v->E_churn = y[HG_Y_E_CHURN];
    v->E_bearings = y[HG_Y_E_BEAR];
    v->E_seals = y[HG_Y_E_SEAL];
}

/* The state's evaluation: what its right-hand side computes (all_pairs 0: the friction table when
 * the state ran on one), or every pair's friction model solved directly (all_pairs 1). */
static void evaluate(const hg_setup *s, const hg_runtime *rt, int all_pairs, hg_dyn_eval *ev)
{
    hg_inputs u;
    double warm[HG_MAX_PAIRS];
    memcpy(warm, rt->T_c_warm, sizeof warm); /* outputs must not perturb the integration */
    hg_stepping_inputs_at(rt, rt->t, &u);
    hg_dyn_evaluate(&s->p, &u, rt->mode, rt->y, all_pairs, warm, ev);
}

void hg_outputs_main(const hg_setup *s, const hg_runtime *rt, long steps, long evals, hg_vars *v)
{
    hg_dyn_eval ev;
    evaluate(s, rt, 0, &ev);
    write_motion(s, rt, &ev, steps, evals, v);
    write_losses(rt, &ev, v);
    write_energy(s, rt->y, &ev, v);
}

void hg_outputs_states(const hg_runtime *rt, hg_vars *v)
{
    int k;
    for (k = 0; k < HG_NY; k++) {
        const hg_var_info *info = &hg_var_table[hg_state_vr[k]];
        if (info->causality == HG_LOCAL) *(double *)hg_var_ptr(v, info) = rt->y[k];
    }
}

void hg_outputs_derivatives(const hg_setup *s, const hg_runtime *rt, hg_vars *v)
{
    hg_dyn_eval ev;
    hg_inputs u;
    double ydot[HG_NY];
    int k;
    evaluate(s, rt, 0, &ev);
    hg_stepping_inputs_at(rt, rt->t, &u);
    hg_dyn_derivatives(&s->p, &u, rt->y, &ev, ydot);
    for (k = 0; k < HG_NY; k++)
        *(double *)hg_var_ptr(v, &hg_var_table[hg_derivative_vr[k]]) = ydot[k];
}

void hg_outputs_pairs(const hg_setup *s, const hg_runtime *rt, hg_vars *v)
{
    hg_dyn_eval ev;
    evaluate(s, rt, 1, &ev);
    write_pairs(v, &ev);
    /* the direct solves' viscous share of the flank loss, applied to P_loss */
    v->P_loss_viscous = ev.P_loss > 0.0 ? v->P_loss * (ev.P_visc / ev.P_loss) : 0.0;
    v->P_loss_boundary = v->P_loss - v->P_loss_viscous;
}
