/* hand_gni_gauss.h — the strongest hand-written implicit mechanical stepper
 * we know how to write, the anchor of the implicit rows of peer_bench.c: an
 * s-stage Gauss collocation method (or, with GNI_LOBATTO, the Lobatto
 * IIIA-IIIB pair of s = 3) for q'' = M^-1 f(t, q) in the style of Hairer's
 * GNI_IRK2 (Hairer, Lubich & Wanner, GNI, sec. VIII.6; the GniCodes
 * Fortran):
 *   - Nystrom form: the unknowns are the position increments Z_i = Q_i - q,
 *       Z_i = c_i h v + h^2 sum_j AA_ij M^-1 F_j,   F_j = f(t + c_j h, q + Z_j),
 *     with AA = A A precomputed (A_ij = alpha_j(c_i), alpha_j(x) the integral
 *     of l_j over [0, x], l_j the Lagrange polynomials at the c);
 *   - fixed-point iteration, stopped when the increment stops decreasing
 *     (round-off reached) or vanishes;
 *   - the start from the previous step's collocation polynomial:
 *       Z_i = c_i h v + h^2 sum_k E_ik M^-1 F_k(previous step),
 *       E_ik = sum_j alpha_j(1 + c_i) A_jk - bb_k - c_i b_k   (equal steps),
 *     the position polynomial q + h sum_j alpha_j(theta) V_j of the previous
 *     step at theta = 1 + c_i, less the new q;
 *   - the update q += h v + h^2 sum bb_j M^-1 F_j (bb = b A = b (1 - c)),
 *     p += h sum b_j F_j
 *     with compensated (TwoSum) sums.
 * Lobatto IIIA-IIIB s = 3 (c = 0, 1/2, 1; A the IIIA matrix, At the IIIB
 * one, whose last column is zero): the same with AA = A At, bb = b At and E
 * built on At.  Q_1 = q and the last stage's force enters no stage, so a
 * sweep evaluates the middle stage's force only; the force at the new q
 * (Q_3 = q1 in exact arithmetic, taken at the compensated q1) closes the
 * step and is the next step's first (first same as last): 1 + sweeps forces
 * per step, and one more at the start of a trajectory.
 * The dimension is static and the force a direct call, so the compiler sees
 * everything.  Instantiate with
 *   #define GNI_NAME name   #define GNI_S 2 or 3   #define GNI_DIM n
 *   #define GNI_LOBATTO 1   (optional, with GNI_S 3)
 *   #define GNI_FORCE f     (void f(double t, const double *q, double *out, void *ctx))
 *   #define GNI_VEL(k, x)   M^-1 applied to component k of x
 *   #include "hand_gni_gauss.h"
 * A measurement anchor, not product code. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define GNI_CAT2(a, b) a##b
#define GNI_CAT(a, b) GNI_CAT2(a, b)
#define GNI_FN(x) GNI_CAT(GNI_NAME, x)

typedef struct {
    double c[GNI_S], b[GNI_S], bb[GNI_S];     /* nodes, weights, bb_j = b_j (1 - c_j) */
    double AA[GNI_S][GNI_S], E[GNI_S][GNI_S];   /* AA = A At, E on At (At = A for Gauss) */
    double Z[GNI_S][GNI_DIM], F[GNI_S][GNI_DIM];
    double cq[GNI_DIM], cp[GNI_DIM];
    double hprev;
    int hist;
    unsigned long forces, sweeps;
} GNI_FN(_ws);

/* alpha_j(x) for the Lagrange basis at the nodes c (monomial expansion) */
static double GNI_FN(_alpha)(const double *c, int j, double x)
{
    double a[GNI_S] = { 1 }, den = 1;     /* coefficients of l_j, low degree first */
    int deg = 0;
    for (int m = 0; m < GNI_S; m++) {
        if (m == j) continue;
        den *= c[j] - c[m];
        for (int k = deg + 1; k > 0; k--) a[k] = a[k - 1] - c[m] * a[k];
        a[0] = -c[m] * a[0];
        deg++;
    }
    double s = 0, xp = x;
    for (int k = 0; k <= deg; k++, xp *= x) s += a[k] / den * xp / (k + 1);
    return s;
}

