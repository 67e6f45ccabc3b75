/* tableau.c — the tableau record: its balls evaluated from the entry texts,
 * the texts certified from the balls, the tableau file written out (read by
 * method/tableau_file.c) and the symplecticity residual. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "core/decimal.h"
#include "core/expr.h"
#include "lua/quote.h"
#include "support/printable.h"
#include "vigen/tableau.h"
#include "vigen/limits.h"
#include "support/strbuf.h"

static char **texts_new(slong n)
{
    /* n is a stage count or its square (at most VIGEN_MAX_STAGES^2), never negative */
    char **t = calloc(n > 0 ? (size_t)n : 1, sizeof(char *));
    if (t == NULL) abort();
    return t;
}

static void texts_free(char **t, slong n)
{
    if (t == NULL) return;
    for (slong i = 0; i < n; i++) free(t[i]);
    free(t);
}

void vigen_tableau_init(vigen_tableau *t, slong s)
{
    memset(t, 0, sizeof(*t));
    t->s = s;
    t->c = _arb_vec_init(s);
    t->b = _arb_vec_init(s);
    t->ct = _arb_vec_init(s);
    t->bt = _arb_vec_init(s);
    arb_mat_init(t->A, s, s);
    arb_mat_init(t->At, s, s);
    t->claim_order = -1;
    t->claim_symplectic = -1;
    t->claim_order_sep = -1;
    t->claim_order_nys = -1;
}

void vigen_tableau_clear(vigen_tableau *t)
{
    slong s = t->s;
    free(t->name);
    texts_free(t->c_text, s);
    texts_free(t->b_text, s);
    texts_free(t->ct_text, s);
    texts_free(t->bt_text, s);
    texts_free(t->A_text, s * s);
    texts_free(t->At_text, s * s);
    _arb_vec_clear(t->c, s);
    _arb_vec_clear(t->b, s);
    _arb_vec_clear(t->ct, s);
    _arb_vec_clear(t->bt, s);
    arb_mat_clear(t->A);
    arb_mat_clear(t->At);
    free(t->description);
    free(t->source);
    free(t->basis);
    free(t->nodes);
    free(t->generator);
    texts_free(t->substep_coef, t->nsubsteps);
    free(t->substep_drift);
    vigen_tableau_set_flows(t, NULL);
    memset(t, 0, sizeof(*t));
}

static char **texts_copy(char *const *src, slong n)
{
    if (src == NULL) return NULL;
    char **t = texts_new(n);
    for (slong i = 0; i < n; i++) t[i] = src[i] ? vigen_strdup(src[i]) : NULL;
    return t;
}

static char *strdup_or_null(const char *s) { return s ? vigen_strdup(s) : NULL; }

void vigen_tableau_set_substeps(vigen_tableau *t, slong n, const int *drift, char *const *coef)
{
    texts_free(t->substep_coef, t->nsubsteps);
    free(t->substep_drift);
    t->nsubsteps = 0;
    t->substep_drift = NULL;
    t->substep_coef = NULL;
    if (n <= 0 || drift == NULL || coef == NULL) return;
    t->substep_drift = malloc(sizeof(int) * (size_t)n);
    if (t->substep_drift == NULL) abort();
    memcpy(t->substep_drift, drift, sizeof(int) * (size_t)n);
    t->substep_coef = texts_copy(coef, n);
    t->nsubsteps = n;
}

static void *bytes_copy(const void *src, size_t n)
{
    if (src == NULL) return NULL;
    void *d = malloc(n ? n : 1);
    if (d == NULL) abort();
    memcpy(d, src, n);
    return d;
}

void vigen_tableau_set_flows(vigen_tableau *t, const vigen_flows *fl)
{
    vigen_flows *old = t->flows;
    if (old) {
        texts_free(old->names, old->nflows);
        for (slong k = 0; k < old->nflows && old->bracket; k++) free(old->bracket[k]);
        free(old->bracket);
        free(old->degree);
        free(old->step_flow);
        texts_free(old->step_coef, old->nstep);
    }
    free(old);
    t->flows = NULL;
    if (fl == NULL) return;
    vigen_flows *c = malloc(sizeof *c);
    if (c == NULL) abort();
    *c = *fl;
    c->names = texts_copy(fl->names, fl->nflows);
    c->degree = bytes_copy(fl->degree, sizeof(int) * (size_t)fl->nflows);
    c->bracket = NULL;
    if (fl->bracket) {
        c->bracket = calloc((size_t)fl->nflows, sizeof *c->bracket);
        if (c->bracket == NULL) abort();
        for (slong k = 0; k < fl->nflows; k++)
            if (fl->bracket[k]) c->bracket[k] = bytes_copy(fl->bracket[k], sizeof(int) * (size_t)fl->degree[k]);
    }
    c->step_flow = bytes_copy(fl->step_flow, sizeof(int) * (size_t)fl->nstep);
    c->step_coef = texts_copy(fl->step_coef, fl->nstep);
    t->flows = c;
}

