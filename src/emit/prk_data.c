/* prk_data.c — the PRK variant's slot builder, first half: the texts of the
 * stepper (names, types, the header and coefficient comments) and the
 * correctly rounded coefficients, structure and extrapolation weights it is
 * written from.  prk_code.c turns these into the C lines of the blocks. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "emit/batch.h"
#include "emit/names.h"
#include "emit/prk.h"
#include "support/strbuf.h"

#ifndef VIGEN_VERSION
#define VIGEN_VERSION "unknown"
#endif

static char **strv(slong n)
{
    char **v = calloc((size_t)(n > 0 ? n : 1), sizeof *v);
    if (v == NULL) abort();
    return v;
}

static void strv_free(char **v, slong n)
{
    if (v == NULL) return;
    for (slong k = 0; k < n; k++) free(v[k]);
    free(v);
}

void vigen_emit_prk_clear(prk_coefs *K)
{
    slong s = K->s;
    strv_free(K->c, s);
    strv_free(K->b, s);
    strv_free(K->bt, s);
    strv_free(K->a, s * s);
    strv_free(K->at, s * s);
    strv_free(K->inv, s * s);
    vigen_emit_explicit_clear(&K->X);
    vigen_emit_nys_clear(&K->Y, s);
    vigen_emit_sub_clear(&K->U);
    memset(K, 0, sizeof *K);
}

/* The literals of a vector part (NULL for an exact zero, or "0" when
 * zero_text). */
static int round_vec(char **out, emit_ctx *E, arb_srcptr v, int part, int zero_text)
{
    for (slong i = 0; i < E->s; i++) {
        int rc = vigen_emit_literal(out + i, E, v + i, vigen_emit_entry_ref(E, part, i, 0), NULL);
        if (rc != VIGEN_OK) return rc;
        if (out[i] == NULL && zero_text) out[i] = vigen_strdup("0");
    }
    return VIGEN_OK;
}

static int round_mat(char **out, emit_ctx *E, const arb_mat_t m, int part)
{
    for (slong i = 0; i < E->s; i++)
        for (slong j = 0; j < E->s; j++) {
            int rc = vigen_emit_literal(out + i * E->s + j, E, arb_mat_entry(m, i, j),
                                        vigen_emit_entry_ref(E, part, i, j), NULL);
            if (rc != VIGEN_OK) return rc;
        }
    return VIGEN_OK;
}

/* The order of the roundings is the order of the messages: c, b, bt, A, At,
 * the extrapolation weights, the explicit structure, the Nystrom
 * coefficients, then the substeps. */
int vigen_emit_prk_round(prk_coefs *K, emit_ctx *E)
{
    slong s = E->s;
    memset(K, 0, sizeof *K);
    K->s = s;
    K->c = strv(s);
    K->b = strv(s);
    K->bt = strv(s);
    K->a = strv(s * s);
    K->at = strv(s * s);
    K->inv = strv(s * s);
    int rc = round_vec(K->c, E, E->c, PART_C, 1);
    if (rc == VIGEN_OK) rc = round_vec(K->b, E, E->b, PART_B, 0);
    if (rc == VIGEN_OK) rc = round_vec(K->bt, E, E->bt, PART_BT, 0);
    if (rc == VIGEN_OK) rc = round_mat(K->a, E, E->A, PART_A);
    if (rc == VIGEN_OK) rc = round_mat(K->at, E, E->At, PART_AT);
    if (rc != VIGEN_OK) return rc;

    /* extrapolation: Lagrange through distinct nodes c */
    int distinct = s >= 2;
    for (slong i = 0; i < s && distinct; i++)
        for (slong j = 0; j < i && distinct; j++)
            if (arb_overlaps(E->c + i, E->c + j)) distinct = 0;
    K->lagrange = distinct;
    if (distinct) {
        arb_t d;
        arb_init(d);
        for (slong j = 0; j < s && rc == VIGEN_OK; j++)
            for (slong m = 0; m < s && rc == VIGEN_OK; m++) {
                if (m == j) continue;
                arb_sub(d, E->c + j, E->c + m, E->prec);
                arb_inv(d, d, E->prec);
                rc = vigen_emit_literal(K->inv + j * s + m, E, d, -1, "1/(c_j - c_m)");
            }
        arb_clear(d);
    }
    if (rc == VIGEN_OK) rc = vigen_emit_plan(&K->X, E);
    if (rc == VIGEN_OK) rc = vigen_emit_nys_round(&K->Y, E);
    /* the substeps, when the step is explicit for separable H (and so for
     * a mechanical problem); their force buffers are work arrays 0 and 1 */
    if (rc == VIGEN_OK && K->X.mode != EMIT_EXPLICIT_NONE) rc = vigen_emit_sub_round(&K->U, E);
    if (rc == VIGEN_OK && K->U.m > 0 && K->X.nx < (K->U.fsal ? 2 : 1)) vigen_emit_sub_clear(&K->U);
    return rc;
}

/* The texts of the stepper: names, types, the header comment and the
 * coefficients as the file gives them. */
