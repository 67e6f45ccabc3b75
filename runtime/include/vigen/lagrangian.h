/* vigen/lagrangian.h — variational integrators that start from a Lagrangian
 * L(t, q, v) instead of a Hamiltonian (double precision).
 *
 *   Hamilton–Pontryagin (HP) integrators, trapezoidal and midpoint discrete
 *   Lagrangians, with a velocity map phi_h(q_n, q_{n+1}; a)   vigen_hp_*
 *   the mid-point variational integrator as a discrete Hamiltonian system
 *   (Cresson–Safi), and its two-step position form           vigen_midpoint_vi_*
 *   the trapezoidal variational integrator on a non-uniform time grid
 *   (the leapfrog for L = 1/2 m v^2 - V), one-step and two-step forms and a
 *   driver over an array of times                             vigen_trapezoidal_vi_*
 *
 * The equations are those of docs/lagrangian.md.  Every stepper takes (t, q, p)
 * with p the discrete momentum (for a regular L, p = dL/dv), its own h on each
 * call, returns VIGEN_SUCCESS or a status code of <vigen/runtime.h>, and on
 * failure leaves t, q, p unchanged bit for bit.  Implicit equations are solved
 * by Newton's method (GSL LU) with the round-off-aware stopping rule of the
 * runtime; a solve that does not converge is an error, never a result.
 * Statistics use vigen_stats: dHdq_evals counts dL/dq calls, dHdp_evals dL/dv
 * calls (and, for vigen_midpoint_vi_step, calls of g), hessian_evals
 * Jacobians (user second derivatives or finite differences), lu_decompositions their factorisations, iterations Newton
 * iterations; steps and failed_steps as for the SPRK steppers (a two-step
 * call is one step); fsal_reuses stays 0.
 *
 * A workspace is not thread-safe; distinct workspaces are independent.
 *
 * Saved states (bit-for-bit restart), for each integrator X:
 *   size_t X_state_size(const X *w)      bytes of a saved state (0 for NULL)
 *   int X_state_get(const X *w, void *buf)   all that later steps depend on
 *       (compensation, predictor history, velocity-map parameters, the end
 *       of the last step, statistics) into buf, X_state_size bytes; save
 *       t, q, p with it
 *   int X_state_set(X *w, const void *buf)   that state into w, an
 *       integrator of the same kind, rule, dimension, number of parameters
 *       and options: the next step from the saved t, q, p is bit for bit the
 *       one the saved integrator would have taken.  VIGEN_ESTATE, w
 *       unchanged, for anything else, another format or runtime version, or
 *       a damaged buffer; VIGEN_EINVAL for a NULL pointer.
 * The buffer has the layout of an emitted stepper's (docs/emit.md).  The
 * problem itself (the callbacks and the velocity map) is not in it: give
 * the new integrator the same one.
 *
 * Stepper types: vigen_hp_type, vigen_midpoint_vi_type (its one-step map)
 * and vigen_trapezoidal_vi_type (its one-step map) drive a workspace of
 * each through the runtime's drivers: vigen_integrate, output at any time
 * (vigen_integrate_at), events (vigen_integrate_events), ensembles
 * (vigen_integrate_ensemble with the workspace as prototype) and restart.
 * Their alloc is NULL (they are made from a Lagrangian, not a Hamiltonian:
 * use X_alloc, or vigen_lagrangian_integrator_alloc, and clone); their
 * vector field is the flow of the Lagrangian in (q, p): v from the inverse
 * Legendre map dL/dv(t, q, v) = p by Newton (the runtime's stopping rule,
 * started from the last step's velocity; a solve that does not converge is
 * the driver's error status, never a result), q' = v, p' = dL/dq(t, q, v).
 * The continuous extension then has the error O(h^4), and output at any
 * time the order min(2, 4) = 2 of these integrators.  Evaluating the flow
 * leaves the integrator's statistics and later steps untouched.
 */
#ifndef VIGEN_LAGRANGIAN_H
#define VIGEN_LAGRANGIAN_H

#include <stddef.h>
#include <vigen/runtime.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---- the problem -------------------------------------------------------- */

/* dL/dq(t, q, v) or dL/dv(t, q, v), written into out[0 .. dim-1]. */
typedef void (*vigen_lgrad_fn)(double t, const double *q, const double *v, double *out, void *ctx);

/* A block of second derivatives of L at (t, q, v), dim x dim, row-major:
 *   d2Ldq2:  out[i*dim + j] = d^2 L / dq_i dq_j
 *   d2Ldv2:  out[i*dim + j] = d^2 L / dv_i dv_j
 *   d2Ldqdv: out[i*dim + j] = d^2 L / dq_i dv_j   (row i: derivative of (dL/dq)_i
 *                                                   with respect to v_j) */
typedef void (*vigen_lhess_fn)(double t, const double *q, const double *v, double *out, void *ctx);

