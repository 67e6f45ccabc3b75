/* run_plan.c — what a run integrates: the problem and its parameters checked by
 * the problem library itself, the step from --h or --steps-per-period and
 * the period, the number of steps from --time or the problem's default. */
#include <math.h>
#include <stdlib.h>
#include "vigen/problems.h"
#include "try/try_internal.h"

/* More steps than this is a mistake (days of running), not a request. */
#define TRY_MAX_STEPS 4000000000.0

int try_plan_make(try_plan *plan, const vigen_try_options *opt, long spp, vigen_error *err)
{
    if (opt->problem == NULL || *opt->problem == '\0')
        return vigen_error_set(err, VIGEN_E_USAGE, "which problem? give --problem NAME ('vigen try --list-problems' lists them)");
    vigen_problem *pb = NULL;
    char why[512] = "";
    int prc = vigen_problem_create(&pb, opt->problem, opt->params ? opt->params : "", why, sizeof why);
    if (prc != VIGEN_SUCCESS) {
        if (prc == VIGEN_ENOMEM) return vigen_error_set(err, VIGEN_E_MEMORY, "out of memory creating the problem");
        return vigen_error_set(err, VIGEN_E_USAGE, "%s ('vigen try --list-problems' lists the problems and their parameters)", why);
    }
    plan->period = vigen_problem_period(pb);
    plan->time = opt->time > 0 ? opt->time : vigen_problem_default_time(pb);
    size_t dim = vigen_problem_dim(pb);
    double *qp = calloc(2 * dim + 1, sizeof(double)), t0 = 0;
    plan->has_reference = 0;
    if (qp) {
        vigen_problem_initial(pb, &t0, qp, qp + dim);
        plan->has_reference = vigen_problem_reference(pb, t0, qp, qp + dim);
    }
    free(qp);
    vigen_problem_free(pb);
    if (spp <= 0) spp = opt->steps_per_period > 0 ? opt->steps_per_period : VIGEN_TRY_DEFAULT_STEPS_PER_PERIOD;
    plan->h = opt->h > 0 ? opt->h : plan->period / (double)spp;
    if (!isfinite(plan->h) || plan->h <= 0 || !isfinite(plan->time) || plan->time <= 0)
        return vigen_error_set(err, VIGEN_E_USAGE, "the step %g and the time %g must be positive and finite", plan->h,
                               plan->time);
    double steps = ceil(plan->time / plan->h - 1e-9);
    if (steps > TRY_MAX_STEPS)
        return vigen_error_set(err, VIGEN_E_USAGE,
                               "%.3g steps of %g to time %g are too many (at most %.0f): take a larger --h or a "
                               "shorter --time", steps, plan->h, plan->time, TRY_MAX_STEPS);
    plan->steps = steps < 1 ? 1 : (unsigned long)steps;
    return VIGEN_OK;
}
