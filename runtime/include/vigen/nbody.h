/* vigen/nbody.h — N-body problems split as H = H_Kepler + H_interaction:
 * the Kepler drift by universal variables, Jacobi and democratic
 * heliocentric coordinates, the flows of each part in the form of
 * vigen_flow_fn (so that an emitted splitting stepper advances them through
 * a vigen_split_problem), the vector field and energy of the whole system,
 * and the symplectic correctors of Wisdom, Holman and Touma (1996).
 * docs/splitting.md tells the coordinates, the splittings and the methods.
 *
 *     vigen_nbody *sys;
 *     vigen_nbody_alloc(&sys, 6, G, mass);            masses m_0 (the star) .. m_5
 *     vigen_split_problem sp;
 *     vigen_nbody_split(sys, VIGEN_NBODY_JACOBI, &sp);  flows "kepler", "interaction", ...
 *     vigen_nbody_to_jacobi(sys, x, p, q, pj);        inertial -> Jacobi (canonical)
 *     ... an emitted splitting stepper, or sp.flow[k](t, h, q, pj, sp.ctx) ...
 *     vigen_nbody_from_jacobi(sys, q, pj, x, p);
 *     vigen_nbody_free(sys);
 *
 * The state of n bodies is q, p in R^(3n), body i at [3i, 3i + 3).  In the
 * inertial frame q holds the positions x_i and p the momenta m_i v_i.
 *
 * Jacobi coordinates (Wisdom & Holman 1991): with M_i = m_0 + ... + m_i and
 * R_i the centre of mass of bodies 0..i, q_0 = R_{n-1} (the centre of mass),
 * q_i = x_i - R_{i-1} (i >= 1); p_0 the total momentum and
 * p_i = p^inertial_i - (m_i/M_i) (p^inertial_0 + ... + p^inertial_i), the
 * conjugate momenta (p_i = m'_i dq_i/dt, m'_i = m_i M_{i-1}/M_i).  Then
 *   H_kepler      = |p_0|^2/(2 M) + sum_{i>=1} |p_i|^2/(2 m'_i) - G m_i M_{i-1}/|q_i|
 *   H_interaction = sum_{i>=1} G m_i M_{i-1}/|q_i| - sum_{i<j} G m_i m_j/|x_i - x_j|
 * and the Kepler flow is, for each i >= 1, the two-body orbit about the
 * centre with mu_i = G M_i (and the free drift of the centre of mass).
 *
 * Democratic heliocentric coordinates (Duncan, Levison & Lee 1998): q_0 the
 * centre of mass, q_i = x_i - x_0 (heliocentric positions); p_0 the total
 * momentum, p_i = p^inertial_i - (m_i/M) p_0 (barycentric momenta).  Then
 *   H_kepler      = |p_0|^2/(2 M) + sum_{i>=1} |p_i|^2/(2 m_i) - G m_0 m_i/|q_i|
 *   H_interaction = - sum_{1<=i<j} G m_i m_j/|q_i - q_j|
 *   H_jump        = |p_1 + ... + p_{n-1}|^2/(2 m_0)
 *
 * Both changes of coordinates are linear: q' = A x, p' = A^-T p, hence
 * canonical.
 *
 * A flow advances (q, p) in place by h and returns VIGEN_SUCCESS, or leaves
 * q and p unchanged (bit for bit) and returns VIGEN_EINVAL (ctx NULL, h not
 * finite, a body at the centre or on a radial orbit into it: a collision),
 * VIGEN_ENONFINITE (a non-finite state or result) or VIGEN_ENOCONV (the
 * Kepler equation not solved to round-off: not seen on finite orbits).  The
 * flows allocate nothing: their scratch memory is on the stack for up to 32
 * bodies (then several threads may call them on one system at once), the
 * system's own above (then one system serves one thread at a time, and
 * vigen_nbody_clone makes another).
 *
 * Only double is provided (no long double or __float128 versions).
 */
#ifndef VIGEN_NBODY_H
#define VIGEN_NBODY_H

#include <stddef.h>
#include <vigen/runtime.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---- the Kepler drift ------------------------------------------------- */