typedef struct {
    size_t dim;
    vigen_lgrad_fn dLdq, dLdv;                                          /* required */
    double (*L)(double t, const double *q, const double *v, void *ctx); /* optional */
    void *ctx;
    /* Optional second derivatives for Newton's Jacobian; when any of the three
     * is NULL the Jacobian comes from finite differences of the gradients
     * (relative step vigen_solver_options.fd_step). */
    vigen_lhess_fn d2Ldq2, d2Ldv2, d2Ldqdv;
} vigen_lagrangian;

/* ---- velocity maps ------------------------------------------------------ */

/* phi_h(q0, q1; a) into v (dim).  Derivatives, row-major:
 *   D1phi: dim x dim, out[i*dim + j] = d phi_i / d q0_j
 *   D2phi: dim x dim, out[i*dim + j] = d phi_i / d q1_j
 *   Daphi: dim x m,   out[i*m + k]   = d phi_i / d a_k */
typedef void (*vigen_vmap_fn)(double h, const double *q0, const double *q1, const double *a,
                              double *out, void *ctx);

typedef struct {
    size_t dim;                 /* must equal the Lagrangian's dim */
    size_t nparams;             /* m, the number of parameters a (0 allowed) */
    vigen_vmap_fn phi, D1phi, D2phi;
    vigen_vmap_fn Daphi;        /* required when nparams > 0, ignored otherwise */
    const double *a0;           /* m initial values (the predictor of the first step);
                                   NULL = zeros */
    void *ctx;
} vigen_velocity_map;

/* ---- every integrator through its stepper type --------------------------- */

extern const vigen_stepper_type vigen_hp_type;
extern const vigen_stepper_type vigen_midpoint_vi_type;
extern const vigen_stepper_type vigen_trapezoidal_vi_type;

enum {
    VIGEN_LAGRANGIAN_HP_TRAPEZOIDAL = 0,   /* vigen_hp, VIGEN_HP_TRAPEZOIDAL, trivial map */
    VIGEN_LAGRANGIAN_HP_MIDPOINT = 1,      /* vigen_hp, VIGEN_HP_MIDPOINT, trivial map */
    VIGEN_LAGRANGIAN_MIDPOINT_VI = 2,      /* vigen_midpoint_vi (needs g) */
    VIGEN_LAGRANGIAN_TRAPEZOIDAL_VI = 3    /* vigen_trapezoidal_vi */
};

/* A workspace of the integrator `method` (above) for lag (g: the inverse
 * Legendre map, used by VIGEN_LAGRANGIAN_MIDPOINT_VI only; opt NULL =
 * defaults), and its type in *type (may be NULL).  NULL (and *type NULL)
 * when the method is unknown, g is missing where needed, or X_alloc fails. */
void *vigen_lagrangian_integrator_alloc(int method, const vigen_lagrangian *lag, vigen_lgrad_fn g,
                                        const vigen_solver_options *opt, const vigen_stepper_type **type);

/* VIGEN_SUCCESS when lag (and phi, which may be NULL) can be integrated:
 * dim > 0, the required callbacks present, phi->dim == lag->dim, Daphi given
 * when nparams > 0; VIGEN_EINVAL otherwise.  If why is not NULL it receives
 * a fixed one-line reason (a static string, e.g. "the velocity map's dim
 * differs from the Lagrangian's"), or NULL on success. */
int vigen_lagrangian_validate(const vigen_lagrangian *lag, const vigen_velocity_map *phi,
                              const char **why);

/* ---- Hamilton–Pontryagin integrators ------------------------------------ */

enum { VIGEN_HP_TRAPEZOIDAL = 0, VIGEN_HP_MIDPOINT = 1 };

typedef struct vigen_hp vigen_hp;

/* NULL phi = the trivial map (q1 - q0)/h with no parameters (exact
 * derivatives built in); NULL opt = defaults (Newton; opt->solver is
 * ignored: these steppers always use Newton).  Returns NULL when
 * vigen_lagrangian_validate fails, rule is unknown, or memory runs out. */
vigen_hp *vigen_hp_alloc(const vigen_lagrangian *lag, int rule, const vigen_velocity_map *phi,
                         const vigen_solver_options *opt);
/* One step from (t, q, p) with step h (any sign, finite, nonzero).  The
 * first step (and any step from a state other than the one the last step
 * returned) predicts v by solving dL/dv(t, q, v) = p; VIGEN_ESINGULAR there
 * means d2L/dv2 is singular: a degenerate Lagrangian, which has no (q, p)
 * phase space for these steppers. */
int vigen_hp_step(vigen_hp *w, double *t, double *q, double *p, double h);
/* The parameters a_{n,n+1} of the last successful step (a0 before the first);
 * nparams entries, NULL when there are none.  They also start the next step's
 * solve. */
const double *vigen_hp_params(const vigen_hp *w);
size_t vigen_hp_nparams(const vigen_hp *w);
/* v_{n+1/2} of the last successful step (dim entries). */
const double *vigen_hp_velocity(const vigen_hp *w);
void vigen_hp_reset(vigen_hp *w);       /* forget history and statistics; a = a0 */
const vigen_stats *vigen_hp_stats(const vigen_hp *w);
void vigen_hp_free(vigen_hp *w);
size_t vigen_hp_state_size(const vigen_hp *w);
int vigen_hp_state_get(const vigen_hp *w, void *buf);
int vigen_hp_state_set(vigen_hp *w, const void *buf);

