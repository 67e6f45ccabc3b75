/* vigen/runtime.h — the library that steppers emitted by `vigen emit` link
 * against: problem types, solver options, status codes, statistics,
 * compensated sums, the stage-equation helpers and the drivers:
 * vigen_integrate (n equal steps), vigen_integrate_at (the same steps, the
 * state at any requested times by a continuous extension) and
 * vigen_integrate_events (the times where a function of the state changes
 * sign, optionally stopping there).
 *
 * An emitted stepper NAME (files NAME.h, NAME.c) offers
 *
 *     NAME_workspace *NAME_alloc(const vigen_hamiltonian *sys,
 *                                const vigen_solver_options *opt);  NULL opt = defaults
 *     NAME_workspace *NAME_alloc_mechanical(const vigen_mechanical *sys,
 *                                const vigen_solver_options *opt);  H = p^T M^-1 p / 2 + V,
 *                                the force -dV/dq given: stepped in Nystrom form
 *     size_t NAME_dim(void);     the only dimension alloc takes (emit --dim), 0 = any
 *     int  NAME_step(NAME_workspace *w, double *t, double *q, double *p, double h);
 *     void NAME_reset(NAME_workspace *w);     forget history (new trajectory)
 *     const vigen_stats *NAME_stats(const NAME_workspace *w);
 *     void NAME_free(NAME_workspace *w);
 *     size_t NAME_state_size(const NAME_workspace *w);   bytes of a saved state
 *     int  NAME_state_get(const NAME_workspace *w, void *buf);   restart state (docs/emit.md)
 *     int  NAME_state_set(NAME_workspace *w, const void *buf);   VIGEN_ESTATE if not this stepper's
 *     extern const vigen_stepper_type NAME_type;   for the drivers (below,
 *                                and vigen_integrate_ensemble of vigen/ensemble.h)
 *
 * The drivers take any integrator as a vigen_stepper_type and a workspace
 * (runtime_real.h): emitted steppers, the Lagrangian integrators
 * (vigen/lagrangian.h) and Poincare-transformed steppers (vigen/poincare.h)
 * alike.
 *
 * NAME_step returns VIGEN_SUCCESS (0) or a status code below; on failure t, q
 * and p are left unchanged (bit for bit) and NAME_stats(w)->last_iterations
 * tells how many stage iterations were spent.  t, h and t + h must be finite
 * (VIGEN_EINVAL); a gradient, stage value or new state that is NaN or
 * infinite gives VIGEN_ENONFINITE, on every path (explicit, fixed point,
 * Newton) and for every real type.  Every call takes its own h (non-uniform grids).
 *
 * The problem:  q' = dH/dp(t, q, p),  p' = -dH/dq(t, q, p),  q, p in R^dim.
 * `separable` promises H = T(p) + V(t, q): dHdp ignores t and q, dHdq ignores
 * p.  Steppers whose tableau is explicit for separable H then run without
 * stage iterations; for them dHdp may be called with any valid q array and
 * dHdq with any valid p array.
 *
 * Three real types exist side by side: double (names as above), long double
 * (suffix _ld: vigen_hamiltonian_ld, vigen_integrate_ld, ...) and, where the
 * compiler has __float128 (GCC, Clang on x86-64), __float128 (suffix _q,
 * type vigen_float128).  Their declarations come from runtime_real.h,
 * included once per type; the double expansion reads:
 *
 *     typedef void (*vigen_grad_fn)(double t, const double *q, const double *p,
 *                                   double *out, void *ctx);
 *     typedef void (*vigen_hess_fn)(double t, const double *q, const double *p,
 *                                   double *out, void *ctx);
 *     typedef struct {
 *         size_t dim;
 *         vigen_grad_fn dHdq, dHdp;
 *         double (*H)(double t, const double *q, const double *p, void *ctx);
 *         void *ctx;
 *         int separable;
 *         vigen_hess_fn hessian;     optional, may be left out of an initialiser
 *     } vigen_hamiltonian;
 *
 *     typedef void (*vigen_force_fn)(double t, const double *q, double *f, void *ctx);
 *     typedef struct {                   H = 1/2 p^T M^-1 p + V(t, q), M diagonal
 *         size_t dim;
 *         vigen_force_fn force;          f = -dV/dq(t, q)
 *         double (*V)(double t, const double *q, void *ctx);   optional
 *         void *ctx;
 *         const double *inv_mass;        dim entries of diag(M^-1); NULL = identity
 *     } vigen_mechanical;
 *
 * State is never shared between workspaces; a workspace is not thread-safe,
 * distinct workspaces are.  Compile emitted code without -ffast-math: the
 * compensated sums rely on IEEE rounding.
 */
#ifndef VIGEN_RUNTIME_H
#define VIGEN_RUNTIME_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

#define VIGEN_RUNTIME_VERSION "0.1.0"

