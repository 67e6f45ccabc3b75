/* show.c — text, LaTeX, JSON and Lua renderings of a tableau.  Texts from
 * the file (name, description, ...) appear escaped in text and LaTeX
 * (support/printable.h: stdout may be a terminal), through the JSON writer in
 * JSON and quoted in Lua. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "core/decimal.h"
#include "core/expr.h"
#include "support/printable.h"
#include "vigen/show.h"
#include "report/json.h"
#include "support/strbuf.h"

/* The formats by name, the one list of them. */
static const struct {
    const char *name;
    vigen_show_format format;
} formats[] = {
    { "text", VIGEN_SHOW_TEXT }, { "latex", VIGEN_SHOW_LATEX }, { "json", VIGEN_SHOW_JSON }, { "lua", VIGEN_SHOW_LUA },
};
enum { NFORMATS = sizeof formats / sizeof formats[0] };

int vigen_show_parse_format(vigen_show_format *fmt, const char *name)
{
    for (size_t k = 0; k < NFORMATS; k++)
        if (strcmp(formats[k].name, name) == 0) {
            *fmt = formats[k].format;
            return 1;
        }
    return 0;
}

/* Composed once from the table (a static buffer: the list is the same for
 * every caller). */
const char *vigen_show_format_names(void)
{
    static char list[64];
    if (list[0] == '\0') {
        size_t n = 0;
        for (size_t k = 0; k < NFORMATS; k++)
            n += (size_t)snprintf(list + n, sizeof list - n, "%s%s",
                                  k == 0 ? "" : k + 1 == NFORMATS ? " or " : ", ", formats[k].name);
    }
    return list;
}

static void free_strings(char **v, slong n)
{
    if (v == NULL) return;
    for (slong i = 0; i < n; i++) free(v[i]);
    free(v);
}

/* One entry: keep a decimal text, else format the ball; NULL = need more precision. */
static char *display(const char *text, const arb_t x, slong digits)
{
    if (text != NULL && vigen_decimal_is_rounded(text)) return vigen_strdup(text);
    if (arb_is_zero(x)) return vigen_strdup("0");
    /* an exact integer stays one ("1", as generated files write it) */
    char *d = vigen_decimal_format_integer(x);
    if (d != NULL) return d;
    d = vigen_decimal_format(x, digits);
    if (d == NULL && arb_contains_zero(x)) {
        /* an exact expression whose value is 0 (sin(pi), sqrt(2)^2 - 2) never
         * gives a ball excluding 0: certify |x| <= 0.5e-digits, as generate does */
        char *z = vigen_decimal_format_zero(x);
        long K = 0;
        if (z != NULL && sscanf(z, "0e%ld", &K) == 1 && K <= -digits) d = vigen_strdup_printf("0e-%ld", (long)digits);
        free(z);
    }
    return d;
}

/* The entry that could not be displayed, for the message. */
static char failed_label[64];

static int fill(char ***out, char **texts, arb_srcptr v, const arb_mat_struct *m, slong s, slong n, slong digits,
                const char *key)
{
    *out = calloc((size_t)n, sizeof(char *));
    for (slong k = 0; k < n; k++) {
        arb_srcptr x = m ? arb_mat_entry(m, k / s, k % s) : v + k;
        (*out)[k] = display(texts ? texts[k] : NULL, x, digits);
        if ((*out)[k] == NULL) {
            if (m) snprintf(failed_label, sizeof failed_label, "%s[%ld][%ld]", key, (long)(k / s + 1), (long)(k % s + 1));
            else snprintf(failed_label, sizeof failed_label, "%s[%ld]", key, (long)(k + 1));
            return 0;
        }
    }
    return 1;
}

