/* vigen/poincare.h — adaptive steps that stay symplectic: the Poincaré time
 * transformation (Hairer, Lubich & Wanner, Geometric Numerical Integration,
 * sec. VIII.2) in extended phase space, and a driver that steps in fictive
 * time and stops at a physical time.  double only.
 *
 * Given H(t, q, p) and a step density g(t, q, p) > 0, the physical time t
 * becomes coordinate n of an extended state of dimension n + 1,
 *
 *     Q = (q, t),   P = (p, e),   K(Q, P) = g(t, q, p) (H(t, q, p) + e),
 *
 * with e = -H(t0, q0, p0) at the start, so that K = 0 along the solution.
 * On K = 0 the flow of K in the fictive time tau is the flow of H with
 * dt/dtau = dK/de = g: a constant fictive step dtau is a physical step
 * g dtau, small where g is small.  K is an ordinary Hamiltonian, so any
 * emitted stepper (implicit: K is not separable) integrates it with a
 * constant step, stays symplectic in the extended space, and keeps K, hence
 * H + e = K / g, near 0 without drift.  The physical time is integrated by the
 * same method as q and p (with the stepper's compensated sums), and e = -H
 * follows H when H depends on t (dH/dt is then required).
 *
 *     vigen_poincare_problem pb = { sys, density, density_ctx, NULL };
 *     vigen_poincare *pc;
 *     if (vigen_poincare_alloc(&pc, &pb) != VIGEN_SUCCESS) ...
 *     void *w = gauss2_type.alloc(vigen_poincare_hamiltonian(pc), NULL);
 *     vigen_poincare_result res;
 *     int st = vigen_poincare_integrate(&gauss2_type, w, pc, &t, q, p, dtau, t_end,
 *                                       max_steps, 0, NULL, NULL, &res);
 *     if (st != VIGEN_SUCCESS) fprintf(stderr, "%s\n", vigen_poincare_message(pc));
 *     gauss2_type.free(w);
 *     vigen_poincare_free(pc);
 *
 * A vigen_poincare holds one trajectory's level e and the evaluation cache:
 * one per trajectory and thread.
 */
#ifndef VIGEN_POINCARE_H
#define VIGEN_POINCARE_H

#include <stddef.h>
#include <vigen/runtime.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The step density: returns g(t, q, p) and writes its gradient into dgdq,
 * dgdp (dim entries each) and *dgdt.  The arrays and *dgdt arrive zeroed:
 * write only the entries g depends on.  g must be positive and finite
 * wherever the trajectory goes (a violation stops the step with
 * VIGEN_EINVAL or VIGEN_ENONFINITE and a message). */
typedef double (*vigen_poincare_density_fn)(double t, const double *q, const double *p, double *dgdq,
                                            double *dgdp, double *dgdt, void *ctx);

/* dH/dt(t, q, p) of a time-dependent H (called with sys->ctx). */
typedef double (*vigen_poincare_dhdt_fn)(double t, const double *q, const double *p, void *ctx);

typedef struct {
    const vigen_hamiltonian *sys;        /* H is required (K needs its value); kept by pointer */
    vigen_poincare_density_fn density;
    void *density_ctx;
    vigen_poincare_dhdt_fn dHdt;          /* NULL: H does not depend on t (checked at the start
                                             of each trajectory: VIGEN_EINVAL if it does) */
} vigen_poincare_problem;

typedef struct vigen_poincare vigen_poincare;

/* Evaluations of the user's functions since alloc. */
typedef struct {
    unsigned long H_evals, dHdq_evals, dHdp_evals, dHdt_evals, density_evals;
    unsigned long cache_hits;            /* K gradients served from the previous point's values */
} vigen_poincare_stats;

/* The transformed problem of pb in *out.  VIGEN_EINVAL (with no object) for
 * a NULL pointer, dim 0, or a missing H, dHdq, dHdp or density; VIGEN_ENOMEM. */
int vigen_poincare_alloc(vigen_poincare **out, const vigen_poincare_problem *pb);
void vigen_poincare_free(vigen_poincare *pc);

/* K as a Hamiltonian of dimension dim + 1 (separable 0, no Hessian: Newton
 * solvers use finite differences); its `t` argument is the fictive time,
 * which K ignores.  Valid until vigen_poincare_free; allocate the stepper's
 * workspace with it (a stepper emitted with --dim N needs N = dim + 1). */
const vigen_hamiltonian *vigen_poincare_hamiltonian(const vigen_poincare *pc);

/* The extended state of (t, q, p): Q = (q, t), P = (p, -H(t, q, p)) (dim + 1
 * entries each), for stepping K by hand.  VIGEN_EINVAL for a NULL pointer or
 * a non-finite t, q or p; VIGEN_ENONFINITE when H is not finite there. */
int vigen_poincare_extend(vigen_poincare *pc, double t, const double *q, const double *p, double *Q,
                          double *P);

/* Observer of the driver: fictive step count, fictive time tau, physical
 * time t and state; nonzero return stops (VIGEN_ESTOPPED). */
typedef int (*vigen_poincare_observer_fn)(unsigned long step, double tau, double t, const double *q,
                                          const double *p, void *ctx);

