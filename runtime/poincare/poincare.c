/* poincare.c — the Poincaré time transformation of <vigen/poincare.h>:
 * K = g (H + e) on the extended phase space Q = (q, t), P = (p, e), its
 * gradients as a vigen_hamiltonian, and the driver that steps K with a
 * constant fictive step and stops at a physical time with a shortened last
 * step. */
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "poincare_internal.h"

static void pc_say(vigen_poincare *pc, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(pc->msg, sizeof pc->msg, fmt, ap);
    va_end(ap);
}

static int all_finite(const double *x, size_t n)
{
    for (size_t k = 0; k < n; k++)
        if (!isfinite(x[k])) return 0;
    return 1;
}

/* H + e, g and the gradient of g at (Q, P), from the cache when the point is
 * the previous one bit for bit (a Newton sweep asks for both gradients of K
 * at each stage).  Returns VIGEN_SUCCESS, VIGEN_ENONFINITE (H, g or its
 * gradient not finite) or VIGEN_EINVAL (g <= 0), with the message set. */
static int pc_common(vigen_poincare *pc, const double *Q, const double *P)
{
    const size_t n = pc->n, bytes = (n + 1) * sizeof(double);
    if (pc->cache_ok && memcmp(Q, pc->cq, bytes) == 0 && memcmp(P, pc->cp, bytes) == 0) {
        pc->stats.cache_hits++;
        return pc->cache_status;
    }
    const double t = Q[n];
    memset(pc->dgdq, 0, n * sizeof(double));
    memset(pc->dgdp, 0, n * sizeof(double));
    pc->dgdt = 0;
    pc->g = pc->pb.density(t, Q, P, pc->dgdq, pc->dgdp, &pc->dgdt, pc->pb.density_ctx);
    pc->stats.density_evals++;
    const double H = pc->pb.sys->H(t, Q, P, pc->pb.sys->ctx);
    pc->stats.H_evals++;
    pc->hpe = H + P[n];
    int st = VIGEN_SUCCESS;
    if (!isfinite(pc->g) || !isfinite(pc->dgdt) || !all_finite(pc->dgdq, n) || !all_finite(pc->dgdp, n)) {
        pc_say(pc, "the step density g or its gradient is not finite at t = %.17g (g = %g): "
                   "make g positive and finite along the orbit", t, pc->g);
        st = VIGEN_ENONFINITE;
    } else if (!(pc->g > 0)) {
        pc_say(pc, "the step density g = %g at t = %.17g is not positive: g must be > 0 "
                   "wherever the orbit goes", pc->g, t);
        st = VIGEN_EINVAL;
    } else if (!isfinite(pc->hpe)) {
        pc_say(pc, "H is not finite at t = %.17g (H = %g)", t, H);
        st = VIGEN_ENONFINITE;
    }
    memcpy(pc->cq, Q, bytes);
    memcpy(pc->cp, P, bytes);
    pc->cache_ok = 1;
    pc->cache_status = st;
    return st;
}

/* A failed evaluation poisons the gradient, so that the stepper refuses the
 * step (VIGEN_ENONFINITE, state unchanged); the driver then reports the
 * density's own status and message. */
static void pc_poison(vigen_poincare *pc, int st, double *out)
{
    if (!pc->err) pc->err = st;
    for (size_t k = 0; k <= pc->n; k++) out[k] = NAN;
}

/* dK/dQ = (g dH/dq + (H + e) dg/dq,  g dH/dt + (H + e) dg/dt). */
static void k_dQ(double tau, const double *Q, const double *P, double *out, void *ctx)
{
    vigen_poincare *pc = ctx;
    const size_t n = pc->n;
    (void)tau;
    int st = pc_common(pc, Q, P);
    if (st != VIGEN_SUCCESS) { pc_poison(pc, st, out); return; }
    const double t = Q[n];
    pc->pb.sys->dHdq(t, Q, P, out, pc->pb.sys->ctx);
    pc->stats.dHdq_evals++;
    for (size_t k = 0; k < n; k++) out[k] = pc->g * out[k] + pc->hpe * pc->dgdq[k];
    double dHdt = 0;
    if (pc->pb.dHdt) {
        dHdt = pc->pb.dHdt(t, Q, P, pc->pb.sys->ctx);
        pc->stats.dHdt_evals++;
    }
    out[n] = pc->g * dHdt + pc->hpe * pc->dgdt;
}

