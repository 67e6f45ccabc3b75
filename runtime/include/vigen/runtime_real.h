/* vigen/runtime_real.h — declarations repeated for each real type.
 *
 * Included by vigen/runtime.h only, once per type, with VIGEN_REAL the type
 * and VIGEN_SFX(name) adding the type's suffix (none, _ld, _q).  No include
 * guard on purpose.  See runtime.h for the double expansion and semantics.
 */
#if !defined(VIGEN_REAL) || !defined(VIGEN_SFX)
#error "include <vigen/runtime.h>, not runtime_real.h"
#endif

/* Gradient of H with respect to q or p, written into out[0 .. dim-1]. */
typedef void (*VIGEN_SFX(vigen_grad_fn))(VIGEN_REAL t, const VIGEN_REAL *q, const VIGEN_REAL *p,
                                         VIGEN_REAL *out, void *ctx);
/* Hessian of H, (2 dim) x (2 dim) row-major as doubles: rows (dH/dq, dH/dp),
 * columns (q, p).  Used only by the Newton solver; NULL = finite differences. */
typedef void (*VIGEN_SFX(vigen_hess_fn))(VIGEN_REAL t, const VIGEN_REAL *q, const VIGEN_REAL *p,
                                         double *out, void *ctx);

typedef struct {
    size_t dim;
    VIGEN_SFX(vigen_grad_fn) dHdq, dHdp;
    VIGEN_REAL (*H)(VIGEN_REAL t, const VIGEN_REAL *q, const VIGEN_REAL *p, void *ctx);
    void *ctx;
    int separable;
    VIGEN_SFX(vigen_hess_fn) hessian;
} VIGEN_SFX(vigen_hamiltonian);

/* A mechanical problem, H = 1/2 p^T M^-1 p + V(t, q) with M diagonal: the
 * user supplies the force f = -dV/dq(t, q) only.  An emitted stepper takes
 * it through NAME_alloc_mechanical and then integrates q' = M^-1 p,
 * p' = f(t, q) in Nystrom form (stage values for the positions only, one
 * force evaluation per stage and sweep, no dH/dp).  V is optional (not
 * called by the stepper); inv_mass holds dim entries of the diagonal of
 * M^-1 (copied at alloc; NULL = identity). */
typedef void (*VIGEN_SFX(vigen_force_fn))(VIGEN_REAL t, const VIGEN_REAL *q, VIGEN_REAL *f, void *ctx);
typedef struct {
    size_t dim;
    VIGEN_SFX(vigen_force_fn) force;
    VIGEN_REAL (*V)(VIGEN_REAL t, const VIGEN_REAL *q, void *ctx);
    void *ctx;
    const VIGEN_REAL *inv_mass;
} VIGEN_SFX(vigen_mechanical);

/* A split problem, H = H_1 + H_2 + ... + H_n, each part with a flow the
 * user solves exactly (a Kepler drift, a harmonic rotation, a free rigid
 * body) or to a stated order.  Flow k advances (q, p) in place by time h of
 * H_k alone, from time t, and returns VIGEN_SUCCESS, or an error status with
 * q and p unchanged (a flow that cannot be evaluated, a collision orbit, a
 * non-finite result).  A flow must be symplectic; the splitting method's
 * order holds when every flow is exact or of at least that order.  flow[k]
 * is the flow named k-th in the splitting file's `flows`; one ctx is passed
 * to every flow.  vector_field (optional, NULL = none) is the flow of the
 * whole H at (t, q, p), q' into dq and p' into dp; output at any time and
 * events need it and refuse with VIGEN_EINVAL without it.  H (optional)
 * serves diagnostics. */
typedef int (*VIGEN_SFX(vigen_flow_fn))(VIGEN_REAL t, VIGEN_REAL h, VIGEN_REAL *q, VIGEN_REAL *p, void *ctx);
typedef struct {
    size_t dim;
    size_t nflows;
    const VIGEN_SFX(vigen_flow_fn) *flow;
    void *ctx;
    int (*vector_field)(VIGEN_REAL t, const VIGEN_REAL *q, const VIGEN_REAL *p, VIGEN_REAL *dq, VIGEN_REAL *dp,
                        void *ctx);
    VIGEN_REAL (*H)(VIGEN_REAL t, const VIGEN_REAL *q, const VIGEN_REAL *p, void *ctx);
} VIGEN_SFX(vigen_split_problem);

