/* nbody_internal.h — the N-body system as its files share it: the masses,
 * the constants of the Jacobi splitting computed once, and the scratch
 * memory of the flows (so that a flow allocates nothing). */
#ifndef VIGEN_NBODY_INTERNAL_H
#define VIGEN_NBODY_INTERNAL_H

#include <vigen/nbody.h>

struct vigen_nbody {
    size_t n;        /* bodies */
    double G;
    double *m;       /* n masses */
    double mtot;     /* M = sum m */
    double *interior; /* M_i = m_0 + ... + m_i */
    double *frac;    /* m_i / M_i (Jacobi), frac[0] = 1 */
    double *mred;    /* m'_i = m_i M_{i-1} / M_i, i >= 1 (mred[0] = M) */
    double *mu;      /* G M_i: the Kepler constant of Jacobi body i */
    double *work;    /* 15 n doubles of scratch for the flows */
    double *saved;   /* 6 n doubles: the state before a corrector */
    double *gjac;    /* G m_i M_{i-1}: the Jacobi term of body i (gjac[0] = 0) */
    double *geo;     /* VIGEN_NBODY_GEO(n) doubles of scratch for the interaction's geometry
                      * above 32 bodies, allocated by the first gradient flow (O(n^2): only
                      * the systems that use that flow pay for it), else NULL */
};

/* Pair forces f_i = -dV/dx_i of V = -sum G m_i m_j/|x_i - x_j| over the
 * pairs i < j with i >= from, the pair (0, 1) left out when skip01 (nbody.c). */
void vigen_nbody_pair_forces(const vigen_nbody *sys, const double *x, double *f, size_t from, int skip01);

/* The force of the Jacobi interaction, f = -dH_interaction/dq (3n
 * entries, f_0 = 0), and the inertial positions x of q on the way
 * (nbody.c).  geo, when not NULL, receives the geometry of the terms
 * (VIGEN_NBODY_GEO(n) doubles) for vigen_nbody_jacobi_pair_hessian and
 * the Hessian of the Jacobi terms: 5 per pair (d = x_j - x_i, k = G m_i
 * m_j/|d|^3, 3/|d|^2), pairs i < j without (0, 1) in row order, then 2
 * per body i >= 2 (k = G m_i M_{i-1}/|q_i|^3, 3/|q_i|^2). */
void vigen_nbody_jacobi_interaction_force(const vigen_nbody *sys, const double *q, double *x, double *f, double *geo);
#define VIGEN_NBODY_GEO(n) (5 * ((n) * ((n) - 1) / 2 - 1) + 2 * (n))

/* df = -Hess(V) u for the pairs of geo (vigen_nbody_jacobi_interaction_force). */
void vigen_nbody_jacobi_pair_hessian(const vigen_nbody *sys, const double *geo, const double *u, double *df);

/* The linear maps of the changes of coordinates (nbody.c), positions and
 * momenta apart: q' = A x (also velocities: dq'/dt = A dx/dt) and
 * p' = A^-T p (also forces), and their inverses; in place allowed. */
void vigen_nbody_jacobi_positions(const vigen_nbody *sys, const double *x, double *q);
void vigen_nbody_jacobi_positions_inverse(const vigen_nbody *sys, const double *q, double *x);
void vigen_nbody_jacobi_momenta(const vigen_nbody *sys, const double *p, double *pj);
void vigen_nbody_jacobi_momenta_inverse(const vigen_nbody *sys, const double *pj, double *p);
void vigen_nbody_democratic_positions(const vigen_nbody *sys, const double *x, double *q);
void vigen_nbody_democratic_positions_inverse(const vigen_nbody *sys, const double *q, double *x);
void vigen_nbody_democratic_momenta(const vigen_nbody *sys, const double *p, double *pd);
void vigen_nbody_democratic_momenta_inverse(const vigen_nbody *sys, const double *pd, double *p);

#endif
