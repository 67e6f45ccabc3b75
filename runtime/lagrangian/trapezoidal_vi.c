/* trapezoidal_vi.c — the variational integrator of the trapezoidal discrete
 * Lagrangian on a non-uniform time grid,
 *     Ld(t0, t1, q0, q1) = (t1 - t0)/2 [L(t0, q0, v) + L(t1, q1, v)],  v = (q1 - q0)/(t1 - t0),
 * as a one-step map in (q, p) (p0 = -D1 Ld, p1 = D2 Ld), as a two-step map in
 * positions (D2 Ld(t0, t1, q0, q1) + D1 Ld(t1, t2, q1, q2) = 0), and as a
 * driver over an array of times.  This discrete Lagrangian is the
 * Hamilton–Pontryagin trapezoidal one with the trivial velocity map, so the
 * one-step map is that stepper (hp.c), step by step with its own h; the
 * two-step form forms p1 = D2 Ld(t0, t1, q0, q1) explicitly and takes the
 * same step from (q1, p1).  For L = 1/2 m v^2 - V(q) it is the leapfrog. */
#include <stdlib.h>
#include <string.h>
#include "hp_internal.h"

struct vigen_trapezoidal_vi {
    vigen_hp *hp;
    vigen_lagrangian lag;
    vigen_solver_options opt;   /* as given (clones are made with them) */
    size_t n;
    double *v, *lv0, *lv1, *lq1, *q, *p;   /* one block */
};

vigen_trapezoidal_vi *vigen_trapezoidal_vi_alloc(const vigen_lagrangian *lag,
                                                 const vigen_solver_options *opt)
{
    vigen_hp *hp = vigen_hp_alloc(lag, VIGEN_HP_TRAPEZOIDAL, NULL, opt);
    if (hp == NULL) return NULL;
    vigen_trapezoidal_vi *w = calloc(1, sizeof *w);
    double *b = calloc(6 * lag->dim, sizeof(double));
    if (w == NULL || b == NULL) {
        free(w);
        free(b);
        vigen_hp_free(hp);
        return NULL;
    }
    w->hp = hp;
    w->lag = *lag;
    if (opt) w->opt = *opt;
    else vigen_solver_options_default(&w->opt);
    w->n = lag->dim;
    w->v = b;
    w->lv0 = b + w->n;
    w->lv1 = b + 2 * w->n;
    w->lq1 = b + 3 * w->n;
    w->q = b + 4 * w->n;
    w->p = b + 5 * w->n;
    return w;
}

void vigen_trapezoidal_vi_free(vigen_trapezoidal_vi *w)
{
    if (w == NULL) return;
    vigen_hp_free(w->hp);
    free(w->v);
    free(w);
}

const vigen_stats *vigen_trapezoidal_vi_stats(const vigen_trapezoidal_vi *w)
{
    return w ? vigen_hp_stats(w->hp) : NULL;
}

void vigen_trapezoidal_vi_reset(vigen_trapezoidal_vi *w)
{
    if (w) vigen_hp_reset(w->hp);
}

int vigen_trapezoidal_vi_step(vigen_trapezoidal_vi *w, double *t, double *q, double *p, double h)
{
    if (w == NULL) return VIGEN_EINVAL;
    return vigen_hp_step(w->hp, t, q, p, h);
}

static int finite(double x) { return x - x == 0; }

/* Strictly monotone finite times a, b, c (either direction). */
static int monotone3(double a, double b, double c)
{
    return finite(a) && finite(b) && finite(c) && ((a < b && b < c) || (a > b && b > c));
}

int vigen_trapezoidal_vi_step2(vigen_trapezoidal_vi *w, double t0, double t1, double t2,
                               const double *q0, const double *q1, double *q2)
{
    if (w == NULL || q0 == NULL || q1 == NULL || q2 == NULL || q2 == q0 || q2 == q1) return VIGEN_EINVAL;
    vigen_stats *st = vigen_hp_stats_rw(w->hp);
    if (!monotone3(t0, t1, t2)) {
        st->failed_steps++;
        return VIGEN_EINVAL;
    }
    const size_t n = w->n;
    const double h0 = t1 - t0;
    /* p1 = D2 Ld(t0, t1, q0, q1) = [dL/dv(t0, q0, v) + dL/dv(t1, q1, v)]/2 + h0/2 dL/dq(t1, q1, v) */
    for (size_t i = 0; i < n; i++) w->v[i] = (q1[i] - q0[i]) / h0;
    w->lag.dLdv(t0, q0, w->v, w->lv0, w->lag.ctx);
    w->lag.dLdv(t1, q1, w->v, w->lv1, w->lag.ctx);
    w->lag.dLdq(t1, q1, w->v, w->lq1, w->lag.ctx);
    st->dHdp_evals += 2;
    st->dHdq_evals += 1;
    int ok = 1;
    for (size_t i = 0; i < n; i++) {
        w->p[i] = 0.5 * (w->lv0[i] + w->lv1[i]) + 0.5 * h0 * w->lq1[i];
        w->q[i] = q1[i];
        ok &= finite(w->p[i]);
    }
    if (!ok) {
        st->failed_steps++;
        return VIGEN_ENONFINITE;
    }
    int rc = vigen_hp_step_between(w->hp, t1, t2, t2 - t1, w->q, w->p, 1);
    if (rc == VIGEN_SUCCESS) memcpy(q2, w->q, n * sizeof(double));
    return rc;
}

