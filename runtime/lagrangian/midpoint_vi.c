/* midpoint_vi.c — the mid-point variational integrator: the discrete
 * Lagrangian Ld(qa, qb) = (tb - ta) L((ta + tb)/2, (qa + qb)/2, (qb - qa)/(tb - ta))
 * as a one-step map in (q, p) (the Cresson–Safi discrete Hamiltonian system,
 * which needs the inverse Legendre map g) and as the two-step discrete
 * Euler–Lagrange equations in positions only.
 *
 * One step (tau = t + h/2, unknown d = q1 - q0, qbar = q0 + d/2, v = d/h):
 *     r(d) = d - h g(tau, qbar, p0 + h/2 dL/dq(tau, qbar, v)) = 0,
 *     q1 = q0 + d,  p1 = p0 + h dL/dq(tau, qbar, v).
 * With P = p0 + h/2 dL/dq this is p1 = p0 + h dL/dq and (p0 + p1)/2 = P, the
 * system of docs/lagrangian.md; the momenta are Wendlandt–Marsden's
 * p_i = -D1 Ld(q_i, q_{i+1}) = D2 Ld(q_{i-1}, q_i).
 *
 * Two steps (unknown d = q2 - q1, h1 = t1 - t0, h2 = t2 - t1):
 *     r(d) = D1 Ld(q1, q1 + d) + D2 Ld(q0, q1)
 *          = h2/2 dL/dq - dL/dv  at (tau2, q1 + d/2, d/h2)
 *          + h1/2 dL/dq + dL/dv  at (tau1, (q0 + q1)/2, (q1 - q0)/h1).
 * The second line is the momentum p1 and is computed once per call.
 *
 * Unknowns are increments, not positions: Newton's relative stopping test
 * then measures the step itself, and q1 = q0 + d is a compensated sum.
 * Statistics: dHdq_evals counts dL/dq calls; dHdp_evals counts dL/dv calls
 * and calls of g (g is dH/dp of the Hamiltonian p.v - L); the shared solver
 * counts iterations, Jacobians (hessian_evals) and LU decompositions. */
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_permutation.h>
#include <vigen/lagrangian.h>
#include "lfield_internal.h"
#include "lsolve_internal.h"
#include "lstate_internal.h"

struct vigen_midpoint_vi {
    vigen_lagrangian lag;
    vigen_lgrad_fn g;
    vigen_solver_options opt;
    vigen_stats stats;
    size_t n;
    int exact_hessian;          /* all three second derivatives given */
    vigen_lsolve *ls;
    double *mem;                /* one block for every array below */
    /* the problem of the current solve */
    double tau, h, coef;        /* time of L, step; coef = h2/2 (two-step) */
    const double *q0, *p0;      /* start (one step) or q1 and p1 (two steps) */
    double *qbar, *v, *lq, *lv, *pm;
    double *d;                  /* the unknown increment */
    double *pc;                 /* p1 of the two-step residual */
    double *qn, *pn, *cqn, *cpn;
    double *cq, *cp, ct;        /* compensation of the q, p and t updates */
    double *vprev, *vprev2;     /* v of the last two steps (predictor) */
    double hprev, hprev2;       /* their steps */
    double *qlast, *plast, tlast;   /* what the last step returned */
    int history;                /* steps behind (0, 1, 2) with vprev.., qlast, plast, tlast
                                   and the compensation valid */
    /* second derivatives: four n x n blocks, a base gradient pair, LU */
    double *Lqq, *Lqv, *Lvq, *Lvv;      /* adjacent, in this order */
    double *gq, *gv, *xq, *xv, *sq, *sv;   /* differences: base, point, shifted gradients */
    gsl_matrix *A;
    gsl_permutation *perm;
    vigen_lfield field;         /* the flow for output at any time and events */
};
/* Of these, a saved state (vigen_midpoint_vi_state_get) holds what later
 * steps read: history, the statistics, tlast, ct, hprev, hprev2, qlast,
 * plast, cq, cp, vprev and vprev2; everything else is rebuilt by every
 * step. */

/* The user's gradients and g, counted and checked: VIGEN_ENONFINITE for an
 * output that is NaN or infinite. */
