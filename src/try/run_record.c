/* run_record.c — one run of a compiled driver: its arguments, and its record file
 * (the format is documented in templates/try/driver.c.in) read into a
 * vigen_try_result with the measures of vigen/try.h. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "try/try_internal.h"
#include "support/strbuf.h"

void try_result_clear(vigen_try_result *r)
{
    free(r->label);
    free(r->message);
    for (size_t k = 0; k < r->ninv; k++) free(r->inv_names[k]);
    free(r->inv_names);
    free(r->inv_max);
    free(r->final_state);
    free(r->ts);
    free(r->energy);
    free(r->x);
    free(r->y);
    free(r->path);
    memset(r, 0, sizeof *r);
}

void vigen_try_results_free(vigen_try_result *results, size_t n)
{
    for (size_t k = 0; results && k < n; k++) try_result_clear(&results[k]);
    free(results);
}

/* Reads up to n numbers after the tag; returns how many. */
static size_t numbers(const char *s, double *v, size_t n)
{
    size_t k = 0;
    char *end;
    while (k < n) {
        double x = strtod(s, &end);
        if (end == s) break;
        v[k++] = x;
        s = end;
    }
    return k;
}

/* Room for one more value in the arrays a and b of n values. */
static int grow(double **a, double **b, size_t n, size_t *cap)
{
    if (n < *cap) return 1;
    size_t nc = *cap ? 2 * *cap : 1024;
    double *ma = realloc(*a, nc * sizeof(double));
    if (ma) *a = ma;
    double *mb = ma ? realloc(*b, nc * sizeof(double)) : NULL;
    if (mb) *b = mb;
    if (!ma || !mb) return 0;
    *cap = nc;
    return 1;
}

static int parse(vigen_try_result *r, FILE *f, vigen_error *err)
{
    char *line = NULL;
    size_t lcap = 0, scap = 0, ocap = 0, ninv_seen = 0;
    int ended = 0, has_ref = 0;
    double *ref = NULL, *row = NULL;
    int rc = VIGEN_OK;
    while (rc == VIGEN_OK && getline(&line, &lcap, f) > 0) {
        line[strcspn(line, "\n")] = '\0';
        if (strncmp(line, "dim ", 4) == 0) {
            r->dim = strtoul(line + 4, NULL, 10);
            r->final_state = calloc(2 * r->dim + 1, sizeof(double));
            ref = calloc(2 * r->dim + 1, sizeof(double));
        } else if (strncmp(line, "ninv ", 5) == 0) {
            r->ninv = strtoul(line + 5, NULL, 10);
            r->inv_names = calloc(r->ninv + 1, sizeof(char *));
            r->inv_max = calloc(r->ninv + 1, sizeof(double));
            row = calloc(r->ninv + 4, sizeof(double));
        } else if (strncmp(line, "inv ", 4) == 0 && ninv_seen < r->ninv && r->inv_names) {
            r->inv_names[ninv_seen++] = vigen_strdup(line + 4);
        } else if (line[0] == 's' && line[1] == ' ' && row) {
            size_t want = r->ninv + 2;
            if (numbers(line + 2, row, want) != want || !grow(&r->ts, &r->energy, r->nsamples, &scap)) {
                rc = vigen_error_set(err, VIGEN_E_TEMPLATE, "%s: the driver wrote a malformed sample", r->label);
                break;
            }
            size_t i = r->nsamples++;
            r->ts[i] = row[0];
            r->energy[i] = row[1];
            if (fabs(row[1]) > r->energy_max || isnan(row[1])) r->energy_max = fabs(row[1]);
            for (size_t k = 0; k < r->ninv; k++)
                if (fabs(row[2 + k]) > r->inv_max[k] || isnan(row[2 + k])) r->inv_max[k] = fabs(row[2 + k]);
        } else if (line[0] == 'o' && line[1] == ' ') {
            double v[2];
            if (numbers(line + 2, v, 2) != 2 || !grow(&r->x, &r->y, r->norbit, &ocap)) {
                rc = vigen_error_set(err, VIGEN_E_TEMPLATE, "%s: the driver wrote a malformed orbit point", r->label);
                break;
            }
            r->x[r->norbit] = v[0];
            r->y[r->norbit++] = v[1];
        } else if (strncmp(line, "fail ", 5) == 0) {
            char *end;
            unsigned long step = strtoul(line + 5, &end, 10);
            double t = strtod(end, &end);
            strtol(end, &end, 10);
            while (*end == ' ') end++;
            r->failed = 1;
            r->message = vigen_strdup_printf("%s: step %lu (t = %.6g) failed: %s; try a smaller step (--h or "
                                             "--steps-per-period)", r->label, step, t, end);
        } else if (strncmp(line, "end ", 4) == 0) {
            double v[5];
            if (numbers(line + 4, v, 5) == 5) {
                r->steps = (unsigned long)v[0];
                r->grad_per_step = v[0] > 0 ? (v[1] + v[2]) / v[0] : NAN;
                r->ns_per_step = v[0] > 0 ? v[3] / v[0] : NAN;
                r->t_end = v[4];
                ended = 1;
            }
        } else if (strncmp(line, "path ", 5) == 0) {
            free(r->path);
            r->path = vigen_strdup(line + 5);
        } else if (strncmp(line, "final ", 6) == 0 && r->final_state) {
            numbers(line + 6, r->final_state, 2 * r->dim);
        } else if (strncmp(line, "ref ", 4) == 0 && ref) {
            has_ref = numbers(line + 4, ref, 2 * r->dim) == 2 * r->dim;
        }
    }
    free(line);
    free(row);
    if (rc == VIGEN_OK && (!ended || r->nsamples == 0 || r->final_state == NULL))
        rc = vigen_error_set(err, VIGEN_E_TEMPLATE, "%s: the driver's output is incomplete", r->label);
    if (rc == VIGEN_OK) {
        r->has_reference = has_ref && !r->failed;
        r->global_error = NAN;
        if (r->has_reference) {
            double s = 0;
            for (size_t i = 0; i < 2 * r->dim; i++) s = hypot(s, r->final_state[i] - ref[i]);
            r->global_error = s;
        }
        r->energy_drift = try_lsq_slope(r->ts, r->energy, r->nsamples);
    }
    free(ref);
    return rc;
}

