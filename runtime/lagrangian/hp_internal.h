/* hp_internal.h — what the trapezoidal variational integrator uses of the
 * Hamilton–Pontryagin stepper (internal to the runtime): a step between two
 * given times, so that a grid's times are used as given rather than
 * re-accumulated from steps, write access to the statistics, and the flow
 * its stepper type offers. */
#ifndef VIGEN_HP_INTERNAL_H
#define VIGEN_HP_INTERNAL_H

#include <vigen/lagrangian.h>

/* One step from (q, p) at t0 to t1 with step h (the caller's t1 - t0, or its
 * own h with t1 its compensated t0 + h).  Same contract as vigen_hp_step,
 * with the time left to the caller.  positions_only: the caller computed p
 * from positions (a two-step form), so the predictor may continue from the
 * last step when t0 and q match it, but compensations do not carry over. */
int vigen_hp_step_between(vigen_hp *w, double t0, double t1, double h, double *q, double *p,
                          int positions_only);
vigen_stats *vigen_hp_stats_rw(vigen_hp *w);
/* The flow at (t, q, p) for the stepper types (lfield_internal.h), Newton
 * started from the last step's velocity. */
int vigen_hp_vector_field(vigen_hp *w, double t, const double *q, const double *p, double *dq, double *dp);

#endif
