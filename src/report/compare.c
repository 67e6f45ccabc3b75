/* compare.c — the figures of several methods side by side (vigen/compare.h):
 * text, LaTeX and JSON tables built from the checker's reports. */
#include <stdlib.h>
#include <string.h>
#include "vigen/compare.h"
#include "check/balls.h"
#include "report/check_figures.h"
#include "report/json.h"
#include "support/printable.h"
#include "support/strbuf.h"

static const char *const family_word[VIGEN_CHECK_EC_FAMILIES] = {"general", "separable", "nystrom"};

/* One method's row: the report and the figures derived from it. */
typedef struct {
    vigen_check_report rep;
    int family;          /* design family, VIGEN_CHECK_EC_* */
    int order;           /* design order p, -1 when not decided */
    int has_constant;    /* C known */
    int has_efficiency;  /* E known: C known, C > 0 and a fixed number of evaluations (explicit) */
    arb_t efficiency;    /* evaluations * C^(1/p) */
} row;

static int design_order(const vigen_check_report *rep, int family)
{
    static const int orders_of[VIGEN_CHECK_EC_FAMILIES] = {VIGEN_CHECK_GENERAL, VIGEN_CHECK_SEPARABLE,
                                                           VIGEN_CHECK_NYSTROM};
    const vigen_check_level *L = &rep->orders[orders_of[family]].level;
    return L->capped || L->undecided ? -1 : L->value;
}

static void row_figures(row *r, slong prec)
{
    r->family = vigen_report_design_family(&r->rep);
    r->order = design_order(&r->rep, r->family);
    const vigen_check_error_constant *e = &r->rep.error_constant[r->family];
    r->has_constant = e->available;
    r->has_efficiency = 0;
    /* an implicit method's evaluations depend on its stage iteration: no
     * fixed cost per step to scale */
    if (e->available && r->rep.cost.explicit_separable && e->order >= 1 && arb_is_positive(e->value)) {
        arb_root_ui(r->efficiency, e->value, (ulong)e->order, prec);
        arb_mul_si(r->efficiency, r->efficiency, r->rep.cost.force, prec);
        r->has_efficiency = arb_is_finite(r->efficiency);
    }
}

/* the certain digits of x (at most 6), or the word */
static char *figure(const arb_t x, int known, const char *unknown)
{
    return known ? vigen_ball_str(x, 6) : vigen_strdup(unknown);
}

static char *stability_text(const vigen_check_report *rep)
{
    const vigen_check_stability *st = &rep->stability;
    if (st->status == VIGEN_CHECK_STAB_UNBOUNDED) return vigen_strdup("unbounded");
    if (st->status == VIGEN_CHECK_STAB_BOUNDED) return vigen_ball_str(st->x, 6);
    if (st->status == VIGEN_CHECK_STAB_NONE) return vigen_strdup("none");
    return vigen_strdup("undecided");
}

static char *order_text(const row *r)
{
    if (r->order < 0) return vigen_strdup("?");
    return vigen_strdup_printf("%d", r->order);
}

static void print_text(FILE *out, row *rows, size_t n)
{
    size_t width = 6;
    char **names = calloc(n, sizeof *names);
    for (size_t k = 0; k < n; k++) {
        names[k] = vigen_printable(rows[k].rep.name ? rows[k].rep.name : "?");
        if (strlen(names[k]) > width) width = strlen(names[k]);
    }
    fprintf(out, "%-*s  %6s  %5s  %-9s  %-12s  %-10s  %5s  %-8s  %s\n", (int)width, "method", "stages", "order",
            "family", "error const", "stability", "evals", "explicit", "efficiency");
    for (size_t k = 0; k < n; k++) {
        row *r = &rows[k];
        const vigen_check_error_constant *e = &r->rep.error_constant[r->family];
        char *o = order_text(r), *c = figure(e->value, r->has_constant, "?"), *st = stability_text(&r->rep);
        char *ef = figure(r->efficiency, r->has_efficiency, "-");
        fprintf(out, "%-*s  %6ld  %5s  %-9s  %-12s  %-10s  %5ld  %-8s  %s\n", (int)width, names[k],
                (long)r->rep.cost.stages, o, family_word[r->family], c, st, (long)r->rep.cost.force,
                r->rep.cost.explicit_separable ? "yes" : "no", ef);
        free(o); free(c); free(st); free(ef);
        free(names[k]);
    }
    free(names);
    fputs("\norder       design order p of the family: general H, separable H = T(p) + V(q) or\n"
          "             Nystrom H = p^T M^-1 p / 2 + V(q)\n"
          "error const  C, the 2-norm of the family's principal error coefficients\n"
          "stability    h omega below which the step of q'' = -omega^2 q is stable\n"
          "evals        force evaluations per step for H = T(p) + V(q)\n"
          "efficiency   evals * C^(1/p), explicit methods only: smaller is better\n", out);
}

/* LaTeX text of a name: the characters TeX treats specially escaped */
static void latex_name(FILE *out, const char *name)
{
    char *p = vigen_printable(name);
    for (const char *c = p; *c; c++) {
        if (strchr("_&%$#{}", *c)) fprintf(out, "\\%c", *c);
        else if (*c == '\\') fputs("\\textbackslash{}", out);
        else if (*c == '^' || *c == '~') fprintf(out, "\\%c{}", *c);
        else fputc(*c, out);
    }
    free(p);
}

