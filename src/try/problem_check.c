/* problem_check.c — the problem of a run checked before anything is built or
 * integrated: that it has a Lagrangian when a built-in Lagrangian method is
 * among the methods, then (vigen/diagnostics.h) its Hamiltonian at the
 * standard initial value, and its Lagrangian there too when such a method
 * is among them.  A problem that fails stops the run with the check's
 * sentence. */
#include <stdlib.h>
#include "vigen/diagnostics.h"
#include "vigen/problems.h"
#include "try/try_internal.h"

/* Whether one of the n methods is a built-in Lagrangian integrator. */
static int any_lagrangian(size_t n, const char *const *names)
{
    for (size_t k = 0; k < n; k++)
        if (!try_method_is_file(names[k]) && try_lagrangian_find(names[k])) return 1;
    return 0;
}

/* The problem has no Lagrangian: a usage error, before anything is built. */
int try_lagrangian_check(size_t n, const char *const *names, const vigen_try_options *opt, vigen_error *err)
{
    for (size_t k = 0; k < n; k++) {
        const try_lagrangian_method *m = try_method_is_file(names[k]) ? NULL : try_lagrangian_find(names[k]);
        if (m == NULL) continue;
        vigen_problem *pb = NULL;
        if (vigen_problem_create(&pb, opt->problem, opt->params ? opt->params : "", NULL, 0) != VIGEN_SUCCESS)
            return vigen_error_set(err, VIGEN_E_USAGE, "%s: cannot create the problem %s", m->name, opt->problem);
        int has = vigen_problem_lagrangian(pb, NULL) != NULL;
        vigen_problem_free(pb);
        if (!has)
            return vigen_error_set(err, VIGEN_E_USAGE,
                                   "%s: the problem %s has no Lagrangian (its Hamiltonian is degenerate); choose a "
                                   "tableau method or another problem", m->name, opt->problem);
    }
    return VIGEN_OK;
}

int try_problem_check(size_t n, const char *const *names, const vigen_try_options *opt, vigen_error *err)
{
    vigen_problem *pb = NULL;
    if (vigen_problem_create(&pb, opt->problem, opt->params ? opt->params : "", NULL, 0) != VIGEN_SUCCESS)
        return vigen_error_set(err, VIGEN_E_USAGE, "cannot create the problem %s", opt->problem);
    size_t dim = vigen_problem_dim(pb);
    double t, *q = malloc(3 * dim * sizeof *q);
    if (q == NULL) {
        vigen_problem_free(pb);
        return vigen_error_set(err, VIGEN_E_MEMORY, "out of memory checking the problem %s", opt->problem);
    }
    double *p = q + dim, *v = p + dim;
    vigen_problem_initial(pb, &t, q, p);
    vigen_problem_report rep;
    const char *what = "Hamiltonian";
    int status = vigen_problem_check(vigen_problem_hamiltonian(pb), t, q, p, &rep);
    vigen_lgrad_fn g = NULL;
    const vigen_lagrangian *lag = vigen_problem_lagrangian(pb, &g);
    if (status == VIGEN_SUCCESS && lag && g && any_lagrangian(n, names)) {
        g(t, q, p, v, lag->ctx);
        what = "Lagrangian";
        status = vigen_lagrangian_check(lag, t, q, v, &rep);
    }
    vigen_problem_free(pb);
    free(q);
    if (status == VIGEN_ENOMEM) return vigen_error_set(err, VIGEN_E_MEMORY, "out of memory checking the problem %s", opt->problem);
    if (status != VIGEN_SUCCESS)
        return vigen_error_set(err, VIGEN_E_DOMAIN, "the problem %s%s%s fails its check (%s): %s", opt->problem,
                               opt->params && *opt->params ? " with " : "", opt->params ? opt->params : "", what,
                               rep.message);
    return VIGEN_OK;
}