int try_run_driver(vigen_try_result *r, const try_build *b, const vigen_try_options *opt, double h,
                   unsigned long steps, unsigned long every, vigen_error *err)
{
    memset(r, 0, sizeof *r);
    r->label = vigen_strdup(b->label);
    r->h = h;
    r->planned = steps;
    char hs[40], ns[32], es[32];
    snprintf(hs, sizeof hs, "%.17g", h);
    snprintf(ns, sizeof ns, "%lu", steps);
    snprintf(es, sizeof es, "%lu", every ? every : 1);
    char *out = vigen_strdup_printf("%s.out", b->exe), *log = vigen_strdup_printf("%s.log", b->exe);
    const char *slash = strrchr(out, '/');
    free(try_workdir_file(slash + 1));
    slash = strrchr(log, '/');
    free(try_workdir_file(slash + 1));
    char *argv[] = { b->exe, (char *)opt->problem, (char *)(opt->params ? opt->params : ""), hs, ns, es, out, NULL };
    int nf = 0;
    int status = try_process_run(argv, log, &nf);
    int rc = VIGEN_OK;
    if (status != 0) {
        char *head = try_log_head(log, 2);
        if (status == 2 && head)
            rc = vigen_error_set(err, VIGEN_E_USAGE, "%s", head);
        else
            rc = vigen_error_set(err, VIGEN_E_TEMPLATE, "%s: the compiled driver failed (status %d)%s%s", b->label,
                                 status, head ? ": " : "", head ? head : "");
        free(head);
    } else {
        FILE *f = fopen(out, "r");
        if (f == NULL) rc = vigen_error_set(err, VIGEN_E_TEMPLATE, "%s: the driver wrote no output", b->label);
        else {
            rc = parse(r, f, err);
            fclose(f);
        }
    }
    remove(out);
    remove(log);
    free(out);
    free(log);
    return rc;
}