/* ---- status codes (values are stable; new codes are appended) ---------- */
enum {
    VIGEN_SUCCESS = 0,
    VIGEN_EINVAL,        /* invalid argument: NULL pointer, dim 0, t or h not finite, or
                          * t + h overflowing (an emitted NAME_step checks pointers
                          * only when compiled with -DVIGEN_CHECK_ARGS; with
                          * -DVIGEN_CHECK_PROBLEM it also checks the problem
                          * at its first step, vigen/diagnostics.h) */
    VIGEN_ENOMEM,        /* allocation failed */
    VIGEN_ENOCONV,       /* stage iteration stopped decreasing above the tolerance (diverges) */
    VIGEN_EMAXITER,      /* stage iteration reached max_iter without converging */
    VIGEN_ESINGULAR,     /* Newton matrix I - h J is singular */
    VIGEN_ENONFINITE,    /* a gradient, stage value or the new state is NaN or infinite */
    VIGEN_EUNSUPPORTED,  /* option not available for this stepper */
    VIGEN_ESTOPPED,      /* the observer asked vigen_integrate to stop */
    VIGEN_EGRADIENT,     /* problem check: a gradient disagrees with differences of H */
    VIGEN_ESEPARABLE,    /* problem check: a problem marked separable is not */
    VIGEN_EHESSIAN,      /* problem check: the Hessian disagrees with differences of the gradients */
    VIGEN_ESTATE,        /* a saved state belongs to another stepper, dimension or version */
    VIGEN_STATUS_MAX
};

/* "success", "stage iteration did not converge (increment stopped decreasing)", ... */
const char *vigen_strerror(int status);

/* ---- solver options ----------------------------------------------------- */
enum { VIGEN_SOLVER_FIXED_POINT = 0, VIGEN_SOLVER_NEWTON = 1 };

typedef struct {
    int solver;          /* VIGEN_SOLVER_FIXED_POINT (default) or VIGEN_SOLVER_NEWTON */
    int max_iter;        /* cap on stage iterations per step; default 50 */
    double tol;          /* relative increment below which a stalled iteration counts as
                            converged; 0 = default 2^20 * epsilon of the real type */
    int kahan;           /* compensated summation of the t, q and p updates; default 1 */
    int extrapolate;     /* start from the previous step's stages extrapolated; default 1 */
    double fd_step;      /* relative step of the finite-difference Hessian; 0 = default
                            (square root of epsilon) */
    int start_force;     /* mechanical problems, implicit tableaux with every node c_i != 1:
                            one more force per step, at the step's start, joins the
                            extrapolation of the previous step's stage forces (degree s
                            instead of s - 1); default 0 (ignored elsewhere) */
} vigen_solver_options;

/* Fills the defaults listed above. */
void vigen_solver_options_default(vigen_solver_options *opt);

/* ---- statistics (cumulative since alloc; reset by NAME_reset too) -------- */
typedef struct {
    unsigned long steps;            /* successful steps */
    unsigned long failed_steps;     /* steps that returned an error */
    unsigned long iterations;       /* stage iterations (gradient sweeps) in all steps */
    unsigned long last_iterations;  /* iterations of the latest step, failed or not */
    unsigned long max_iterations;   /* largest per-step count seen */
    unsigned long dHdq_evals;       /* calls of sys->dHdq */
    unsigned long dHdp_evals;       /* calls of sys->dHdp */
    unsigned long hessian_evals;    /* Hessians (user or finite differences) */
    unsigned long lu_decompositions;
    unsigned long fsal_reuses;      /* gradients carried over from the previous step */
} vigen_stats;

/* ---- stage iteration stopping rule -------------------------------------- */
/* The round-off-aware rule shared by every emitted solver: iterate until the
 * relative increment is exactly zero or stops decreasing.  "Stops decreasing"
 * compares with the increment two iterations back, a lenient test that
 * tolerates one non-monotone step (with the Jacobi sweeps used earlier, the q
 * and p increments of separable H came in equal pairs; the Gauss-Seidel sweeps
 * used now need no such allowance but do not suffer from it).  A stall counts
 * as convergence
 * when one of the last two increments is below tol; otherwise three stalls
 * mean divergence (VIGEN_ENOCONV).  max_iter increments without either outcome
 * give VIGEN_EMAXITER (or success if the last is below tol).  A NaN or
 * infinite increment gives VIGEN_ENONFINITE. */
typedef struct {
    double prev1, prev2;  /* previous two increments, -1 before they exist */
    int strikes;          /* stalls seen above tol */
    int iter;             /* increments judged so far */
} vigen_iter_monitor;

static inline void vigen_iter_start(vigen_iter_monitor *m)
{
    m->prev1 = m->prev2 = -1.0;
    m->strikes = 0;
    m->iter = 0;
}

/* Judges one increment: returns -1 to go on iterating, VIGEN_SUCCESS when
 * converged, or an error status. */
