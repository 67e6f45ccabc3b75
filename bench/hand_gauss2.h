/* hand_gauss2.h — a careful hand-written 2-stage Gauss stepper (fixed-point
 * iteration with Gauss-Seidel sweeps over the partitions, the same
 * round-off-aware stopping rule and starting values extrapolated from the
 * previous step as the emitted steppers, compensated update), calling the
 * problem's gradients directly.  Instantiate with
 *   #define HG2_NAME name  #define HG2_DQ dq_fn  #define HG2_DP dp_fn
 *   #include "hand_gauss2.h"
 * where dq_fn, dp_fn have the vigen_grad_fn signature (static inline is best). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define HG2_CAT2(a, b) a##b
#define HG2_CAT(a, b) HG2_CAT2(a, b)
#define HG2_FN(x) HG2_CAT(HG2_NAME, x)

#ifndef HG2_ABSBITS
#define HG2_ABSBITS
#include <stdint.h>
/* |x| as bits: integer order = order of magnitude, NaN above infinity, so a
 * maximum over them cannot skip a NaN increment */
static inline uint64_t hg2_absbits(double x)
{
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    return u & UINT64_C(0x7fffffffffffffff);
}
static inline double hg2_bits_value(uint64_t u) { double d; memcpy(&d, &u, sizeof d); return d; }
#endif

typedef struct {
    size_t n;
    double *Q1, *Q2, *P1, *P2, *F1, *F2, *G1, *G2, *Fo1, *Fo2, *Go1, *Go2, *cq, *cp;
    double hprev;
    int hist;
    unsigned long evals, iters;
} HG2_FN(_ws);

static HG2_FN(_ws) *HG2_FN(_alloc)(size_t n)
{
    HG2_FN(_ws) *w = calloc(1, sizeof *w);
    double *m = calloc(14 * n, sizeof(double));
    w->n = n;
    double **ptrs[] = { &w->Q1, &w->Q2, &w->P1, &w->P2, &w->F1, &w->F2, &w->G1, &w->G2,
                        &w->Fo1, &w->Fo2, &w->Go1, &w->Go2, &w->cq, &w->cp };
    for (int k = 0; k < 14; k++) *ptrs[k] = m + (size_t)k * n;
    return w;
}

static void HG2_FN(_free)(HG2_FN(_ws) *w) { free(w->Q1); free(w); }