static GNI_FN(_ws) *GNI_FN(_alloc)(void)
{
    GNI_FN(_ws) *w = calloc(1, sizeof *w);
    if (w == NULL) return NULL;
#if defined(GNI_LOBATTO) && GNI_S == 3
    const double c[3] = { 0, 0.5, 1 }, b[3] = { 1.0 / 6, 4.0 / 6, 1.0 / 6 };
#elif defined(GNI_LOBATTO)
#error "GNI_LOBATTO needs GNI_S 3"
#elif GNI_S == 2
    const double r = sqrt(3.0) / 6;
    const double c[2] = { 0.5 - r, 0.5 + r }, b[2] = { 0.5, 0.5 };
#elif GNI_S == 3
    const double r = sqrt(15.0) / 10;
    const double c[3] = { 0.5 - r, 0.5, 0.5 + r }, b[3] = { 5.0 / 18, 8.0 / 18, 5.0 / 18 };
#else
#error "GNI_S must be 2 or 3"
#endif
    double A[GNI_S][GNI_S], At[GNI_S][GNI_S];
    for (int i = 0; i < GNI_S; i++) {
        w->c[i] = c[i];
        w->b[i] = b[i];
        for (int j = 0; j < GNI_S; j++) A[i][j] = GNI_FN(_alpha)(c, j, c[i]);
    }
    /* At: the symplectic partner b_i at_ij + b_j a_ji = b_i b_j (A itself
     * for Gauss, Lobatto IIIB for Lobatto IIIA); bb = b At */
    for (int i = 0; i < GNI_S; i++)
        for (int j = 0; j < GNI_S; j++) {
#ifdef GNI_LOBATTO
            At[i][j] = b[j] - b[j] * A[j][i] / b[i];
#else
            At[i][j] = A[i][j];
#endif
        }
    for (int k = 0; k < GNI_S; k++) {
#ifdef GNI_LOBATTO
        w->bb[k] = 0;
        for (int j = 0; j < GNI_S; j++) w->bb[k] += b[j] * At[j][k];
#else
        w->bb[k] = b[k] * (1 - c[k]);
#endif
    }
    for (int i = 0; i < GNI_S; i++)
        for (int k = 0; k < GNI_S; k++) {
            double aa = 0, e = 0;
            for (int j = 0; j < GNI_S; j++) {
                aa += A[i][j] * At[j][k];
                e += GNI_FN(_alpha)(c, j, 1 + c[i]) * At[j][k];
            }
            w->AA[i][k] = aa;
            w->E[i][k] = e - w->bb[k] - c[i] * b[k];
        }
    return w;
}

static void GNI_FN(_reset)(GNI_FN(_ws) *w)
{
    w->hist = 0;
    memset(w->cq, 0, sizeof w->cq);
    memset(w->cp, 0, sizeof w->cp);
}

static inline double GNI_FN(_twosum)(double x, double d, double *c)
{
    double e = d + *c, s = x + e, bb = s - x;
    *c = (x - (s - bb)) + (e - bb);
    return s;
}

#ifdef GNI_LOBATTO
/* 0 on success, 1 when the iteration diverged or did not settle.  F[0]
 * holds f(t, q) from the previous step's end (w->hist). */
