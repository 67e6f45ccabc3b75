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
 * by k (du - 3 (d.du) d/|d|^2), du = u_j - u_i. */
#include <math.h>
#include <string.h>
#include "nbody_internal.h"

enum { STACK_BODIES = 32 };

/* The change of the pair forces of x along u: df = -Hess(V) u (pairs
 * i < j, the pair (0, 1) left out). */
static void pair_force_change(const vigen_nbody *sys, const double *x, const double *u, double *df)
{
    size_t n = sys->n;
    memset(df, 0, 3 * n * sizeof *df);
    for (size_t i = 0; i < n; i++)
        for (size_t j = i + 1; j < n; j++) {
            if (i == 0 && j == 1) continue;
            double d[3], du[3], r2 = 0, dot = 0;
            for (int c = 0; c < 3; c++) {
                d[c] = x[3 * j + c] - x[3 * i + c];
                du[c] = u[3 * j + c] - u[3 * i + c];
                r2 += d[c] * d[c];
                dot += d[c] * du[c];
            }
            double k = sys->G * sys->m[i] * sys->m[j] / (r2 * sqrt(r2)), s = 3 * dot / r2;
            for (int c = 0; c < 3; c++) {
                double e = k * (du[c] - s * d[c]);
                df[3 * i + c] += e;
                df[3 * j + c] -= e;
            }
        }
}

int vigen_nbody_jacobi_interaction_gradient(double t, double h, double *q, double *p, void *ctx)
{
    (void)t;
    vigen_nbody *sys = ctx;
    if (sys == NULL || q == NULL || p == NULL || !isfinite(h)) return VIGEN_EINVAL;
    size_t n = sys->n, d = 3 * n;
    double local[15 * STACK_BODIES], *work = n <= STACK_BODIES ? local : sys->work;
    double *x = work, *f = work + d, *u = work + 2 * d, *df = work + 3 * d, *pn = work + 4 * d;
    /* f = -dB/dq; w = -f/m' into u, then u = A^-1 w */
    vigen_nbody_jacobi_interaction_force(sys, q, x, f);
    for (int c = 0; c < 3; c++) u[c] = 0;
    for (size_t k = 3; k < d; k++) u[k] = -f[k] / sys->mred[k / 3];
    vigen_nbody_jacobi_positions_inverse(sys, u, u);
    pair_force_change(sys, x, u, df);
    vigen_nbody_jacobi_momenta(sys, df, df);
    /* the Jacobi terms G m_i M_{i-1}/|q_i|, i >= 2: their force c q_i/|q_i|^3
     * changes along w_i by c (w_i - 3 (q_i.w_i) q_i/|q_i|^2)/|q_i|^3 */
    for (size_t i = 2; i < n; i++) {
        const double *qi = q + 3 * i;
        double w[3], r2 = 0, dot = 0;
        for (int c = 0; c < 3; c++) {
            w[c] = -f[3 * i + c] / sys->mred[i];
            r2 += qi[c] * qi[c];
            dot += qi[c] * w[c];
        }
        double k = sys->G * sys->m[i] * sys->interior[i - 1] / (r2 * sqrt(r2)), s = 3 * dot / r2;
        for (int c = 0; c < 3; c++) df[3 * i + c] += k * (w[c] - s * qi[c]);
    }
    /* df = -Hess(B) w: p -= h 2 Hess(B) w */
    for (int c = 0; c < 3; c++) pn[c] = p[c];
    for (size_t k = 3; k < d; k++) pn[k] = p[k] + 2 * h * df[k];
    for (size_t k = 0; k < d; k++)
        if (!isfinite(pn[k])) return VIGEN_ENONFINITE;
    memcpy(p, pn, d * sizeof *p);
    return VIGEN_SUCCESS;
}
