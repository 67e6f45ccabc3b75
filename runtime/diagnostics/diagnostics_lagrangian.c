/* diagnostics_lagrangian.c — vigen_lagrangian_check: a Lagrangian checked
 * at (t, q, v) and two points nearby: L and its first derivatives finite,
 * dL/dq and dL/dv against central differences of L (when L is given), and
 * the optional second derivatives d2Ldq2, d2Ldv2, d2Ldqdv against
 * differences of the first. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "diagnostics_internal.h"

static int lag_validate(const vigen_lagrangian *lag, double t, const double *q, const double *v,
                        vigen_problem_report *rep)
{
    if (lag == NULL || q == NULL || v == NULL)
        return vigen_dg_report_set(rep, VIGEN_EINVAL, "the Lagrangian check needs the Lagrangian and the state q, v (a NULL pointer was given)");
    if (lag->dim == 0 || lag->dLdq == NULL || lag->dLdv == NULL)
        return vigen_dg_report_set(rep, VIGEN_EINVAL, "the Lagrangian is incomplete: it needs dim > 0, dLdq and dLdv");
    return vigen_dg_state_check(rep, t, "q", q, "v", v, lag->dim);
}

/* What the second-derivative check of each point needs. */
typedef struct {
    const vigen_lagrangian *lag;
    double t;
    const vigen_dg_function *f;
    const double *s;      /* scales of the state */
    double *buf;          /* 3 dim^2: the given blocks */
    vigen_dg_tally second;
    vigen_problem_report *rep;
} lag_points;

/* The given second derivatives at y against differences of the first. */
static int lag_point(void *ctx, const double *y, int point, vigen_dg_rng *r)
{
    lag_points *lp = ctx;
    const vigen_lagrangian *lag = lp->lag;
    size_t n = lag->dim;
    struct { const char *name; vigen_lhess_fn fn; size_t row0, col0; } all[3] = {
        { "d2Ldq2", lag->d2Ldq2, 0, 0 }, { "d2Ldv2", lag->d2Ldv2, n, n }, { "d2Ldqdv", lag->d2Ldqdv, 0, n } };
    vigen_dg_block b[3];
    size_t nb = 0;
    for (int i = 0; i < 3; i++) {
        if (all[i].fn == NULL) continue;
        double *a = lp->buf + nb * n * n;
        all[i].fn(lp->t, y, y + n, a, lag->ctx);
        size_t e = vigen_dg_first_nonfinite(a, n * n);
        if (e < n * n) {
            lp->rep->worst_part = all[i].row0 ? 1 : 0;
            lp->rep->worst_index = e / n;
            lp->rep->worst_column = all[i].col0 + e % n;
            return vigen_dg_report_set(lp->rep, VIGEN_ENONFINITE, "%s entry (%zu, %zu) is %g %s", all[i].name, e / n,
                                 e % n, a[e], vigen_dg_where(point));
        }
        b[nb++] = (vigen_dg_block){ all[i].name, all[i].row0, all[i].col0, n, n, n, a };
    }
    return vigen_dg_compare_second(lp->f, y, lp->s, b, nb, point, r, &lp->second);
}

/* The sentence of a Lagrangian that passed. */
static void lag_success(vigen_problem_report *rep, const vigen_lagrangian *lag, const vigen_dg_function *f,
                        const vigen_dg_tally *grad, int second)
{
    char head[140];
    vigen_dg_report_largest(rep, grad);
    if (lag->L && grad->largest.found)
        snprintf(head, sizeof head, "L agrees with dL/dq and dL/dv at %d points (largest relative mismatch %.1e, %s[%zu])",
                 rep->points, grad->largest.rel, f->part_name[grad->largest.part], grad->largest.index);
    else
        snprintf(head, sizeof head, "the gradient check was skipped because L is %s; dL/dq and dL/dv are finite",
                 lag->L ? "not finite next to the state" : "not given");
    int given = lag->d2Ldq2 || lag->d2Ldv2 || lag->d2Ldqdv;
    vigen_dg_report_set(rep, VIGEN_SUCCESS, "%s%s%s.", head,
                  second ? "; the second derivatives given agree with differences of dL/dq and dL/dv"
                  : given ? "; second derivatives not checked (dimension > 1024)"
                          : "",
                  grad->sampled ? "; 64 components per part sampled, all along random directions" : "");
}

int vigen_lagrangian_check(const vigen_lagrangian *lag, double t, const double *q, const double *v,
                           vigen_problem_report *rep)
{
    vigen_dg_report_start(rep);
    if (lag_validate(lag, t, q, v, rep) != VIGEN_SUCCESS) return rep->status;
    size_t n = lag->dim, m = 2 * n;
    int second = (lag->d2Ldq2 || lag->d2Ldv2 || lag->d2Ldqdv) && m <= DG_MAX_SECOND;
    double *x = m <= (size_t)-1 / sizeof(double) / 8 ? malloc((3 * m + (second ? 3 * n * n : 0)) * sizeof(double)) : NULL;
    if (x == NULL) return vigen_dg_report_set(rep, VIGEN_ENOMEM, "out of memory checking the Lagrangian (dimension %zu)", n);
    double *g = x + m, *s = g + m;
    vigen_dg_pair self = { n, t, lag->L, { lag->dLdq, lag->dLdv }, lag->ctx };
    vigen_dg_function f = { n, 2, lag->L ? vigen_dg_pair_value : NULL, vigen_dg_pair_gradient, &self, "L", { "dL/dq", "dL/dv" },
                      { "q", "v" }, { 1, 1 } };
    lag_points lp = { .lag = lag, .t = t, .f = &f, .s = s, .buf = s + m, .rep = rep };
    memcpy(x, q, n * sizeof *x);
    memcpy(x + n, v, n * sizeof *x);
    int rc = vigen_dg_state_values(&f, x, g, rep);
    if (rc == VIGEN_SUCCESS) {
        vigen_dg_tally grad;
        vigen_dg_tally_init(&lp.second);
        rc = vigen_dg_check_points(&f, x, s, &grad, second ? lag_point : NULL, &lp, &rep->points);
        rep->gradient_checked = lag->L != NULL && grad.compared > 0;
        rep->second_checked = second;
        if (rc == VIGEN_ENOMEM)
            vigen_dg_report_set(rep, VIGEN_ENOMEM, "out of memory checking the Lagrangian (dimension %zu)", n);
        else if (rc != VIGEN_SUCCESS)
            ;   /* the report is set */
        else if (grad.flagged.found)
            vigen_dg_report_mismatch(rep, &f, &grad.flagged, VIGEN_EGRADIENT);
        else if (lp.second.flagged.found)
            vigen_dg_report_mismatch(rep, &f, &lp.second.flagged, VIGEN_EHESSIAN);
        else
            lag_success(rep, lag, &f, &grad, second);
    }
    free(x);
    return rep->status;
}
