/* order.c — `vigen order`: the empirical order of a method under step
 * halving, next to the order the checker certifies for its tableau.  The
 * errors are the global errors at the final time against the problem's
 * reference solution, or, for a problem without one, against the same
 * method at a step 4 times finer than the finest level.  That run's own
 * error, 4^-p times the finest level's for a method of order p, raises the
 * finest order to log2((2^p - 4^-p) / (1 - 4^-p)): by 0.07 for p = 2 and
 * less for higher p. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "support/progress.h"
#include "report/json.h"
#include "try/try_internal.h"
#include "support/strbuf.h"

/* Coarsest steps per period when neither --h nor --steps-per-period is given. */
#define TRY_ORDER_BASE 64
/* Errors below this (relative to the size of the state) are round-off: the
 * order between them says nothing about the method. */
#define TRY_ORDER_FLOOR 1e-11

void vigen_try_order_clear(vigen_try_order_result *res)
{
    free(res->label);
    free(res->h);
    free(res->error);
    free(res->order);
    memset(res, 0, sizeof *res);
}

static double state_norm(const vigen_try_result *r)
{
    double s = 0;
    for (size_t i = 0; i < 2 * r->dim; i++) s = hypot(s, r->final_state[i]);
    return s > 1 ? s : 1;
}

static int measure(vigen_try_order_result *res, const try_build *b, const vigen_try_options *opt, int levels,
                   vigen_error *err)
{
    try_plan plan;
    vigen_try_options o = *opt;
    int rc = try_plan_make(&plan, &o, opt->steps_per_period > 0 ? opt->steps_per_period : TRY_ORDER_BASE, err);
    if (rc != VIGEN_OK) return rc;
    double T = opt->time > 0 ? opt->time : plan.period;
    double h0 = opt->h > 0 ? opt->h : plan.period / (double)(opt->steps_per_period > 0 ? opt->steps_per_period : TRY_ORDER_BASE);
    unsigned long n0 = (unsigned long)ceil(T / h0 - 1e-9);
    if (n0 < 1) n0 = 1;
    h0 = T / (double)n0; /* every level ends at the same time */
    res->against_reference = plan.has_reference;
    int runs = levels + (plan.has_reference ? 0 : 1);
    vigen_try_result *r = calloc((size_t)runs, sizeof *r);
    if (r == NULL) return vigen_error_set(err, VIGEN_E_MEMORY, "out of memory");
    int done = 0;
    for (int l = 0; l < runs && rc == VIGEN_OK; l++) {
        int fine = l == levels; /* the comparison run, 4 times finer than the finest level */
        unsigned long steps = n0 << (fine ? levels + 1 : l);
        double h = h0 / (double)(1UL << (fine ? levels + 1 : l));
        vigen_progress_set("%s: h = %.4g, %lu steps", b->label, h, steps);
        rc = try_run_driver(&r[l], b, &o, h, steps, steps, err);
        done = l + 1;
        if (rc == VIGEN_OK && r[l].failed) rc = vigen_error_set(err, VIGEN_E_DOMAIN, "%s", r[l].message);
    }
    if (rc == VIGEN_OK) {
        for (int l = 0; l < levels; l++) {
            res->h[l] = r[l].h;
            if (plan.has_reference) res->error[l] = r[l].global_error;
            else {
                double s = 0;
                for (size_t i = 0; i < 2 * r[l].dim; i++) s = hypot(s, r[l].final_state[i] - r[levels].final_state[i]);
                res->error[l] = s;
            }
        }
        double floor = TRY_ORDER_FLOOR * state_norm(&r[0]);
        res->estimate = NAN;
        for (int l = 0; l + 1 < levels; l++) {
            res->order[l] = log2(res->error[l] / res->error[l + 1]);
            if (res->error[l + 1] > floor && isfinite(res->order[l])) res->estimate = res->order[l];
        }
        res->order[levels - 1] = NAN;
        res->levels = (size_t)levels;
    }
    for (int l = 0; l < done; l++) try_result_clear(&r[l]);
    free(r);
    return rc;
}

int vigen_try_order(const char *method, const vigen_try_options *opt, int levels, vigen_try_order_result *res,
                    vigen_error *err)
{
    memset(res, 0, sizeof *res);
    if (levels <= 1) levels = 5;
    if (levels > 12) return vigen_error_set(err, VIGEN_E_USAGE, "at most 12 levels of halving, not %d", levels);
    try_plan plan;
    int rc = try_plan_make(&plan, opt, 0, err);
    if (rc == VIGEN_OK) rc = try_lagrangian_check(1, &method, opt, err);
    if (rc == VIGEN_OK) rc = try_problem_check(1, &method, opt, err);
    if (rc != VIGEN_OK) return rc;
    try_paths paths;
    if ((rc = try_paths_find(&paths, err)) != VIGEN_OK) return rc;
    res->h = calloc((size_t)levels, sizeof(double));
    res->error = calloc((size_t)levels, sizeof(double));
    res->order = calloc((size_t)levels, sizeof(double));
    if (!res->h || !res->error || !res->order) {
        vigen_try_order_clear(res);
        try_paths_clear(&paths);
        return vigen_error_set(err, VIGEN_E_MEMORY, "out of memory");
    }
    if (opt->progress) vigen_progress_begin("vigen order");
    rc = try_workdir_create(err);
    int made = rc == VIGEN_OK;
    try_build b;
    memset(&b, 0, sizeof b);
    if (rc == VIGEN_OK) rc = try_build_method(&b, 0, method, &paths, try_cc(opt), 1, opt->allow_inexact, err);
    if (rc == VIGEN_OK) {
        res->label = vigen_strdup(b.label);
        res->certified = b.certified;
        res->certified_separable = b.certified_separable;
        res->builtin = b.builtin;
        rc = measure(res, &b, opt, levels, err);
    }
    try_build_clear(&b);
    if (made) try_workdir_remove();
    vigen_progress_end();
    try_paths_clear(&paths);
    if (rc != VIGEN_OK) vigen_try_order_clear(res);
    return rc;
}