void vigen_tableau_copy(vigen_tableau *dst, const vigen_tableau *src)
{
    slong s = src->s;
    vigen_tableau_init(dst, s);
    dst->name = strdup_or_null(src->name);
    dst->has_At = src->has_At;
    dst->has_ct = src->has_ct;
    dst->has_bt = src->has_bt;
    dst->c_text = texts_copy(src->c_text, s);
    dst->b_text = texts_copy(src->b_text, s);
    dst->ct_text = texts_copy(src->ct_text, s);
    dst->bt_text = texts_copy(src->bt_text, s);
    dst->A_text = texts_copy(src->A_text, s * s);
    dst->At_text = texts_copy(src->At_text, s * s);
    dst->prec = src->prec;
    _arb_vec_set(dst->c, src->c, s);
    _arb_vec_set(dst->b, src->b, s);
    _arb_vec_set(dst->ct, src->ct, s);
    _arb_vec_set(dst->bt, src->bt, s);
    arb_mat_set(dst->A, src->A);
    arb_mat_set(dst->At, src->At);
    dst->digits = src->digits;
    dst->description = strdup_or_null(src->description);
    dst->source = strdup_or_null(src->source);
    dst->basis = strdup_or_null(src->basis);
    dst->nodes = strdup_or_null(src->nodes);
    dst->generator = strdup_or_null(src->generator);
    dst->claim_order = src->claim_order;
    dst->claim_symplectic = src->claim_symplectic;
    dst->claim_order_sep = src->claim_order_sep;
    dst->claim_order_nys = src->claim_order_nys;
    dst->generated_now = src->generated_now;
    vigen_tableau_set_substeps(dst, src->nsubsteps, src->substep_drift, src->substep_coef);
    vigen_tableau_set_flows(dst, src->flows);
}

int vigen_tableau_entry_eval(arb_t res, const char *text, slong prec, vigen_error *err)
{
    if (vigen_decimal_parse_rounded(res, text, prec)) return VIGEN_OK;
    vigen_expr *e = NULL;
    int rc = vigen_expr_parse(&e, text, 0, err);
    if (rc != VIGEN_OK) {
        arb_indeterminate(res);
        return rc;
    }
    vigen_expr_round_decimals(e);
    rc = vigen_expr_eval_arb(res, e, NULL, prec, err);
    vigen_expr_free(e);
    return rc;
}

int vigen_tableau_entry_is_rounded(const char *text)
{
    if (text == NULL) return 0;
    if (vigen_decimal_is_rounded(text)) return 1;
    vigen_expr *e = NULL;
    vigen_error err;
    vigen_error_init(&err);
    int rounded = vigen_expr_parse(&e, text, 0, &err) == VIGEN_OK && vigen_expr_decimal_count(e) > 0;
    vigen_expr_free(e);
    vigen_error_clear(&err);
    return rounded;
}

static int eval_texts(arb_ptr out, char **texts, slong n, slong prec, const char *key, vigen_error *err)
{
    for (slong k = 0; k < n; k++) {
        int rc = vigen_tableau_entry_eval(out + k, texts[k], prec, err);
        if (rc != VIGEN_OK) return vigen_error_prefix(err, "%s[%ld]: ", key, (long)(k + 1));
        if (!arb_is_finite(out + k))
            return vigen_error_set(err, VIGEN_E_DOMAIN, "%s[%ld] is not finite", key, (long)(k + 1));
    }
    return VIGEN_OK;
}

static int eval_matrix(arb_mat_t out, char **texts, slong prec, const char *key, slong s, vigen_error *err)
{
    for (slong i = 0; i < s; i++)
        for (slong j = 0; j < s; j++) {
            arb_ptr x = arb_mat_entry(out, i, j);
            int rc = vigen_tableau_entry_eval(x, texts[i * s + j], prec, err);
            if (rc != VIGEN_OK) return vigen_error_prefix(err, "%s[%ld][%ld]: ", key, (long)(i + 1), (long)(j + 1));
            if (!arb_is_finite(x))
                return vigen_error_set(err, VIGEN_E_DOMAIN, "%s[%ld][%ld] is not finite", key, (long)(i + 1), (long)(j + 1));
        }
    return VIGEN_OK;
}

