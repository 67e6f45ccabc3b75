/* vigen/ensemble.h — ensembles: many independent trajectories of one problem
 * spread over the cores (OpenMP), and the batched problem types of the
 * steppers emitted with `vigen emit --batch` (docs/ensembles.md).
 *
 * Double precision only.
 */
#ifndef VIGEN_ENSEMBLE_H
#define VIGEN_ENSEMBLE_H

#include <stddef.h>
#include "vigen/runtime.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- an ensemble over the cores ----------------------------------------- */
/* What every trajectory of the ensemble is integrated with.  One workspace
 * is made per thread: by alloc(alloc_ctx) when alloc is set, else by
 * type->clone(prototype) when prototype is set (any integrator: an emitted
 * stepper's workspace from NAME_alloc_mechanical, a Lagrangian integrator,
 * a Poincare-transformed stepper), else by type->alloc(sys, opt). */
typedef struct {
    const vigen_stepper_type *type;   /* the integrator: NAME_type, vigen_hp_type, ... */
    const vigen_hamiltonian *sys;     /* the problem (NULL when alloc or prototype is set) */
    const vigen_solver_options *opt;  /* NULL = defaults (only with sys) */
    void *(*alloc)(void *alloc_ctx);  /* optional workspace maker */
    void *alloc_ctx;
    size_t dim;                       /* dimension of q and p; 0 = sys->dim, or
                                         type->dim(prototype) */
    int threads;                      /* 0 = OpenMP's default (OMP_NUM_THREADS, else
                                         every core); 1 = serial */
    const void *prototype;            /* a workspace of type to clone (only read; it
                                         steps no trajectory) */
} vigen_ensemble;

/* Integrates ntraj trajectories of the problem, each nsteps steps of size h
 * with the same stepper: trajectory i starts at t[i], q[i dim .. i dim +
 * dim - 1], p[i dim ...] and ends there.  Every trajectory starts with a
 * reset workspace, so that its result is the bits of a fresh workspace
 * stepping it alone (vigen_integrate), whatever the number of threads and
 * whichever thread runs it; the trajectories are shared among the threads
 * in contiguous blocks (a static schedule).
 *
 * status[i] (ntraj entries) receives the trajectory's status, steps[i]
 * (ntraj entries, may be NULL) the steps it took; a trajectory that fails
 * stays at its last good step and the others go on.  Returns VIGEN_SUCCESS
 * when every trajectory succeeded, else the status of the failed trajectory
 * of lowest index; VIGEN_EINVAL (a NULL pointer or type, no dimension, h
 * not finite) and VIGEN_ENOMEM (a workspace could not be made) before any
 * trajectory is touched, status[] then untouched too (also for a type
 * without reset, or without clone when prototype is the source).  Built without
 * OpenMP, the runtime runs the trajectories one after the other (same
 * results). */
int vigen_integrate_ensemble(const vigen_ensemble *e, size_t ntraj, double *t, double *q, double *p, double h,
                             unsigned long nsteps, int *status, unsigned long *steps);

/* The number of threads an ensemble with threads = 0 uses: OpenMP's
 * default, or 1 when the runtime was built without OpenMP. */
int vigen_ensemble_max_threads(void);

/* ---- batched problems (steppers emitted with --batch) -------------------- */
/* W trajectories side by side in structure-of-arrays layout: component k of
 * trajectory j at x[k W + j]; t[j] is trajectory j's time.  A batched
 * gradient or force fills out[k W + j] for every k < dim and j < W, so that
 * its loops run across trajectories (vectorised by the compiler). */
typedef void (*vigen_grad_batch_fn)(const double *t, const double *q, const double *p, double *out, size_t W,
                                    void *ctx);
typedef void (*vigen_force_batch_fn)(const double *t, const double *q, double *f, size_t W, void *ctx);

/* H(t, q, p) given by its gradients (the batched steppers need an explicit
 * path, hence a separable H: dHdq ignores p, dHdp ignores t and q). */
typedef struct {
    size_t dim;
    vigen_grad_batch_fn dHdq, dHdp;
    void *ctx;
} vigen_hamiltonian_batch;

/* H = 1/2 p^T M^-1 p + V(t, q), M diagonal, f = -dV/dq. */
typedef struct {
    size_t dim;
    vigen_force_batch_fn force;
    void *ctx;
    const double *inv_mass;           /* dim entries of diag(M^-1); NULL = identity */
} vigen_mechanical_batch;

#ifdef __cplusplus
}
#endif

#endif
