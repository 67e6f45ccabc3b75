/* problems_internal.h — what the registry (problems.c) and the problem files
 * (problem_<id>.c) share: the problem object they fill together and the
 * setup function of each row of problems.def.
 *
 * problems.c parses the parameters, allocates the object and calls the row's
 * setup, which sets the dimension, the Hamiltonian (ctx = the problem), the
 * initial value and the rest below; everything not set stays zero/NULL
 * (no Lagrangian, no invariants, no reference). */
#ifndef VIGEN_PROBLEMS_INTERNAL_H
#define VIGEN_PROBLEMS_INTERNAL_H

#include <vigen/problems.h>
#include <vigen/nbody.h>

typedef double (*vigen_pbi_invariant_fn)(const vigen_problem *pb, size_t k, double t, const double *q,
                                   const double *p);
typedef int (*vigen_pbi_reference_fn)(const vigen_problem *pb, double t, double *q, double *p);

enum { PBI_MAX_PARAMS = 8 };

struct vigen_problem {
    const vigen_problem_info *info;
    double param[PBI_MAX_PARAMS]; /* values, in the order of info->params */
    size_t dim;
    vigen_hamiltonian ham;        /* ctx = this problem */
    vigen_lagrangian lag;         /* dim 0: none; ctx = this problem */
    vigen_lgrad_fn legendre_inverse;
    double t0, *q0, *p0;          /* dim each, allocated by vigen_pbi_set_dim */
    double period, default_time;
    size_t ninvariants;
    const char *const *invariant_names;
    vigen_pbi_invariant_fn invariant;
    vigen_pbi_reference_fn reference;
    void *data;                   /* the problem's own, freed with free() */
    /* The Kepler splitting (split NULL: none): fills out for the coordinates
     * (VIGEN_NBODY_JACOBI or _DEMOCRATIC; VIGEN_EINVAL when not offered),
     * and changes a state between the problem's coordinates and the split
     * problem's (to_split 1: (q, p) -> (qs, ps); 0: back). */
    int (*split)(vigen_problem *pb, int coords, vigen_split_problem *out);
    int (*split_convert)(const vigen_problem *pb, int to_split, const double *q, const double *p, double *qs,
                         double *ps);
    int split_coords;             /* the coordinates of the last vigen_problem_split */
    vigen_nbody *nbody;           /* the N-body system of the splitting, or NULL */
};

/* Allocates q0 and p0 (dim entries each, zeroed) after setting pb->dim;
 * VIGEN_ENOMEM when memory runs out (initial_value.c). */
int vigen_pbi_set_dim(vigen_problem *pb, size_t dim);

/* Unit mass (mechanics.c): out = v (dim entries), for dL/dv, dH/dp and the
 * inverse Legendre map; the identity and the zero dim x dim blocks, for
 * d2L/dv2 and d2L/dqdv.  ctx is the problem. */
void vigen_pbi_copy_v(double t, const double *q, const double *v, double *out, void *ctx);
void vigen_pbi_unit_block(double t, const double *q, const double *v, double *out, void *ctx);
void vigen_pbi_zero_block(double t, const double *q, const double *v, double *out, void *ctx);

/* Sets the Hamiltonian H = |p|^2/2 + V(q) (given H and dH/dq; dim set
 * before) with its Hessian, its Lagrangian |v|^2/2 - V(q) with
 * d2L/dq2 = -d2V/dq2 as given, and the identity as inverse Legendre map. */
void vigen_pbi_unit_mass(vigen_problem *pb, vigen_grad_fn dHdq, double (*H)(double, const double *, const double *, void *),
                   vigen_lhess_fn d2Ldq2);

/* The Hessian of a separable H = T(p) + V(q) (vigen_hess_fn layout, 2 dim
 * square) with d2V/dq2 = -pb->lag.d2Ldq2 and every other block zero; the
 * caller fills d2T/dp2. */
void vigen_pbi_separable_hessian(const vigen_problem *pb, double t, const double *q, double *out);

/* The Kepler splitting of an N-body problem whose state is inertial
 * positions and momenta m_i v_i (nbody_split.c): makes pb->nbody from the
 * masses and sets pb->split and pb->split_convert.  VIGEN_SUCCESS or
 * VIGEN_ENOMEM. */
int vigen_pbi_nbody_split_setup(vigen_problem *pb, size_t n, double G, const double *mass);

#define PBI_PI 3.14159265358979323846

#define PARAM(...)
#define PROBLEM(id, name, description, ...) int vigen_pbi_##id##_setup(vigen_problem *pb);
#include "problems.def"
#undef PROBLEM
#undef PARAM

#endif