/* An integrator as a const type object (GSL style): the one seam through
 * which every driver of the runtime (vigen_integrate, output at any time,
 * events, ensembles, restart, vigen_poincare_integrate) reaches it, with
 * nothing but the type and a workspace.  Emitted steppers have NAME_type;
 * the Lagrangian integrators vigen_hp_type, vigen_midpoint_vi_type and
 * vigen_trapezoidal_vi_type (vigen/lagrangian.h); a Poincare-transformed
 * stepper vigen_poincare_type (vigen/poincare.h).  Fields are only ever
 * appended, so that positional initialisers of older types still compile
 * (the missing fields are then NULL, and the drivers that need them say
 * VIGEN_EINVAL). */
typedef struct {
    const char *name;          /* tableau or integrator name */
    int stages;
    int order;                 /* order certified by the checker for general H, -1 not decided */
    int explicit_separable;    /* 1 when explicit for separable H */
    /* A workspace for the Hamiltonian sys (NULL opt = defaults); NULL for
     * integrators made from another problem (a Lagrangian, a Poincare
     * transformation): make their workspace with their own alloc, and more
     * of them with clone. */
    void *(*alloc)(const VIGEN_SFX(vigen_hamiltonian) *sys, const vigen_solver_options *opt);
    int (*step)(void *w, VIGEN_REAL *t, VIGEN_REAL *q, VIGEN_REAL *p, VIGEN_REAL h);
    void (*reset)(void *w);
    const vigen_stats *(*stats)(const void *w);
    void (*free)(void *w);
    /* Saved states (bit-for-bit restart, NAME_state_size/_get/_set): the
     * bytes of the buffer, the workspace's state into a buffer of that size,
     * and that state back into a workspace of the same stepper, real type,
     * dimension, problem kind and options (VIGEN_ESTATE otherwise, the
     * workspace unchanged; VIGEN_EINVAL for a NULL pointer). */
    size_t (*state_size)(const void *w);
    int (*state_get)(const void *w, void *buf);
    int (*state_set)(void *w, const void *buf);
    /* The dimension of q and of p. */
    size_t (*dim)(const void *w);
    /* The flow of the workspace's problem at (t, q, p): q' into dq, p' into
     * dp (dim entries each), in the time the step advances (for a
     * Hamiltonian q' = dH/dp, p' = -dH/dq).  It feeds the continuous
     * extension of output at any time and events.  It leaves what later
     * steps read untouched (a run with it is bit for bit a run without) and
     * returns VIGEN_SUCCESS or an error status (an inverse Legendre map that
     * did not converge, a problem that cannot be evaluated), never an
     * unconverged result.  Not thread-safe with steps of the same workspace. */
    int (*vector_field)(void *w, VIGEN_REAL t, const VIGEN_REAL *q, const VIGEN_REAL *p, VIGEN_REAL *dq,
                        VIGEN_REAL *dp);
    /* A fresh workspace (no history, statistics zero) of the same
     * integrator, problem and options; NULL when out of memory.  Ensembles
     * make one per thread from a prototype. */
    void *(*clone)(const void *w);
} VIGEN_SFX(vigen_stepper_type);

/* Observer: called with the step count done so far; nonzero return stops. */
typedef int (*VIGEN_SFX(vigen_observer_fn))(unsigned long step, VIGEN_REAL t, const VIGEN_REAL *q,
                                            const VIGEN_REAL *p, void *ctx);

/* Takes nsteps steps of size h from (t, q, p) with the workspace w of type T,
 * calling obs (may be NULL) at step 0, after every `every` steps (0 = never
 * in between) and after the last step.  Returns VIGEN_SUCCESS, the stepper's
 * error status (state left at the last good step), or VIGEN_ESTOPPED.
 * *done (may be NULL) receives the number of steps taken. */
int VIGEN_SFX(vigen_integrate)(const VIGEN_SFX(vigen_stepper_type) *T, void *w, VIGEN_REAL *t,
                               VIGEN_REAL *q, VIGEN_REAL *p, VIGEN_REAL h, unsigned long nsteps,
                               unsigned long every, VIGEN_SFX(vigen_observer_fn) obs, void *obs_ctx,
                               unsigned long *done);

/* Finite-difference Hessian (forward differences of the gradients, 2 dim
 * evaluations of each gradient) into hess ((2 dim)^2 doubles).  work holds
 * 6 dim reals.  rel_step 0 = default.  Adds the calls made to *nq, *np. */
void VIGEN_SFX(vigen_hessian_fd)(const VIGEN_SFX(vigen_hamiltonian) *sys, VIGEN_REAL t,
                                 const VIGEN_REAL *q, const VIGEN_REAL *p, double *hess,
                                 VIGEN_REAL *work, double rel_step, unsigned long *nq,
                                 unsigned long *np);

