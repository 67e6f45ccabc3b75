/* hand_verlet.h — a hand-written Stormer-Verlet (kick-drift-kick) stepper
 * for separable H, keeping the force of the step's end for the next step,
 * optionally with the same compensated update as the emitted steppers.
 * Instantiate with HV_NAME, HV_DQ, HV_DP as in hand_gauss2.h. */
#include <stdlib.h>

#define HV_CAT2(a, b) a##b
#define HV_CAT(a, b) HV_CAT2(a, b)
#define HV_FN(x) HV_CAT(HV_NAME, x)

typedef struct {
    size_t n;
    double *g, *v, *cq, *cp;
    int have_g, kahan;
    unsigned long evals;
} HV_FN(_ws);

static HV_FN(_ws) *HV_FN(_alloc)(size_t n, int kahan)
{
    HV_FN(_ws) *w = calloc(1, sizeof *w);
    double *m = calloc(4 * n, sizeof(double));
    w->n = n;
    w->g = m; w->v = m + n; w->cq = m + 2 * n; w->cp = m + 3 * n;
    w->kahan = kahan;
    return w;
}

static void HV_FN(_free)(HV_FN(_ws) *w) { free(w->g); free(w); }

static inline double HV_FN(_twosum)(double x, double d, double *c)
{
    double e = d + *c, s = x + e, bb = s - x;
    *c = (x - (s - bb)) + (e - bb);
    return s;
}

/* kick (h/2), drift (h), kick (h/2); the last force is the next step's first */
static int HV_FN(_step)(HV_FN(_ws) *w, double *t, double *q, double *p, double h, void *ctx)
{
    const size_t n = w->n;
    double *g = w->g, *v = w->v;
    if (!w->have_g) { HV_DQ(*t, q, p, g, ctx); w->evals++; w->have_g = 1; }
    if (w->kahan) {
        for (size_t k = 0; k < n; k++) p[k] = HV_FN(_twosum)(p[k], -0.5 * h * g[k], &w->cp[k]);
        HV_DP(*t, q, p, v, ctx);
        for (size_t k = 0; k < n; k++) q[k] = HV_FN(_twosum)(q[k], h * v[k], &w->cq[k]);
        HV_DQ(*t + h, q, p, g, ctx);
        for (size_t k = 0; k < n; k++) p[k] = HV_FN(_twosum)(p[k], -0.5 * h * g[k], &w->cp[k]);
    } else {
        for (size_t k = 0; k < n; k++) p[k] -= 0.5 * h * g[k];
        HV_DP(*t, q, p, v, ctx);
        for (size_t k = 0; k < n; k++) q[k] += h * v[k];
        HV_DQ(*t + h, q, p, g, ctx);
        for (size_t k = 0; k < n; k++) p[k] -= 0.5 * h * g[k];
    }
    w->evals += 2;
    *t += h;
    return 0;
}

#undef HV_FN
#undef HV_NAME
#undef HV_DQ
#undef HV_DP
