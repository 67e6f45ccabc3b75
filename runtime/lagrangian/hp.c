/* hp.c — the Hamilton–Pontryagin steppers (trapezoidal and midpoint
 * discrete Lagrangians, any velocity map) of <vigen/lagrangian.h>.
 *
 * Given (t_n, q_n, p_n) and h the unknowns are x = (dq, a), dq = q_{n+1} - q_n,
 * with v = phi_h(q_n, q_{n+1}; a) and p_{n+1/2} functions of them:
 *   trapezoidal  p_{n+1/2} = [dL/dv(t_n, q_n, v) + dL/dv(t_n + h, q_{n+1}, v)] / 2
 *                r_q = p_n + h/2 dL/dq(t_n, q_n, v) + h D1phi^T p_{n+1/2}
 *   midpoint     p_{n+1/2} = dL/dv(t_n + h/2, qbar, v),  qbar = q_n + dq/2
 *                r_q = p_n + h/2 dL/dq(t_n + h/2, qbar, v) + h D1phi^T p_{n+1/2}
 *   both         r_a = Daphi^T p_{n+1/2}
 * Newton (lsolve.c) solves r = 0.  The new momentum p_{n+1} = h D2phi^T
 * p_{n+1/2} + h/2 dL/dq(t_{n+1} or t_n + h/2, ...) is applied as the
 * increment it equals once r_q = 0,
 *   trapezoidal  dp = h/2 [dL/dq(t_n, q_n, v) + dL/dq(t_n + h, q_{n+1}, v)] + h (D1phi + D2phi)^T p_{n+1/2}
 *   midpoint     dp = h dL/dq(t_n + h/2, qbar, v) + h (D1phi + D2phi)^T p_{n+1/2}
 * (the last term vanishes for the trivial map), so that q, p and t are
 * updated by compensated sums like the SPRK steppers' and a solution near
 * round-off is not rounded again through p_{n+1/2}.
 *
 * The Jacobian is exact when the map is the trivial one and the Lagrangian
 * gives its three second-derivative blocks; otherwise it comes from forward
 * differences of the residual.  The predictor is v_{n-1/2} extrapolated
 * linearly in time from the last two steps (only the last one when
 * opt->extrapolate is 0), with the last step's parameters; without history
 * (the first step, after a reset, or when the state passed in is not the
 * one the last step returned) v is the solution of dL/dv(t_n, q_n, v) = p_n
 * by Newton.  That inversion fails with VIGEN_ESINGULAR exactly when
 * d2L/dv2 is singular from two starting velocities: such a degenerate
 * Lagrangian has no (q, p) phase space in which these steppers are maps. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "hp_internal.h"
#include "lfield_internal.h"
#include "lsolve_internal.h"
#include "lstate_internal.h"
#include "vmap_internal.h"

struct vigen_hp {
    vigen_lagrangian lag;
    vigen_velocity_map map;     /* a copy of the user's; unused when trivial */
    const vigen_velocity_map *phi;  /* &map, or NULL for the trivial map */
    int rule;
    size_t n, m, N;             /* dim, parameters, unknowns n + m */
    vigen_solver_options opt;
    vigen_stats stats;
    vigen_lsolve *ls;           /* the step's system (N) */
    int exact_jac;
    /* the system being solved */
    double t0, t1, h;
    const double *q0, *p0;
    double *block;              /* every array below lives in it */
    double *x, *r;              /* unknowns (dq, a), residual */
    double *q1, *qb, *v, *ph, *lq0, *lq1, *lv0, *lv1, *tmp, *D;
    double *H1, *H2, *H3;       /* second-derivative blocks, n x n */
    /* parameters and history */
    double *a, *a0;
    double *vh, *vh_prev, tm_h, tm_prev;
    int nhist;
    int have_end;
    double t_end, *q_end, *p_end;
    double ct, *cq, *cp, *qn, *pn, *cqn, *cpn, *dq, *dp;
    vigen_lfield field;         /* the Legendre inversion: the predictor's and the flow's */
};
/* Of these, a saved state (vigen_hp_state_get) holds what later steps read:
 * nhist, have_end, the statistics, t_end, ct, tm_h, tm_prev, q_end, p_end,
 * cq, cp, vh, vh_prev and a; everything else is rebuilt by every step. */