static int mvi_dLdq(vigen_midpoint_vi *w, double t, const double *q, const double *v, double *out)
{
    w->lag.dLdq(t, q, v, out, w->lag.ctx);
    w->stats.dHdq_evals++;
    return vigen_lsolve_finite(out, w->n) ? VIGEN_SUCCESS : VIGEN_ENONFINITE;
}

static int mvi_dLdv(vigen_midpoint_vi *w, double t, const double *q, const double *v, double *out)
{
    w->lag.dLdv(t, q, v, out, w->lag.ctx);
    w->stats.dHdp_evals++;
    return vigen_lsolve_finite(out, w->n) ? VIGEN_SUCCESS : VIGEN_ENONFINITE;
}

static int mvi_g(vigen_midpoint_vi *w, double t, const double *q, const double *p, double *out)
{
    w->g(t, q, p, out, w->lag.ctx);
    w->stats.dHdp_evals++;
    return vigen_lsolve_finite(out, w->n) ? VIGEN_SUCCESS : VIGEN_ENONFINITE;
}

/* qbar = base + d/2 and v = d/h for the current unknown d. */
static void mvi_midpoint(vigen_midpoint_vi *w, const double *base, const double *d, double h)
{
    for (size_t k = 0; k < w->n; k++) {
        w->qbar[k] = base[k] + 0.5 * d[k];
        w->v[k] = d[k] / h;
    }
}

/* ---- second derivatives of L ------------------------------------------- */

/* Lqq, Lqv (row i: d(dL/dq)_i / dv_j), Lvq (row i: d(dL/dv)_i / dq_j) and
 * Lvv at (t, q, v): the user's callbacks when all three are given (then
 * Lvq = Lqv^T), forward differences of the gradients otherwise. */
static int mvi_hessian(vigen_midpoint_vi *w, double t, const double *q, const double *v)
{
    const size_t n = w->n;
    if (w->exact_hessian) {
        w->lag.d2Ldq2(t, q, v, w->Lqq, w->lag.ctx);
        w->lag.d2Ldqdv(t, q, v, w->Lqv, w->lag.ctx);
        w->lag.d2Ldv2(t, q, v, w->Lvv, w->lag.ctx);
        for (size_t i = 0; i < n; i++)
            for (size_t j = 0; j < n; j++) w->Lvq[i * n + j] = w->Lqv[j * n + i];
        return vigen_lsolve_finite(w->Lqq, 4 * n * n) ? VIGEN_SUCCESS : VIGEN_ENONFINITE;   /* the 4 blocks */
    }
    const double fd = w->opt.fd_step > 0 ? w->opt.fd_step : sqrt(DBL_EPSILON);
    int st = mvi_dLdq(w, t, q, v, w->gq);
    if (st == VIGEN_SUCCESS) st = mvi_dLdv(w, t, q, v, w->gv);
    memcpy(w->xq, q, n * sizeof *q);
    memcpy(w->xv, v, n * sizeof *v);
    for (size_t j = 0; j < n && st == VIGEN_SUCCESS; j++) {
        for (int which = 0; which < 2 && st == VIGEN_SUCCESS; which++) {
            double *x = which == 0 ? w->xq : w->xv;
            const double x0 = x[j];
            const double e = fd * (fabs(x0) > 1.0 ? fabs(x0) : 1.0);
            x[j] = x0 + e;
            const double dx = x[j] - x0;        /* the step actually taken */
            double *rq = which == 0 ? w->Lqq : w->Lqv, *rv = which == 0 ? w->Lvq : w->Lvv;
            st = mvi_dLdq(w, t, w->xq, w->xv, w->sq);
            if (st == VIGEN_SUCCESS) st = mvi_dLdv(w, t, w->xq, w->xv, w->sv);
            for (size_t i = 0; i < n; i++) {       /* columns j of the two blocks */
                rq[i * n + j] = (w->sq[i] - w->gq[i]) / dx;
                rv[i * n + j] = (w->sv[i] - w->gv[i]) / dx;
            }
            x[j] = x0;
        }
    }
    return st;
}

