/* cmd_try.c — `vigen try METHOD... --problem NAME`: runs the methods on a
 * problem of the collection (vigen/try.h) and prints the summary, or the
 * work-precision table; writes the figures with --plot. */
#include <stdlib.h>
#include <string.h>
#include "cli.h"
#include "vigen/try.h"
#include "support/strbuf.h"

/* The methods of the operand, one a line (option_parser.c collects them). */
static size_t split_methods(char *text, const char **methods, size_t cap)
{
    size_t n = 0;
    for (char *line = text; line && n < cap;) {
        char *nl = strchr(line, '\n');
        if (nl) *nl = '\0';
        methods[n++] = line;
        line = nl ? nl + 1 : NULL;
    }
    return n;
}

enum { MAX_METHODS = 16 };

static int work_precision(const vigen_cli_args *args, size_t n, const char **methods, vigen_try_options *opt)
{
    long long levels = 6;
    int rc;
    if (args->value[VIGEN_OPT_try_levels] && (rc = vigen_cli_whole(&levels, args, VIGEN_OPT_try_levels, 2, 12)) >= 0)
        return rc;
    vigen_error err;
    vigen_error_init(&err);
    vigen_try_wp_curve *c = NULL;
    if (vigen_try_work_precision(n, methods, opt, (int)levels, &c, &err) != VIGEN_OK)
        return vigen_cli_fail(args->command, &err);
    if (args->value[VIGEN_OPT_try_json]) vigen_try_wp_print_json(stdout, opt, c, n);
    else vigen_try_wp_print(stdout, c, n);
    int status = 0;
    const char *dir = args->value[VIGEN_OPT_try_plot];
    if (dir && vigen_try_wp_plot(dir, opt, c, n, &err) != VIGEN_OK) status = vigen_cli_fail(args->command, &err);
    else if (dir) fprintf(stderr, "vigen try: wrote %s/work_precision_evals.{svg,png,csv} and %s/work_precision_seconds.{svg,png,csv}\n", dir, dir);
    for (size_t k = 0; status == 0 && k < n; k++)
        if (c[k].message) status = 2;
    vigen_try_wp_free(c, n);
    return status;
}

int vigen_cmd_try(const vigen_cli_args *args)
{
    if (args->value[VIGEN_OPT_try_list_problems]) {
        vigen_try_print_problems(stdout);
        return 0;
    }
    if (args->value[VIGEN_OPT_try_list_methods]) {
        vigen_try_print_methods(stdout);
        return 0;
    }
    if (args->operand == NULL)
        return vigen_cli_usage_error(args->command,
                                     "which methods? give tableau or spec files or published names, e.g. vigen try "
                                     "gauss_2 stormer_verlet_velocity --problem kepler");
    if (args->value[VIGEN_OPT_try_problem] == NULL)
        return vigen_cli_usage_error(args->command, "which problem? give --problem NAME, e.g. --problem kepler "
                                                    "('vigen try --list-problems' lists them)");
    if (args->value[VIGEN_OPT_try_levels] && !args->value[VIGEN_OPT_try_work_precision])
        return vigen_cli_usage_error(args->command, "--levels is an option of --work-precision");
    size_t count = 1;
    for (const char *c = args->operand; *c; c++) count += *c == '\n';
    if (count > MAX_METHODS)
        return vigen_cli_usage_error(args->command, "at most %d methods at a time, not %zu", MAX_METHODS, count);
    char *text = vigen_strdup(args->operand);
    const char *methods[MAX_METHODS];
    size_t n = split_methods(text, methods, MAX_METHODS);
    vigen_error err;
    vigen_error_init(&err);
    vigen_try_options opt;
    if (vigen_try_options_set(&opt, args->value[VIGEN_OPT_try_problem], args->value[VIGEN_OPT_try_param],
                              args->value[VIGEN_OPT_try_h], args->value[VIGEN_OPT_try_steps_per_period],
                              args->value[VIGEN_OPT_try_time], &err) != VIGEN_OK) {
        free(text);
        int rc = vigen_cli_usage_error(args->command, "%s", err.message);
        vigen_error_clear(&err);
        free((char *)opt.params);
        return rc;
    }
    opt.progress = 1;
    opt.allow_inexact = args->value[VIGEN_OPT_try_allow_inexact] != NULL;
    int status;
    if (args->value[VIGEN_OPT_try_work_precision]) {
        status = work_precision(args, n, methods, &opt);
    } else {
        vigen_try_result *r = NULL;
        if (vigen_try_run(n, methods, &opt, &r, &err) != VIGEN_OK) status = vigen_cli_fail(args->command, &err);
        else {
            status = 0;
            if (args->value[VIGEN_OPT_try_json]) vigen_try_print_json(stdout, &opt, r, n);
            else vigen_try_print_summary(stdout, &opt, r, n);
            for (size_t k = 0; k < n; k++)
                if (r[k].failed) {
                    fprintf(stderr, "vigen try: %s\n", r[k].message);
                    status = 2;
                }
            const char *dir = args->value[VIGEN_OPT_try_plot];
            if (dir && vigen_try_plot(dir, &opt, r, n, &err) != VIGEN_OK) status = vigen_cli_fail(args->command, &err);
            else if (dir)
                fprintf(stderr, "vigen try: wrote %s/energy.{svg,png,csv} and %s/orbit.{svg,png,csv}\n", dir, dir);
            vigen_try_results_free(r, n);
        }
    }
    free((char *)opt.params);
    free(text);
    return status;
}