/* ---- the residual and its Jacobian -------------------------------------- */

static int residual(const double *x, double *r, void *ctx)
{
    vigen_hp *w = ctx;
    const size_t n = w->n, m = w->m;
    const double *dq = x, *a = x + n, h = w->h;
    const vigen_lagrangian *L = &w->lag;
    for (size_t i = 0; i < n; i++) w->q1[i] = w->q0[i] + dq[i];
    vigen_vmap_value(w->phi, n, h, w->q0, w->q1, dq, a, w->v);
    if (w->rule == VIGEN_HP_TRAPEZOIDAL) {
        L->dLdq(w->t0, w->q0, w->v, w->lq0, L->ctx);
        L->dLdv(w->t0, w->q0, w->v, w->lv0, L->ctx);
        L->dLdv(w->t1, w->q1, w->v, w->lv1, L->ctx);
        w->stats.dHdq_evals += 1;
        w->stats.dHdp_evals += 2;
        for (size_t i = 0; i < n; i++) w->ph[i] = 0.5 * (w->lv0[i] + w->lv1[i]);
    } else {
        const double tm = w->t0 + 0.5 * h;
        for (size_t i = 0; i < n; i++) w->qb[i] = w->q0[i] + 0.5 * dq[i];
        L->dLdq(tm, w->qb, w->v, w->lq0, L->ctx);
        L->dLdv(tm, w->qb, w->v, w->ph, L->ctx);
        w->stats.dHdq_evals += 1;
        w->stats.dHdp_evals += 1;
    }
    vigen_vmap_apply_transpose(w->phi, VIGEN_VMAP_D1, n, h, w->q0, w->q1, a, w->ph, h, w->D, w->tmp);
    for (size_t i = 0; i < n; i++) r[i] = w->p0[i] + 0.5 * h * w->lq0[i] + w->tmp[i];
    if (m > 0) vigen_vmap_apply_transpose(w->phi, VIGEN_VMAP_DA, n, h, w->q0, w->q1, a, w->ph, 1.0, w->D, r + n);
    return vigen_lsolve_finite(w->v, n) ? VIGEN_SUCCESS : VIGEN_ENONFINITE;
}

/* Exact Jacobian d r_q / d dq for the trivial map (v = dq/h), with
 * Lqv[i][j] = d(dL/dq)_i / dv_j and d(dL/dv)_i / dq_j = Lqv[j][i]:
 *   trapezoidal  J = 1/2 Lqv(t_n, q_n, v) - 1/2 Lqv(t_{n+1}, q_{n+1}, v)^T
 *                    - [Lvv(t_n, q_n, v) + Lvv(t_{n+1}, q_{n+1}, v)] / (2h)
 *   midpoint     J = h/4 Lqq + 1/2 (Lqv - Lqv^T) - Lvv / h   at (t_n + h/2, qbar, v) */
static int jacobian(const double *x, double *J, void *ctx)
{
    vigen_hp *w = ctx;
    const size_t n = w->n;
    const double h = w->h;
    const vigen_lagrangian *L = &w->lag;
    for (size_t i = 0; i < n; i++) {
        w->q1[i] = w->q0[i] + x[i];
        w->qb[i] = w->q0[i] + 0.5 * x[i];
        w->v[i] = x[i] / h;
    }
    if (w->rule == VIGEN_HP_TRAPEZOIDAL) {
        L->d2Ldqdv(w->t0, w->q0, w->v, w->H1, L->ctx);
        L->d2Ldv2(w->t0, w->q0, w->v, w->H2, L->ctx);
        for (size_t k = 0; k < n * n; k++) J[k] = 0.5 * w->H1[k] - w->H2[k] / (2.0 * h);
        L->d2Ldqdv(w->t1, w->q1, w->v, w->H1, L->ctx);
        L->d2Ldv2(w->t1, w->q1, w->v, w->H2, L->ctx);
        for (size_t i = 0; i < n; i++)
            for (size_t j = 0; j < n; j++) J[i * n + j] -= 0.5 * w->H1[j * n + i] + w->H2[i * n + j] / (2.0 * h);
    } else {
        const double tm = w->t0 + 0.5 * h;
        L->d2Ldq2(tm, w->qb, w->v, w->H3, L->ctx);
        L->d2Ldqdv(tm, w->qb, w->v, w->H1, L->ctx);
        L->d2Ldv2(tm, w->qb, w->v, w->H2, L->ctx);
        for (size_t i = 0; i < n; i++)
            for (size_t j = 0; j < n; j++)
                J[i * n + j] = 0.25 * h * w->H3[i * n + j] + 0.5 * (w->H1[i * n + j] - w->H1[j * n + i])
                               - w->H2[i * n + j] / h;
    }
    return VIGEN_SUCCESS;
}