/* The second derivatives at the mid-point of the current solve's unknown d. */
static int mvi_hessian_at(vigen_midpoint_vi *w, const double *d)
{
    mvi_midpoint(w, w->q0, d, w->h);
    return mvi_hessian(w, w->tau, w->qbar, w->v);
}

/* LU of Lvv into w->A, w->perm.  VIGEN_ESINGULAR when Lvv is singular to
 * working precision (a degenerate Lagrangian: dL/dv cannot be inverted). */
static int mvi_factor_lvv(vigen_midpoint_vi *w)
{
    const size_t n = w->n;
    double big = 0.0;
    for (size_t k = 0; k < n * n; k++) {
        w->A->data[(k / n) * w->A->tda + k % n] = w->Lvv[k];
        if (fabs(w->Lvv[k]) > big) big = fabs(w->Lvv[k]);
    }
    int signum = 0;
    if (big == 0.0 || gsl_linalg_LU_decomp(w->A, w->perm, &signum) != GSL_SUCCESS)
        return VIGEN_ESINGULAR;
    const double tiny = 64.0 * (double)n * DBL_EPSILON * big;
    for (size_t k = 0; k < n; k++)
        if (!(fabs(gsl_matrix_get(w->A, k, k)) > tiny)) return VIGEN_ESINGULAR;
    return VIGEN_SUCCESS;
}

/* ---- the one-step map --------------------------------------------------- */

static int mvi_residual1(const double *d, double *r, void *ctx)
{
    vigen_midpoint_vi *w = ctx;
    const size_t n = w->n;
    mvi_midpoint(w, w->q0, d, w->h);
    int st = mvi_dLdq(w, w->tau, w->qbar, w->v, w->lq);
    if (st != VIGEN_SUCCESS) return st;
    for (size_t k = 0; k < n; k++) w->pm[k] = w->p0[k] + 0.5 * w->h * w->lq[k];
    st = mvi_g(w, w->tau, w->qbar, w->pm, w->lv);
    if (st != VIGEN_SUCCESS) return st;
    for (size_t k = 0; k < n; k++) r[k] = d[k] - w->h * w->lv[k];
    return VIGEN_SUCCESS;
}

/* dr/dd = I - A^-1 (-h/2 B + h^2/4 Lqq + h/2 Lqv) with A = Lvv, B = Lvq at
 * (tau, qbar, u), u = g(tau, qbar, P) (differentiating dL/dv(q, g(q, p)) = p
 * gives dg/dp = A^-1, dg/dq = -A^-1 B), and Lqq, Lqv at (tau, qbar, v).
 * Only with the user's second derivatives (else the solver differences r). */
static int mvi_jacobian1(const double *d, double *J, void *ctx)
{
    vigen_midpoint_vi *w = ctx;
    const size_t n = w->n;
    const double h = w->h;
    int st = mvi_hessian_at(w, d);
    if (st != VIGEN_SUCCESS) return st;
    for (size_t k = 0; k < n * n; k++) J[k] = 0.25 * h * h * w->Lqq[k] + 0.5 * h * w->Lqv[k];
    st = mvi_dLdq(w, w->tau, w->qbar, w->v, w->lq);
    if (st != VIGEN_SUCCESS) return st;
    for (size_t k = 0; k < n; k++) w->pm[k] = w->p0[k] + 0.5 * h * w->lq[k];
    st = mvi_g(w, w->tau, w->qbar, w->pm, w->lv);
    if (st == VIGEN_SUCCESS) st = mvi_hessian(w, w->tau, w->qbar, w->lv);
    if (st == VIGEN_SUCCESS) st = mvi_factor_lvv(w);
    if (st != VIGEN_SUCCESS) return st;
    for (size_t k = 0; k < n * n; k++) J[k] -= 0.5 * h * w->Lvq[k];
    gsl_vector_view col = gsl_vector_view_array(w->pm, n);
    for (size_t j = 0; j < n; j++) {
        for (size_t i = 0; i < n; i++) w->pm[i] = J[i * n + j];
        if (gsl_linalg_LU_svx(w->A, w->perm, &col.vector) != GSL_SUCCESS) return VIGEN_ESINGULAR;
        for (size_t i = 0; i < n; i++) J[i * n + j] = (i == j ? 1.0 : 0.0) - w->pm[i];
    }
    return vigen_lsolve_finite(J, n * n) ? VIGEN_SUCCESS : VIGEN_ENONFINITE;
}