int vigen_tableau_evaluate(vigen_tableau *t, slong prec, vigen_error *err)
{
    /* every evaluation of entries goes through here: show's refinement too */
    if (vigen_prec_limit_check(prec, "evaluating the entries asks for", err)) return VIGEN_E_LIMIT;
    slong s = t->s;
    int rc = eval_texts(t->c, t->c_text, s, prec, "c", err);
    if (rc == VIGEN_OK) rc = eval_texts(t->b, t->b_text, s, prec, "b", err);
    if (rc == VIGEN_OK) rc = eval_matrix(t->A, t->A_text, prec, "A", s, err);
    if (rc == VIGEN_OK && t->has_At) rc = eval_matrix(t->At, t->At_text, prec, "At", s, err);
    if (rc == VIGEN_OK && t->has_ct) rc = eval_texts(t->ct, t->ct_text, s, prec, "ct", err);
    if (rc == VIGEN_OK && t->has_bt) rc = eval_texts(t->bt, t->bt_text, s, prec, "bt", err);
    if (rc != VIGEN_OK) return rc;
    if (!t->has_bt) _arb_vec_set(t->bt, t->b, s);
    if (t->has_At && !t->has_ct)
        /* ct not given: the natural one, ct_i = sum_j at_ij (has_ct stays 0) */
        for (slong i = 0; i < s; i++) {
            arb_zero(t->ct + i);
            for (slong j = 0; j < s; j++) arb_add(t->ct + i, t->ct + i, arb_mat_entry(t->At, i, j), prec);
        }
    t->prec = prec;
    return VIGEN_OK;
}

/* ---------------------------------------------------------------- writing */

/* True when the ball is far narrower than `digits` digits need: if those
 * digits still cannot be certified, the value sits (within the radius) on a
 * rounding tie, which no precision can decide. */
static int tight_for(const arb_t x, slong digits)
{
    if (arb_contains_zero(x) || arb_is_exact(x)) return 0;
    arb_t q;
    arb_init(q);
    arb_get_rad_arb(q, x);
    arb_div_arf(q, q, arb_midref(x), 64);
    arb_abs(q, q);
    arb_t lim;
    arb_init(lim);
    arb_set_si(lim, 10);
    arb_pow_ui(lim, lim, (ulong)(digits + 8), 64);
    arb_mul(q, q, lim, 64);
    int tight = arf_cmpabs_2exp_si(arb_midref(q), 0) < 0;
    arb_clear(q);
    arb_clear(lim);
    return tight;
}

static int format_entry(char **out, const arb_t x, slong digits)
{
    /* an exact integer (the node 1 of Lobatto or equispaced nodes, an exact 0)
     * is written as one, an exact literal, not as the rounded "1.000..." */
    char *text = vigen_decimal_format_integer(x);
    if (text == NULL) text = vigen_decimal_format(x, digits);
    /* A value on a tie (9/40 = 0.225 at 2 digits) has two correct roundings
     * and a ball around it never picks one: write it with the fewest extra
     * digits that are certified (0.225), which is still a correct rounding. */
    for (slong extra = 1; text == NULL && extra <= 20 && tight_for(x, digits); extra++)
        text = vigen_decimal_format(x, digits + extra);
    if (text == NULL && arb_contains_zero(x)) {
        /* a ball around zero: certify |x| <= 10^-digits / 2, written "0e-digits" */
        char *z = vigen_decimal_format_zero(x);
        if (z != NULL) {
            long K = 0;
            if (strcmp(z, "0") == 0) text = z;
            else if (sscanf(z, "0e%ld", &K) == 1 && K <= -digits) {
                free(z);
                text = vigen_strdup_printf("0e-%ld", (long)digits);
            } else free(z);
        }
    }
    if (text == NULL) return VIGEN_E_PRECISION;
    free(*out);
    *out = text;
    return VIGEN_OK;
}

/* 1 when |x| is certainly outside what a decimal can carry (exponents of
 * at most VIGEN_DECIMAL_EXP_MAX, about 2^332192810): no precision would make
 * it writable, so refining is pointless. */