/* ---- the Legendre inversion dL/dv(t_n, q_n, v) = p_n -------------------- */

/* The velocity at (t_n, q_n, p_n) into w->v: Newton from v = 0, then from
 * v = p_n when d2L/dv2 is singular at 0.  VIGEN_ESINGULAR when it is at
 * both; any other failure leaves the predictor v = 0 (the step's own solve
 * decides). */
static int legendre_velocity(vigen_hp *w)
{
    const size_t n = w->n;
    int st = vigen_lfield_velocity(&w->field, NULL, w->t0, w->q0, w->p0, &w->stats);
    if (st == VIGEN_ESINGULAR) return st;
    if (st == VIGEN_SUCCESS) memcpy(w->v, w->field.v, n * sizeof(double));
    else memset(w->v, 0, n * sizeof(double));
    return VIGEN_SUCCESS;
}

/* ---- allocation ----------------------------------------------------------- */

vigen_hp *vigen_hp_alloc(const vigen_lagrangian *lag, int rule, const vigen_velocity_map *phi,
                         const vigen_solver_options *opt)
{
    if (vigen_lagrangian_validate(lag, phi, NULL) != VIGEN_SUCCESS) return NULL;
    if (rule != VIGEN_HP_TRAPEZOIDAL && rule != VIGEN_HP_MIDPOINT) return NULL;
    vigen_hp *w = calloc(1, sizeof *w);
    if (w == NULL) return NULL;
    w->lag = *lag;
    w->rule = rule;
    w->n = lag->dim;
    w->m = phi ? phi->nparams : 0;
    w->N = w->n + w->m;
    if (phi) {
        w->map = *phi;
        w->phi = &w->map;
    }
    if (opt) w->opt = *opt;
    else vigen_solver_options_default(&w->opt);
    w->exact_jac = phi == NULL && lag->d2Ldq2 && lag->d2Ldv2 && lag->d2Ldqdv;
    const size_t n = w->n, m = w->m, nd = n * (n > m ? n : m);
    double **vecs[] = { &w->q1, &w->qb, &w->v, &w->ph, &w->lq0, &w->lq1, &w->lv0, &w->lv1, &w->tmp, &w->vh,
                        &w->vh_prev, &w->q_end, &w->p_end, &w->cq, &w->cp, &w->qn, &w->pn, &w->cqn,
                        &w->cpn, &w->dq, &w->dp };
    const size_t nvec = sizeof vecs / sizeof vecs[0];
    /* one block for every array: the vectors of n, a and a0, x and r, 3 n x n, D */
    double *buf = calloc(nvec * n + 2 * m + 2 * w->N + 3 * n * n + nd, sizeof(double));
    w->ls = vigen_lsolve_alloc(w->N);
    const int field = vigen_lfield_init(&w->field, &w->lag, &w->opt);
    if (buf == NULL || w->ls == NULL || field != VIGEN_SUCCESS) {
        free(buf);
        vigen_lsolve_free(w->ls);
        vigen_lfield_clear(&w->field);
        free(w);
        return NULL;
    }
    double *b = w->block = buf;
    for (size_t k = 0; k < nvec; k++, b += n) *vecs[k] = b;
    w->a = b; b += m;
    w->a0 = b; b += m;
    w->x = b; b += w->N;
    w->r = b; b += w->N;
    w->H1 = b; b += n * n;
    w->H2 = b; b += n * n;
    w->H3 = b; b += n * n;
    w->D = b;
    if (phi && phi->a0) memcpy(w->a0, phi->a0, m * sizeof(double));
    vigen_hp_reset(w);
    return w;
}