static void print_latex(FILE *out, row *rows, size_t n)
{
    fputs("\\begin{tabular}{lrrlllrl}\n"
          "method & stages & $p$ & family & $C$ & stability & evals & $E = \\mathrm{evals}\\, C^{1/p}$ \\\\\n"
          "\\hline\n", out);
    for (size_t k = 0; k < n; k++) {
        row *r = &rows[k];
        const vigen_check_error_constant *e = &r->rep.error_constant[r->family];
        char *o = order_text(r), *c = figure(e->value, r->has_constant, "?"), *st = stability_text(&r->rep);
        char *ef = figure(r->efficiency, r->has_efficiency, "--");
        latex_name(out, r->rep.name ? r->rep.name : "?");
        fprintf(out, " & %ld & %s & %s & %s & %s & %ld & %s \\\\\n", (long)r->rep.cost.stages, o,
                family_word[r->family], c, strcmp(st, "unbounded") == 0 ? "$\\infty$" : st, (long)r->rep.cost.force,
                ef);
        free(o); free(c); free(st); free(ef);
    }
    fputs("\\end{tabular}\n", out);
}

/* a JSON number: the midpoint to 17 digits, or null */
static void json_number(FILE *out, const arb_t x, int known)
{
    if (!known || !arb_is_finite(x)) fputs("null", out);
    else fprintf(out, "%.17g", arf_get_d(arb_midref(x), ARF_RND_NEAR));
}

static void print_json(FILE *out, row *rows, size_t n)
{
    fputs("{\"methods\": [", out);
    for (size_t k = 0; k < n; k++) {
        row *r = &rows[k];
        const vigen_check_error_constant *e = &r->rep.error_constant[r->family];
        fputs(k ? ",\n  {\"name\": " : "\n  {\"name\": ", out);
        vigen_json_write_string(out, r->rep.name ? r->rep.name : "");
        fputs(", \"path\": ", out);
        vigen_json_write_string(out, r->rep.path ? r->rep.path : "");
        fprintf(out, ", \"stages\": %ld, \"order\": ", (long)r->rep.cost.stages);
        if (r->order < 0) fputs("null", out);
        else fprintf(out, "%d", r->order);
        fprintf(out, ", \"family\": \"%s\", \"error_constant\": ", family_word[r->family]);
        json_number(out, e->value, r->has_constant);
        fputs(", \"stability_interval\": ", out);
        json_number(out, r->rep.stability.x, r->rep.stability.status == VIGEN_CHECK_STAB_BOUNDED);
        fprintf(out, ", \"stability\": \"%s\"", r->rep.stability.status == VIGEN_CHECK_STAB_UNBOUNDED ? "unbounded"
                     : r->rep.stability.status == VIGEN_CHECK_STAB_BOUNDED ? "bounded"
                     : r->rep.stability.status == VIGEN_CHECK_STAB_NONE ? "none" : "undecided");
        fprintf(out, ", \"evaluations_per_step\": %ld, \"explicit\": %s, \"efficiency\": ", (long)r->rep.cost.force,
                r->rep.cost.explicit_separable ? "true" : "false");
        json_number(out, r->efficiency, r->has_efficiency);
        fputc('}', out);
    }
    fputs("\n]}\n", out);
}

int vigen_compare_run(const char *const *paths, size_t n, const vigen_check_options *opt, int format, FILE *out,
                      vigen_error *err)
{
    if (n == 0) return vigen_error_set(err, VIGEN_E_USAGE, "no file to compare");
    row *rows = calloc(n, sizeof *rows);
    if (rows == NULL) return vigen_error_set(err, VIGEN_E_MEMORY, "out of memory");
    size_t done = 0;
    int rc = VIGEN_OK;
    for (; done < n && rc == VIGEN_OK; done++) {
        row *r = &rows[done];
        vigen_check_report_init(&r->rep);
        arb_init(r->efficiency);
        vigen_tableau t;
        rc = opt->load ? opt->load(&t, paths[done], opt->spec_digits, err) : vigen_tableau_load(&t, paths[done], NULL, err);
        if (rc != VIGEN_OK) continue;
        vigen_check_options o = *opt;
        o.path = paths[done];
        o.against = NULL;
        rc = vigen_check_tableau(&r->rep, &t, NULL, &o, err);
        if (rc != VIGEN_OK) vigen_error_prefix(err, "%s: ", paths[done]);
        else row_figures(r, r->rep.prec > 64 ? r->rep.prec : 128);
        vigen_tableau_clear(&t);
    }
    if (rc == VIGEN_OK) {
        if (format == VIGEN_COMPARE_LATEX) print_latex(out, rows, n);
        else if (format == VIGEN_COMPARE_JSON) print_json(out, rows, n);
        else print_text(out, rows, n);
    }
    for (size_t k = 0; k < done; k++) {
        vigen_check_report_clear(&rows[k].rep);
        arb_clear(rows[k].efficiency);
    }
    free(rows);
    return rc;
}