static int beyond_decimal_range(const arb_t x)
{
    const slong bits = 332192810; /* ceil(VIGEN_DECIMAL_EXP_MAX * log2(10)) */
    if (arb_contains_zero(x)) return 0;
    mag_t lo, hi;
    mag_init(lo);
    mag_init(hi);
    arb_get_mag_lower(lo, x);
    arb_get_mag(hi, x);
    int beyond = mag_cmp_2exp_si(lo, bits) > 0 || mag_cmp_2exp_si(hi, -bits) < 0;
    mag_clear(lo);
    mag_clear(hi);
    return beyond;
}

/* Formats one named entry; on failure says which entry and why. */
static int format_named(char **out, const arb_t x, slong digits, slong prec, const char *label, vigen_error *err)
{
    if (format_entry(out, x, digits) == VIGEN_OK) return VIGEN_OK;
    if (beyond_decimal_range(x)) {
        char *v = arb_get_str(x, 5, 0);
        int code = vigen_error_set(err, VIGEN_E_DOMAIN,
                                   "%s = %s is beyond the decimals vigen writes and reads (exponents up to "
                                   "10^8 in magnitude): the spec gives no usable method; check its basis and nodes",
                                   label, v);
        flint_free(v);
        return code;
    }
    char *v = arb_get_str(x, digits + 20, 0);
    if (!tight_for(x, digits)) {
        int code = vigen_error_set(err, VIGEN_E_PRECISION, "%s = %s is not certified to %ld digits at %ld bits",
                                   label, v, (long)digits, (long)prec);
        flint_free(v);
        return code;
    }
    int code = vigen_error_set(err, VIGEN_E_PRECISION,
                               "%s = %s cannot be rounded to %ld certified digits at %ld bits (if the exact value "
                               "lies halfway between two %ld-digit decimals, no precision decides it: ask for "
                               "--digits %ld)", label, v, (long)digits, (long)prec, (long)digits, (long)(digits + 1));
    flint_free(v);
    return code;
}

static int format_vector(char ***texts, arb_srcptr v, slong n, slong digits, slong prec, const char *key,
                         vigen_error *err)
{
    if (*texts == NULL) *texts = texts_new(n);
    for (slong k = 0; k < n; k++) {
        char label[64];
        snprintf(label, sizeof label, "%s[%ld]", key, (long)(k + 1));
        int rc = format_named(&(*texts)[k], v + k, digits, prec, label, err);
        if (rc != VIGEN_OK) return rc;
    }
    return VIGEN_OK;
}

static int format_matrix(char ***texts, const arb_mat_t m, slong s, slong digits, slong prec, const char *key,
                         vigen_error *err)
{
    if (*texts == NULL) *texts = texts_new(s * s);
    for (slong i = 0; i < s; i++)
        for (slong j = 0; j < s; j++) {
            char label[64];
            snprintf(label, sizeof label, "%s[%ld][%ld]", key, (long)(i + 1), (long)(j + 1));
            int rc = format_named(&(*texts)[i * s + j], arb_mat_entry(m, i, j), digits, prec, label, err);
            if (rc != VIGEN_OK) return rc;
        }
    return VIGEN_OK;
}

int vigen_tableau_texts_from_balls(vigen_tableau *t, slong digits, vigen_error *err)
{
    slong s = t->s, p = t->prec;
    int rc = format_vector(&t->c_text, t->c, s, digits, p, "c", err);
    if (rc == VIGEN_OK) rc = format_vector(&t->b_text, t->b, s, digits, p, "b", err);
    if (rc == VIGEN_OK) rc = format_matrix(&t->A_text, t->A, s, digits, p, "A", err);
    if (rc == VIGEN_OK && t->has_At) rc = format_matrix(&t->At_text, t->At, s, digits, p, "At", err);
    if (rc == VIGEN_OK && t->has_ct) rc = format_vector(&t->ct_text, t->ct, s, digits, p, "ct", err);
    if (rc == VIGEN_OK && t->has_bt) rc = format_vector(&t->bt_text, t->bt, s, digits, p, "bt", err);
    if (rc != VIGEN_OK) return rc;
    t->digits = digits;
    return VIGEN_OK;
}

static void append_vector(vigen_strbuf *sb, const char *key, char **texts, slong s)
{
    vigen_strbuf_printf(sb, "  %s = {", key);
    for (slong i = 0; i < s; i++) {
        vigen_strbuf_append(sb, i ? ", " : " ");
        vigen_lua_quote(sb, texts[i]);
    }
    vigen_strbuf_append(sb, " },\n");
}

