/* try.c — vigen_try_run: every method built once in the private working
 * directory, then run on the problem with the plan's step; the directory
 * is removed whatever happens. */
#include <stdlib.h>
#include <string.h>
#include "support/progress.h"
#include "try/try_internal.h"

const char *try_cc(const vigen_try_options *opt)
{
    if (opt->cc && *opt->cc) return opt->cc;
    const char *cc = getenv("CC");
    return cc && *cc ? cc : "cc";
}

int vigen_try_run(size_t n, const char *const *methods, const vigen_try_options *opt, vigen_try_result **results,
                  vigen_error *err)
{
    *results = NULL;
    try_plan plan;
    int rc = try_plan_make(&plan, opt, 0, err);
    if (rc == VIGEN_OK) rc = try_lagrangian_check(n, methods, opt, err);
    if (rc == VIGEN_OK) rc = try_problem_check(n, methods, opt, err);
    if (rc != VIGEN_OK) return rc;
    try_paths paths;
    if ((rc = try_paths_find(&paths, err)) != VIGEN_OK) return rc;
    vigen_try_result *res = calloc(n ? n : 1, sizeof *res);
    if (res == NULL) {
        try_paths_clear(&paths);
        return vigen_error_set(err, VIGEN_E_MEMORY, "out of memory");
    }
    if (opt->progress) vigen_progress_begin("vigen try");
    rc = try_workdir_create(err);
    int made = rc == VIGEN_OK;
    unsigned long every = plan.steps / VIGEN_TRY_SAMPLES;
    if (every == 0) every = 1;
    for (size_t k = 0; k < n && rc == VIGEN_OK; k++) {
        try_build b;
        rc = try_build_method(&b, k, methods[k], &paths, try_cc(opt), 0, opt->allow_inexact, err);
        if (rc == VIGEN_OK) {
            vigen_progress_set("%s: %lu steps on %s", b.label, plan.steps, opt->problem);
            rc = try_run_driver(&res[k], &b, opt, plan.h, plan.steps, every, err);
        }
        try_build_clear(&b);
    }
    if (made) try_workdir_remove();
    vigen_progress_end();
    try_paths_clear(&paths);
    if (rc != VIGEN_OK) {
        vigen_try_results_free(res, n);
        return rc;
    }
    *results = res;
    return VIGEN_OK;
}