void vigen_hp_free(vigen_hp *w)
{
    if (w == NULL) return;
    vigen_lsolve_free(w->ls);
    vigen_lfield_clear(&w->field);
    free(w->block);
    free(w);
}

void vigen_hp_reset(vigen_hp *w)
{
    if (w == NULL) return;
    memset(&w->stats, 0, sizeof w->stats);
    if (w->m) memcpy(w->a, w->a0, w->m * sizeof(double));
    memset(w->v, 0, w->n * sizeof(double));
    memset(w->vh, 0, w->n * sizeof(double));
    w->nhist = 0;
    w->have_end = 0;
}

const double *vigen_hp_params(const vigen_hp *w) { return w && w->m ? w->a : NULL; }
size_t vigen_hp_nparams(const vigen_hp *w) { return w ? w->m : 0; }
const double *vigen_hp_velocity(const vigen_hp *w) { return w ? w->vh : NULL; }
const vigen_stats *vigen_hp_stats(const vigen_hp *w) { return w ? &w->stats : NULL; }
vigen_stats *vigen_hp_stats_rw(vigen_hp *w) { return &w->stats; }

/* ---- the step --------------------------------------------------------------- */

/* Whether (t0, q, p) is the state the last successful step returned; if not,
 * the history (predictor, compensations) belongs to another trajectory and
 * is dropped.  A position-only continuation (p recomputed by the caller)
 * keeps the predictor but not the compensations. */
static void continues(vigen_hp *w, double t0, const double *q, const double *p, int positions_only)
{
    const size_t bytes = w->n * sizeof(double);
    int same = w->have_end && t0 == w->t_end && memcmp(q, w->q_end, bytes) == 0;
    if (!same) w->nhist = 0;
    if (!same || positions_only || memcmp(p, w->p_end, bytes) != 0) {
        w->ct = 0.0;
        memset(w->cq, 0, bytes);
        memset(w->cp, 0, bytes);
        if (!positions_only) w->nhist = 0;
    }
}

/* The predictor of (dq, a) into w->x; VIGEN_ESINGULAR for a degenerate
 * Lagrangian (see the file comment). */
static int predict(vigen_hp *w)
{
    const size_t n = w->n;
    const double h = w->h, tm = w->t0 + 0.5 * h;
    if (w->nhist == 0) {
        int st = legendre_velocity(w);
        if (st != VIGEN_SUCCESS) return st;
        for (size_t i = 0; i < n; i++) w->x[i] = h * w->v[i];
    } else if (w->nhist >= 2 && w->opt.extrapolate && w->tm_h != w->tm_prev &&
               (tm - w->tm_h) / (w->tm_h - w->tm_prev) > 0 && (tm - w->tm_h) / (w->tm_h - w->tm_prev) <= 4) {
        /* the steps go on in the same direction at comparable sizes (a
         * reversal, or a step many times the last, is not extrapolated) */
        const double s = (tm - w->tm_h) / (w->tm_h - w->tm_prev);
        for (size_t i = 0; i < n; i++) w->x[i] = h * (w->vh[i] + s * (w->vh[i] - w->vh_prev[i]));
    } else {
        for (size_t i = 0; i < n; i++) w->x[i] = h * w->vh[i];
    }
    if (w->m) memcpy(w->x + n, w->a, w->m * sizeof(double));
    return vigen_lsolve_finite(w->x, w->N) ? VIGEN_SUCCESS : VIGEN_ENONFINITE;
}

