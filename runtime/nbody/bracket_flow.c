/* bracket_flow.c — the flow of the Jacobi splitting's double bracket
 * Phi = {{H_kepler, H_interaction}, H_interaction} = sum_i |dB/dq_i|^2 / m'_i
 * (B = H_interaction, a function of the positions only; m'_i the Jacobi
 * masses), which the methods with modified kicks (SABAC_n, the kernels of
 * Wisdom, Holman and Touma) advance by small times tau ~ h^3.  Phi depends
 * on q alone, so its flow is the kick p -= tau dPhi/dq with
 *   dPhi/dq = 2 Hess(B) w,   w = M^-1 dB/dq (w_i = (dB/dq_i)/m'_i, w_0 = 0),
 * computed exactly: B = V(A^-1 q) + sum_{i>=2} G m_i M_{i-1}/|q_i| (V the
 * pairwise potential without the pair (0, 1), which cancels the Jacobi term
 * of body 1), so Hess(B) w = A^-T Hess(V) A^-1 w plus the Hessians of the
 * Jacobi terms; A^-1 maps w like positions, A^-T the result like forces
 * (nbody.c).  The Hessian of one pair's -G m_i m_j/|d| (d = x_j - x_i)
 * along a displacement u changes the pair force k d (k = G m_i m_j/|d|^3)
 * by k (du - 3 (d.du) d/|d|^2), du = u_j - u_i: the pass over the pairs
 * for the force keeps d, k and 3/|d|^2 of each pair (geo) for the pass of
 * the Hessian. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "nbody_internal.h"

enum { STACK_BODIES = 32 };

int vigen_nbody_jacobi_interaction_gradient(double t, double h, double *q, double *p, void *ctx)
{
    (void)t;
    vigen_nbody *sys = ctx;
    if (sys == NULL || q == NULL || p == NULL || !isfinite(h)) return VIGEN_EINVAL;
    size_t n = sys->n, d = 3 * n;
    double local[15 * STACK_BODIES], lgeo[VIGEN_NBODY_GEO(STACK_BODIES)];
    if (n > STACK_BODIES && sys->geo == NULL) {
        sys->geo = n < ((size_t)1 << 24) ? malloc(VIGEN_NBODY_GEO(n) * sizeof *sys->geo) : NULL;
        if (sys->geo == NULL) return VIGEN_ENOMEM;
    }
    double *work = n <= STACK_BODIES ? local : sys->work, *geo = n <= STACK_BODIES ? lgeo : sys->geo;
    double *x = work, *f = work + d, *w = work + 2 * d, *u = work + 3 * d, *df = work + 4 * d, *pn = x;
    /* f = -dB/dq with the geometry of its terms; w = -f/m', u = A^-1 w */
    vigen_nbody_jacobi_interaction_force(sys, q, x, f, geo);
    for (int c = 0; c < 3; c++) w[c] = 0;
    for (size_t i = 1; i < n; i++) {
        double mi = sys->mred[i];
        for (int c = 0; c < 3; c++) w[3 * i + c] = -f[3 * i + c] / mi;
    }
    vigen_nbody_jacobi_positions_inverse(sys, w, u);
    vigen_nbody_jacobi_pair_hessian(sys, geo, u, df);
    /* df mapped like forces, plus the Jacobi terms G m_i M_{i-1}/|q_i|,
     * i >= 2, whose force k q_i changes along w_i by k (w_i - 3 (q_i.w_i)
     * q_i/|q_i|^2); df = -Hess(B) w: p -= h 2 Hess(B) w */
    const double *jgeo = geo + VIGEN_NBODY_GEO(n) - 2 * n;
    double P[3] = { df[0], df[1], df[2] }, h2 = 2 * h, z = 0;
    for (int c = 0; c < 3; c++) {
        pn[c] = p[c];
        z += 0 * p[c];
    }
    for (size_t i = 1; i < n; i++) {
        double *gi = df + 3 * i;
        for (int c = 0; c < 3; c++) {
            P[c] += gi[c];
            gi[c] -= sys->frac[i] * P[c];
        }
        if (i >= 2) {
            const double *qi = q + 3 * i, *wi = w + 3 * i;
            double k = jgeo[0], s = jgeo[1] * (qi[0] * wi[0] + qi[1] * wi[1] + qi[2] * wi[2]);
            for (int c = 0; c < 3; c++) gi[c] += k * (wi[c] - s * qi[c]);
            jgeo += 2;
        }
        for (int c = 0; c < 3; c++) {
            pn[3 * i + c] = p[3 * i + c] + h2 * gi[c];
            z += 0 * pn[3 * i + c];
        }
    }
    /* z is 0 when every value is finite, NaN otherwise */
    if (z != 0) return VIGEN_ENONFINITE;
    memcpy(p, pn, d * sizeof *p);
    return VIGEN_SUCCESS;
}