/* ---- the mid-point variational integrator ------------------------------- */

typedef struct vigen_midpoint_vi vigen_midpoint_vi;

/* g(t, q, p, v, ctx) writes the v with dL/dv(t, q, v) = p (the inverse
 * Legendre map, called with lag->ctx).  g may be NULL: then only the two-step
 * form is available (vigen_midpoint_vi_step returns VIGEN_EUNSUPPORTED). */
vigen_midpoint_vi *vigen_midpoint_vi_alloc(const vigen_lagrangian *lag, vigen_lgrad_fn g,
                                           const vigen_solver_options *opt);
/* Cresson–Safi discrete Hamiltonian system:
 *   p1 = p0 + h dL/dq(t + h/2, (q0 + q1)/2, (q1 - q0)/h)
 *   q1 = q0 + h g(t + h/2, (q0 + q1)/2, (p0 + p1)/2)                         */
int vigen_midpoint_vi_step(vigen_midpoint_vi *w, double *t, double *q, double *p, double h);
/* Two-step position form: given q0 at t0 and q1 at t1, solves the discrete
 * Euler–Lagrange equations D1 Ld(q1, q2) + D2 Ld(q0, q1) = 0 of
 * Ld(qa, qb) = (tb - ta) L((ta + tb)/2, (qa + qb)/2, (qb - qa)/(tb - ta))
 * for q2 at t2 (times strictly monotone).  q2 may not alias q0 or q1. */
int vigen_midpoint_vi_step2(vigen_midpoint_vi *w, double t0, double t1, double t2,
                            const double *q0, const double *q1, double *q2);
const vigen_stats *vigen_midpoint_vi_stats(const vigen_midpoint_vi *w);
/* Forget the history and statistics (the next one-step call starts a new
 * trajectory). */
void vigen_midpoint_vi_reset(vigen_midpoint_vi *w);
void vigen_midpoint_vi_free(vigen_midpoint_vi *w);
/* The state of the one-step form (the two-step form keeps none). */
size_t vigen_midpoint_vi_state_size(const vigen_midpoint_vi *w);
int vigen_midpoint_vi_state_get(const vigen_midpoint_vi *w, void *buf);
int vigen_midpoint_vi_state_set(vigen_midpoint_vi *w, const void *buf);

/* ---- the trapezoidal variational integrator on a non-uniform grid -------- */

typedef struct vigen_trapezoidal_vi vigen_trapezoidal_vi;

/* Ld(t0, t1, q0, q1) = (t1 - t0)/2 [L(t0, q0, v) + L(t1, q1, v)],
 * v = (q1 - q0)/(t1 - t0). */
vigen_trapezoidal_vi *vigen_trapezoidal_vi_alloc(const vigen_lagrangian *lag,
                                                 const vigen_solver_options *opt);
/* One-step map (q0, p0) at t -> (q1, p1) at t + h with p0 = -D1 Ld, p1 = D2 Ld. */
int vigen_trapezoidal_vi_step(vigen_trapezoidal_vi *w, double *t, double *q, double *p, double h);
/* Two-step position form on the grid t0, t1, t2 (strictly monotone). */
int vigen_trapezoidal_vi_step2(vigen_trapezoidal_vi *w, double t0, double t1, double t2,
                               const double *q0, const double *q1, double *q2);
/* Integrates over the grid times[0 .. ntimes-1] (strictly monotone, finite)
 * from (q, p) at times[0]; on return (q, p) is the state at the last time
 * reached.  qs and ps (ntimes x dim each, may be NULL) receive the state at
 * every time, row n at times[n].  *done (may be NULL) receives the number of
 * steps taken; on error the state is the last good one.  Each step runs
 * from times[n] to times[n+1] as given (no accumulated sum of steps); a grid
 * that is not strictly monotone and finite is VIGEN_EINVAL before any step. */
int vigen_trapezoidal_vi_integrate(vigen_trapezoidal_vi *w, const double *times, size_t ntimes,
                                   double *q, double *p, double *qs, double *ps, size_t *done);
const vigen_stats *vigen_trapezoidal_vi_stats(const vigen_trapezoidal_vi *w);
void vigen_trapezoidal_vi_reset(vigen_trapezoidal_vi *w);   /* vigen_hp_reset of its stepper */
void vigen_trapezoidal_vi_free(vigen_trapezoidal_vi *w);
/* The state of the Hamilton-Pontryagin stepper it runs (named vigen_hp). */
size_t vigen_trapezoidal_vi_state_size(const vigen_trapezoidal_vi *w);
int vigen_trapezoidal_vi_state_get(const vigen_trapezoidal_vi *w, void *buf);
int vigen_trapezoidal_vi_state_set(vigen_trapezoidal_vi *w, const void *buf);

#ifdef __cplusplus
}
#endif

#endif