/* Solves the step's system and forms the increments w->dq, w->dp. */
static int solve_step(vigen_hp *w)
{
    const size_t n = w->n;
    const double h = w->h;
    int st = predict(w);
    if (st != VIGEN_SUCCESS) return st;
    st = vigen_lsolve_run(w->ls, w->x, residual, w->exact_jac ? jacobian : NULL, w, &w->opt, &w->stats);
    if (st != VIGEN_SUCCESS) return st;
    /* the pieces at the solution: v, p_{n+1/2}, dL/dq */
    st = residual(w->x, w->r, w);
    if (st != VIGEN_SUCCESS) return st;
    const double *a = w->x + n;
    memcpy(w->dq, w->x, n * sizeof(double));
    if (w->rule == VIGEN_HP_TRAPEZOIDAL) {
        w->lag.dLdq(w->t1, w->q1, w->v, w->lq1, w->lag.ctx);
        w->stats.dHdq_evals++;
        for (size_t i = 0; i < n; i++) w->dp[i] = 0.5 * h * (w->lq0[i] + w->lq1[i]);
    } else {
        for (size_t i = 0; i < n; i++) w->dp[i] = h * w->lq0[i];
    }
    if (w->phi) {
        vigen_vmap_apply_transpose(w->phi, VIGEN_VMAP_D1_PLUS_D2, n, h, w->q0, w->q1, a, w->ph, h, w->D, w->tmp);
        for (size_t i = 0; i < n; i++) w->dp[i] += w->tmp[i];
    }
    return vigen_lsolve_finite(w->dp, n) && vigen_lsolve_finite(w->v, n) ? VIGEN_SUCCESS : VIGEN_ENONFINITE;
}

int vigen_hp_step_between(vigen_hp *w, double t0, double t1, double h, double *q, double *p,
                          int positions_only)
{
    const size_t n = w->n;
    continues(w, t0, q, p, positions_only);
    w->t0 = t0;
    w->t1 = t1;
    w->h = h;
    w->q0 = q;
    w->p0 = p;
    int st = solve_step(w);
    const int kahan = w->opt.kahan;
    for (size_t i = 0; st == VIGEN_SUCCESS && i < n; i++) {
        if (kahan) {
            w->qn[i] = vigen_twosum_next(q[i], w->dq[i], w->cq[i], &w->cqn[i]);
            w->pn[i] = vigen_twosum_next(p[i], w->dp[i], w->cp[i], &w->cpn[i]);
        } else {
            w->qn[i] = q[i] + w->dq[i];
            w->pn[i] = p[i] + w->dp[i];
        }
        if (!(w->qn[i] - w->qn[i] == 0 && w->pn[i] - w->pn[i] == 0)) st = VIGEN_ENONFINITE;
    }
    if (st != VIGEN_SUCCESS) {
        w->stats.failed_steps++;
        return st;
    }
    /* commit: state, compensations, history, parameters */
    memcpy(q, w->qn, n * sizeof(double));
    memcpy(p, w->pn, n * sizeof(double));
    if (kahan) {
        memcpy(w->cq, w->cqn, n * sizeof(double));
        memcpy(w->cp, w->cpn, n * sizeof(double));
    }
    memcpy(w->vh_prev, w->vh, n * sizeof(double));
    memcpy(w->vh, w->v, n * sizeof(double));
    w->tm_prev = w->tm_h;
    w->tm_h = t0 + 0.5 * h;
    if (w->nhist < 2) w->nhist++;   /* 0, 1 or 2 and more steps behind: all the predictor asks */
    if (w->m) memcpy(w->a, w->x + n, w->m * sizeof(double));
    w->have_end = 1;
    w->t_end = t1;
    memcpy(w->q_end, q, n * sizeof(double));
    memcpy(w->p_end, p, n * sizeof(double));
    w->stats.steps++;
    return VIGEN_SUCCESS;
}

int vigen_hp_step(vigen_hp *w, double *t, double *q, double *p, double h)
{
    if (w == NULL || t == NULL || q == NULL || p == NULL) return VIGEN_EINVAL;
    const double t0 = *t;
    double ct = w->have_end && t0 == w->t_end ? w->ct : 0.0, ctn = 0.0;
    double t1 = w->opt.kahan ? vigen_twosum_next(t0, h, ct, &ctn) : t0 + h;
    if (!(h - h == 0) || h == 0.0 || !(t0 - t0 == 0) || !(t1 - t1 == 0)) {
        w->stats.failed_steps++;
        w->stats.last_iterations = 0;
        return VIGEN_EINVAL;
    }
    int st = vigen_hp_step_between(w, t0, t1, h, q, p, 0);
    if (st == VIGEN_SUCCESS) {
        *t = t1;
        w->ct = ctn;
        w->t_end = t1;
    }
    return st;
}