static int HG2_FN(_step)(HG2_FN(_ws) *w, double *t, double *q, double *p, double h, void *ctx)
{
    static const double s3 = 1.7320508075688772;       /* sqrt(3) */
    const double a11 = 0.25, a12 = 0.25 - s3 / 6, a21 = 0.25 + s3 / 6, a22 = 0.25;
    const double c1 = 0.5 - s3 / 6, c2 = 0.5 + s3 / 6;
    const size_t n = w->n;
    double *Q1 = w->Q1, *Q2 = w->Q2, *P1 = w->P1, *P2 = w->P2;
    double *F1 = w->F1, *F2 = w->F2, *G1 = w->G1, *G2 = w->G2;
    if (w->hist) {
        double r = h / w->hprev, x1 = 1 + c1 * r, x2 = 1 + c2 * r, d = c2 - c1;
        double w11 = (c2 - x1) / d, w12 = (x1 - c1) / d, w21 = (c2 - x2) / d, w22 = (x2 - c1) / d;
        for (size_t k = 0; k < n; k++) {
            F1[k] = w11 * w->Fo1[k] + w12 * w->Fo2[k];
            F2[k] = w21 * w->Fo1[k] + w22 * w->Fo2[k];
            G1[k] = w11 * w->Go1[k] + w12 * w->Go2[k];
            G2[k] = w21 * w->Go1[k] + w22 * w->Go2[k];
        }
    } else {
        HG2_DP(*t, q, p, F1, ctx);
        HG2_DQ(*t, q, p, G1, ctx);
        w->evals += 2;
        memcpy(F2, F1, n * sizeof(double));
        memcpy(G2, G1, n * sizeof(double));
    }
    /* starting stage values and their scales, then Gauss-Seidel sweeps:
     * G(Q, P), P, F(Q, P), Q */
    double sq = 0, sp = 0;
    for (size_t k = 0; k < n; k++) {
        Q1[k] = q[k] + h * (a11 * F1[k] + a12 * F2[k]);
        Q2[k] = q[k] + h * (a21 * F1[k] + a22 * F2[k]);
        P1[k] = p[k] - h * (a11 * G1[k] + a12 * G2[k]);
        P2[k] = p[k] - h * (a21 * G1[k] + a22 * G2[k]);
        double e1 = fabs(Q1[k]), e2 = fabs(Q2[k]);
        sq = e1 > sq ? e1 : sq; sq = e2 > sq ? e2 : sq;
        e1 = fabs(P1[k]); e2 = fabs(P2[k]);
        sp = e1 > sp ? e1 : sp; sp = e2 > sp ? e2 : sp;
    }
    if (sq == 0) sq = 1;
    if (sp == 0) sp = 1;
    double prev1 = -1, prev2 = -1;
    int strikes = 0, it = 0;
    for (;;) {
        uint64_t dq = 0, dp = 0;
        HG2_DQ(*t + c1 * h, Q1, P1, G1, ctx);
        HG2_DQ(*t + c2 * h, Q2, P2, G2, ctx);
        for (size_t k = 0; k < n; k++) {
            double u1 = p[k] - h * (a11 * G1[k] + a12 * G2[k]);
            double u2 = p[k] - h * (a21 * G1[k] + a22 * G2[k]);
            uint64_t e1 = hg2_absbits(u1 - P1[k]), e2 = hg2_absbits(u2 - P2[k]);
            dp = e1 > dp ? e1 : dp; dp = e2 > dp ? e2 : dp;
            P1[k] = u1; P2[k] = u2;
        }
        HG2_DP(*t + c1 * h, Q1, P1, F1, ctx);
        HG2_DP(*t + c2 * h, Q2, P2, F2, ctx);
        for (size_t k = 0; k < n; k++) {
            double v1 = q[k] + h * (a11 * F1[k] + a12 * F2[k]);
            double v2 = q[k] + h * (a21 * F1[k] + a22 * F2[k]);
            uint64_t d1 = hg2_absbits(v1 - Q1[k]), d2 = hg2_absbits(v2 - Q2[k]);
            dq = d1 > dq ? d1 : dq; dq = d2 > dq ? d2 : dq;
            Q1[k] = v1; Q2[k] = v2;
        }
        w->evals += 4;
        it++;
        double rq = dq == 0 ? 0 : hg2_bits_value(dq) / sq, rp = dp == 0 ? 0 : hg2_bits_value(dp) / sp;
        double delta = rq > rp || rq != rq ? rq : rp;
        if (!(delta < 1e300)) return 1;
        if (delta == 0) break;
        if (prev2 >= 0 && delta >= prev2) {
            if (delta <= 2.3e-10 || prev1 <= 2.3e-10) break;
            if (++strikes >= 3) return 1;
        }
        if (it >= 50) return 1;
        prev2 = prev1;
        prev1 = delta;
    }
    w->iters += (unsigned long)it;
    for (size_t k = 0; k < n; k++) {     /* compensated (TwoSum) update */
        double e = h * 0.5 * (F1[k] + F2[k]) + w->cq[k], s = q[k] + e, bb = s - q[k];
        w->cq[k] = (q[k] - (s - bb)) + (e - bb);
        q[k] = s;
        e = -h * 0.5 * (G1[k] + G2[k]) + w->cp[k];
        s = p[k] + e;
        bb = s - p[k];
        w->cp[k] = (p[k] - (s - bb)) + (e - bb);
        p[k] = s;
    }
    *t += h;
    double *tmp;
    tmp = w->F1; w->F1 = w->Fo1; w->Fo1 = tmp;
    tmp = w->F2; w->F2 = w->Fo2; w->Fo2 = tmp;
    tmp = w->G1; w->G1 = w->Go1; w->Go1 = tmp;
    tmp = w->G2; w->G2 = w->Go2; w->Go2 = tmp;
    w->hprev = h;
    w->hist = 1;
    return 0;
}

#undef HG2_FN
#undef HG2_NAME
#undef HG2_DQ
#undef HG2_DP