/* dK/dP = (g dH/dp + (H + e) dg/dp,  g): g does not depend on e. */
static void k_dP(double tau, const double *Q, const double *P, double *out, void *ctx)
{
    vigen_poincare *pc = ctx;
    const size_t n = pc->n;
    (void)tau;
    int st = pc_common(pc, Q, P);
    if (st != VIGEN_SUCCESS) { pc_poison(pc, st, out); return; }
    pc->pb.sys->dHdp(Q[n], Q, P, out, pc->pb.sys->ctx);
    pc->stats.dHdp_evals++;
    for (size_t k = 0; k < n; k++) out[k] = pc->g * out[k] + pc->hpe * pc->dgdp[k];
    out[n] = pc->g;
}

static double k_value(double tau, const double *Q, const double *P, void *ctx)
{
    vigen_poincare *pc = ctx;
    (void)tau;
    int st = pc_common(pc, Q, P);
    if (st != VIGEN_SUCCESS) { if (!pc->err) pc->err = st; return NAN; }
    return pc->g * pc->hpe;
}

int vigen_poincare_alloc(vigen_poincare **out, const vigen_poincare_problem *pb)
{
    if (out == NULL) return VIGEN_EINVAL;
    *out = NULL;
    if (pb == NULL || pb->sys == NULL || pb->density == NULL || pb->sys->dim == 0 || pb->sys->H == NULL
        || pb->sys->dHdq == NULL || pb->sys->dHdp == NULL)
        return VIGEN_EINVAL;
    const size_t n = pb->sys->dim;
    if (n > ((size_t)-1) / sizeof(double) / 16) return VIGEN_ENOMEM;
    vigen_poincare *pc = calloc(1, sizeof *pc);
    double *mem = calloc(8 * (n + 1), sizeof(double));
    if (pc == NULL || mem == NULL) { free(pc); free(mem); return VIGEN_ENOMEM; }
    pc->pb = *pb;
    pc->n = n;
    pc->cq = mem;
    pc->cp = mem + (n + 1);
    pc->dgdq = mem + 2 * (n + 1);
    pc->dgdp = mem + 3 * (n + 1);
    pc->Q = mem + 4 * (n + 1);
    pc->P = mem + 5 * (n + 1);
    pc->Qs = mem + 6 * (n + 1);
    pc->Ps = mem + 7 * (n + 1);
    pc->K.dim = n + 1;
    pc->K.dHdq = k_dQ;
    pc->K.dHdp = k_dP;
    pc->K.H = k_value;
    pc->K.ctx = pc;
    pc->K.separable = 0;
    pc->K.hessian = NULL;
    *out = pc;
    return VIGEN_SUCCESS;
}

void vigen_poincare_free(vigen_poincare *pc)
{
    if (pc == NULL) return;
    free(pc->cq);
    free(pc);
}

const vigen_hamiltonian *vigen_poincare_hamiltonian(const vigen_poincare *pc) { return pc ? &pc->K : NULL; }
const char *vigen_poincare_message(const vigen_poincare *pc) { return pc ? pc->msg : ""; }
const vigen_poincare_stats *vigen_poincare_get_stats(const vigen_poincare *pc) { return pc ? &pc->stats : NULL; }

int vigen_poincare_extend(vigen_poincare *pc, double t, const double *q, const double *p, double *Q, double *P)
{
    if (pc == NULL || q == NULL || p == NULL || Q == NULL || P == NULL) return VIGEN_EINVAL;
    const size_t n = pc->n;
    if (!isfinite(t) || !all_finite(q, n) || !all_finite(p, n)) {
        pc_say(pc, "the state at t = %.17g is not finite: give finite t, q and p", t);
        return VIGEN_EINVAL;
    }
    memmove(Q, q, n * sizeof(double));
    memmove(P, p, n * sizeof(double));
    Q[n] = t;
    const double H = pc->pb.sys->H(t, Q, P, pc->pb.sys->ctx);
    pc->stats.H_evals++;
    if (!isfinite(H)) {
        pc_say(pc, "H is not finite at the start (t = %.17g, H = %g)", t, H);
        return VIGEN_ENONFINITE;
    }
    P[n] = -H;
    return VIGEN_SUCCESS;
}

/* A new trajectory from (t, q, p): the extended state, and the checks that
 * K can be stepped there (H ignores t when no dH/dt is given; g is positive
 * and finite at the start). */