int vigen_trapezoidal_vi_integrate(vigen_trapezoidal_vi *w, const double *times, size_t ntimes,
                                   double *q, double *p, double *qs, double *ps, size_t *done)
{
    if (done) *done = 0;
    if (w == NULL || times == NULL || q == NULL || p == NULL || ntimes == 0) return VIGEN_EINVAL;
    for (size_t k = 0; k < ntimes; k++) {
        if (!finite(times[k])) return VIGEN_EINVAL;
        if (k >= 2 && !monotone3(times[k - 2], times[k - 1], times[k])) return VIGEN_EINVAL;
        if (k == 1 && times[0] == times[1]) return VIGEN_EINVAL;
    }
    const size_t n = w->n, bytes = n * sizeof(double);
    if (qs) memcpy(qs, q, bytes);
    if (ps) memcpy(ps, p, bytes);
    for (size_t k = 0; k + 1 < ntimes; k++) {
        int rc = vigen_hp_step_between(w->hp, times[k], times[k + 1], times[k + 1] - times[k], q, p, 0);
        if (rc != VIGEN_SUCCESS) return rc;
        if (qs) memcpy(qs + (k + 1) * n, q, bytes);
        if (ps) memcpy(ps + (k + 1) * n, p, bytes);
        if (done) *done = k + 1;
    }
    return VIGEN_SUCCESS;
}

/* The state is the Hamilton-Pontryagin stepper's: the one-step map is that
 * stepper, and the two-step form and the driver keep nothing of their own
 * between calls. */
size_t vigen_trapezoidal_vi_state_size(const vigen_trapezoidal_vi *w) { return w ? vigen_hp_state_size(w->hp) : 0; }

int vigen_trapezoidal_vi_state_get(const vigen_trapezoidal_vi *w, void *buf)
{
    return w ? vigen_hp_state_get(w->hp, buf) : VIGEN_EINVAL;
}

int vigen_trapezoidal_vi_state_set(vigen_trapezoidal_vi *w, const void *buf)
{
    return w ? vigen_hp_state_set(w->hp, buf) : VIGEN_EINVAL;
}

/* ---- the stepper type: the one-step map ------------------------------------- */

static int tvi_step(void *w, double *t, double *q, double *p, double h) { return vigen_trapezoidal_vi_step(w, t, q, p, h); }
static void tvi_reset(void *w) { vigen_trapezoidal_vi_reset(w); }
static const vigen_stats *tvi_stats(const void *w) { return vigen_trapezoidal_vi_stats(w); }
static void tvi_free(void *w) { vigen_trapezoidal_vi_free(w); }
static size_t tvi_state_size(const void *w) { return vigen_trapezoidal_vi_state_size(w); }
static int tvi_state_get(const void *w, void *buf) { return vigen_trapezoidal_vi_state_get(w, buf); }
static int tvi_state_set(void *w, const void *buf) { return vigen_trapezoidal_vi_state_set(w, buf); }
static size_t tvi_dim(const void *w) { return ((const vigen_trapezoidal_vi *)w)->n; }
static int tvi_field(void *w, double t, const double *q, const double *p, double *dq, double *dp)
{
    return vigen_hp_vector_field(((vigen_trapezoidal_vi *)w)->hp, t, q, p, dq, dp);
}
static void *tvi_clone(const void *ws)
{
    const vigen_trapezoidal_vi *w = ws;
    return vigen_trapezoidal_vi_alloc(&w->lag, &w->opt);
}

const vigen_stepper_type vigen_trapezoidal_vi_type = {
    "vigen_trapezoidal_vi", 1, 2, 0,
    NULL, tvi_step, tvi_reset, tvi_stats, tvi_free,
    tvi_state_size, tvi_state_get, tvi_state_set,
    tvi_dim, tvi_field, tvi_clone
};
