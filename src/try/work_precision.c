/* work_precision.c — `vigen try --work-precision`: each method built once,
 * run at step sizes halving from level to level, its error against its cost
 * (gradient evaluations, seconds), printed and drawn log-log. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "support/progress.h"
#include "report/json.h"
#include "try/try_internal.h"
#include "support/strbuf.h"

/* Coarsest steps per period when none is given, and the final time in
 * periods when --time is not given: long enough for the global error to
 * grow, short enough that the finest level is a few seconds at most. */
#define TRY_WP_BASE 64
#define TRY_WP_PERIODS 10

void vigen_try_wp_free(vigen_try_wp_curve *c, size_t n)
{
    for (size_t k = 0; c && k < n; k++) {
        free(c[k].label);
        free(c[k].h);
        free(c[k].evals);
        free(c[k].seconds);
        free(c[k].error);
        free(c[k].message);
    }
    free(c);
}

static int run_levels(vigen_try_wp_curve *c, const try_build *b, const vigen_try_options *opt, double period,
                      int levels, vigen_error *err)
{
    long base = opt->steps_per_period > 0 ? opt->steps_per_period : TRY_WP_BASE;
    int rc = VIGEN_OK;
    for (int l = 0; l < levels && rc == VIGEN_OK && c->message == NULL; l++) {
        try_plan plan;
        vigen_try_options o = *opt;
        o.h = 0;
        if (o.time <= 0) o.time = TRY_WP_PERIODS * period;
        if ((rc = try_plan_make(&plan, &o, base << l, err)) != VIGEN_OK) break;
        vigen_progress_set("%s: %lu steps (level %d of %d)", b->label, plan.steps, l + 1, levels);
        vigen_try_result r;
        unsigned long every = plan.steps / 200 ? plan.steps / 200 : 1;
        rc = try_run_driver(&r, b, &o, plan.h, plan.steps, every, err);
        if (rc == VIGEN_OK && r.failed) c->message = vigen_strdup(r.message);
        else if (rc == VIGEN_OK) {
            size_t i = c->npoints++;
            c->h[i] = plan.h;
            c->evals[i] = r.grad_per_step * (double)r.steps;
            c->seconds[i] = r.ns_per_step * (double)r.steps * 1e-9;
            c->error_is_energy = !r.has_reference;
            c->error[i] = r.has_reference ? r.global_error : r.energy_max;
        }
        try_result_clear(&r);
    }
    return rc;
}

int vigen_try_work_precision(size_t n, const char *const *methods, const vigen_try_options *opt, int levels,
                             vigen_try_wp_curve **curves, vigen_error *err)
{
    *curves = NULL;
    if (levels <= 0) levels = 6;
    try_plan plan;
    int rc = try_plan_make(&plan, opt, 0, err);
    if (rc == VIGEN_OK) rc = try_lagrangian_check(n, methods, opt, err);
    if (rc == VIGEN_OK) rc = try_problem_check(n, methods, opt, err);
    if (rc != VIGEN_OK) return rc;
    try_paths paths;
    if ((rc = try_paths_find(&paths, err)) != VIGEN_OK) return rc;
    vigen_try_wp_curve *c = calloc(n ? n : 1, sizeof *c);
    for (size_t k = 0; c && k < n; k++) {
        c[k].h = calloc((size_t)levels, sizeof(double));
        c[k].evals = calloc((size_t)levels, sizeof(double));
        c[k].seconds = calloc((size_t)levels, sizeof(double));
        c[k].error = calloc((size_t)levels, sizeof(double));
        if (!c[k].h || !c[k].evals || !c[k].seconds || !c[k].error) rc = VIGEN_E_MEMORY;
    }
    if (c == NULL || rc != VIGEN_OK) {
        vigen_try_wp_free(c, n);
        try_paths_clear(&paths);
        return vigen_error_set(err, VIGEN_E_MEMORY, "out of memory");
    }
    if (opt->progress) vigen_progress_begin("vigen try --work-precision");
    rc = try_workdir_create(err);
    int made = rc == VIGEN_OK;
    for (size_t k = 0; k < n && rc == VIGEN_OK; k++) {
        try_build b;
        rc = try_build_method(&b, k, methods[k], &paths, try_cc(opt), 0, opt->allow_inexact, err);
        if (rc == VIGEN_OK) {
            c[k].label = vigen_strdup(b.label);
            rc = run_levels(&c[k], &b, opt, plan.period, levels, err);
        }
        try_build_clear(&b);
    }
    if (made) try_workdir_remove();
    vigen_progress_end();
    try_paths_clear(&paths);
    if (rc != VIGEN_OK) {
        vigen_try_wp_free(c, n);
        return rc;
    }
    *curves = c;
    return VIGEN_OK;
}

void vigen_try_wp_print(FILE *out, const vigen_try_wp_curve *c, size_t n)
{
    int energy = n > 0 && c[0].error_is_energy;
    fprintf(out, "%-24s %12s %12s %12s %12s\n", "method", "h", "grad evals", "seconds",
            energy ? "max|dE|" : "error");
    for (size_t k = 0; k < n; k++) {
        for (size_t i = 0; i < c[k].npoints; i++)
            fprintf(out, "%-24s %12.5g %12.4g %12.4g %12.4g\n", c[k].label, c[k].h[i], c[k].evals[i],
                    c[k].seconds[i], c[k].error[i]);
        if (c[k].message) fprintf(out, "  %s\n", c[k].message);
    }
    if (energy) fputs("the problem has no reference solution: the error is the largest relative energy error\n", out);
}