static int pc_start(vigen_poincare *pc, double t, const double *q, const double *p)
{
    const size_t n = pc->n;
    pc->have = 0;
    int st = vigen_poincare_extend(pc, t, q, p, pc->Q, pc->P);
    if (st != VIGEN_SUCCESS) return st;
    if (pc->pb.dHdt == NULL) {
        /* an H that ignores t returns the same bits at other times */
        const double d = ldexp(fabs(t) > 1 ? fabs(t) : 1.0, -6);
        const double h0 = -pc->P[n];
        const double h1 = pc->pb.sys->H(t + d, pc->Q, pc->P, pc->pb.sys->ctx);
        const double h2 = pc->pb.sys->H(t - d, pc->Q, pc->P, pc->pb.sys->ctx);
        pc->stats.H_evals += 2;
        if (h1 != h0 || h2 != h0) {
            pc_say(pc, "H depends on t (H(t0 + %g) - H(t0) = %g) but vigen_poincare_problem.dHdt is "
                       "NULL: give dH/dt", d, h1 - h0);
            return VIGEN_EINVAL;
        }
    }
    pc->cache_ok = 0;
    st = pc_common(pc, pc->Q, pc->P);
    if (st != VIGEN_SUCCESS) return st;
    pc->tau = 0;
    pc->have = 1;
    return VIGEN_SUCCESS;
}

/* One trial step of fictive size sigma from the saved state (Qs, Ps, tau0)
 * into (Q, P, tau). */
static int pc_trial(const vigen_stepper_type *T, void *w, vigen_poincare *pc, double tau0, double sigma)
{
    const size_t bytes = (pc->n + 1) * sizeof(double);
    memcpy(pc->Q, pc->Qs, bytes);
    memcpy(pc->P, pc->Ps, bytes);
    pc->tau = tau0;
    pc->err = 0;
    return T->step(w, &pc->tau, pc->Q, pc->P, sigma);
}

/* The shortened last step: sigma in (0, |dtau|) (signed like dtau) with
 * t(sigma) = t_end, t(sigma) increasing, found by regula falsi with the
 * Illinois modification on the bracket [0, |dtau|] (values fa < 0 < fb),
 * until |t(sigma) - t_end| <= 2 eps max(|t_end|, |t0|) or the bracket cannot shrink.
 * The state of the best trial is left in (Q, P, tau). */
static int pc_shorten(const vigen_stepper_type *T, void *w, vigen_poincare *pc, double tau0, double dtau,
                      double t_end, double fa, double fb, vigen_poincare_result *res)
{
    const size_t n = pc->n;
    const double dir = dtau > 0 ? 1.0 : -1.0;
    const double scale = fmax(fabs(t_end), fabs(pc->Qs[n]));
    const double tol = 2 * DBL_EPSILON * (scale > DBL_MIN ? scale : DBL_MIN);
    double a = 0, b = fabs(dtau), best_s = b, best_f = fb, s = b, fs = fb;
    int side = 0, st = VIGEN_SUCCESS;
    for (int it = 0; it < 64; it++) {
        s = (a * fb - b * fa) / (fb - fa);
        if (!(s > a && s < b)) s = a + (b - a) / 2;
        if (!(s > a && s < b)) break;                 /* the bracket cannot shrink further */
        st = pc_trial(T, w, pc, tau0, dir * s);
        res->end_trials++;
        if (st != VIGEN_SUCCESS) return st;
        fs = dir * (pc->Q[n] - t_end);
        if (fabs(fs) < fabs(best_f)) { best_f = fs; best_s = s; }
        if (fabs(fs) <= tol) break;
        if (fs < 0) { a = s; fa = fs; if (side == -1) fb /= 2; side = -1; }
        else { b = s; fb = fs; if (side == 1) fa /= 2; side = 1; }
    }
    if (s != best_s) {
        st = pc_trial(T, w, pc, tau0, dir * best_s);
        res->end_trials++;
        if (st != VIGEN_SUCCESS) return st;
    }
    res->last_dtau = dir * best_s;
    res->t_mismatch = pc->Q[n] - t_end;
    return VIGEN_SUCCESS;
}

/* The status of a failed step, with its message. */
static int pc_failed(vigen_poincare *pc, int st, double t)
{
    if (pc->err) return pc->err;            /* the density's message is set */
    pc_say(pc, "the fictive step from t = %.17g failed: %s", t, vigen_strerror(st));
    return st;
}

int vigen_poincare_begin(vigen_poincare *pc, double t, const double *q, const double *p)
{
    const size_t n = pc->n;
    const int same = pc->have && t == pc->t_rep && memcmp(q, pc->Q, n * sizeof(double)) == 0
                     && memcmp(p, pc->P, n * sizeof(double)) == 0;
    return same ? VIGEN_SUCCESS : pc_start(pc, t, q, p);
}