/* Does (t, q, p) differ (bit for bit) from what the last step returned? */
static int mvi_moved(const vigen_midpoint_vi *w, double t, const double *q, const double *p)
{
    return !w->history || memcmp(&t, &w->tlast, sizeof t) != 0
           || memcmp(q, w->qlast, w->n * sizeof *q) != 0 || memcmp(p, w->plast, w->n * sizeof *p) != 0;
}

static int mvi_step1(vigen_midpoint_vi *w, double *t, double *q, double *p, double h)
{
    const size_t n = w->n;
    if (mvi_moved(w, *t, q, p)) {
        /* a new trajectory: no compensation, no velocity to extrapolate */
        w->history = 0;
        w->ct = 0.0;
        memset(w->cq, 0, n * sizeof *w->cq);
        memset(w->cp, 0, n * sizeof *w->cp);
    }
    w->tau = *t + 0.5 * h;
    w->h = h;
    w->q0 = q;
    w->p0 = p;
    int st = VIGEN_SUCCESS;
    /* v at the midpoints t - hprev/2 and t - hprev - hprev2/2, linearly
     * extrapolated to t + h/2: s is the ratio of the distances.  Not across
     * a reversal of direction (the two midpoints may coincide), nor to a
     * step many times the last ones (the line would be followed far out). */
    const int same_way = w->history == 2 && (w->hprev > 0) == (h > 0) && (w->hprev2 > 0) == (h > 0);
    const double s = same_way ? (w->hprev + h) / (w->hprev2 + w->hprev) : 0.0;
    if (same_way && w->opt.extrapolate && s <= 4.0) {
        for (size_t k = 0; k < n; k++) w->d[k] = h * (w->vprev[k] + s * (w->vprev[k] - w->vprev2[k]));
    } else if (w->history) {
        for (size_t k = 0; k < n; k++) w->d[k] = h * w->vprev[k];
    } else {
        st = mvi_g(w, *t, q, p, w->lv);
        for (size_t k = 0; k < n; k++) w->d[k] = h * w->lv[k];
    }
    if (st == VIGEN_SUCCESS)
        st = vigen_lsolve_run(w->ls, w->d, mvi_residual1, w->exact_hessian ? mvi_jacobian1 : NULL, w,
                              &w->opt, &w->stats);
    if (st != VIGEN_SUCCESS) return st;
    /* p1 from the converged d (the solver's last residual may be at another iterate) */
    mvi_midpoint(w, q, w->d, h);
    st = mvi_dLdq(w, w->tau, w->qbar, w->v, w->lq);
    if (st != VIGEN_SUCCESS) return st;
    const int kahan = w->opt.kahan;
    for (size_t k = 0; k < n; k++) {
        const double dp = h * w->lq[k];
        if (kahan) {
            w->qn[k] = vigen_twosum_next(q[k], w->d[k], w->cq[k], &w->cqn[k]);
            w->pn[k] = vigen_twosum_next(p[k], dp, w->cp[k], &w->cpn[k]);
        } else {
            w->qn[k] = q[k] + w->d[k];
            w->pn[k] = p[k] + dp;
        }
    }
    double ct = w->ct;
    const double t1 = kahan ? vigen_twosum_update(*t, h, &ct) : *t + h;
    if (!vigen_lsolve_finite(w->qn, n) || !vigen_lsolve_finite(w->pn, n) || !(t1 - t1 == 0)) return VIGEN_ENONFINITE;
    /* commit */
    memcpy(q, w->qn, n * sizeof *q);
    memcpy(p, w->pn, n * sizeof *p);
    if (kahan) {
        memcpy(w->cq, w->cqn, n * sizeof *q);
        memcpy(w->cp, w->cpn, n * sizeof *p);
        w->ct = ct;
    }
    *t = t1;
    double *v2 = w->vprev2;
    w->vprev2 = w->vprev;
    w->vprev = v2;
    memcpy(w->vprev, w->v, n * sizeof *q);
    w->hprev2 = w->hprev;
    w->hprev = h;
    memcpy(w->qlast, q, n * sizeof *q);
    memcpy(w->plast, p, n * sizeof *p);
    w->tlast = t1;
    w->history = w->history < 2 ? w->history + 1 : 2;
    return VIGEN_SUCCESS;
}