typedef struct {
    unsigned long steps;          /* fictive steps accepted, the shortened last one included */
    unsigned long end_trials;     /* extra steps spent locating the shortened last step */
    double tau;                   /* fictive time since the trajectory's start */
    double last_dtau;             /* the shortened last fictive step, 0 when none was taken */
    double t_mismatch;            /* physical time of the last step minus t_end (round-off) */
    double energy_error;          /* H(t, q, p) + e at the end: the drift of the energy level
                                     (for autonomous H, H - H0) */
    int capped;                   /* 1 when max_steps ran out before t_end */
} vigen_poincare_result;

/* Integrates from (*t, q, p) to the physical time t_end with constant
 * fictive steps dtau (its sign that of t_end - *t), the workspace w of
 * stepper T allocated for vigen_poincare_hamiltonian(pc).  A step that would
 * pass t_end is replaced by a shortened fictive step sigma in (0, dtau) found
 * by safeguarded secant iteration on t(sigma) = t_end (each trial one step
 * from the same state); the state is that step's, *t is set to t_end and the
 * remaining round-off difference is res->t_mismatch.  obs (may be NULL) is
 * called at step 0, every `every` steps (0 = never in between) and at the
 * end, with the physical state.
 *
 * A call with the (t, q, p) a previous call returned continues that
 * trajectory (same level e, same fictive time); any other state starts a new
 * one with e = -H(t, q, p) (and, without dHdt, checks that H ignores t).
 *
 * Returns VIGEN_SUCCESS with *t == t_end; VIGEN_ESTOPPED when obs asked or
 * max_steps fictive steps (0 = no cap) ran out (res->capped); the stepper's
 * status, or VIGEN_EINVAL / VIGEN_ENONFINITE for a density that is not
 * positive and finite, with the state left at the last accepted step.
 * VIGEN_EINVAL also for NULL pointers, non-finite arguments or dtau of the
 * wrong sign.  vigen_poincare_message(pc) says what went wrong in one line.
 * res may be NULL. */
int vigen_poincare_integrate(const vigen_stepper_type *T, void *w, vigen_poincare *pc, double *t, double *q,
                             double *p, double dtau, double t_end, unsigned long max_steps,
                             unsigned long every, vigen_poincare_observer_fn obs, void *obs_ctx,
                             vigen_poincare_result *res);

/* ---- the transformed stepper as a stepper type ---------------------------- */
/* A workspace of vigen_poincare_type: its own vigen_poincare for pb (kept:
 * pb->sys by pointer, as vigen_poincare_alloc does) and a workspace of the
 * stepper T (T->alloc with opt, NULL = defaults) for its K.  Its step
 * (t, q, p, h) is one fictive step h from the physical state (t, q, p): q
 * and p of dimension dim, and t the physical time, advanced by the step's
 * own amount (about g h).  A step from the state the last step returned
 * continues the trajectory (same level e, fictive time); any other state
 * starts one, as vigen_poincare_integrate does.  Through the type:
 *   vigen_integrate        n fictive steps (no stop at a physical time: use
 *                          vigen_poincare_integrate for that);
 *   vigen_integrate_at,    interpolated in the physical times the steps
 *   vigen_integrate_events returned, with the physical flow (dH/dp, -dH/dq)
 *                          as slopes; output times are physical times, h the
 *                          fictive step (its sign that of the run);
 *   vigen_integrate_ensemble  with the workspace as prototype (clone makes
 *                          a new vigen_poincare and inner workspace);
 *   state_size/get/set     the trajectory and the inner workspace's state.
 * Its alloc is NULL, its order -1 (that of T), its statistics T's (fictive
 * steps).  NULL when T has no alloc, or pb or memory fails. */
typedef struct vigen_poincare_stepper vigen_poincare_stepper;
extern const vigen_stepper_type vigen_poincare_type;
vigen_poincare_stepper *vigen_poincare_stepper_alloc(const vigen_stepper_type *T, const vigen_poincare_problem *pb,
                                                     const vigen_solver_options *opt);
void vigen_poincare_stepper_free(vigen_poincare_stepper *s);
/* Its transformed problem: messages (vigen_poincare_message) and
 * evaluation counts. */
vigen_poincare *vigen_poincare_stepper_transform(const vigen_poincare_stepper *s);
/* vigen_poincare_integrate with the stepper, workspace and transformed
 * problem of s: to a physical time t_end, the last step shortened.  Steps
 * through the type and this driver continue each other's trajectory. */
int vigen_poincare_stepper_integrate(vigen_poincare_stepper *s, double *t, double *q, double *p, double dtau,
                                     double t_end, unsigned long max_steps, unsigned long every,
                                     vigen_poincare_observer_fn obs, void *obs_ctx, vigen_poincare_result *res);

/* The last failure in one line ("" when none). */
const char *vigen_poincare_message(const vigen_poincare *pc);
const vigen_poincare_stats *vigen_poincare_get_stats(const vigen_poincare *pc);

/* A ready density: g = r^alpha with r^2 = sum of q_k^2 for k in
 * [first, first + count) (the distance to a centre at the origin in a
 * Kepler-like problem).  ctx points to a vigen_poincare_power. */
typedef struct {
    double alpha;
    size_t first, count;
} vigen_poincare_power;
/* The density function of vigen_poincare_power (a vigen_poincare_density_fn):
 * returns g at (t, q, p) and writes its derivatives into dgdq, dgdp, dgdt. */
double vigen_poincare_density_power(double t, const double *q, const double *p, double *dgdq, double *dgdp,
                                    double *dgdt, void *ctx);

#ifdef __cplusplus
}
#endif

#endif