/* Forward-difference Jacobian of the mechanical velocity field for the
 * simplified Newton of a Nystrom step, in the layout of vigen_hessian_fd:
 * hess ((2 dim)^2 doubles, rows (dH/dq, dH/dp), columns (q, p)) gets
 * rows dim .. 2 dim - 1, columns 0 .. dim - 1 set to d(M^-1 f)/dq and every
 * other entry 0, so that vigen_newton_matrix_block(nw, i, j, h^2 (A At)_ij, 0)
 * builds I - h^2 (A At) (x) M^-1 J in the position rows.  inv_mass: dim
 * entries.  work holds 3 dim reals.  dim + 1 force evaluations, added to
 * *nf.  rel_step 0 = default. */
void VIGEN_SFX(vigen_mechanical_jacobian_fd)(const VIGEN_SFX(vigen_mechanical) *sys, const VIGEN_REAL *inv_mass,
                                             VIGEN_REAL t, const VIGEN_REAL *q, double *hess, VIGEN_REAL *work,
                                             double rel_step, unsigned long *nf);

/* Machine epsilon of the type and the default stall tolerance 2^20 eps. */
double VIGEN_SFX(vigen_epsilon)(void);
double VIGEN_SFX(vigen_default_tol)(void);

/* TwoSum update x <- x + d with compensation c carried between calls:
 * the low-order bits lost in x are kept in c and fed back next time. */
static inline VIGEN_REAL VIGEN_SFX(vigen_twosum_update)(VIGEN_REAL x, VIGEN_REAL d, VIGEN_REAL *c)
{
    VIGEN_REAL e = d + *c;
    VIGEN_REAL s = x + e;
    VIGEN_REAL bb = s - x;
    *c = (x - (s - bb)) + (e - bb);
    return s;
}

/* The same update written elsewhere: returns x + d with the compensation c
 * fed in, and the new compensation in *c_out (x and c are left as they are,
 * so that a step can be refused after computing it).  Bit for bit the result
 * of vigen_twosum_update. */
static inline VIGEN_REAL VIGEN_SFX(vigen_twosum_next)(VIGEN_REAL x, VIGEN_REAL d, VIGEN_REAL c, VIGEN_REAL *c_out)
{
    VIGEN_REAL e = d + c;
    VIGEN_REAL s = x + e;
    VIGEN_REAL bb = s - x;
    *c_out = (x - (s - bb)) + (e - bb);
    return s;
}

/* Compensated sum of an array of this type. */
VIGEN_REAL VIGEN_SFX(vigen_sum_kahan)(const VIGEN_REAL *x, size_t n);

/* ---- output at any time and events (runtime/drive) ------------------ */
/* Both drivers step exactly as vigen_integrate does (the same calls of
 * T->step, so the steps and the final state are those of vigen_integrate
 * bit for bit) and look between step ends through a continuous extension:
 * on a step from (t0, y0) to (t1, y1), y = (q, p), with t0 and t1 the
 * times the step started from and returned (not t0 + h: a Poincare step
 * advances t by its own amount), the cubic Hermite polynomial through y0
 * and y1 with the slopes f(y0), f(y1) of the flow.  Its error is O(h^4),
 * so that the output has the error O(h^min(p, 4)) of a method of order p.
 * The slopes cost one evaluation of the flow per step end, only for the
 * steps that hold an output time or an event (a slope at a step end serves
 * both steps that share it); other steps cost nothing beyond the
 * stepper's work.
 *
 * The flow is the type's vector_field (and its dim the dimension); the
 * _sys variants take a Hamiltonian instead (q' = dH/dp, p' = -dH/dq),
 * which overrides it, for a stepper type without a vector field. */

/* An event function; events are the sign changes of g along the solution.
 * It returns the real type (the root is refined in that type). */
typedef VIGEN_REAL (*VIGEN_SFX(vigen_event_fn))(VIGEN_REAL t, const VIGEN_REAL *q, const VIGEN_REAL *p, void *ctx);

#ifndef VIGEN_DENSE_STATS_DEFINED
#define VIGEN_DENSE_STATS_DEFINED
/* What a dense-output or event run cost beyond the steps themselves. */
typedef struct {
    unsigned long steps;           /* steps taken */
    unsigned long dHdq_evals;      /* slopes of the extension: calls of dH/dq (or of the
                                      type's vector field, counted here and in dHdp_evals) */
    unsigned long dHdp_evals;      /* calls of dH/dp */
    unsigned long event_evals;     /* calls of the event function */
    unsigned long root_iterations; /* root finder iterations, all events together */
} vigen_dense_stats;
#endif