int vigen_show_entry_strings(vigen_tableau *t, slong digits, char ***c, char ***A, char ***b, char ***ct,
                             char ***At, char ***bt, vigen_error *err)
{
    slong s = t->s, prec = t->prec;
    for (int attempt = 0; attempt < 6; attempt++) {
        *c = *A = *b = *ct = *At = *bt = NULL;
        int ok = fill(c, t->c_text, t->c, NULL, s, s, digits, "c") &&
                 fill(A, t->A_text, NULL, t->A, s, s * s, digits, "A") &&
                 fill(b, t->b_text, t->b, NULL, s, s, digits, "b");
        if (ok && t->has_At) ok = fill(At, t->At_text, NULL, t->At, s, s * s, digits, "At");
        if (ok && t->has_At) ok = fill(ct, t->has_ct ? t->ct_text : NULL, t->ct, NULL, s, s, digits, "ct");
        if (ok && t->has_bt) ok = fill(bt, t->bt_text, t->bt, NULL, s, s, digits, "bt");
        if (ok) return VIGEN_OK;
        free_strings(*c, s); free_strings(*A, s * s); free_strings(*b, s);
        free_strings(*ct, s); free_strings(*At, s * s); free_strings(*bt, s);
        *c = *A = *b = *ct = *At = *bt = NULL;
        if (t->c_text == NULL) break; /* balls without texts cannot be refined */
        prec *= 2;
        int rc = vigen_tableau_evaluate(t, prec, err);
        if (rc != VIGEN_OK) return rc;
    }
    return vigen_error_set(err, VIGEN_E_PRECISION, "%s: %s cannot be printed with %ld certified digits (it may lie "
                           "exactly halfway between two %ld-digit decimals: try --digits %ld)",
                           t->name ? t->name : "the tableau", failed_label, (long)digits, (long)digits,
                           (long)(digits + 1));
}

static void json_vector(vigen_strbuf *sb, const char *key, char **v, slong s)
{
    vigen_strbuf_printf(sb, ", \"%s\": [", key);
    for (slong i = 0; i < s; i++) {
        if (i) vigen_strbuf_append(sb, ", ");
        vigen_json_string(sb, v[i]);
    }
    vigen_strbuf_append(sb, "]");
}

static void json_matrix(vigen_strbuf *sb, const char *key, char **m, slong s)
{
    vigen_strbuf_printf(sb, ", \"%s\": [", key);
    for (slong i = 0; i < s; i++) {
        vigen_strbuf_append(sb, i ? ", [" : "[");
        for (slong j = 0; j < s; j++) {
            if (j) vigen_strbuf_append(sb, ", ");
            vigen_json_string(sb, m[i * s + j]);
        }
        vigen_strbuf_append(sb, "]");
    }
    vigen_strbuf_append(sb, "]");
}

/* LaTeX: a decimal "1.5e-7" becomes 1.5\times10^{-7}. */
static void latex_number(vigen_strbuf *sb, const char *text)
{
    const char *e = strpbrk(text, "eE");
    if (e == NULL) { vigen_strbuf_append(sb, text); return; }
    vigen_strbuf_appendn(sb, text, (size_t)(e - text));
    vigen_strbuf_printf(sb, "\\times 10^{%ld}", strtol(e + 1, NULL, 10));
}

/* One entry in LaTeX: an exact expression from a hand-written file as the
 * expression (1/4 - sqrt(3)/6 as \frac{1}{4} - \frac{\sqrt{3}}{6}); anything
 * else (generated or rounded data) as its certified decimal. */
static void latex_entry(vigen_strbuf *sb, const char *text, const char *decimal)
{
    if (text != NULL && !vigen_decimal_is_rounded(text)) {
        vigen_expr *e = NULL;
        vigen_error err;
        vigen_error_init(&err);
        if (vigen_expr_parse(&e, text, 0, &err) == VIGEN_OK) {
            char *l = vigen_expr_latex(e);
            vigen_strbuf_append(sb, l);
            free(l);
            vigen_expr_free(e);
            return;
        }
        vigen_error_clear(&err);
    }
    latex_number(sb, decimal);
}

