/* The model as an ordinary differential equation for a host's integrator (FMI Model Exchange):
 * the host owns the time and the state vector (hg_dyn's y, HG_NY states) and integrates the
 * derivatives; the model says where its right-hand side changes (event indicators: the backlash's
 * two contact edges and the averaging window's two ends, hg_stepping_roots) and what it does
 * there (the contact mode, the window's efficiency), and asks for an event after an integrator
 * step that left the friction tables' key or needs the pinion angle wrapped, which it then does.
 * The inputs are held between the host's settings (no derivatives). The model's own integrator
 * is not used. Knows nothing of FMI. */
#ifndef HG_EXCHANGE_H
#define HG_EXCHANGE_H

#include "model/hypoid.h"

/* Hands the model over to the host's integrator after hg_model_setup or hg_model_restore, with
 * the inputs of v: keys the friction tables on the current state. */
void hg_exchange_begin(hg_model *m, const hg_vars *v);

/* The inputs of v changed; the time; the state vector (x: HG_NY values, in hg_dyn's order). */
void hg_exchange_inputs(hg_model *m, const hg_vars *v);
void hg_exchange_set_time(hg_model *m, double t);
void hg_exchange_set_states(hg_model *m, const double *x);
void hg_exchange_states(const hg_model *m, double *x);

/* dx/dt at the current time, state and inputs. Returns the index of the first derivative that is
 * not finite, or -1. */
int hg_exchange_derivatives(hg_model *m, double *dx);

/* The event indicators (HG_STEPPING_N_ROOTS values): an event is due where one changes sign. */
void hg_exchange_indicators(const hg_model *m, double *z);

/* The scale of each state: its absolute tolerance over the relative one (atol_k / rtol of the
 * model's parameters), so that a host that takes rtol * nominal as its absolute tolerance
 * weighs the states as the model's own integrator does. */
void hg_exchange_nominals(const hg_model *m, double *nominal);

/* After an integrator step of the host ended at the current time and state: 1 when an event is
 * due (the friction tables' key no longer covers the operating point, or the angle must wrap). */
int hg_exchange_step_done(hg_model *m);

/* The event at the current time and state: the contact mode the deflection has reached, the end
 * of an averaging window, the angle's wrap and the friction tables' key. *states_changed: the
 * state vector changed (the wrap), the host must read it again. */
void hg_exchange_event(hg_model *m, int *states_changed);

#endif