int vigen_poincare_fictive_step(vigen_poincare *pc, const vigen_stepper_type *T, void *w, double dtau)
{
    const double t0 = pc->Q[pc->n];
    pc->err = 0;
    const int st = T->step(w, &pc->tau, pc->Q, pc->P, dtau);
    return st == VIGEN_SUCCESS ? st : pc_failed(pc, st, t0);
}

int vigen_poincare_integrate(const vigen_stepper_type *T, void *w, vigen_poincare *pc, double *t, double *q,
                             double *p, double dtau, double t_end, unsigned long max_steps,
                             unsigned long every, vigen_poincare_observer_fn obs, void *obs_ctx,
                             vigen_poincare_result *res)
{
    vigen_poincare_result scratch;
    if (res == NULL) res = &scratch;
    memset(res, 0, sizeof *res);
    if (pc == NULL) return VIGEN_EINVAL;
    pc->msg[0] = 0;
    if (T == NULL || w == NULL || t == NULL || q == NULL || p == NULL) {
        pc_say(pc, "vigen_poincare_integrate: NULL stepper, workspace or state");
        return VIGEN_EINVAL;
    }
    const size_t n = pc->n, bytes = (n + 1) * sizeof(double);
    if (!isfinite(dtau) || dtau == 0 || !isfinite(t_end) || !isfinite(*t)
        || (t_end != *t && (dtau > 0) != (t_end > *t))) {
        pc_say(pc, "vigen_poincare_integrate: dtau = %g and t_end = %g from t = %g: give finite values, "
                   "dtau nonzero and of the sign of t_end - t", dtau, t_end, *t);
        return VIGEN_EINVAL;
    }
    int st = vigen_poincare_begin(pc, *t, q, p);
    if (st != VIGEN_SUCCESS) return st;
    const double dir = dtau > 0 ? 1.0 : -1.0;
    unsigned long k = 0;
    int finished = (t_end == *t);
    if (obs && obs(0, pc->tau, *t, pc->Q, pc->P, obs_ctx)) st = VIGEN_ESTOPPED;
    while (st == VIGEN_SUCCESS && !finished) {
        if (max_steps && k >= max_steps) { res->capped = 1; st = VIGEN_ESTOPPED; break; }
        const double tau0 = pc->tau, t0 = pc->Q[n];
        memcpy(pc->Qs, pc->Q, bytes);
        memcpy(pc->Ps, pc->P, bytes);
        st = vigen_poincare_fictive_step(pc, T, w, dtau);
        if (st != VIGEN_SUCCESS) break;
        const double ahead = dir * (pc->Q[n] - t_end);
        if (ahead >= 0) {
            if (ahead > 0) {
                st = pc_shorten(T, w, pc, tau0, dtau, t_end, dir * (t0 - t_end), ahead, res);
                if (st != VIGEN_SUCCESS) {
                    st = pc_failed(pc, st, t0);
                    memcpy(pc->Q, pc->Qs, bytes);         /* back to the last accepted step */
                    memcpy(pc->P, pc->Ps, bytes);
                    pc->tau = tau0;
                    break;
                }
            }
            finished = 1;
        }
        k++;
        if (obs && !finished && every && k % every == 0
            && obs(k, pc->tau, pc->Q[n], pc->Q, pc->P, obs_ctx)) st = VIGEN_ESTOPPED;
    }
    memcpy(q, pc->Q, n * sizeof(double));
    memcpy(p, pc->P, n * sizeof(double));
    *t = finished ? t_end : pc->Q[n];
    pc->t_rep = *t;
    res->steps = k;
    res->tau = pc->tau;
    const double H = pc->pb.sys->H(pc->Q[n], pc->Q, pc->P, pc->pb.sys->ctx);
    pc->stats.H_evals++;
    res->energy_error = H + pc->P[n];
    if (finished && k > 0 && st == VIGEN_SUCCESS && obs && obs(k, pc->tau, *t, q, p, obs_ctx)) st = VIGEN_ESTOPPED;
    return st;
}

double vigen_poincare_density_power(double t, const double *q, const double *p, double *dgdq, double *dgdp,
                                    double *dgdt, void *ctx)
{
    const vigen_poincare_power *pw = ctx;
    (void)t; (void)p; (void)dgdp; (void)dgdt;
    double r2 = 0;
    for (size_t k = pw->first; k < pw->first + pw->count; k++) r2 += q[k] * q[k];
    const double g = pow(r2, pw->alpha / 2);
    if (r2 > 0)
        for (size_t k = pw->first; k < pw->first + pw->count; k++) dgdq[k] = pw->alpha * g / r2 * q[k];
    return g;
}