void vigen_try_wp_print_json(FILE *out, const vigen_try_options *opt, const vigen_try_wp_curve *c, size_t n)
{
    fputs("{\"problem\": ", out);
    vigen_json_write_string(out, opt->problem);
    fputs(", \"params\": ", out);
    vigen_json_write_string(out, opt->params ? opt->params : "");
    fprintf(out, ", \"error_is_energy\": %s, \"methods\": [", n > 0 && c[0].error_is_energy ? "true" : "false");
    for (size_t k = 0; k < n; k++) {
        fputs(k ? ", {\"name\": " : "{\"name\": ", out);
        vigen_json_write_string(out, c[k].label);
        fputs(", \"points\": [", out);
        for (size_t i = 0; i < c[k].npoints; i++) {
            fputs(i ? ", {\"h\": " : "{\"h\": ", out);
            try_json_number(out, c[k].h[i]);
            fputs(", \"evals\": ", out);
            try_json_number(out, c[k].evals[i]);
            fputs(", \"seconds\": ", out);
            try_json_number(out, c[k].seconds[i]);
            fputs(", \"error\": ", out);
            try_json_number(out, c[k].error[i]);
            fputs("}", out);
        }
        fputs("], \"failed\": ", out);
        if (c[k].message) vigen_json_write_string(out, c[k].message);
        else fputs("null", out);
        fputs("}", out);
    }
    fputs("]}\n", out);
}

static int wp_figure(try_figures *figs, const char *dir, const char *stem, const char *xcol, const char *xlabel,
                     const vigen_try_options *opt, const vigen_try_wp_curve *c, size_t n, const char *csv,
                     vigen_error *err)
{
    vigen_strbuf gp;
    vigen_strbuf_init(&gp);
    char *t0 = vigen_strdup_printf("%s%s%s: work-precision", opt->problem, opt->params && *opt->params ? " " : "",
                                   opt->params ? opt->params : "");
    char *t = try_gnuplot_quote(t0);
    free(t0);
    int energy = n > 0 && c[0].error_is_energy;
    vigen_strbuf_printf(&gp, "set title \"%s\"\nset xlabel \"%s\"\nset ylabel \"%s\"\nset logscale xy\n"
                             "set format y \"1e%%L\"\nset key below\n",
                        t, xlabel, energy ? "max relative energy error" : "global error at the final time");
    free(t);
    int curves = 0;
    for (size_t k = 0; k < n; k++) {
        if (c[k].npoints == 0) continue;
        char *label = try_gnuplot_quote(c[k].label);
        vigen_strbuf_printf(&gp, "%s datafile using (strcol(\"method\") eq \"%s\" ? column(\"%s\") : 1/0):"
                                 "(column(\"error\") > 0 ? column(\"error\") : 1/0) with linespoints lw 1.5 "
                                 "title \"%s\"",
                            curves ? ", \\\n    " : "plot", label, xcol, label);
        free(label);
        curves++;
    }
    if (curves == 0) vigen_strbuf_append(&gp, "plot 1/0 notitle");
    vigen_strbuf_append(&gp, "\n");
    int rc = try_plot_files(figs, dir, stem, csv, gp.data, err);
    vigen_strbuf_clear(&gp);
    return rc;
}

int vigen_try_wp_plot(const char *dir, const vigen_try_options *opt, const vigen_try_wp_curve *c, size_t n,
                      vigen_error *err)
{
    size_t points = 0;
    for (size_t k = 0; k < n; k++) points += c[k].npoints;
    /* gnuplot cannot draw a figure without data: say what to change instead */
    if (points == 0)
        return vigen_error_set(err, VIGEN_E_DOMAIN, "no method completed any step size, so there is nothing to "
                               "draw; try a smaller step (--h or --steps-per-period)");
    int rc = try_plot_dir(dir, err);
    if (rc == VIGEN_OK) rc = try_workdir_create(err);
    if (rc != VIGEN_OK) return rc;
    vigen_strbuf csv;
    vigen_strbuf_init(&csv);
    vigen_strbuf_append(&csv, "method,h,evals,seconds,error\n");
    for (size_t k = 0; k < n; k++) {
        char *label = try_gnuplot_quote(c[k].label);
        for (size_t i = 0; i < c[k].npoints; i++)
            vigen_strbuf_printf(&csv, "%s,%.17g,%.17g,%.17g,%.17g\n", label, c[k].h[i], c[k].evals[i],
                                c[k].seconds[i], c[k].error[i]);
        free(label);
    }
    try_figures figs;
    memset(&figs, 0, sizeof figs);
    rc = wp_figure(&figs, dir, "work_precision_evals", "evals", "gradient evaluations", opt, c, n, csv.data, err);
    if (rc == VIGEN_OK)
        rc = wp_figure(&figs, dir, "work_precision_seconds", "seconds", "seconds", opt, c, n, csv.data, err);
    vigen_strbuf_clear(&csv);
    try_workdir_remove();
    if (rc == VIGEN_OK) rc = try_figures_commit(&figs, dir, err);
    try_figures_clear(&figs);
    return rc;
}
