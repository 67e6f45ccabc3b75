/* vigen/problems.h — the collection of standard test problems (library
 * vigen_problems, beside the runtime): Hamiltonian, gradients, a standard
 * initial value, invariants, and a reference solution where one is known.
 *
 *     vigen_problem *pb;
 *     char why[200];
 *     if (vigen_problem_create(&pb, "kepler", "e=0.9", why, sizeof why) != VIGEN_SUCCESS)
 *         { fprintf(stderr, "%s\n", why); ... }
 *     const vigen_hamiltonian *H = vigen_problem_hamiltonian(pb);
 *     size_t dim = vigen_problem_dim(pb);          (fput: n; outer-solar-system: 18)
 *     double t, *q = malloc(dim * sizeof *q), *p = malloc(dim * sizeof *p);
 *     vigen_problem_initial(pb, &t, q, p);
 *     ... integrate with any stepper ...
 *     double dE = vigen_problem_energy(pb, t, q, p) - E0;
 *     vigen_problem_free(pb);
 *
 * Names (the registry, one row per problem): kepler, pendulum,
 * harmonic-oscillator, henon-heiles, fput, outer-solar-system,
 * point-vortices, charged-particle, jupiter-saturn.
 */
#ifndef VIGEN_PROBLEMS_H
#define VIGEN_PROBLEMS_H

#include <stddef.h>
#include <vigen/runtime.h>
#include <vigen/lagrangian.h>
#include <vigen/nbody.h>

#ifdef __cplusplus
extern "C" {
#endif

/* One parameter of a problem: its name, default and meaning. */
typedef struct {
    const char *name;          /* "e" */
    double default_value;      /* 0.6 */
    const char *description;   /* "eccentricity, 0 <= e < 1" */
} vigen_problem_param;

/* What the registry says about a problem, without creating it. */
typedef struct {
    const char *name;                  /* "kepler" */
    const char *description;           /* one line */
    const vigen_problem_param *params; /* nparams entries */
    size_t nparams;
} vigen_problem_info;

/* The problems of the collection: how many, the i-th (in the order of
 * problems.def), and one by name. */
size_t vigen_problem_count(void);
const vigen_problem_info *vigen_problem_info_at(size_t i);      /* NULL past the end */
const vigen_problem_info *vigen_problem_info_find(const char *name); /* NULL if unknown */

typedef struct vigen_problem vigen_problem;

/* Creates problem `name` with parameters "k=v,k=v" (NULL or "" = defaults).
 * On an unknown name, an unknown or malformed parameter or a value out of
 * range returns VIGEN_EINVAL and writes a one-line reason naming the problem
 * or parameter and what is accepted into why (may be NULL); VIGEN_ENOMEM when
 * memory runs out. */
int vigen_problem_create(vigen_problem **out, const char *name, const char *params, char *why,
                         size_t why_size);
void vigen_problem_free(vigen_problem *pb);

/* What a created problem is: its collection entry, the value of one of its
 * parameters, its dimension. */
const vigen_problem_info *vigen_problem_info_of(const vigen_problem *pb);
double vigen_problem_param_value(const vigen_problem *pb, const char *name); /* NaN if none */
size_t vigen_problem_dim(const vigen_problem *pb);                  /* dimension of q (= of p) */

/* The Hamiltonian (valid until vigen_problem_free); separable is set where
 * H = T(p) + V(q); hessian (for Newton's method) is given by every problem
 * but point-vortices and jupiter-saturn (there the stepper uses finite
 * differences). */
const vigen_hamiltonian *vigen_problem_hamiltonian(const vigen_problem *pb);
/* The Lagrangian formulation, for the integrators of <vigen/lagrangian.h>,
 * with inverse Legendre map g (v with dL/dv(q, v) = p) in *g when g is not
 * NULL; NULL when the problem has none (point vortices: degenerate). */
const vigen_lagrangian *vigen_problem_lagrangian(const vigen_problem *pb, vigen_lgrad_fn *g);

/* Standard initial value: t0, q0, p0 (dim entries each). */
void vigen_problem_initial(const vigen_problem *pb, double *t, double *q, double *p);
/* A characteristic time (period of the standard orbit, or of the linearised
 * motion) for --steps-per-period, and a default final time. */
double vigen_problem_period(const vigen_problem *pb);
double vigen_problem_default_time(const vigen_problem *pb);

/* H(t, q, p). */
double vigen_problem_energy(const vigen_problem *pb, double t, const double *q, const double *p);
/* Further invariants (angular momentum, momentum maps, Casimirs): count,
 * name ("angular-momentum") and value. */
size_t vigen_problem_invariant_count(const vigen_problem *pb);
const char *vigen_problem_invariant_name(const vigen_problem *pb, size_t k);
double vigen_problem_invariant(const vigen_problem *pb, size_t k, double t, const double *q,
                               const double *p);

/* Reference solution at time t from the standard initial value: 1 and (q, p)
 * written when the problem has one (exact, or computed to near full double
 * accuracy, as documented per problem), 0 otherwise. */
int vigen_problem_reference(const vigen_problem *pb, double t, double *q, double *p);

/* The Kepler splitting H = H_kepler + H_interaction (+ H_jump) of the
 * problems that have one (kepler: the whole H is the Kepler part, the
 * interaction is zero; outer-solar-system and jupiter-saturn: the N-body
 * splittings of <vigen/nbody.h>), for the splitting methods whose flows
 * are named "kepler", "interaction" (and "jump").  coordinates: NULL or
 * "jacobi", or "democratic-heliocentric" (N-body problems only).  Fills
 * *out (valid until vigen_problem_free; its flows may run on several
 * threads at once) and returns VIGEN_SUCCESS, or VIGEN_EINVAL with a
 * one-line reason in why (may be NULL) when the problem has no such
 * splitting.  The split problem's state is in its own coordinates:
 * vigen_problem_split_state changes a state between the problem's
 * coordinates (those of vigen_problem_initial, _energy, _invariant,
 * _reference) and the split problem's, to_split 1: (q, p) -> (qs, ps), 0:
 * back (the coordinates of the last vigen_problem_split).  The name of flow
 * k of the split problem is vigen_problem_split_flow_name (NULL past the
 * end, or before any split). */
int vigen_problem_split(vigen_problem *pb, const char *coordinates, vigen_split_problem *out, char *why,
                        size_t why_size);
const char *vigen_problem_split_flow_name(const vigen_problem *pb, size_t k);
int vigen_problem_split_state(const vigen_problem *pb, int to_split, const double *q, const double *p, double *qs,
                              double *ps);

#ifdef __cplusplus
}
#endif

#endif