/* texts: the file's texts of c, A, b (each may be NULL), for exact entries */
static void latex_array(vigen_strbuf *sb, char **c, char **A, char **b, char *const *tc, char *const *tA,
                        char *const *tb, slong s)
{
    vigen_strbuf_append(sb, "\\begin{array}{c|");
    for (slong j = 0; j < s; j++) vigen_strbuf_append(sb, "c");
    vigen_strbuf_append(sb, "}\n");
    for (slong i = 0; i < s; i++) {
        latex_entry(sb, tc ? tc[i] : NULL, c[i]);
        for (slong j = 0; j < s; j++) {
            vigen_strbuf_append(sb, " & ");
            latex_entry(sb, tA ? tA[i * s + j] : NULL, A[i * s + j]);
        }
        vigen_strbuf_append(sb, " \\\\\n");
    }
    vigen_strbuf_append(sb, "\\hline\n");
    for (slong j = 0; j < s; j++) {
        vigen_strbuf_append(sb, " & ");
        latex_entry(sb, tb ? tb[j] : NULL, b[j]);
    }
    vigen_strbuf_append(sb, "\n\\end{array}\n");
}

static void text_array(vigen_strbuf *sb, const char *title, char **c, char **A, char **b, slong s)
{
    size_t w = 1;
    for (slong k = 0; k < s * s; k++) w = strlen(A[k]) > w ? strlen(A[k]) : w;
    for (slong k = 0; k < s; k++) {
        w = strlen(b[k]) > w ? strlen(b[k]) : w;
        w = strlen(c[k]) > w ? strlen(c[k]) : w;
    }
    vigen_strbuf_printf(sb, "%s\n", title);
    for (slong i = 0; i < s; i++) {
        vigen_strbuf_printf(sb, "  %*s |", (int)w, c[i]);
        for (slong j = 0; j < s; j++) vigen_strbuf_printf(sb, " %*s", (int)w, A[i * s + j]);
        vigen_strbuf_append(sb, "\n");
    }
    vigen_strbuf_printf(sb, "  %*s-+", (int)w, "");
    for (slong j = 0; j < s; j++) {
        vigen_strbuf_append(sb, " ");
        for (size_t k = 0; k < w; k++) vigen_strbuf_append(sb, "-");
    }
    vigen_strbuf_printf(sb, "\n  %*s |", (int)w, "");
    for (slong j = 0; j < s; j++) vigen_strbuf_printf(sb, " %*s", (int)w, b[j]);
    vigen_strbuf_append(sb, "\n");
}

static void text_summary(vigen_strbuf *sb, const vigen_tableau *t)
{
    slong s = t->s, prec = t->prec;
    arb_t r, worst;
    arb_init(r);
    arb_init(worst);
    arb_zero(worst);
    for (slong i = 0; i < s; i++) {
        arb_zero(r);
        for (slong j = 0; j < s; j++) arb_add(r, r, arb_mat_entry(t->A, i, j), prec);
        arb_sub(r, r, t->c + i, prec);
        arb_abs(r, r);
        arb_max(worst, worst, r, prec);
    }
    char *w = arb_get_str(worst, 5, 0);
    vigen_strbuf_printf(sb, "\nrow sums       max_i |sum_j a_ij - c_i|   = %s\n", w);
    flint_free(w);
    if (t->has_At) {
        arb_zero(worst);
        for (slong i = 0; i < s; i++) {
            arb_zero(r);
            for (slong j = 0; j < s; j++) arb_add(r, r, arb_mat_entry(t->At, i, j), prec);
            arb_sub(r, r, t->ct + i, prec);
            arb_abs(r, r);
            arb_max(worst, worst, r, prec);
        }
        w = arb_get_str(worst, 5, 0);
        vigen_strbuf_printf(sb, "               max_i |sum_j at_ij - ct_i| = %s\n", w);
        flint_free(w);
        vigen_tableau_symplectic_residual(worst, t, prec);
        w = arb_get_str(worst, 5, 0);
        vigen_strbuf_printf(sb, "symplecticity  max_ij |b_i at_ij + b_j a_ji - b_i b_j| = %s  (%s)\n", w,
                            arb_contains_zero(worst) ? "contains 0: symplectic within the certified digits"
                                                     : "excludes 0: NOT symplectic");
        flint_free(w);
    }
    arb_clear(r);
    arb_clear(worst);
}

/* A text of the file, escaped (support/printable.h). */
static void shown(vigen_strbuf *sb, const char *text)
{
    vigen_printable_append(sb, text, strlen(text));
}