int vigen_midpoint_vi_step(vigen_midpoint_vi *w, double *t, double *q, double *p, double h)
{
    if (w == NULL || t == NULL || q == NULL || p == NULL) return VIGEN_EINVAL;
    const double t1 = *t + h;
    if (!(h - h == 0) || h == 0.0 || !(t1 - t1 == 0)) return VIGEN_EINVAL;
    if (w->g == NULL) return VIGEN_EUNSUPPORTED;
    const int st = mvi_step1(w, t, q, p, h);
    if (st == VIGEN_SUCCESS) w->stats.steps++;
    else w->stats.failed_steps++;
    return st;
}

/* ---- the two-step position form ------------------------------------------ */

static int mvi_residual2(const double *d, double *r, void *ctx)
{
    vigen_midpoint_vi *w = ctx;
    mvi_midpoint(w, w->q0, d, w->h);
    int st = mvi_dLdq(w, w->tau, w->qbar, w->v, w->lq);
    if (st == VIGEN_SUCCESS) st = mvi_dLdv(w, w->tau, w->qbar, w->v, w->lv);
    if (st != VIGEN_SUCCESS) return st;
    for (size_t k = 0; k < w->n; k++) r[k] = w->coef * w->lq[k] - w->lv[k] + w->pc[k];
    return VIGEN_SUCCESS;
}

/* dr/dd = h2/4 Lqq + 1/2 Lqv - 1/2 Lvq - Lvv/h2, from the user's second
 * derivatives or differences of the gradients.  The method needs Lvv
 * invertible (a regular Lagrangian); a singular one is VIGEN_ESINGULAR
 * even where the whole matrix happens not to be. */
static int mvi_jacobian2(const double *d, double *J, void *ctx)
{
    vigen_midpoint_vi *w = ctx;
    const size_t n = w->n;
    const double h = w->h;
    int st = mvi_hessian_at(w, d);
    if (st == VIGEN_SUCCESS) st = mvi_factor_lvv(w);
    if (st != VIGEN_SUCCESS) return st;
    for (size_t k = 0; k < n * n; k++)
        J[k] = 0.25 * h * w->Lqq[k] + 0.5 * (w->Lqv[k] - w->Lvq[k]) - w->Lvv[k] / h;
    return vigen_lsolve_finite(J, n * n) ? VIGEN_SUCCESS : VIGEN_ENONFINITE;
}

int vigen_midpoint_vi_step2(vigen_midpoint_vi *w, double t0, double t1, double t2,
                            const double *q0, const double *q1, double *q2)
{
    if (w == NULL || q0 == NULL || q1 == NULL || q2 == NULL || q2 == q0 || q2 == q1) return VIGEN_EINVAL;
    const double h1 = t1 - t0, h2 = t2 - t1;
    if (!(t0 - t0 == 0) || !(t1 - t1 == 0) || !(t2 - t2 == 0) || !(h1 - h1 == 0) || !(h2 - h2 == 0)
        || h1 == 0.0 || h2 == 0.0 || (h1 > 0) != (h2 > 0))
        return VIGEN_EINVAL;
    const size_t n = w->n;
    /* p1 = D2 Ld(q0, q1) */
    for (size_t k = 0; k < n; k++) w->d[k] = q1[k] - q0[k];
    mvi_midpoint(w, q0, w->d, h1);
    const double tau1 = t0 + 0.5 * h1;
    int st = mvi_dLdq(w, tau1, w->qbar, w->v, w->lq);
    if (st == VIGEN_SUCCESS) st = mvi_dLdv(w, tau1, w->qbar, w->v, w->lv);
    if (st == VIGEN_SUCCESS) {
        for (size_t k = 0; k < n; k++) {
            w->pc[k] = 0.5 * h1 * w->lq[k] + w->lv[k];
            w->d[k] *= h2 / h1;             /* predictor: the same velocity */
        }
        w->tau = t1 + 0.5 * h2;
        w->h = h2;
        w->coef = 0.5 * h2;
        w->q0 = q1;
        st = vigen_lsolve_run(w->ls, w->d, mvi_residual2, mvi_jacobian2, w, &w->opt, &w->stats);
    }
    if (st == VIGEN_SUCCESS) {
        for (size_t k = 0; k < n; k++) w->qn[k] = q1[k] + w->d[k];
        if (!vigen_lsolve_finite(w->qn, n)) st = VIGEN_ENONFINITE;
    }
    if (st != VIGEN_SUCCESS) {
        w->stats.failed_steps++;
        return st;
    }
    memcpy(q2, w->qn, n * sizeof *q2);
    w->stats.steps++;
    return VIGEN_SUCCESS;
}