/* Advances the two-body orbit x'' = -mu x/|x|^3 by time h: x (3 entries,
 * position) and v (3 entries, velocity) in place.  Universal variables
 * (Stumpff functions; the universal Kepler equation solved by Halley's
 * method from the series of the anomaly in h, Laguerre-Conway iterations
 * inside a bisection bracket where that fails; f and g functions applied
 * as increments), for every eccentricity: elliptic, parabolic and
 * hyperbolic orbits alike; a bound orbit's h is reduced modulo its period
 * first.  The map is evaluated in long double and rounded once, so that
 * the energy of a two-body orbit carries no drift, only a round-off
 * growing like the square root of the drifts (where long double is wider
 * than double).  Returns VIGEN_SUCCESS; VIGEN_EINVAL (mu <= 0 or not finite, h not
 * finite, x = 0, or a radial orbit (zero angular momentum) that falls into
 * the centre or is bound: a collision orbit) or VIGEN_ENONFINITE (a
 * non-finite input or result: a hyperbolic orbit driven past overflow) or
 * VIGEN_ENOCONV (the equation not solved), with x and v unchanged. */
int vigen_kepler_drift(double mu, double h, double *x, double *v);

/* ---- the system --------------------------------------------------------- */

typedef struct vigen_nbody vigen_nbody;

/* The coordinates of a splitting. */
enum { VIGEN_NBODY_JACOBI = 0, VIGEN_NBODY_DEMOCRATIC = 1 };

/* n >= 2 bodies with masses mass[0..n-1] (> 0, finite; body 0 is the
 * central one) and gravitational constant G > 0.  VIGEN_SUCCESS and *out,
 * VIGEN_EINVAL on a bad argument, VIGEN_ENOMEM. */
int vigen_nbody_alloc(vigen_nbody **out, size_t n, double G, const double *mass);
/* Another system with the same bodies (its own scratch memory); NULL when
 * out of memory. */
vigen_nbody *vigen_nbody_clone(const vigen_nbody *sys);
void vigen_nbody_free(vigen_nbody *sys);
/* The number of bodies; the dimension of q (and p) is 3 times that. */
size_t vigen_nbody_count(const vigen_nbody *sys);

/* Energy of the whole system in inertial coordinates, H(x, p) =
 * sum |p_i|^2/(2 m_i) - sum_{i<j} G m_i m_j/|x_i - x_j|, summed with
 * compensation. */
double vigen_nbody_energy(const vigen_nbody *sys, const double *x, const double *p);
/* The forces f_i = -dV/dx_i in the inertial frame (3n entries). */
void vigen_nbody_forces(const vigen_nbody *sys, const double *x, double *f);

/* Changes of coordinates (inertial <-> Jacobi, inertial <-> democratic
 * heliocentric), positions and momenta together; out may be the input
 * itself (in place), otherwise the arrays must not overlap.  They return
 * VIGEN_SUCCESS, or VIGEN_EINVAL for a NULL pointer. */
int vigen_nbody_to_jacobi(const vigen_nbody *sys, const double *x, const double *p, double *q, double *pj);
int vigen_nbody_from_jacobi(const vigen_nbody *sys, const double *q, const double *pj, double *x, double *p);
int vigen_nbody_to_democratic(const vigen_nbody *sys, const double *x, const double *p, double *q, double *pd);
int vigen_nbody_from_democratic(const vigen_nbody *sys, const double *q, const double *pd, double *x, double *p);
/* The same by coordinate code (VIGEN_NBODY_JACOBI or _DEMOCRATIC;
 * VIGEN_EINVAL for another). */
int vigen_nbody_to_coordinates(const vigen_nbody *sys, int coords, const double *x, const double *p, double *q,
                               double *pc);
int vigen_nbody_from_coordinates(const vigen_nbody *sys, int coords, const double *q, const double *pc, double *x,
                                 double *p);

/* ---- flows (vigen_flow_fn; ctx is the vigen_nbody) --------------------- */

/* Jacobi: the Kepler drift of every body and the centre of mass; the
 * interaction kick p -= h dH_interaction/dq. */
int vigen_nbody_jacobi_kepler(double t, double h, double *q, double *p, void *ctx);
int vigen_nbody_jacobi_interaction(double t, double h, double *q, double *p, void *ctx);
/* Jacobi: the flow of the double bracket
 *   Phi = {{H_kepler, H_interaction}, H_interaction} = sum_{i>=1} |dB/dq_i|^2 / m'_i
 * (B = H_interaction, m'_i = m_i M_{i-1}/M_i) by time h (a method passes
 * tau = c h^3, of either sign): Phi depends on q only, so its flow is the
 * kick p -= h dPhi/dq = h 2 Hess(B) M^-1 dB/dq, computed exactly (the
 * Hessians of the pair potentials along the Jacobi map); q and p_0
 * unchanged.  The modified kicks of SABAC_n and of the kernels of Wisdom,
 * Holman and Touma (1996) compose it with the interaction kick.  Above 32
 * bodies its first call allocates O(n^2) scratch in the system
 * (VIGEN_ENOMEM when it cannot, the state unchanged). */