void vigen_emit_prk_texts(vigen_slots *S, emit_ctx *E, const vigen_emit_options *opt, const char *ident)
{
    const vigen_emit_real_type *R = &vigen_emit_reals[opt->real];
    const vigen_tableau *t = E->t;
    slong s = E->s;
    char *uname = vigen_strdup(ident);
    for (char *c = uname; *c; c++)
        if (*c >= 'a' && *c <= 'z') *c = (char)(*c - 'a' + 'A');
    char *tname = vigen_emit_safe_name(t->name ? t->name : "unnamed");
    vigen_slots_text(S, "NAME", ident);
    vigen_slots_text(S, "UNAME", uname);
    vigen_slots_text(S, "REAL", R->ctype);
    vigen_slots_text(S, "SFX", R->suffix);
    vigen_slots_textf(S, "HAM", "vigen_hamiltonian%s", R->suffix);
    vigen_slots_textf(S, "STEPPER_TYPE", "vigen_stepper_type%s", R->suffix);
    vigen_slots_flag(S, "DOUBLE", opt->real == VIGEN_REAL_DOUBLE);
    vigen_slots_flag(S, "LONG_DOUBLE", opt->real == VIGEN_REAL_LONG_DOUBLE);
    vigen_slots_flag(S, "FLOAT128", opt->real == VIGEN_REAL_FLOAT128);
    vigen_slots_text(S, "TABLEAU_NAME", tname);
    vigen_slots_textf(S, "STAGES", "%ld", (long)s);
    /* the order the checker certifies, not merely what the file claims */
    const int order = vigen_emit_certified_order(t);
    vigen_slots_textf(S, "ORDER", "%d", order);
    /* what the coefficient comments may promise */
    if (E->inexact_done)
        vigen_slots_textf(S, "COEF_HEAD",
                          "rounded to %s from the decimals as written (--allow-inexact: some entries have too few "
                          "digits to round correctly, so the coefficients are only as good as those decimals)",
                          R->ctype);
    else
        vigen_slots_textf(S, "COEF_HEAD", "correctly rounded to %s", R->ctype);

    vigen_slot *H = vigen_slots_lines(S, "HEADER");
    char *inp = vigen_emit_safe_text(opt->input_label ? opt->input_label : "-", 200);
    char dim[40] = "";
    if (opt->dim > 0) snprintf(dim, sizeof dim, " --dim %zu", opt->dim);
    if (opt->batch) strcat(dim, " --batch");
    vigen_slot_line(H, "Generated by vigen %s: vigen emit %s --name %s --real %s%s%s%s%s", VIGEN_VERSION, inp, ident,
                    R->name, E->variant ? " --variant " : "", E->variant ? E->variant : "", dim,
                    E->inexact_done ? " --allow-inexact" : "");
    if (t->generated_now)
        vigen_slot_line(H, "Tableau generated from the spec %s with %ld certified digits (as by vigen generate %s "
                        "--digits %ld)", inp, (long)t->digits, inp, (long)t->digits);
    free(inp);
    vigen_slot_line(H, "Tableau digest (FNV-1a 64 of the canonical text): %016llx", vigen_emit_digest(t));
    if (order >= 0)
        vigen_slot_line(H, "Stages: %ld; certified order: %d%s", (long)s, order,
                        t->claim_symplectic == 1 ? "; claimed symplectic" : "");
    else
        vigen_slot_line(H, "Stages: %ld; certified order: not decided%s", (long)s,
                        t->claim_symplectic == 1 ? "; claimed symplectic" : "");
    vigen_emit_header_about(H, t);

    vigen_slot *C = vigen_slots_lines(S, "COEF_LINES");
    struct { const char *label; char **texts; slong n; int matrix; } parts[] = {
        { "c", t->c_text, s, 0 }, { "A", t->A_text, s * s, 1 }, { "b", t->b_text, s, 0 },
        { "At", E->At_text, s * s, 1 }, { "bt", E->bt_text, s, 0 },
    };
    for (size_t k = 0; k < sizeof parts / sizeof parts[0]; k++) {
        if ((k == 3 && !t->has_At) || (k == 4 && !t->has_bt)) continue;
        for (slong e = 0; e < parts[k].n; e++) {
            if (strcmp(parts[k].texts[e], "0") == 0) continue;
            char *d = vigen_emit_safe_text(parts[k].texts[e], 200);
            if (parts[k].matrix)
                vigen_slot_line(C, "%s[%ld][%ld] = %s", parts[k].label, (long)(e / s + 1), (long)(e % s + 1), d);
            else
                vigen_slot_line(C, "%s[%ld] = %s", parts[k].label, (long)(e + 1), d);
            free(d);
        }
    }
    if (!t->has_At) vigen_slot_line(C, "At = A, bt = b (a Runge-Kutta method)");
    else if (!t->has_bt) vigen_slot_line(C, "bt = b");
    free(uname);
    free(tname);
}

int vigen_emit_prk_slots(vigen_slots *S, emit_ctx *E, const vigen_emit_options *opt, const char *ident)
{
    prk_coefs K;
    int rc = vigen_emit_prk_round(&K, E);
    if (rc == VIGEN_OK) {
        vigen_emit_prk_texts(S, E, opt, ident);
        vigen_emit_prk_code(S, &K, ident, opt->real);
        vigen_emit_nys_code(S, &K, ident, opt->real);
        vigen_emit_sub_code(S, &K, ident, opt->real);
        vigen_slots_flag(S, "STATIC_DIM", opt->dim > 0);
        vigen_slots_textf(S, "DIM", "%zu", opt->dim);
        if (opt->batch) {
            vigen_emit_nys_batch_code(S, &K, ident);
            vigen_emit_batch_code(S, &K, ident);
        }
    }
    vigen_emit_prk_clear(&K);
    return rc;
}