/* "LABEL TEXT\n" with the text escaped, when there is a text. */
static void shown_line(vigen_strbuf *sb, const char *label, const char *text)
{
    if (text == NULL) return;
    vigen_strbuf_append(sb, label);
    shown(sb, text);
    vigen_strbuf_append(sb, "\n");
}

int vigen_show_render(char **out, vigen_tableau *t, vigen_show_format fmt, slong digits, vigen_error *err)
{
    if (fmt == VIGEN_SHOW_LUA) {
        *out = vigen_tableau_to_lua(t);
        return VIGEN_OK;
    }
    char **c, **A, **b, **ct, **At, **bt;
    int rc = vigen_show_entry_strings(t, digits, &c, &A, &b, &ct, &At, &bt, err);
    if (rc != VIGEN_OK) return rc;
    slong s = t->s;
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    char **bp = t->has_bt ? bt : b;
    if (fmt == VIGEN_SHOW_JSON) {
        vigen_strbuf_append(&sb, "{\"name\": ");
        vigen_json_string(&sb, t->name);
        vigen_strbuf_printf(&sb, ", \"s\": %ld", (long)s);
        json_vector(&sb, "c", c, s);
        json_matrix(&sb, "A", A, s);
        json_vector(&sb, "b", b, s);
        if (t->has_At) {
            json_matrix(&sb, "At", At, s);
            json_vector(&sb, "ct", ct, s);
            if (t->has_bt) json_vector(&sb, "bt", bt, s);
        }
        vigen_strbuf_append(&sb, "}\n");
    } else if (fmt == VIGEN_SHOW_LATEX) {
        /* the name in a comment, escaped: one line, no control character */
        vigen_strbuf_append(&sb, "% ");
        shown(&sb, t->name);
        vigen_strbuf_append(&sb, " (vigen)\n\\[\n");
        latex_array(&sb, c, A, b, t->c_text, t->A_text, t->b_text, s);
        if (t->has_At) {
            vigen_strbuf_append(&sb, "\\qquad\n");
            latex_array(&sb, ct, At, bp, t->has_ct ? t->ct_text : NULL, t->At_text,
                        t->has_bt ? t->bt_text : t->b_text, s);
        }
        vigen_strbuf_append(&sb, "\\]\n");
    } else {
        shown(&sb, t->name);
        vigen_strbuf_printf(&sb, ": %ld stage%s\n", (long)s, s == 1 ? "" : "s");
        /* metadata is what the file says about itself, not something show verifies */
        if (t->generated_now) {
            /* a spec: the digits were certified just now */
            vigen_strbuf_append(&sb, "generated from the spec by ");
            shown(&sb, t->generator ? t->generator : "vigen");
            vigen_strbuf_printf(&sb, ": %ld certified digits\n", (long)t->digits);
        } else if (t->digits > 0 || t->generator) {
            vigen_strbuf_append(&sb, "the file states:");
            if (t->digits > 0) vigen_strbuf_printf(&sb, " %ld certified digits", (long)t->digits);
            if (t->generator) {
                vigen_strbuf_append(&sb, t->digits > 0 ? ", generated by " : " generated by ");
                shown(&sb, t->generator);
            }
            vigen_strbuf_append(&sb, "\n");
        }
        shown_line(&sb, "", t->description);
        shown_line(&sb, "source: ", t->source);
        shown_line(&sb, "basis:  ", t->basis);
        shown_line(&sb, "nodes:  ", t->nodes);
        vigen_strbuf_append(&sb, "\n");
        text_array(&sb, "q part (c | A, b), applied to dH/dp:", c, A, b, s);
        if (t->has_At) {
            vigen_strbuf_append(&sb, "\n");
            text_array(&sb, "p part (ct | At, bt), applied to -dH/dq:", ct, At, bp, s);
        }
        text_summary(&sb, t);
    }
    free_strings(c, s); free_strings(A, s * s); free_strings(b, s);
    free_strings(ct, s); free_strings(At, s * s); free_strings(bt, s);
    *out = sb.data;
    return VIGEN_OK;
}
