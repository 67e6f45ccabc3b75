/* list.c — `vigen list`: every method of the library with what the checker
 * certifies about it (vigen/library.h). */
#include <stdlib.h>
#include <string.h>
#include "check/balls.h"
#include "library/library_internal.h"
#include "report/json.h"
#include "vigen/check.h"
#include "vigen/method.h"
#include "support/printable.h"
#include "support/strbuf.h"

typedef struct {
    char *name, *dir, *path;
    int shadowed;            /* an earlier directory has a method of this name */
    vigen_check_report rep;
    char *source;
    int checked;
} entry;

static int by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* "6", "8+" (at least), "4?" (the next order undecided) */
static char *order_word(const vigen_check_report *rep, int family)
{
    /* bracket flows: the tableau is the plain flows' alone; the order is the generalized table's */
    if (rep->generalized != NULL && rep->generalized->brackets > 0) return vigen_strdup("-");
    int at_least, undecided;
    int p = vigen_check_certified_order(rep, family, &at_least, &undecided);
    return vigen_strdup_printf("%d%s", p, undecided ? "?" : at_least ? "+" : "");
}

static const char *symplectic_word(const vigen_check_report *rep)
{
    if (rep->symplectic == VIGEN_CHECK_YES) return "yes";
    if (rep->symplectic_separable == VIGEN_CHECK_YES) return "separable H";
    if (rep->symplectic == VIGEN_CHECK_NO) return "no";
    return "undecided";
}

static int check_entry(entry *e, vigen_error *err)
{
    vigen_tableau t;
    int rc = vigen_source_load(&t, e->path, 34, err);
    if (rc != VIGEN_OK) return rc;
    e->source = vigen_strdup(t.source ? t.source : "");
    vigen_check_options opt;
    vigen_check_options_init(&opt);
    opt.path = e->path;
    vigen_check_report_init(&e->rep);
    rc = vigen_check_tableau(&e->rep, &t, NULL, &opt, err);
    vigen_tableau_clear(&t);
    e->checked = rc == VIGEN_OK;
    return rc;
}

static void print_text_row(FILE *out, const entry *e)
{
    char *name = vigen_printable(e->name), *dir = vigen_printable(e->dir);
    if (!e->checked) {
        fprintf(out, "%-26s %-10s %s\n", name, dir, e->shadowed ? "(shadowed by a method of the same name above)"
                                                                 : "(could not be checked)");
    } else {
        char *g = order_word(&e->rep, VIGEN_CHECK_GENERAL), *s = order_word(&e->rep, VIGEN_CHECK_SEPARABLE);
        char *n = order_word(&e->rep, VIGEN_CHECK_NYSTROM), *src = vigen_printable(e->source);
        if (strlen(src) > 48) strcpy(src + 45, "...");
        fprintf(out, "%-26s %-10s %6ld %5s %5s %5s %5ld  %-11s %s\n", name, dir, (long)e->rep.cost.stages, g, s, n,
                (long)e->rep.cost.force, symplectic_word(&e->rep), src);
        free(g); free(s); free(n); free(src);
    }
    free(name);
    free(dir);
}

/* "(10,6,4)", an entry not decided written ">=r" */
static char *generalized_word(const vigen_check_generalized *g)
{
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    if (g->why) vigen_strbuf_append(&sb, "-");
    else {
        vigen_strbuf_append(&sb, "(");
        for (int j = 1; j <= g->k; j++)
            vigen_strbuf_printf(&sb, "%s%s%d", j > 1 ? "," : "", g->state[j] == VIGEN_GEN_DECIDED ? "" : ">=", g->r[j]);
        vigen_strbuf_append(&sb, ")");
    }
    return sb.data;
}

static int has_generalized(const entry *e)
{
    return e->checked && e->rep.generalized && e->rep.generalized->computed;
}

