/* lfield_internal.h — the flow of a Lagrangian problem in (q, p), the
 * vector field of the Lagrangian integrators' stepper types (internal to
 * the runtime).
 *
 * At (t, q, p) the velocity v solves the inverse Legendre map
 * dL/dv(t, q, v) = p (Newton, lsolve_internal.h, with the runtime's
 * stopping rule: a solve that does not converge is an error status, never
 * a result), and then q' = v, p' = dL/dq(t, q, v): the Euler-Lagrange
 * equations d/dt dL/dv = dL/dq with p = dL/dv.  Each integrator keeps one
 * vigen_lfield, so that evaluating the flow touches nothing its steps read
 * (statistics included). */
#ifndef VIGEN_LFIELD_INTERNAL_H
#define VIGEN_LFIELD_INTERNAL_H

#include <vigen/lagrangian.h>
#include "lsolve_internal.h"

typedef struct {
    const vigen_lagrangian *lag;        /* the owner's copy */
    const vigen_solver_options *opt;    /* the owner's options */
    vigen_lsolve *inv;
    double *v;                          /* dim entries */
    double t;                           /* the point of the current solve */
    const double *q, *p;
    vigen_stats stats;                  /* the flow's own counts, never reported */
    vigen_stats *count;                 /* where the current solve counts */
} vigen_lfield;

/* Prepares f for lag and opt (both kept by pointer); VIGEN_ENOMEM. */
int vigen_lfield_init(vigen_lfield *f, const vigen_lagrangian *lag, const vigen_solver_options *opt);
void vigen_lfield_clear(vigen_lfield *f);

/* The v with dL/dv(t, q, v) = p into f->v: Newton from v_start (NULL =
 * zero), then from v = p when d2L/dv2 is singular at the first start.
 * Counts dL/dv calls (dHdp_evals) and the solver's work into *stats.
 * VIGEN_SUCCESS or the solver's status. */
int vigen_lfield_velocity(vigen_lfield *f, const double *v_start, double t, const double *q, const double *p,
                          vigen_stats *stats);

/* q' into dq and p' into dp at (t, q, p), Newton started from v_start (the
 * integrator's last velocity; dim entries), and from v = p when d2L/dv2 is
 * singular there.  VIGEN_SUCCESS, the solver's status (VIGEN_ESINGULAR,
 * VIGEN_ENOCONV, VIGEN_EMAXITER, VIGEN_ENONFINITE) or VIGEN_ENONFINITE for
 * a dL/dq that is not finite. */
int vigen_lfield_eval(vigen_lfield *f, const double *v_start, double t, const double *q, const double *p,
                      double *dq, double *dp);

#endif