/* ---- workspace ----------------------------------------------------------- */

vigen_midpoint_vi *vigen_midpoint_vi_alloc(const vigen_lagrangian *lag, vigen_lgrad_fn g,
                                           const vigen_solver_options *opt)
{
    if (vigen_lagrangian_validate(lag, NULL, NULL) != VIGEN_SUCCESS) return NULL;
    const size_t n = lag->dim;
    enum { NVEC = 23, NMAT = 4 };
    if ((size_t)-1 / sizeof(double) / (NVEC + NMAT) / n < n) return NULL;   /* size overflows */
    gsl_set_error_handler_off();
    vigen_midpoint_vi *w = calloc(1, sizeof *w);
    if (w == NULL) return NULL;
    w->lag = *lag;
    w->g = g;
    w->n = n;
    if (opt) w->opt = *opt;
    else vigen_solver_options_default(&w->opt);
    w->opt.solver = VIGEN_SOLVER_NEWTON;
    w->exact_hessian = lag->d2Ldq2 != NULL && lag->d2Ldv2 != NULL && lag->d2Ldqdv != NULL;
    w->mem = calloc(NVEC * n + NMAT * n * n, sizeof(double));
    w->ls = vigen_lsolve_alloc(n);
    w->A = gsl_matrix_alloc(n, n);
    w->perm = gsl_permutation_alloc(n);
    const int field = vigen_lfield_init(&w->field, &w->lag, &w->opt);
    if (w->mem == NULL || w->ls == NULL || w->A == NULL || w->perm == NULL || field != VIGEN_SUCCESS) {
        vigen_midpoint_vi_free(w);
        return NULL;
    }
    double *m = w->mem;
    double **vecs[NVEC] = {&w->qbar, &w->v, &w->lq, &w->lv, &w->pm, &w->d, &w->pc, &w->qn, &w->pn,
                           &w->cqn, &w->cpn, &w->cq, &w->cp, &w->vprev, &w->vprev2, &w->qlast, &w->plast,
                           &w->gq, &w->gv, &w->xq, &w->xv, &w->sq, &w->sv};
    for (size_t i = 0; i < NVEC; i++, m += n) *vecs[i] = m;
    double **mats[NMAT] = {&w->Lqq, &w->Lqv, &w->Lvq, &w->Lvv};
    for (size_t i = 0; i < NMAT; i++, m += n * n) *mats[i] = m;
    return w;
}

const vigen_stats *vigen_midpoint_vi_stats(const vigen_midpoint_vi *w) { return &w->stats; }

void vigen_midpoint_vi_reset(vigen_midpoint_vi *w)
{
    if (w == NULL) return;
    memset(&w->stats, 0, sizeof w->stats);
    w->history = 0;   /* the next step starts a trajectory: no compensation, no velocity to extrapolate */
}

void vigen_midpoint_vi_free(vigen_midpoint_vi *w)
{
    if (w == NULL) return;
    vigen_lsolve_free(w->ls);
    if (w->A) gsl_matrix_free(w->A);
    if (w->perm) gsl_permutation_free(w->perm);
    vigen_lfield_clear(&w->field);
    free(w->mem);
    free(w);
}

