/* correctors.c — the symplectic correctors of Wisdom, Holman & Touma
 * (1996, Fields Inst. Commun. 10, 217) for a kernel of H = A + eps B with
 * exact flows of A (Kepler) and B (interaction).
 *
 * The kernel's modified Hamiltonian is, to first order in eps,
 * A + eps f(h ad_A) B with f(x) = (x/2)/tanh(x/2) for kick-drift-kick and
 * (x/2)/sinh(x/2) for drift-kick-drift.  A corrector C = exp(eps W) with
 * h ad_A W = (f(h ad_A) - 1) B conjugates the kernel into the exact flow up
 * to the order kept in W.  W is built from the pairs
 *   Z(a, b) = X(a, b) X(-a, -b),  X(a, b) = K(a h) I(b h) K(-a h),
 * whose generator is 2 b h sinh(a h ad_A) B + O(eps^2): with a_i = i alpha,
 * alpha = sqrt(7/40), the b_i solve sum_i 2 b_i a_i^k / k! = [x^k] (f(x) - 1)/x
 * for the odd k < order - 1.  The b_i below are those rational solutions
 * (times 1/alpha), computed exactly (Bernoulli numbers) and rounded to 17
 * digits; the order-3 value is 1/(48 alpha) for drift-kick-drift, as in
 * Wisdom, Holman & Touma and Rein & Tamayo (2015, MNRAS 452, 376). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "nbody_internal.h"

enum { MAX_PAIRS = 8 };

typedef struct {
    int order, pairs;
    double b[2][MAX_PAIRS]; /* [kernel][i] */
} corrector_row;

static const corrector_row rows[] = {
    { 3, 1, { { 0.09960238411119947 }, { -0.049801192055599735 } } },
    { 5, 2, { { 0.15177506150278014, -0.026086338695790337 }, { -0.083001986759332892, 0.016600397351866578 } } },
    { 7, 3,
      { { 0.18668590685694854, -0.054015014979125051, 0.0069821690708336784 },
        { -0.107928798186255, 0.036541846493404263, -0.0049853622853844212 } } },
    { 11, 5,
      { { 0.23427635945511453, -0.10464537238581183, 0.031937934539971711, -0.0059325720498267966,
          0.0005066508014201308 },
        { -0.14518678949768548, 0.076243227362577301, -0.024618157184039893, 0.0046974430584590708,
          -0.00040723159295709303 } } },
    { 17, 8,
      { { 0.28229004358307257, -0.16810655651392713, 0.079009431783230329, -0.028628934853513029,
          0.0077379362514915766, -0.0014712131404797559, 0.00017569288875457891, -9.9193769398896663e-6 },
        { -0.18611220754285192, 0.13038572715275579, -0.064844397729427161, 0.024143521644684582,
          -0.0066265154138761311, 0.0012719996615163532, -0.00015287271045587148, 8.669483094674716e-6 } } },
};

int vigen_nbody_corrector_coefficients(int kernel, int order, double *a, double *b)
{
    if (kernel != VIGEN_NBODY_KERNEL_KDK && kernel != VIGEN_NBODY_KERNEL_DKD) return 0;
    for (size_t r = 0; r < sizeof rows / sizeof rows[0]; r++) {
        if (rows[r].order != order) continue;
        double alpha = sqrt(7.0 / 40.0);
        for (int i = 0; i < rows[r].pairs; i++) {
            if (a) a[i] = (i + 1) * alpha;
            if (b) b[i] = rows[r].b[kernel][i];
        }
        return rows[r].pairs;
    }
    return 0;
}

/* The corrector's flows in place; (q, p) may be left changed on failure
 * (the callers restore it). */
static int corrector_run(const vigen_split_problem *sp, int kernel, int order, double h, double *q, double *p,
                         int direction)
{
    double a[MAX_PAIRS], b[MAX_PAIRS];
    int m = vigen_nbody_corrector_coefficients(kernel, order, a, b);
    if (m == 0 || (direction != 1 && direction != -1) || sp->nflows < 2 || !isfinite(h)) return VIGEN_EINVAL;
    vigen_flow_fn K = sp->flow[0], I = sp->flow[1];
    for (int k = 0; k < m; k++) {
        /* C = Z(-a_1, b_1) ... Z(-a_m, b_m) and C^-1 = Z(a_m, b_m) ... Z(a_1, b_1),
         * Z(a, b) the inverse of Z(-a, b); the sign of a in C is that of the
         * maps applied in sequence (the generators above compose in the
         * opposite order) */
        int i = direction > 0 ? k : m - 1 - k;
        double ah = -direction * a[i] * h, bh = b[i] * h;
        int st;
        if ((st = K(0, ah, q, p, sp->ctx)) != VIGEN_SUCCESS) return st;
        if ((st = I(0, bh, q, p, sp->ctx)) != VIGEN_SUCCESS) return st;
        if ((st = K(0, -2 * ah, q, p, sp->ctx)) != VIGEN_SUCCESS) return st;
        if ((st = I(0, -bh, q, p, sp->ctx)) != VIGEN_SUCCESS) return st;
        if ((st = K(0, ah, q, p, sp->ctx)) != VIGEN_SUCCESS) return st;
    }
    return VIGEN_SUCCESS;
}

static int corrector_restoring(const vigen_split_problem *sp, int kernel, int order, double h, double *q, double *p,
                               int direction, double *saved)
{
    size_t d = sp->dim;
    memcpy(saved, q, d * sizeof *q);
    memcpy(saved + d, p, d * sizeof *p);
    int st = corrector_run(sp, kernel, order, h, q, p, direction);
    if (st != VIGEN_SUCCESS) {
        memcpy(q, saved, d * sizeof *q);
        memcpy(p, saved + d, d * sizeof *p);
    }
    return st;
}

int vigen_split_corrector_apply(const vigen_split_problem *sp, int kernel, int order, double h, double *q,
                                double *p, int direction)
{
    if (sp == NULL || sp->flow == NULL || q == NULL || p == NULL) return VIGEN_EINVAL;
    double *saved = malloc(2 * sp->dim * sizeof *saved);
    if (saved == NULL) return VIGEN_ENOMEM;
    int st = corrector_restoring(sp, kernel, order, h, q, p, direction, saved);
    free(saved);
    return st;
}

int vigen_nbody_corrector_apply(vigen_nbody *sys, int kernel, int order, double h, double *q, double *p,
                                int direction)
{
    vigen_split_problem sp;
    if (sys == NULL || q == NULL || p == NULL) return VIGEN_EINVAL;
    vigen_nbody_split(sys, VIGEN_NBODY_JACOBI, &sp);
    /* the copy of the state on the stack for up to 32 bodies (thread-safe
     * like the flows), in the system's memory above */
    double local[6 * 32];
    return corrector_restoring(&sp, kernel, order, h, q, p, direction, sys->n <= 32 ? local : sys->saved);
}
