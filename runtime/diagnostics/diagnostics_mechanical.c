/* diagnostics_mechanical.c — vigen_mechanical_check: a mechanical problem
 * (H = 1/2 p^T M^-1 p + V, the force f = -dV/dq given) checked at a
 * position and two nearby: the inverse masses and the force finite, and the
 * force against central differences of -V when V is given. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "diagnostics_internal.h"

typedef struct {
    const vigen_mechanical *sys;
    double t;
} mech_self;

static double mech_value(const void *self, const double *x)
{
    const mech_self *s = self;
    return s->sys->V(s->t, x, s->sys->ctx);
}

/* The gradient of V: -f. */
static void mech_gradient(const void *self, const double *x, double *g)
{
    const mech_self *s = self;
    s->sys->force(s->t, x, g, s->sys->ctx);
    for (size_t k = 0; k < s->sys->dim; k++) g[k] = -g[k];
}

static int mech_validate(const vigen_mechanical *sys, double t, const double *q, vigen_problem_report *rep)
{
    if (sys == NULL || q == NULL)
        return vigen_dg_report_set(rep, VIGEN_EINVAL, "the problem check needs the problem and the positions q (a NULL pointer was given)");
    if (sys->dim == 0 || sys->force == NULL)
        return vigen_dg_report_set(rep, VIGEN_EINVAL, "the mechanical problem is incomplete: it needs dim > 0 and force");
    if (vigen_dg_state_check(rep, t, "q", q, NULL, NULL, sys->dim) != VIGEN_SUCCESS) return rep->status;
    size_t k = sys->inv_mass ? vigen_dg_first_nonfinite(sys->inv_mass, sys->dim) : sys->dim;
    if (k < sys->dim)
        return vigen_dg_report_set(rep, VIGEN_EINVAL, "inv_mass[%zu] is %g: the inverse masses must be finite", k,
                             sys->inv_mass[k]);
    return VIGEN_SUCCESS;
}

int vigen_mechanical_check(const vigen_mechanical *sys, double t, const double *q, vigen_problem_report *rep)
{
    vigen_dg_report_start(rep);
    if (mech_validate(sys, t, q, rep) != VIGEN_SUCCESS) return rep->status;
    size_t n = sys->dim;
    double *g = n <= (size_t)-1 / sizeof(double) / 2 ? malloc(2 * n * sizeof(double)) : NULL;
    if (g == NULL) return vigen_dg_report_set(rep, VIGEN_ENOMEM, "out of memory checking the problem (dimension %zu)", n);
    double *s = g + n;
    mech_self self = { sys, t };
    vigen_dg_function f = { n, 1, sys->V ? mech_value : NULL, mech_gradient, &self, "V", { "force", NULL },
                      { "q", NULL }, { -1, 1 } };
    int rc = vigen_dg_state_values(&f, q, g, rep);
    if (rc == VIGEN_SUCCESS) {
        vigen_dg_tally grad;
        rc = vigen_dg_check_points(&f, q, s, &grad, NULL, NULL, &rep->points);
        rep->gradient_checked = grad.compared > 0;
        if (rc == VIGEN_ENOMEM)
            vigen_dg_report_set(rep, VIGEN_ENOMEM, "out of memory checking the problem (dimension %zu)", n);
        else if (grad.flagged.found)
            vigen_dg_report_mismatch(rep, &f, &grad.flagged, VIGEN_EGRADIENT);
        else if (sys->V && grad.largest.found) {
            vigen_dg_report_largest(rep, &grad);
            vigen_dg_report_set(rep, VIGEN_SUCCESS,
                          "the force agrees with -dV/dq at %d points (largest relative mismatch %.1e, force[%zu])%s.",
                          rep->points, rep->worst_rel_error, rep->worst_index,
                          grad.sampled ? "; 64 components sampled, all along random directions" : "");
        } else
            vigen_dg_report_set(rep, VIGEN_SUCCESS, "the force check was skipped because V is %s; the force is finite.",
                          sys->V ? "not finite next to the state" : "not given");
    }
    free(g);
    return rep->status;
}

int vigen_mechanical_check_or_say(const char *who, const vigen_mechanical *sys, double t, const double *q)
{
    vigen_problem_report rep;
    int status = vigen_mechanical_check(sys, t, q, &rep);
    if (status != VIGEN_SUCCESS) fprintf(stderr, "%s: %s\n", who ? who : "vigen", rep.message);
    return status;
}