/* ---- saved states ----------------------------------------------------------- */

/* The payload in its order (lstate_internal.h): the flag first, as vigen_lstate_check
 * reads it, then the statistics, times and arrays. */
static size_t mvi_state_walk(void *ws, void *buf, int save)
{
    vigen_midpoint_vi *w = ws;
    const size_t n = w->n;
    vigen_lstate_io io;
    vigen_lstate_begin(&io, buf, save);
    vigen_lstate_flag(&io, &w->history);
    vigen_lstate_stats(&io, &w->stats);
    double *const scalars[] = { &w->tlast, &w->ct, &w->hprev, &w->hprev2 };
    for (size_t i = 0; i < sizeof scalars / sizeof scalars[0]; i++) vigen_lstate_reals(&io, scalars[i], 1);
    double *const arrays[] = { w->qlast, w->plast, w->cq, w->cp, w->vprev, w->vprev2 };
    for (size_t i = 0; i < sizeof arrays / sizeof arrays[0]; i++) vigen_lstate_reals(&io, arrays[i], n);
    return vigen_lstate_end(&io);
}

/* history is 0 .. 2 */
static vigen_lstate_kind mvi_state_kind(const vigen_midpoint_vi *w)
{
    return (vigen_lstate_kind){ "vigen_midpoint_vi", w->n, 0, w->g != NULL, &w->opt, mvi_state_walk, 1, 2 };
}

size_t vigen_midpoint_vi_state_size(const vigen_midpoint_vi *w)
{
    if (w == NULL) return 0;
    const vigen_lstate_kind k = mvi_state_kind(w);
    return vigen_lstate_size(w, &k);
}

int vigen_midpoint_vi_state_get(const vigen_midpoint_vi *w, void *buf)
{
    if (w == NULL) return VIGEN_EINVAL;
    const vigen_lstate_kind k = mvi_state_kind(w);
    return vigen_lstate_get(w, &k, buf);
}

int vigen_midpoint_vi_state_set(vigen_midpoint_vi *w, const void *buf)
{
    if (w == NULL) return VIGEN_EINVAL;
    const vigen_lstate_kind k = mvi_state_kind(w);
    return vigen_lstate_set(w, &k, buf);
}

/* ---- the stepper type ------------------------------------------------------- */

/* The flow, Newton started from the last step's velocity (zero before the
 * first step). */
static int mvi_field(void *ws, double t, const double *q, const double *p, double *dq, double *dp)
{
    vigen_midpoint_vi *w = ws;
    return vigen_lfield_eval(&w->field, w->history ? w->vprev : NULL, t, q, p, dq, dp);
}

static int mvi_type_step(void *w, double *t, double *q, double *p, double h)
{
    return vigen_midpoint_vi_step(w, t, q, p, h);
}
static void mvi_type_reset(void *w) { vigen_midpoint_vi_reset(w); }
static const vigen_stats *mvi_type_stats(const void *w) { return vigen_midpoint_vi_stats(w); }
static void mvi_type_free(void *w) { vigen_midpoint_vi_free(w); }
static size_t mvi_type_state_size(const void *w) { return vigen_midpoint_vi_state_size(w); }
static int mvi_type_state_get(const void *w, void *buf) { return vigen_midpoint_vi_state_get(w, buf); }
static int mvi_type_state_set(void *w, const void *buf) { return vigen_midpoint_vi_state_set(w, buf); }
static size_t mvi_type_dim(const void *w) { return ((const vigen_midpoint_vi *)w)->n; }
static void *mvi_type_clone(const void *ws)
{
    const vigen_midpoint_vi *w = ws;
    return vigen_midpoint_vi_alloc(&w->lag, w->g, &w->opt);
}

const vigen_stepper_type vigen_midpoint_vi_type = {
    "vigen_midpoint_vi", 1, 2, 0,
    NULL, mvi_type_step, mvi_type_reset, mvi_type_stats, mvi_type_free,
    mvi_type_state_size, mvi_type_state_get, mvi_type_state_set,
    mvi_type_dim, mvi_field, mvi_type_clone
};