static void append_matrix(vigen_strbuf *sb, const char *key, char **texts, slong s)
{
    vigen_strbuf_printf(sb, "  %s = {\n", key);
    for (slong i = 0; i < s; i++) {
        vigen_strbuf_append(sb, "    {");
        for (slong j = 0; j < s; j++) {
            vigen_strbuf_append(sb, j ? ", " : " ");
            vigen_lua_quote(sb, texts[i * s + j]);
        }
        vigen_strbuf_append(sb, " },\n");
    }
    vigen_strbuf_append(sb, "  },\n");
}

static void append_string_field(vigen_strbuf *sb, const char *key, const char *value)
{
    if (value == NULL) return;
    vigen_strbuf_printf(sb, "  %s = ", key);
    vigen_lua_quote(sb, value);
    vigen_strbuf_append(sb, ",\n");
}

char *vigen_tableau_to_lua(const vigen_tableau *t)
{
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    if (t->generator != NULL) {
        /* the field may come from a file: escaped, it cannot end the comment */
        char *generator = vigen_printable(t->generator);
        vigen_strbuf_printf(&sb, "-- Generated by %s; do not edit: regenerate with `vigen generate`.\n", generator);
        free(generator);
        vigen_strbuf_printf(&sb, "-- Every decimal entry is the correct rounding of the exact coefficient to %ld\n"
                                 "-- significant digits (more for a value on a rounding tie); an integer (\"0\",\n"
                                 "-- \"1\") is exact and \"0e-%ld\" a certified |x| <= 0.5e-%ld.\n",
                            (long)t->digits, (long)t->digits, (long)t->digits);
    }
    vigen_strbuf_append(&sb, "return {\n");
    append_string_field(&sb, "name", t->name);
    append_string_field(&sb, "description", t->description);
    append_string_field(&sb, "source", t->source);
    append_string_field(&sb, "basis", t->basis);
    append_string_field(&sb, "nodes", t->nodes);
    append_string_field(&sb, "generator", t->generator);
    if (t->digits > 0) vigen_strbuf_printf(&sb, "  digits = %ld,\n", (long)t->digits);
    if (t->claim_order >= 0) vigen_strbuf_printf(&sb, "  order = %d,\n", t->claim_order);
    if (t->claim_symplectic >= 0)
        vigen_strbuf_printf(&sb, "  symplectic = %s,\n", t->claim_symplectic ? "true" : "false");
    if (t->claim_order_sep >= 0) vigen_strbuf_printf(&sb, "  order_separable = %d,\n", t->claim_order_sep);
    if (t->claim_order_nys >= 0) vigen_strbuf_printf(&sb, "  order_nystrom = %d,\n", t->claim_order_nys);
    vigen_strbuf_printf(&sb, "  s = %ld,\n", (long)t->s);
    append_vector(&sb, "c", t->c_text, t->s);
    append_matrix(&sb, "A", t->A_text, t->s);
    append_vector(&sb, "b", t->b_text, t->s);
    if (t->has_At) append_matrix(&sb, "At", t->At_text, t->s);
    if (t->has_ct) append_vector(&sb, "ct", t->ct_text, t->s);
    if (t->has_bt) append_vector(&sb, "bt", t->bt_text, t->s);
    vigen_strbuf_append(&sb, "}\n");
    return sb.data;
}

void vigen_tableau_symplectic_residual(arb_t res, const vigen_tableau *t, slong prec)
{
    slong s = t->s;
    arb_t r, u;
    arb_init(r);
    arb_init(u);
    arb_zero(res);
    for (slong i = 0; i < s; i++)
        for (slong j = 0; j < s; j++) {
            arb_mul(r, t->b + i, arb_mat_entry(t->At, i, j), prec);
            arb_addmul(r, t->b + j, arb_mat_entry(t->A, j, i), prec);
            arb_mul(u, t->b + i, t->b + j, prec);
            arb_sub(r, r, u, prec);
            arb_abs(r, r);
            arb_max(res, res, r, prec);
        }
    /* bt must equal b as well */
    for (slong i = 0; i < s; i++) {
        arb_sub(r, t->bt + i, t->b + i, prec);
        arb_abs(r, r);
        arb_max(res, res, r, prec);
    }
    arb_clear(r);
    arb_clear(u);
}
