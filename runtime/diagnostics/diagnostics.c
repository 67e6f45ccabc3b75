/* diagnostics.c — vigen_problem_check: a Hamiltonian problem checked at a
 * state and two points nearby (finiteness, both gradients against central
 * differences of H, the separability promise, the Hessian against
 * differences of the gradients), and the check that says what it found on
 * standard error. */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "diagnostics_internal.h"

/* What the checks of each point need besides the engine's. */
typedef struct {
    const vigen_hamiltonian *sys;
    double t;
    const vigen_dg_function *f;
    const double *x, *s, *g;    /* the state, its scales and its gradient */
    double *xs, *gs, *hess;     /* work: 2 dim, 2 dim, (2 dim)^2 (NULL: no Hessian check) */
    vigen_dg_tally sep, second;
    vigen_problem_report *rep;
} ham_points;

/* Separability at the nearby point y: dH/dp at (t + dt, y_q, p) and dH/dq at
 * (t, q, y_p) against g (at the state).  A separable H gives the same
 * gradients (bit for bit when coded without the other variables); a change
 * above a few ulps of the part's scale is a coupling. */
static void separability(ham_points *h, const double *y, int point, vigen_dg_rng *r)
{
    const vigen_hamiltonian *sys = h->sys;
    size_t n = sys->dim;
    double ts = h->t + 0x1p-10 * vigen_dg_rng_uniform(r) * fmax(fabs(h->t), 1), scale[2] = { 0, 0 };
    for (size_t k = 0; k < 2 * n; k++) scale[k / n] = fmax(scale[k / n], fabs(h->g[k]));
    memcpy(h->xs, y, n * sizeof *h->xs);            /* q moved, p kept */
    memcpy(h->xs + n, h->x + n, n * sizeof *h->xs);
    sys->dHdp(ts, h->xs, h->xs + n, h->gs + n, sys->ctx);
    memcpy(h->xs, h->x, n * sizeof *h->xs);         /* p moved, q kept */
    memcpy(h->xs + n, y + n, n * sizeof *h->xs);
    sys->dHdq(h->t, h->xs, h->xs + n, h->gs, sys->ctx);
    for (size_t k = 0; k < 2 * n; k++) {
        if (!isfinite(h->gs[k])) continue;
        double d = fabs(h->gs[k] - h->g[k]), den = fmax(fmax(fabs(h->g[k]), fabs(h->gs[k])), scale[k / n]);
        double rel = den > 0 ? d / den : 0;
        vigen_dg_mismatch m = { rel / (64 * DBL_EPSILON), rel, h->g[k], h->gs[k], 0, (int)(k / n), k % n, (size_t)-1,
                          NULL, point, 1 };
        vigen_dg_tally_add(&h->sep, &m);
    }
}

/* The checks of a point beyond the gradient: separability (nearby points)
 * and the Hessian. */
static int ham_point(void *ctx, const double *y, int point, vigen_dg_rng *r)
{
    ham_points *h = ctx;
    const vigen_hamiltonian *sys = h->sys;
    size_t n = sys->dim, m = 2 * n;
    if (point > 0 && sys->separable) separability(h, y, point, r);
    if (h->hess == NULL) return VIGEN_SUCCESS;
    sys->hessian(h->t, y, y + n, h->hess, sys->ctx);
    size_t e = vigen_dg_first_nonfinite(h->hess, m * m);
    if (e < m * m) {
        h->rep->worst_part = (int)(e / m / n);
        h->rep->worst_index = e / m % n;
        h->rep->worst_column = e % m;
        return vigen_dg_report_set(h->rep, VIGEN_ENONFINITE, "the Hessian entry (%zu, %zu) is %g %s", e / m, e % m,
                             h->hess[e], vigen_dg_where(point));
    }
    vigen_dg_block b = { "the Hessian", 0, 0, m, m, m, h->hess };
    return vigen_dg_compare_second(h->f, y, h->s, &b, 1, point, r, &h->second);
}

static int ham_validate(const vigen_hamiltonian *sys, double t, const double *q, const double *p,
                        vigen_problem_report *rep)
{
    if (sys == NULL || q == NULL || p == NULL)
        return vigen_dg_report_set(rep, VIGEN_EINVAL, "the problem check needs the problem and the state q, p (a NULL pointer was given)");
    if (sys->dim == 0 || sys->dHdq == NULL || sys->dHdp == NULL)
        return vigen_dg_report_set(rep, VIGEN_EINVAL, "the problem is incomplete: it needs dim > 0, dHdq and dHdp");
    return vigen_dg_state_check(rep, t, "q", q, "p", p, sys->dim);
}