static int GNI_FN(_step)(GNI_FN(_ws) *w, double *t, double *q, double *p, double h, void *ctx)
{
    const double h2 = h * h, c1 = w->c[1];
    double v[GNI_DIM];
    for (size_t k = 0; k < GNI_DIM; k++) v[k] = GNI_VEL(k, p[k]);
    if (w->hist && w->hprev == h) {
        for (size_t k = 0; k < GNI_DIM; k++) {
            double s = 0;
            for (int j = 0; j < GNI_S; j++) s += w->E[1][j] * GNI_VEL(k, w->F[j][k]);
            w->Z[1][k] = c1 * h * v[k] + h2 * s;
        }
        memcpy(w->F[0], w->F[2], sizeof w->F[0]);
    } else {
        if (!w->hist) {
            GNI_FORCE(*t, q, w->F[0], ctx);
            w->forces++;
        } else {
            memcpy(w->F[0], w->F[2], sizeof w->F[0]);
        }
        for (size_t k = 0; k < GNI_DIM; k++) w->Z[1][k] = c1 * h * v[k] + 0.5 * c1 * c1 * h2 * GNI_VEL(k, w->F[0][k]);
    }
    double rden[GNI_DIM];
    for (size_t k = 0; k < GNI_DIM; k++) rden[k] = 1 / (fabs(q[k]) > 0.1 ? fabs(q[k]) : 0.1);
    const double tiny = 1e-32 * GNI_DIM, settled = 1e-20 * GNI_DIM;
    const double a0 = w->AA[1][0], a1 = w->AA[1][1];
    double dynold = 0;
    for (int it = 1;; it++) {
        double Q[GNI_DIM];
        for (size_t k = 0; k < GNI_DIM; k++) Q[k] = q[k] + w->Z[1][k];
        GNI_FORCE(*t + c1 * h, Q, w->F[1], ctx);
        w->forces++;
        w->sweeps++;
        double dyno = 0;
        for (size_t k = 0; k < GNI_DIM; k++) {
            double z = c1 * h * v[k] + h2 * GNI_VEL(k, a0 * w->F[0][k] + a1 * w->F[1][k]);
            double d = (z - w->Z[1][k]) * rden[k];
            dyno += d * d;
            w->Z[1][k] = z;
        }
        if (!(dyno < 1e300)) return 1;
        if (dyno < tiny || (it >= 2 && dyno >= dynold && dyno < settled)) break;
        if (it >= 50) return 1;
        dynold = dyno;
    }
    /* bb_3 = 0: the last stage's force enters q1 no more than the stages */
    for (size_t k = 0; k < GNI_DIM; k++)
        q[k] = GNI_FN(_twosum)(q[k], h * v[k] + h2 * GNI_VEL(k, w->bb[0] * w->F[0][k] + w->bb[1] * w->F[1][k]),
                               &w->cq[k]);
    GNI_FORCE(*t + h, q, w->F[2], ctx);
    w->forces++;
    for (size_t k = 0; k < GNI_DIM; k++)
        p[k] = GNI_FN(_twosum)(p[k], h * (w->b[0] * w->F[0][k] + w->b[1] * w->F[1][k] + w->b[2] * w->F[2][k]),
                               &w->cp[k]);
    *t += h;
    w->hprev = h;
    w->hist = 1;
    return 0;
}
#else
/* 0 on success, 1 when the iteration diverged or did not settle */
static int GNI_FN(_step)(GNI_FN(_ws) *w, double *t, double *q, double *p, double h, void *ctx)
{
    const double h2 = h * h;
    double v[GNI_DIM];
    for (size_t k = 0; k < GNI_DIM; k++) v[k] = GNI_VEL(k, p[k]);
    if (w->hist && w->hprev == h) {
        for (int i = 0; i < GNI_S; i++)
            for (size_t k = 0; k < GNI_DIM; k++) {
                double s = 0;
                for (int j = 0; j < GNI_S; j++) s += w->E[i][j] * GNI_VEL(k, w->F[j][k]);
                w->Z[i][k] = w->c[i] * h * v[k] + h2 * s;
            }
    } else {
        GNI_FORCE(*t, q, w->F[0], ctx);
        w->forces++;
        for (int i = 0; i < GNI_S; i++)
            for (size_t k = 0; k < GNI_DIM; k++)
                w->Z[i][k] = w->c[i] * h * v[k] + 0.5 * w->c[i] * w->c[i] * h2 * GNI_VEL(k, w->F[0][k]);
    }
    /* the increment's scale per component, max(|q_k|, 0.1) as GNI_IRK2, as
     * reciprocals; the test compares mean squares (no square root) */
    double rden[GNI_DIM];
    for (size_t k = 0; k < GNI_DIM; k++) rden[k] = 1 / (fabs(q[k]) > 0.1 ? fabs(q[k]) : 0.1);
    const double tiny = 1e-32 * (GNI_S * GNI_DIM), settled = 1e-20 * (GNI_S * GNI_DIM);
    double dynold = 0;
    for (int it = 1;; it++) {
        double Q[GNI_DIM];
        for (int j = 0; j < GNI_S; j++) {
            for (size_t k = 0; k < GNI_DIM; k++) Q[k] = q[k] + w->Z[j][k];
            GNI_FORCE(*t + w->c[j] * h, Q, w->F[j], ctx);
        }
        w->forces += GNI_S;
        w->sweeps++;
        double dyno = 0;
        for (int i = 0; i < GNI_S; i++)
            for (size_t k = 0; k < GNI_DIM; k++) {
                double s = 0;
                for (int j = 0; j < GNI_S; j++) s += w->AA[i][j] * GNI_VEL(k, w->F[j][k]);
                double z = w->c[i] * h * v[k] + h2 * s, d = (z - w->Z[i][k]) * rden[k];
                dyno += d * d;
                w->Z[i][k] = z;
            }
        if (!(dyno < 1e300)) return 1;
        /* stop at round-off: the increment vanished, or stopped decreasing
         * once small */
        if (dyno < tiny || (it >= 2 && dyno >= dynold && dyno < settled)) break;
        if (it >= 50) return 1;
        dynold = dyno;
    }
    for (size_t k = 0; k < GNI_DIM; k++) {
        double sq = 0, sp = 0;
        for (int j = 0; j < GNI_S; j++) {
            sq += w->bb[j] * w->F[j][k];
            sp += w->b[j] * w->F[j][k];
        }
        q[k] = GNI_FN(_twosum)(q[k], h * v[k] + h2 * GNI_VEL(k, sq), &w->cq[k]);
        p[k] = GNI_FN(_twosum)(p[k], h * sp, &w->cp[k]);
    }
    *t += h;
    w->hprev = h;
    w->hist = 1;
    return 0;
}
#endif

#undef GNI_FN
#undef GNI_LOBATTO
#undef GNI_NAME
#undef GNI_S