int vigen_nbody_jacobi_interaction_gradient(double t, double h, double *q, double *p, void *ctx);
/* Democratic heliocentric: the Kepler drift, the planet-planet kick, and
 * the jump q_i += h (p_1 + ... + p_{n-1})/m_0 (i >= 1). */
int vigen_nbody_democratic_kepler(double t, double h, double *q, double *p, void *ctx);
int vigen_nbody_democratic_interaction(double t, double h, double *q, double *p, void *ctx);
int vigen_nbody_democratic_jump(double t, double h, double *q, double *p, void *ctx);

/* The whole H in the coordinates: its vector field (q' = dH/dp into dq,
 * p' = -dH/dq into dp; VIGEN_SUCCESS or VIGEN_ENONFINITE) and its value. */
int vigen_nbody_jacobi_vector_field(double t, const double *q, const double *p, double *dq, double *dp, void *ctx);
int vigen_nbody_democratic_vector_field(double t, const double *q, const double *p, double *dq, double *dp,
                                        void *ctx);
double vigen_nbody_jacobi_energy(double t, const double *q, const double *p, void *ctx);
double vigen_nbody_democratic_energy(double t, const double *q, const double *p, void *ctx);

/* Fills *out with the split problem of sys in coordinates coords: dim 3n,
 * ctx sys, the flows in the order of vigen_nbody_flow_name (Jacobi:
 * "kepler", "interaction", "interaction_gradient"; democratic: "kepler",
 * "interaction", "jump"),
 * the vector field and H above.  VIGEN_SUCCESS or VIGEN_EINVAL. */
int vigen_nbody_split(vigen_nbody *sys, int coords, vigen_split_problem *out);
/* The name of flow k of the coordinates' splitting; NULL past the end. */
const char *vigen_nbody_flow_name(int coords, size_t k);

/* ---- symplectic correctors (Wisdom, Holman & Touma 1996) -------------- */

/* The kernel a corrector belongs to: kick-drift-kick
 * (interaction h/2, kepler h, interaction h/2) or drift-kick-drift. */
enum { VIGEN_NBODY_KERNEL_KDK = 0, VIGEN_NBODY_KERNEL_DKD = 1 };

/* Applies the corrector of the given order (3, 5, 7, 11 or 17) for the
 * kernel to (q, p) in the Jacobi split problem's coordinates: direction
 * +1 the corrector C (mapped state -> true state: apply to a copy of the
 * state for output), -1 its inverse (true state -> mapped state: apply
 * once before the first step).  The kernel's energy error O(eps h^2)
 * becomes O(eps h^(order+1) + eps^2 h^2).  The corrector is a composition
 * of the Kepler flow K and the interaction flow I with a_i = i sqrt(7/40)
 * and b_i of vigen_nbody_corrector_coefficients, m = (order - 1)/2:
 *   C    = for i = 1..m:  K(-a_i h) I(b_i h) K(2 a_i h) I(-b_i h) K(-a_i h)
 *   C^-1 = for i = m..1:  K(a_i h) I(b_i h) K(-2 a_i h) I(-b_i h) K(a_i h)
 * (each line applied left to right).  Returns VIGEN_SUCCESS, a flow's
 * status (q and p unchanged) or VIGEN_EINVAL (an order not offered, a bad
 * kernel or direction). */
int vigen_nbody_corrector_apply(vigen_nbody *sys, int kernel, int order, double h, double *q, double *p,
                                int direction);
/* The same with the flows of any split problem (flow[0] the Kepler part,
 * flow[1] the perturbation), for problems split like the N-body one;
 * VIGEN_ENOMEM when the copy of the state cannot be allocated. */
int vigen_split_corrector_apply(const vigen_split_problem *sp, int kernel, int order, double h, double *q,
                                double *p, int direction);
/* The coefficients of the corrector: m = (order - 1)/2 pairs a[i], b[i]
 * (arrays of at least 8); returns m, or 0 for an order or kernel not
 * offered. */
int vigen_nbody_corrector_coefficients(int kernel, int order, double *a, double *b);

#ifdef __cplusplus
}
#endif

#endif