/* the methods of named flows: their classical and generalized orders */
static void print_generalized(FILE *out, const entry *es, size_t n)
{
    size_t count = 0;
    for (size_t k = 0; k < n; k++) count += has_generalized(&es[k]);
    if (count == 0) return;
    fprintf(out, "\n%-26s %5s  %-13s %s\n", "named flows", "order", "generalized", "H = A + eps B");
    for (size_t k = 0; k < n; k++) {
        if (!has_generalized(&es[k])) continue;
        const vigen_check_generalized *g = es[k].rep.generalized;
        char *name = vigen_printable(es[k].name), *w = generalized_word(g);
        char *a = vigen_printable(g->letter_a), *b = vigen_printable(g->letter_b);
        char p[16] = "-";
        if (!g->why) snprintf(p, sizeof p, "%s%d", g->classical_state == VIGEN_GEN_DECIDED ? "" : ">=", g->classical);
        fprintf(out, "%-26s %5s  %-13s %s + eps %s%s\n", name, p, w, a, b, g->processed ? " (processed)" : "");
        free(name); free(w); free(a); free(b);
    }
    fputs("order: classical order for general A + B; generalized (r1, r2, ...): error O(eps h^r1 + eps^2 h^r2\n"
          "+ ...), certified from the Lie-algebra terms of one step (vigen check shows them).\n", out);
}

static void print_json_row(FILE *out, const entry *e, int first)
{
    fputs(first ? "\n  {\"name\": " : ",\n  {\"name\": ", out);
    vigen_json_write_string(out, e->name);
    fputs(", \"directory\": ", out);
    vigen_json_write_string(out, e->dir);
    fputs(", \"path\": ", out);
    vigen_json_write_string(out, e->path);
    fprintf(out, ", \"shadowed\": %s", e->shadowed ? "true" : "false");
    if (e->checked) {
        static const int fam[3] = {VIGEN_CHECK_GENERAL, VIGEN_CHECK_SEPARABLE, VIGEN_CHECK_NYSTROM};
        static const char *const key[3] = {"general", "separable", "nystrom"};
        fprintf(out, ", \"stages\": %ld, \"orders\": {", (long)e->rep.cost.stages);
        for (int f = 0; f < 3; f++) {
            int at_least, undecided, p = vigen_check_certified_order(&e->rep, fam[f], &at_least, &undecided);
            fprintf(out, "%s\"%s\": {\"order\": %d, \"at_least\": %s, \"undecided_above\": %s}", f ? ", " : "",
                    key[f], p, at_least ? "true" : "false", undecided ? "true" : "false");
        }
        fprintf(out, "}, \"claim_order\": ");
        if (e->rep.claim_order >= 0) fprintf(out, "%d", e->rep.claim_order);
        else fputs("null", out);
        fprintf(out, ", \"claim_order_holds\": %s, \"evaluations_per_step\": %ld, \"explicit\": %s, \"symplectic\": ",
                e->rep.claim_order >= 0 && e->rep.claim_order_status == VIGEN_CHECK_YES ? "true" : "false",
                (long)e->rep.cost.force, e->rep.cost.explicit_separable ? "true" : "false");
        vigen_json_write_string(out, symplectic_word(&e->rep));
        fputs(", \"source\": ", out);
        vigen_json_write_string(out, e->source);
        if (has_generalized(e)) {
            const vigen_check_generalized *g = e->rep.generalized;
            fputs(", \"generalized\": {\"A\": ", out);
            vigen_json_write_string(out, g->letter_a);
            fputs(", \"B\": ", out);
            vigen_json_write_string(out, g->letter_b);
            fprintf(out, ", \"processed\": %s, \"decided\": %s", g->processed ? "true" : "false",
                    g->why ? "false" : "true");
            if (g->brackets > 0) fprintf(out, ", \"bracket_flows\": %d", g->brackets);
            if (!g->why) {
                fprintf(out, ", \"classical_order\": %d, \"classical_at_least\": %s, \"orders\": [", g->classical,
                        g->classical_state == VIGEN_GEN_DECIDED ? "false" : "true");
                for (int j = 1; j <= g->k; j++) fprintf(out, "%s%d", j > 1 ? ", " : "", g->r[j]);
                fputs("], \"orders_at_least\": [", out);
                for (int j = 1; j <= g->k; j++)
                    fprintf(out, "%s%s", j > 1 ? ", " : "", g->state[j] == VIGEN_GEN_DECIDED ? "false" : "true");
                fputc(']', out);
            }
            fprintf(out, ", \"claim_holds\": %s}", g->claim_status == VIGEN_CHECK_YES ? "true" : "false");
        }
    }
    fputc('}', out);
}