void vigen_try_order_print(FILE *out, const vigen_try_options *opt, const vigen_try_order_result *res, int json)
{
    if (json) {
        fputs("{\"method\": ", out);
        vigen_json_write_string(out, res->label);
        fputs(", \"problem\": ", out);
        vigen_json_write_string(out, opt->problem);
        if (res->builtin) fprintf(out, ", \"certified_order\": null, \"proven_order\": %d", res->certified);
        else
            fprintf(out, ", \"certified_order\": %d, \"certified_order_separable\": %d", res->certified,
                    res->certified_separable);
        fprintf(out, ", \"against_reference\": %s, \"levels\": [", res->against_reference ? "true" : "false");
        for (size_t l = 0; l < res->levels; l++) {
            fprintf(out, "%s{\"h\": %.17g, \"error\": %.17g, \"order\": ", l ? ", " : "", res->h[l], res->error[l]);
            if (isfinite(res->order[l])) fprintf(out, "%.6g}", res->order[l]);
            else fputs("null}", out);
        }
        fputs("], \"estimate\": ", out);
        if (isfinite(res->estimate)) fprintf(out, "%.6g}\n", res->estimate);
        else fputs("null}\n", out);
        return;
    }
    fprintf(out, "%s on %s%s%s: error at t = end %s\n", res->label, opt->problem,
            opt->params && *opt->params ? " " : "", opt->params ? opt->params : "",
            res->against_reference ? "against the reference solution"
                                   : "against the same method at a 4 x finer step than the finest");
    fprintf(out, "%12s %12s %8s\n", "h", "error", "order");
    for (size_t l = 0; l < res->levels; l++) {
        fprintf(out, "%12.5g %12.4e", res->h[l], res->error[l]);
        if (isfinite(res->order[l])) fprintf(out, " %8.3f\n", res->order[l]);
        else fputs("        -\n", out);
    }
    fprintf(out, "empirical order: ");
    if (isfinite(res->estimate)) fprintf(out, "%.2f", res->estimate);
    else fputs("- (every error is at round-off: take a larger --h)", out);
    if (res->builtin) fprintf(out, "   proven order (built-in Lagrangian integrator): %d", res->certified);
    else fprintf(out, "   certified order (vigen check): %d", res->certified);
    if (!res->builtin && res->certified_separable != res->certified)
        fprintf(out, " (%d for separable H)", res->certified_separable);
    fputc('\n', out);
}

int vigen_try_order_plot(const char *dir, const vigen_try_options *opt, const vigen_try_order_result *res,
                         vigen_error *err)
{
    int rc = try_plot_dir(dir, err);
    if (rc == VIGEN_OK) rc = try_workdir_create(err);
    if (rc != VIGEN_OK) return rc;
    vigen_strbuf csv, gp;
    vigen_strbuf_init(&csv);
    vigen_strbuf_init(&gp);
    vigen_strbuf_append(&csv, "h,error,order\n");
    for (size_t l = 0; l < res->levels; l++) {
        vigen_strbuf_printf(&csv, "%.17g,%.17g,", res->h[l], res->error[l]);
        if (isfinite(res->order[l])) vigen_strbuf_printf(&csv, "%.6g", res->order[l]);
        vigen_strbuf_append(&csv, "\n");
    }
    char *label = try_gnuplot_quote(res->label), *prob = try_gnuplot_quote(opt->problem);
    size_t last = res->levels ? res->levels - 1 : 0;
    int p = res->certified > 0 ? res->certified : 1;
    vigen_strbuf_printf(&gp, "set title \"%s on %s: error under step halving\"\nset xlabel \"h\"\n"
                             "set ylabel \"global error\"\nset logscale xy\nset format y \"1e%%L\"\n"
                             "set key left top\n"
                             "plot datafile using 1:(column(2) > 0 ? column(2) : 1/0) with linespoints lw 1.5 "
                             "title \"%s\", \\\n    %.17g * (x / %.17g)**%d with lines dt 2 title \"slope %d "
                             "(%s order)\"\n",
                        label, prob, label, res->levels ? res->error[last] : 1.0, res->levels ? res->h[last] : 1.0,
                        p, p, res->builtin ? "proven" : "certified");
    free(label);
    free(prob);
    try_figures figs;
    memset(&figs, 0, sizeof figs);
    rc = try_plot_files(&figs, dir, "order", csv.data, gp.data, err);
    vigen_strbuf_clear(&csv);
    vigen_strbuf_clear(&gp);
    try_workdir_remove();
    if (rc == VIGEN_OK) rc = try_figures_commit(&figs, dir, err);
    try_figures_clear(&figs);
    return rc;
}
