/* diagnostics_report.c — the report of the problem checks: clearing it,
 * its one-sentence messages (a mismatch of a gradient, of a second
 * derivative or along a direction), the values at the state that must be
 * finite, and the state itself. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "diagnostics_internal.h"

void vigen_dg_report_start(vigen_problem_report *rep)
{
    memset(rep, 0, sizeof *rep);
    rep->worst_part = -1;
    rep->worst_column = (size_t)-1;
}

int vigen_dg_report_set(vigen_problem_report *rep, int status, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(rep->message, sizeof rep->message, fmt, ap);
    va_end(ap);
    rep->status = status;
    return status;
}

int vigen_dg_state_values(const vigen_dg_function *f, const double *x, double *g, vigen_problem_report *rep)
{
    size_t m = (size_t)f->nparts * f->n;
    f->gradient(f->self, x, g);
    size_t k = vigen_dg_first_nonfinite(g, m);
    double v = f->value ? f->value(f->self, x) : 0;
    if (!isfinite(v))
        return vigen_dg_report_set(rep, VIGEN_ENONFINITE, "%s is %g at the state: the problem is not finite there",
                             f->value_name, v);
    if (k < m) {
        int part = (int)(k / f->n);
        rep->worst_part = part;
        rep->worst_index = k % f->n;
        return vigen_dg_report_set(rep, VIGEN_ENONFINITE, "%s[%zu] is %g at the state: the problem's derivatives are not "
                             "finite there", f->part_name[part], k % f->n, f->part_sign[part] * g[k]);
    }
    return VIGEN_SUCCESS;
}

int vigen_dg_state_check(vigen_problem_report *rep, double t, const char *na, const double *a, const char *nb,
                   const double *b, size_t n)
{
    if (!isfinite(t)) return vigen_dg_report_set(rep, VIGEN_EINVAL, "the time t = %g of the state is not finite", t);
    for (int i = 0; i < 2; i++) {
        const double *v = i ? b : a;
        size_t k = v ? vigen_dg_first_nonfinite(v, n) : n;
        if (k < n)
            return vigen_dg_report_set(rep, VIGEN_EINVAL, "the state is not finite: %s[%zu] is %g", i ? nb : na, k, v[k]);
    }
    return VIGEN_SUCCESS;
}

const char *vigen_dg_where(int point) { return point == 0 ? "at the state" : "near the state"; }

int vigen_dg_report_mismatch(vigen_problem_report *rep, const vigen_dg_function *f, const vigen_dg_mismatch *m, int status)
{
    rep->worst_rel_error = m->rel;
    rep->worst_part = m->part;
    rep->worst_index = m->index;
    rep->worst_column = m->column;
    if (m->part < 0) {   /* along a direction: the force or the gradient */
        double sign = f->part_sign[0];
        return vigen_dg_report_set(rep, status,
                             "along a random direction %s, %s gives the derivative %.6g but the central difference "
                             "of %s%s gives %.6g, a relative mismatch of %.2g (a component outside the %d compared "
                             "one by one is wrong)",
                             vigen_dg_where(m->point), f->nparts == 1 ? f->part_name[0] : "the gradient", sign * m->given,
                             sign < 0 ? "-" : "", f->value_name, sign * m->differences, m->rel, DG_MAX_COMPONENTS);
    }
    const char *part = f->part_name[m->part];
    if (m->column == (size_t)-1) {
        double sign = f->part_sign[m->part];
        return vigen_dg_report_set(rep, status,
                              "%s[%zu] is %.6g %s but the central difference of %s%s is %.6g, a relative "
                              "mismatch of %.2g (the difference is accurate to %.1g)",
                              part, m->index, sign * m->given, vigen_dg_where(m->point), sign < 0 ? "-" : "",
                              f->value_name, sign * m->differences, m->rel, m->accuracy);
    }
    int cpart = (int)(m->column / f->n);
    return vigen_dg_report_set(rep, status,
                          "%s entry d(%s[%zu])/d%s[%zu] is %.6g %s but the central difference of %s[%zu] is "
                          "%.6g, a relative mismatch of %.2g (the difference is accurate to %.1g)",
                          m->block, part, m->index, f->var_name[cpart], m->column % f->n, m->given,
                          vigen_dg_where(m->point), part, m->index, m->differences, m->rel, m->accuracy);
}

void vigen_dg_report_largest(vigen_problem_report *rep, const vigen_dg_tally *t)
{
    if (!t->largest.found) return;
    rep->worst_rel_error = t->largest.rel;
    rep->worst_part = t->largest.part;
    rep->worst_index = t->largest.index;
}