/* Steps with h from *t (h may be negative) until the last of the n_out
 * output times t_out is reached, and writes the state at t_out[k] into
 * q_out[k dim ..], p_out[k dim ..] (dim = T->dim(w), or sys->dim).
 * t_out must be monotone in the direction of h (equal times allowed) and
 * not before *t; an output time equal to a step end (or to the start) gets
 * that state exactly.  On return t, q, p hold the last step's state (past
 * or at the last output time) and *done (may be NULL) the steps taken.
 * Returns VIGEN_SUCCESS, VIGEN_EINVAL (NULL pointer, h zero or not finite,
 * output times out of order or before *t, a type without vector field
 * and dim and no sys: nothing is stepped or written; also when the steps
 * have not reached the last output time after 5/4 of (t_last - t)/h + 16
 * steps and, at the average advance of t per step seen so far, would not
 * either: h too small to move t), VIGEN_ENOMEM, VIGEN_ENONFINITE (a slope
 * or an interpolated state not finite), the vector field's status or the
 * stepper's status (the state left at the last good step, the outputs
 * before it written). */
int VIGEN_SFX(vigen_integrate_at)(const VIGEN_SFX(vigen_stepper_type) *T, void *w, VIGEN_REAL *t, VIGEN_REAL *q,
                                  VIGEN_REAL *p, VIGEN_REAL h, const VIGEN_REAL *t_out, size_t n_out,
                                  VIGEN_REAL *q_out, VIGEN_REAL *p_out, unsigned long *done);

/* The same with the flow given by a Hamiltonian (sys; NULL = the type's
 * vector field) and the cost reported in *st (may be NULL). */
int VIGEN_SFX(vigen_integrate_at_sys)(const VIGEN_SFX(vigen_stepper_type) *T, void *w,
                                      const VIGEN_SFX(vigen_hamiltonian) *sys, VIGEN_REAL *t, VIGEN_REAL *q,
                                      VIGEN_REAL *p, VIGEN_REAL h, const VIGEN_REAL *t_out, size_t n_out,
                                      VIGEN_REAL *q_out, VIGEN_REAL *p_out, unsigned long *done,
                                      vigen_dense_stats *st);

/* Takes nsteps steps of size h from (t, q, p) and records the times where
 * g changes sign: g is evaluated at every step end, and a step whose end
 * values have opposite signs (rising: g0 < 0 <= g1, falling: g0 > 0 >= g1;
 * direction +1 rising only, -1 falling only, 0 both) holds an event, found
 * on the extension by Brent's method (GSL) to double round-off and then
 * refined in the real type by bracketing to its round-off.  A start on a
 * zero of g is not an event; two sign changes within one step cancel and
 * are not seen.  The first max_events event times go to t_events (may be
 * NULL when max_events is 0) in order, *n_events receives the number
 * found.  terminal nonzero: the run stops at the first event with (t, q, p)
 * set to the extension's state there (the steps before it are untouched);
 * the workspace then holds a state it did not produce, which every
 * integrator of the runtime detects on its next step (it restarts its
 * compensation and history).
 * Returns VIGEN_SUCCESS (also after a terminal event), VIGEN_EINVAL (NULL
 * pointer, h zero or not finite, direction not -1, 0 or +1),
 * VIGEN_ENOMEM, VIGEN_ENONFINITE (g, a slope or an interpolated state not
 * finite), VIGEN_ENOCONV (the refinement did not close its bracket) or the
 * stepper's status (state at the last good step). */
int VIGEN_SFX(vigen_integrate_events)(const VIGEN_SFX(vigen_stepper_type) *T, void *w, VIGEN_REAL *t,
                                      VIGEN_REAL *q, VIGEN_REAL *p, VIGEN_REAL h, unsigned long nsteps,
                                      VIGEN_SFX(vigen_event_fn) g, int direction, int terminal, void *ctx,
                                      VIGEN_REAL *t_events, size_t max_events, size_t *n_events);

/* The same with the flow given by a Hamiltonian (sys; NULL = the type's
 * vector field) and the cost reported in *st (may be NULL; st->steps tells
 * where a terminal event stopped the run). */
int VIGEN_SFX(vigen_integrate_events_sys)(const VIGEN_SFX(vigen_stepper_type) *T, void *w,
                                          const VIGEN_SFX(vigen_hamiltonian) *sys, VIGEN_REAL *t, VIGEN_REAL *q,
                                          VIGEN_REAL *p, VIGEN_REAL h, unsigned long nsteps,
                                          VIGEN_SFX(vigen_event_fn) g, int direction, int terminal, void *ctx,
                                          VIGEN_REAL *t_events, size_t max_events, size_t *n_events,
                                          vigen_dense_stats *st);