int vigen_library_list(FILE *out, int json, vigen_error *err)
{
    char **dirs = vigen_library_dirs();
    size_t n = 0, cap = 0, ndirs = 0;
    while (dirs && dirs[ndirs]) ndirs++;
    entry *es = NULL;
    for (size_t k = 0; dirs && dirs[k]; k++) {
        char *one[2] = {dirs[k], NULL};
        char **names = vigen_library_names(one);
        size_t m = 0;
        while (names && names[m]) m++;
        if (m > 1) qsort(names, m, sizeof *names, by_name);
        for (size_t j = 0; j < m; j++) {
            if (n == cap) {
                entry *more = realloc(es, (cap ? 2 * cap : 64) * sizeof *es);
                if (more == NULL) break;
                es = more;
                cap = cap ? 2 * cap : 64;
            }
            entry *e = &es[n++];
            memset(e, 0, sizeof *e);
            e->name = names[j];
            names[j] = NULL;
            /* the installed library's two parts come last */
            e->dir = vigen_strdup(k + 2 >= ndirs ? library_parts[k + 2 - ndirs] : dirs[k]);
            e->path = vigen_strdup_printf("%s/%s.lua", dirs[k], e->name);
            for (size_t i = 0; i + 1 < n; i++)
                if (strcmp(es[i].name, e->name) == 0) e->shadowed = 1;
        }
        for (size_t j = 0; j < m; j++) free(names[j]);
        free(names);
    }
    vigen_library_dirs_free(dirs);
    int rc = n == 0 ? vigen_error_set(err, VIGEN_E_IO, "no method found: the library is not installed and VIGEN_PATH "
                                      "names no folder with tableau files") : VIGEN_OK;
    /* every method is checked before anything is printed */
    for (size_t k = 0; k < n && rc == VIGEN_OK; k++)
        if (!es[k].shadowed && check_entry(&es[k], err) != VIGEN_OK) {
            vigen_warn("%s", err->message ? err->message : "could not be checked");
            vigen_error_clear(err);
            vigen_error_init(err);
        }
    if (rc == VIGEN_OK && json) {
        fputs("{\"methods\": [", out);
        for (size_t k = 0; k < n; k++) print_json_row(out, &es[k], k == 0);
        fputs("\n]}\n", out);
    } else if (rc == VIGEN_OK) {
        fprintf(out, "%-26s %-10s %6s %5s %5s %5s %5s  %-11s %s\n", "method", "folder", "stages", "gen", "sep", "nys",
                "evals", "symplectic", "source");
        for (size_t k = 0; k < n; k++) print_text_row(out, &es[k]);
        fputs("\ngen, sep, nys: certified order for general H, separable H = T(p) + V(q) and Nystrom\n"
              "H = p^T M^-1 p / 2 + V(q) (8+: every order checked holds); evals: force evaluations per\n"
              "step for separable H.  Any command takes a method's name in place of a file.\n", out);
        int brackets = 0;
        for (size_t k = 0; k < n; k++) brackets |= has_generalized(&es[k]) && es[k].rep.generalized->brackets > 0;
        if (brackets)
            fputs("-: a method with bracket flows, whose stages and evals are its plain flows' and whose\n"
                  "orders are in the table of named flows below.\n", out);
        print_generalized(out, es, n);
    }
    for (size_t k = 0; k < n; k++) {
        free(es[k].name);
        free(es[k].dir);
        free(es[k].path);
        free(es[k].source);
        if (es[k].checked) vigen_check_report_clear(&es[k].rep);
    }
    free(es);
    return rc;
}
