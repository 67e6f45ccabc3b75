/* summary.c — what `vigen try` prints: one row per method (energy error,
 * drift, invariants, global error, cost), or the same as one JSON object,
 * and the list of problems. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "vigen/problems.h"
#include "report/json.h"
#include "try/try_internal.h"

static void num(FILE *out, double v, int width)
{
    if (isnan(v)) fprintf(out, " %*s", width, "-");
    else fprintf(out, " %*.2e", width, v);
}

static int inv_width(const char *name) { return strlen(name) > 9 ? (int)strlen(name) : 9; }

void vigen_try_print_summary(FILE *out, const vigen_try_options *opt, const vigen_try_result *r, size_t n)
{
    if (n == 0) return;
    fprintf(out, "%s%s%s: h = %.6g, %lu steps to t = %.6g\n", opt->problem, opt->params && *opt->params ? " " : "",
            opt->params ? opt->params : "", r[0].h, r[0].planned, r[0].h * (double)r[0].planned);
    size_t w = 6;
    for (size_t k = 0; k < n; k++) w = strlen(r[k].label) > w ? strlen(r[k].label) : w;
    fprintf(out, "%-*s %9s %9s", (int)w, "method", "max|dE|", "drift/t");
    for (size_t i = 0; i < r[0].ninv; i++) fprintf(out, " %*s", inv_width(r[0].inv_names[i]), r[0].inv_names[i]);
    fprintf(out, " %9s %9s %9s\n", "error", "grad/step", "ns/step");
    for (size_t k = 0; k < n; k++) {
        fprintf(out, "%-*s", (int)w, r[k].label);
        num(out, r[k].steps ? r[k].energy_max : NAN, 9);
        num(out, r[k].energy_drift, 9);
        for (size_t i = 0; i < r[k].ninv; i++) num(out, r[k].inv_max[i], inv_width(r[k].inv_names[i]));
        num(out, r[k].global_error, 9);
        if (r[k].steps == 0) fprintf(out, " %9s %9s\n", "-", "-");
        else fprintf(out, " %9.2f %9.1f\n", r[k].grad_per_step, r[k].ns_per_step);
        if (r[k].failed) fprintf(out, "  %s\n", r[k].message);
    }
    fputs("max|dE|: largest relative energy error; drift/t: its least-squares slope per unit time;\n", out);
    fputs("invariants: largest deviation; error: |(q,p) - reference| at the end; grad/step: dH/dq\n"
          "and dH/dp calls per step\n", out);
    /* the path of each method when it is not the general one */
    for (size_t k = 0; k < n; k++) {
        if (r[k].path == NULL || strcmp(r[k].path, "general") == 0 || strcmp(r[k].path, "lagrangian") == 0) continue;
        if (strcmp(r[k].path, "mechanical") == 0)
            fprintf(out, "%s: mechanical problem, stepped in Nystrom form (NAME_alloc_mechanical): grad/step counts "
                    "forces\n", r[k].label);
        else if (strcmp(r[k].path, "split") == 0)
            fprintf(out, "%s: the problem's exact flows (NAME_alloc_split): grad/step counts flow calls\n",
                    r[k].label);
    }
}

void try_json_number(FILE *out, double v)
{
    if (isfinite(v)) fprintf(out, "%.17g", v);
    else fputs("null", out);
}

void vigen_try_print_json(FILE *out, const vigen_try_options *opt, const vigen_try_result *r, size_t n)
{
    fputs("{\"problem\": ", out);
    vigen_json_write_string(out, opt->problem);
    fputs(", \"params\": ", out);
    vigen_json_write_string(out, opt->params ? opt->params : "");
    fputs(", \"methods\": [", out);
    for (size_t k = 0; k < n; k++) {
        fputs(k ? ", {\"name\": " : "{\"name\": ", out);
        vigen_json_write_string(out, r[k].label);
        fputs(", \"h\": ", out);
        try_json_number(out, r[k].h);
        fprintf(out, ", \"steps\": %lu, \"t_end\": ", r[k].steps);
        try_json_number(out, r[k].t_end);
        fputs(", \"energy_error_max\": ", out);
        try_json_number(out, r[k].energy_max);
        fputs(", \"energy_drift\": ", out);
        try_json_number(out, r[k].energy_drift);
        fputs(", \"invariants\": {", out);
        for (size_t i = 0; i < r[k].ninv; i++) {
            if (i) fputs(", ", out);
            vigen_json_write_string(out, r[k].inv_names[i]);
            fputs(": ", out);
            try_json_number(out, r[k].inv_max[i]);
        }
        fputs("}, \"global_error\": ", out);
        try_json_number(out, r[k].global_error);
        fputs(", \"grad_evals_per_step\": ", out);
        try_json_number(out, r[k].grad_per_step);
        fputs(", \"ns_per_step\": ", out);
        try_json_number(out, r[k].ns_per_step);
        fputs(", \"path\": ", out);
        if (r[k].path) vigen_json_write_string(out, r[k].path);
        else fputs("null", out);
        fputs(", \"failed\": ", out);
        if (r[k].failed) vigen_json_write_string(out, r[k].message);
        else fputs("null", out);
        fputs("}", out);
    }
    fputs("]}\n", out);
}

void vigen_try_print_problems(FILE *out)
{
    for (size_t i = 0; i < vigen_problem_count(); i++) {
        const vigen_problem_info *info = vigen_problem_info_at(i);
        fprintf(out, "%-20s %s\n", info->name, info->description);
        for (size_t k = 0; k < info->nparams; k++) {
            char kv[64];
            snprintf(kv, sizeof kv, "%s=%g", info->params[k].name, info->params[k].default_value);
            fprintf(out, "  --param %-18s %s\n", kv, info->params[k].description);
        }
    }
}