/* The sentence of a problem that passed. */
static void ham_success(vigen_problem_report *rep, const vigen_hamiltonian *sys, const vigen_dg_tally *tally,
                        int hessian_checked)
{
    static const char *const names[2] = { "dH/dq", "dH/dp" };
    char head[140];
    if (sys->H && tally->largest.found)
        snprintf(head, sizeof head, "H agrees with dH/dq and dH/dp at %d points (largest relative mismatch %.1e, %s[%zu])",
                 rep->points, tally->largest.rel, names[tally->largest.part], tally->largest.index);
    else
        snprintf(head, sizeof head, "the gradient check was skipped because H is %s; dH/dq and dH/dp are finite",
                 sys->H ? "not finite next to the state" : "not given");
    vigen_dg_report_set(rep, VIGEN_SUCCESS, "%s%s%s%s.", head,
                  sys->separable ? "; dH/dp ignores t and q and dH/dq ignores p" : "",
                  !sys->hessian ? "" : hessian_checked ? "; the Hessian agrees with differences of the gradients"
                                                       : "; Hessian not checked (dimension > 1024)",
                  tally->sampled ? "; 64 components per part sampled, all along random directions" : "");
}

/* The verdict once every point is checked: the first kind of mismatch found. */
static void ham_verdict(vigen_problem_report *rep, const vigen_hamiltonian *sys, const vigen_dg_function *f,
                        const vigen_dg_tally *grad, const ham_points *h)
{
    rep->gradient_checked = sys->H != NULL && grad->compared > 0;
    rep->second_checked = h->hess != NULL;
    if (grad->flagged.found) {
        vigen_dg_report_mismatch(rep, f, &grad->flagged, VIGEN_EGRADIENT);
    } else if (h->sep.flagged.found) {
        const vigen_dg_mismatch *s = &h->sep.flagged;
        rep->worst_rel_error = s->rel;
        rep->worst_part = s->part;
        rep->worst_index = s->index;
        vigen_dg_report_set(rep, VIGEN_ESEPARABLE,
                      "the problem is marked separable but %s[%zu] changes by a relative %.2g when %s (%.6g at "
                      "the state, %.6g nearby)",
                      f->part_name[s->part], s->index, s->rel, s->part == 1 ? "t and q move" : "p moves", s->given,
                      s->differences);
    } else if (h->second.flagged.found) {
        vigen_dg_report_mismatch(rep, f, &h->second.flagged, VIGEN_EHESSIAN);
    } else {
        vigen_dg_report_largest(rep, grad);
        ham_success(rep, sys, grad, h->hess != NULL);
    }
}

int vigen_problem_check(const vigen_hamiltonian *sys, double t, const double *q, const double *p,
                        vigen_problem_report *rep)
{
    vigen_dg_report_start(rep);
    if (ham_validate(sys, t, q, p, rep) != VIGEN_SUCCESS) return rep->status;
    size_t n = sys->dim, m = 2 * n;
    int hessian = sys->hessian != NULL && m <= DG_MAX_SECOND;
    /* x, its scales, its gradient, the separability work, the Hessian */
    double *x = m <= (size_t)-1 / sizeof(double) / 8 ? malloc((5 * m + (hessian ? m * m : 0)) * sizeof *x) : NULL;
    if (x == NULL) return vigen_dg_report_set(rep, VIGEN_ENOMEM, "out of memory checking the problem (dimension %zu)", n);
    vigen_dg_pair self = { n, t, sys->H, { sys->dHdq, sys->dHdp }, sys->ctx };
    vigen_dg_function f = { n, 2, sys->H ? vigen_dg_pair_value : NULL, vigen_dg_pair_gradient, &self, "H", { "dH/dq", "dH/dp" },
                      { "q", "p" }, { 1, 1 } };
    ham_points h = { .sys = sys, .t = t, .f = &f, .x = x, .s = x + m, .g = x + 2 * m, .xs = x + 3 * m,
                     .gs = x + 4 * m, .hess = hessian ? x + 5 * m : NULL, .rep = rep };
    double *s = x + m, *g = x + 2 * m;
    memcpy(x, q, n * sizeof *x);
    memcpy(x + n, p, n * sizeof *x);
    int rc = vigen_dg_state_values(&f, x, g, rep);
    if (rc == VIGEN_SUCCESS) {
        vigen_dg_tally grad;
        vigen_dg_tally_init(&h.sep);
        vigen_dg_tally_init(&h.second);
        rc = vigen_dg_check_points(&f, x, s, &grad, ham_point, &h, &rep->points);
        if (rc == VIGEN_ENOMEM)
            vigen_dg_report_set(rep, VIGEN_ENOMEM, "out of memory checking the problem (dimension %zu)", n);
        else if (rc == VIGEN_SUCCESS)
            ham_verdict(rep, sys, &f, &grad, &h);
    }
    free(x);
    return rep->status;
}

int vigen_problem_check_or_say(const char *who, const vigen_hamiltonian *sys, double t, const double *q,
                               const double *p)
{
    vigen_problem_report rep;
    int status = vigen_problem_check(sys, t, q, p, &rep);
    if (status != VIGEN_SUCCESS) fprintf(stderr, "%s: %s\n", who ? who : "vigen", rep.message);
    return status;
}