static inline int vigen_iter_judge(vigen_iter_monitor *m, double delta, double tol, int max_iter)
{
    int verdict = -1;
    m->iter++;
    if (delta != delta || delta > 1.0e308) {      /* NaN or infinite */
        verdict = VIGEN_ENONFINITE;
    } else if (delta == 0.0) {
        verdict = VIGEN_SUCCESS;
    } else if (m->prev2 >= 0.0 && delta >= m->prev2) {
        if (delta <= tol || m->prev1 <= tol) verdict = VIGEN_SUCCESS;
        else if (++m->strikes >= 3) verdict = VIGEN_ENOCONV;
    }
    if (verdict < 0 && m->iter >= max_iter) verdict = (delta <= tol) ? VIGEN_SUCCESS : VIGEN_EMAXITER;
    m->prev2 = m->prev1;
    m->prev1 = delta;
    return verdict;
}

/* ---- Newton linear algebra (double; GSL LU) ----------------------------- */
/* Simplified Newton for the stage equations of an s-stage PRK method in
 * dimension n.  Unknowns are ordered (Q_1..Q_s, P_1..P_s), each of length n.
 * The Hessian buffer is (2n) x (2n), row-major: rows are the components of
 * (dH/dq, dH/dp), columns the variables (q, p).  The iteration matrix is
 *     M = I - [ h a_ij (d dHdp/d(q,p)) ; -h at_ij (d dHdq/d(q,p)) ]   (blocks i, j).
 * GSL's aborting error handler is switched off by vigen_newton_alloc. */
typedef struct vigen_newton vigen_newton;

/* The solver of an s-stage method in dimension n (NULL when memory runs out),
 * and its release. */
vigen_newton *vigen_newton_alloc(size_t stages, size_t dim);
/* The solver of the Nystrom form of a mechanical problem's stage equations:
 * the unknowns are the s stage positions alone (s n of them), the iteration
 * matrix M = I - [ h^2 (A At)_ij M^-1 J ] (blocks i, j), with M^-1 J in the
 * Hessian buffer's rows n..2n-1, columns 0..n-1 (where
 * vigen_mechanical_jacobian_fd puts it) and ha = h^2 (A At)_ij given to
 * vigen_newton_matrix_block (hat is not used); the right-hand side has s n
 * entries.  NULL when memory runs out or stages or dim is 0. */
vigen_newton *vigen_newton_alloc_nystrom(size_t stages, size_t dim);
void vigen_newton_free(vigen_newton *nw);
double *vigen_newton_hessian(vigen_newton *nw);              /* buffer to fill */
void vigen_newton_matrix_identity(vigen_newton *nw);         /* M = I */
void vigen_newton_matrix_block(vigen_newton *nw, size_t i, size_t j, double ha, double hat);
/* LU; VIGEN_ESINGULAR for a zero pivot, VIGEN_ENONFINITE for a NaN or
 * infinite entry of M (a Hessian from gradients that are not finite) or an
 * overflowing factorisation. */
int vigen_newton_factor(vigen_newton *nw);
double *vigen_newton_rhs(vigen_newton *nw);                  /* 2 s n doubles (s n: Nystrom) */
/* rhs <- M^-1 rhs; VIGEN_ENONFINITE when rhs or the solution is not finite. */
int vigen_newton_solve(vigen_newton *nw);

/* ---- compensated summation (double; typed variants in runtime_real.h) ---- */
/* Neumaier-compensated running sum. */
typedef struct { double sum, comp; } vigen_neumaier;
static inline void vigen_neumaier_init(vigen_neumaier *acc) { acc->sum = 0.0; acc->comp = 0.0; }
static inline void vigen_neumaier_add(vigen_neumaier *acc, double x)
{
    double s = acc->sum + x;
    double bb = s - acc->sum;
    acc->comp += (acc->sum - (s - bb)) + (x - bb);   /* TwoSum: exact error of s */
    acc->sum = s;
}
static inline double vigen_neumaier_result(const vigen_neumaier *acc) { return acc->sum + acc->comp; }
/* Naive left-to-right sum (for comparison; see vigen_sum_kahan for the
 * compensated one). */
double vigen_sum_naive(const double *x, size_t n);

/* ---- the per-real-type part --------------------------------------------- */
#define VIGEN_REAL double
#define VIGEN_SFX(name) name
#include "runtime_real.h"
#undef VIGEN_REAL
#undef VIGEN_SFX

#define VIGEN_REAL long double
#define VIGEN_SFX(name) name##_ld
#include "runtime_real.h"
#undef VIGEN_REAL
#undef VIGEN_SFX

#if defined(__SIZEOF_FLOAT128__) && !defined(VIGEN_NO_FLOAT128)
#define VIGEN_HAVE_FLOAT128 1
__extension__ typedef __float128 vigen_float128;
#define VIGEN_REAL vigen_float128
#define VIGEN_SFX(name) name##_q
#include "runtime_real.h"
#undef VIGEN_REAL
#undef VIGEN_SFX
#endif

#ifdef __cplusplus
}
#endif

#endif