/* ---- saved states ----------------------------------------------------------- */

/* The payload in its order (lstate_internal.h): the flags first, as
 * vigen_lstate_check reads them, then the statistics, times and arrays. */
static size_t state_walk(void *ws, void *buf, int save)
{
    vigen_hp *w = ws;
    const size_t n = w->n;
    vigen_lstate_io io;
    vigen_lstate_begin(&io, buf, save);
    vigen_lstate_flag(&io, &w->nhist);
    vigen_lstate_flag(&io, &w->have_end);
    vigen_lstate_stats(&io, &w->stats);
    double *const scalars[] = { &w->t_end, &w->ct, &w->tm_h, &w->tm_prev };
    for (size_t i = 0; i < sizeof scalars / sizeof scalars[0]; i++) vigen_lstate_reals(&io, scalars[i], 1);
    double *const arrays[] = { w->q_end, w->p_end, w->cq, w->cp, w->vh, w->vh_prev };
    for (size_t i = 0; i < sizeof arrays / sizeof arrays[0]; i++) vigen_lstate_reals(&io, arrays[i], n);
    vigen_lstate_reals(&io, w->a, w->m);
    return vigen_lstate_end(&io);
}

/* nhist is 0 .. 2, have_end 0 or 1 */
static vigen_lstate_kind state_kind(const vigen_hp *w)
{
    return (vigen_lstate_kind){ "vigen_hp", w->n, w->m, w->rule, &w->opt, state_walk, 2, 2 };
}

size_t vigen_hp_state_size(const vigen_hp *w)
{
    if (w == NULL) return 0;
    const vigen_lstate_kind k = state_kind(w);
    return vigen_lstate_size(w, &k);
}

int vigen_hp_state_get(const vigen_hp *w, void *buf)
{
    if (w == NULL) return VIGEN_EINVAL;
    const vigen_lstate_kind k = state_kind(w);
    return vigen_lstate_get(w, &k, buf);
}

int vigen_hp_state_set(vigen_hp *w, const void *buf)
{
    if (w == NULL) return VIGEN_EINVAL;
    const vigen_lstate_kind k = state_kind(w);
    return vigen_lstate_set(w, &k, buf);
}

/* ---- the stepper type ------------------------------------------------------- */

/* The flow, Newton started from the last step's velocity v_{n+1/2} (zero
 * before the first step). */
int vigen_hp_vector_field(vigen_hp *w, double t, const double *q, const double *p, double *dq, double *dp)
{
    if (w == NULL || q == NULL || p == NULL || dq == NULL || dp == NULL) return VIGEN_EINVAL;
    return vigen_lfield_eval(&w->field, w->vh, t, q, p, dq, dp);
}

static void *type_clone(const void *ws)
{
    const vigen_hp *w = ws;
    vigen_velocity_map map = w->map;
    map.a0 = w->a0;   /* the copy made at alloc, not the caller's array */
    return vigen_hp_alloc(&w->lag, w->rule, w->phi ? &map : NULL, &w->opt);
}

static int type_step(void *w, double *t, double *q, double *p, double h) { return vigen_hp_step(w, t, q, p, h); }
static void type_reset(void *w) { vigen_hp_reset(w); }
static const vigen_stats *type_stats(const void *w) { return vigen_hp_stats(w); }
static void type_free(void *w) { vigen_hp_free(w); }
static size_t type_state_size(const void *w) { return vigen_hp_state_size(w); }
static int type_state_get(const void *w, void *buf) { return vigen_hp_state_get(w, buf); }
static int type_state_set(void *w, const void *buf) { return vigen_hp_state_set(w, buf); }
static size_t type_dim(const void *w) { return ((const vigen_hp *)w)->n; }
static int type_field(void *w, double t, const double *q, const double *p, double *dq, double *dp)
{
    return vigen_hp_vector_field(w, t, q, p, dq, dp);
}

const vigen_stepper_type vigen_hp_type = {
    "vigen_hp", 1, 2, 0,
    NULL, type_step, type_reset, type_stats, type_free,
    type_state_size, type_state_get, type_state_set,
    type_dim, type_field, type_clone
};
