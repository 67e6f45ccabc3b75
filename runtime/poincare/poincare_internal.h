/* poincare_internal.h — the transformed problem's object, shared by the
 * driver (poincare.c) and the stepper type (poincare_stepper.c); internal
 * to the runtime. */
#ifndef VIGEN_POINCARE_INTERNAL_H
#define VIGEN_POINCARE_INTERNAL_H

#include <vigen/poincare.h>

struct vigen_poincare {
    vigen_poincare_problem pb;
    size_t n;                  /* dimension of q; K has n + 1 */
    vigen_hamiltonian K;
    vigen_poincare_stats stats;
    /* the common part of both gradients of K at the point (cq, cp):
     * hpe = H + e, g and its gradient; cache_status its verdict */
    double *cq, *cp, *dgdq, *dgdp;
    double hpe, g, dgdt;
    int cache_ok, cache_status;
    int err;                   /* first density failure seen inside a step */
    /* the trajectory: extended state, fictive time, the physical time reported */
    double *Q, *P, *Qs, *Ps;
    double tau, t_rep;
    int have;
    char msg[256];
};


/* Continues the trajectory when (t, q, p) is the state last reported
 * (pc->t_rep and the first n entries of Q, P), else starts a new one from
 * it (level e = -H, fictive time 0).  VIGEN_SUCCESS or the start's status,
 * with its message. */
int vigen_poincare_begin(vigen_poincare *pc, double t, const double *q, const double *p);

/* One fictive step dtau of the extended state (Q, P, tau) with the
 * workspace w of T.  On failure the stepper left them unchanged; the status
 * is the density's when it failed inside the step, with a message. */
int vigen_poincare_fictive_step(vigen_poincare *pc, const vigen_stepper_type *T, void *w, double dtau);

#endif
