/* plot.c — the figures of a `vigen try` run: the energy error against time
 * (log scale, one curve per method) and the orbit or phase portrait, each
 * with its data as CSV (gnuplot.c draws and writes them). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "try/try_internal.h"
#include "support/strbuf.h"

/* A CSV field: the label with commas and quotes replaced. */
static void csv_label(vigen_strbuf *sb, const char *prefix, const char *label)
{
    vigen_strbuf_append(sb, prefix);
    for (const char *c = label; *c; c++) vigen_strbuf_appendn(sb, (*c == ',' || *c == '"' || *c == '\n') ? "_" : c, 1);
}

static char *energy_csv(const vigen_try_result *r, size_t n)
{
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    vigen_strbuf_append(&sb, "t");
    size_t rows = 0, longest = 0;
    for (size_t k = 0; k < n; k++) {
        csv_label(&sb, ",", r[k].label);
        if (r[k].nsamples > rows) {
            rows = r[k].nsamples;
            longest = k;
        }
    }
    vigen_strbuf_append(&sb, "\n");
    for (size_t i = 0; i < rows; i++) {
        vigen_strbuf_printf(&sb, "%.17g", r[longest].ts[i]);
        for (size_t k = 0; k < n; k++) {
            if (i < r[k].nsamples) vigen_strbuf_printf(&sb, ",%.17g", r[k].energy[i]);
            else vigen_strbuf_append(&sb, ",");
        }
        vigen_strbuf_append(&sb, "\n");
    }
    return sb.data;
}

static char *orbit_csv(const vigen_try_result *r, size_t n, const char *xname, const char *yname)
{
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    size_t rows = 0;
    for (size_t k = 0; k < n; k++) {
        csv_label(&sb, k ? "," : "", r[k].label);
        vigen_strbuf_printf(&sb, " %s", xname);
        csv_label(&sb, ",", r[k].label);
        vigen_strbuf_printf(&sb, " %s", yname);
        if (r[k].norbit > rows) rows = r[k].norbit;
    }
    vigen_strbuf_append(&sb, "\n");
    for (size_t i = 0; i < rows; i++) {
        for (size_t k = 0; k < n; k++) {
            if (i < r[k].norbit) vigen_strbuf_printf(&sb, "%s%.17g,%.17g", k ? "," : "", r[k].x[i], r[k].y[i]);
            else vigen_strbuf_append(&sb, k ? ",," : ",");
        }
        vigen_strbuf_append(&sb, "\n");
    }
    return sb.data;
}

static char *title(const vigen_try_options *opt, const char *what)
{
    char *t = vigen_strdup_printf("%s%s%s: %s", opt->problem, opt->params && *opt->params ? " " : "",
                                  opt->params ? opt->params : "", what);
    char *q = try_gnuplot_quote(t);
    free(t);
    return q;
}

static int plot_energy(try_figures *figs, const char *dir, const vigen_try_options *opt, const vigen_try_result *r,
                       size_t n, vigen_error *err);
static int plot_orbit(try_figures *figs, const char *dir, const vigen_try_options *opt, const vigen_try_result *r,
                      size_t n, vigen_error *err);

int vigen_try_plot(const char *dir, const vigen_try_options *opt, const vigen_try_result *r, size_t n,
                   vigen_error *err)
{
    int rc = try_plot_dir(dir, err);
    if (rc == VIGEN_OK) rc = try_workdir_create(err);
    if (rc != VIGEN_OK) return rc;
    try_figures figs;
    memset(&figs, 0, sizeof figs);
    rc = plot_energy(&figs, dir, opt, r, n, err);
    if (rc == VIGEN_OK) rc = plot_orbit(&figs, dir, opt, r, n, err);
    try_workdir_remove();
    if (rc == VIGEN_OK) rc = try_figures_commit(&figs, dir, err);
    try_figures_clear(&figs);
    return rc;
}

/* Methods whose error is ever non-zero (a log scale shows no zero). */
static int plot_energy(try_figures *figs, const char *dir, const vigen_try_options *opt, const vigen_try_result *r,
                       size_t n, vigen_error *err)
{
    vigen_strbuf gp;
    vigen_strbuf_init(&gp);
    char *t = title(opt, "relative energy error");
    vigen_strbuf_printf(&gp, "set title \"%s\"\nset xlabel \"t\"\nset ylabel \"|H - H0| / |H0|\"\n"
                             "set logscale y\nset format y \"1e%%L\"\nset key below\n", t);
    free(t);
    int curves = 0;
    for (size_t k = 0; k < n; k++) {
        if (!(r[k].energy_max > 0)) continue;
        char *label = try_gnuplot_quote(r[k].label);
        vigen_strbuf_printf(&gp, "%s datafile using 1:(abs(column(%zu)) > 0 ? abs(column(%zu)) : 1/0) with lines "
                                 "lw 1.5 title \"%s\"",
                            curves ? ", \\\n    " : "plot", k + 2, k + 2, label);
        free(label);
        curves++;
    }
    if (curves == 0) vigen_strbuf_append(&gp, "unset logscale y\nset format y\nplot datafile using 1:2 with lines title \"all zero\"");
    vigen_strbuf_append(&gp, "\n");
    char *csv = energy_csv(r, n);
    int rc = try_plot_files(figs, dir, "energy", csv, gp.data, err);
    free(csv);
    vigen_strbuf_clear(&gp);
    return rc;
}

static int plot_orbit(try_figures *figs, const char *dir, const vigen_try_options *opt, const vigen_try_result *r,
                      size_t n, vigen_error *err)
{
    vigen_strbuf gp;
    vigen_strbuf_init(&gp);
    char *t;
    int phase = n > 0 && r[0].dim == 1;
    const char *xname = "q1", *yname = phase ? "p1" : "q2";
    t = title(opt, phase ? "phase portrait (first steps)" : "orbit (first steps)");
    vigen_strbuf_printf(&gp, "set title \"%s\"\nset xlabel \"%s\"\nset ylabel \"%s\"\nset size ratio -1\n"
                             "set key below\n", t, xname, yname);
    free(t);
    for (size_t k = 0; k < n; k++) {
        char *label = try_gnuplot_quote(r[k].label);
        vigen_strbuf_printf(&gp, "%s datafile using %zu:%zu with lines lw 1.2 title \"%s\"",
                            k ? ", \\\n    " : "plot", 2 * k + 1, 2 * k + 2, label);
        free(label);
    }
    vigen_strbuf_append(&gp, "\n");
    char *csv = orbit_csv(r, n, xname, yname);
    int rc = try_plot_files(figs, dir, "orbit", csv, gp.data, err);
    free(csv);
    vigen_strbuf_clear(&gp);
    return rc;
}
