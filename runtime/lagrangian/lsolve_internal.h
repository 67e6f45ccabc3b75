/* lsolve_internal.h — the Newton solver shared by the Lagrangian integrators
 * (internal to the runtime, not installed).
 *
 * Solves a small square system r(x) = 0 by Newton's method with GSL LU, the
 * stopping rule of the emitted steppers (vigen_iter_judge on the relative
 * increment) and a Jacobian from the caller or from forward differences of
 * the residual.  The Jacobian is refreshed at every iteration while the
 * relative increment is above sqrt(tol) and kept (simplified Newton) below
 * it: there the frozen matrix is accurate enough to gain about as many
 * digits per iteration as full Newton would, and the two or three
 * iterations at round-off that the stopping rule needs cost one solve each
 * instead of a Jacobian (n residuals when it comes from differences).
 * Equations and unknowns are equilibrated (rows, then columns, scaled by
 * their largest entry) before the factorisation, so that the singularity
 * test — a pivot below 16 n epsilon — does not depend on their units.
 * A step that lands where the residual is not finite (a relativistic
 * velocity beyond c, a square root of a negative number) is halved, up to
 * ten times, until it is back in the finite region; such damped steps are
 * not shown to the stopping rule (a shrinking step towards the edge of the
 * region is no convergence), and a solve that keeps needing them until
 * max_iter gives VIGEN_ENONFINITE.  A residual that is not finite at the
 * starting point is VIGEN_ENONFINITE at once. */
#ifndef VIGEN_LSOLVE_H
#define VIGEN_LSOLVE_H

#include <stddef.h>
#include <vigen/runtime.h>

/* Residual r(x) (n entries). Returns VIGEN_SUCCESS, or a status (e.g.
 * VIGEN_ENONFINITE when a callback produced NaN/inf) that stops the solve. */
typedef int (*vigen_lsolve_residual_fn)(const double *x, double *r, void *ctx);
/* Jacobian J[i*n + j] = d r_i / d x_j at x; NULL = forward finite
 * differences of the residual (relative step opt->fd_step, default sqrt(eps)). */
typedef int (*vigen_lsolve_jacobian_fn)(const double *x, double *J, void *ctx);

typedef struct vigen_lsolve vigen_lsolve;
vigen_lsolve *vigen_lsolve_alloc(size_t n);     /* NULL for n == 0 or no memory */
void vigen_lsolve_free(vigen_lsolve *s);
/* Solves r(x) = 0 by Newton's method with GSL LU from the guess in x, stopping
 * with vigen_iter_judge on the relative increment (opt->tol, opt->max_iter;
 * opt NULL = defaults). On VIGEN_SUCCESS x holds the solution; on any error
 * (VIGEN_ESINGULAR, VIGEN_ENOCONV, VIGEN_EMAXITER, VIGEN_ENONFINITE, or the
 * callbacks' status) x is unspecified and the caller keeps its own state.
 * stats (may be NULL): iterations, last_iterations, max_iterations,
 * hessian_evals (Jacobians), lu_decompositions are updated. */
int vigen_lsolve_run(vigen_lsolve *s, double *x, vigen_lsolve_residual_fn r,
                     vigen_lsolve_jacobian_fn J, void *ctx,
                     const vigen_solver_options *opt, vigen_stats *stats);

/* The dimension n given to vigen_lsolve_alloc. */
size_t vigen_lsolve_dim(const vigen_lsolve *s);

/* 1 when x[0 .. n-1] are all finite (x - x is 0 exactly when x is), for the
 * checks of every Lagrangian integrator. */
int vigen_lsolve_finite(const double *x, size_t n);

#endif
