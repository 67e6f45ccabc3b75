/* literals.c — correct rounding of the tableau's entries to the target
 * type as exact C hex-float literals, the evaluation of the entries at the
 * working precision, and the messages about entries that cannot be rounded:
 * the refusal (with what to do) and the warnings of the last pass. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "emit/literals.h"
#include "emit/names.h"
#include "support/strbuf.h"



slong vigen_emit_n_entries(slong s) { return 3 * s + 2 * s * s; }

slong vigen_emit_entry_ref(const emit_ctx *E, int part, slong i, slong j)
{
    slong s = E->s;
    if (part == PART_AT && !E->t->has_At) part = PART_A;
    if (part == PART_BT && !E->t->has_bt) part = PART_B;
    switch (part) {
    case PART_C: return i;
    case PART_A: return s + i * s + j;
    case PART_B: return s + s * s + i;
    case PART_AT: return 2 * s + s * s + i * s + j;
    default: return 2 * s + 2 * s * s + i;
    }
}

void vigen_emit_entry_describe(const emit_ctx *E, slong ref, char *label, size_t n, const char **text, arb_srcptr *value)
{
    const vigen_tableau *t = E->t;
    slong s = E->s;
    const char *name;
    const char *tx;
    arb_srcptr v;
    slong i, j = -1;
    if (ref < s) { name = "c"; i = ref; tx = t->c_text[i]; v = E->c + i; }
    else if (ref < s + s * s) { name = "A"; i = (ref - s) / s; j = (ref - s) % s; tx = t->A_text[i * s + j]; v = arb_mat_entry(E->A, i, j); }
    else if (ref < 2 * s + s * s) { name = "b"; i = ref - s - s * s; tx = t->b_text[i]; v = E->b + i; }
    else if (ref < 2 * s + 2 * s * s) {
        name = "At"; i = (ref - 2 * s - s * s) / s; j = (ref - 2 * s - s * s) % s;
        tx = E->At_text[i * s + j]; v = arb_mat_entry(E->At, i, j);
    } else { name = "bt"; i = ref - 2 * s - 2 * s * s; tx = E->bt_text[i]; v = E->bt + i; }
    if (j >= 0) snprintf(label, n, "%s[%ld][%ld]", name, (long)(i + 1), (long)(j + 1));
    else snprintf(label, n, "%s[%ld]", name, (long)(i + 1));
    if (text) *text = tx;
    if (value) *value = v;
}

int vigen_emit_tiny_zero(const emit_ctx *E, const arb_t x)
{
    if (arb_is_zero(x)) return 1;
    if (!arb_contains_zero(x)) return 0;
    return mag_cmp_2exp_si(arb_radref(x), -(E->bits + 20)) < 0;
}

/* Records why x cannot be rounded (the message is rewritten with advice by
 * vigen_emit_precision_message once more precision has not helped). */
static int refuse(emit_ctx *E, int kind, slong ref, const char *label)
{
    E->fail_kind = kind;
    E->fail_ref = ref;
    snprintf(E->fail_label, sizeof E->fail_label, "%s", label);
    return vigen_error_set(E->err, VIGEN_E_PRECISION, "%s: %s", label,
                           kind == 1 ? "the value is not known well enough to round it correctly"
                                     : "the ball contains zero; it cannot be rounded to the target type");
}

int vigen_emit_literal(char **out, emit_ctx *E, const arb_t x, slong ref, const char *label)
{
    *out = NULL;
    char lab[64];
    if (ref >= 0) vigen_emit_entry_describe(E, ref, lab, sizeof lab, NULL, NULL);
    else snprintf(lab, sizeof lab, "%s", label);
    if (arb_is_zero(x)) return VIGEN_OK;
    if (arb_contains_zero(x)) {
        if (vigen_emit_tiny_zero(E, x)) {
            if (ref >= 0) E->marks[ref] |= MARK_ZERO;
            else
                vigen_warn("%s is only known to lie within %.3g of zero; emitted as an exact 0", lab,
                           mag_get_d(arb_radref(x)));
            return VIGEN_OK;
        }
        return refuse(E, 2, ref, lab);
    }
    arf_t lo, hi;
    arf_init(lo);
    arf_init(hi);
    arb_get_lbound_arf(lo, x, E->prec + 64);
    arb_get_ubound_arf(hi, x, E->prec + 64);
    arf_set_round(lo, lo, E->bits, ARF_RND_NEAR);
    arf_set_round(hi, hi, E->bits, ARF_RND_NEAR);
    int rc = VIGEN_OK;
    if (!arf_equal(lo, hi) && E->allow_inexact && E->inexact_done) {
        arf_set_round(lo, arb_midref(x), E->bits, ARF_RND_NEAR);
        arf_set(hi, lo);
        if (ref >= 0) E->marks[ref] |= MARK_INEXACT;
        else E->inexact_derived++;
    }
    if (!arf_equal(lo, hi)) {
        rc = refuse(E, 1, ref, lab);
    } else if (arf_cmpabs_2exp_si(lo, -1000) < 0 || arf_cmpabs_2exp_si(lo, 1000) > 0) {
        rc = vigen_error_set(E->err, VIGEN_E_DOMAIN, "%s: magnitude outside [2^-1000, 2^1000]", lab);
    } else {
        fmpz_t m, e, fr;
        fmpz_init(m);
        fmpz_init(e);
        fmpz_init(fr);
        arf_get_fmpz_2exp(m, e, lo);
        int neg = fmpz_sgn(m) < 0;
        fmpz_abs(m, m);
        slong k = (slong)fmpz_bits(m);
        slong ex = fmpz_get_si(e) + k - 1;
        slong f = k - 1, pad = (4 - f % 4) % 4;
        vigen_strbuf sb;
        vigen_strbuf_init(&sb);
        vigen_strbuf_append(&sb, "");
        if (f == 0) {
            vigen_strbuf_printf(&sb, "0x1p%+ld", (long)ex);
        } else {
            fmpz_set(fr, m);
            fmpz_clrbit(fr, (ulong)(k - 1));
            fmpz_mul_2exp(fr, fr, (ulong)pad);
            char *hex = fmpz_get_str(NULL, 16, fr);
            slong nd = (f + pad) / 4, len = (slong)strlen(hex);
            vigen_strbuf_append(&sb, "0x1.");
            for (slong z = len; z < nd; z++) vigen_strbuf_append(&sb, "0");
            vigen_strbuf_append(&sb, hex);
            vigen_strbuf_printf(&sb, "p%+ld", (long)ex);
            flint_free(hex);
        }
        const char *mag = sb.data;
        if (E->real == VIGEN_REAL_DOUBLE) *out = neg ? vigen_strdup_printf("(-%s)", mag) : vigen_strdup(mag);
        else if (E->real == VIGEN_REAL_LONG_DOUBLE)
            *out = neg ? vigen_strdup_printf("(-%sL)", mag) : vigen_strdup_printf("%sL", mag);
        else
            *out = neg ? vigen_strdup_printf("(-(__extension__ %sQ))", mag) : vigen_strdup_printf("(__extension__ %sQ)", mag);
        vigen_strbuf_clear(&sb);
        fmpz_clear(m);
        fmpz_clear(e);
        fmpz_clear(fr);
    }
    arf_clear(lo);
    arf_clear(hi);
    return rc;
}


int vigen_emit_evaluate(emit_ctx *E, vigen_error *err)
{
    const vigen_tableau *t = E->t;
    slong s = E->s;
    for (slong i = 0; i < s; i++) {
        int rc = vigen_tableau_entry_eval(E->c + i, t->c_text[i], E->prec, err);
        if (rc == VIGEN_OK) rc = vigen_tableau_entry_eval(E->b + i, t->b_text[i], E->prec, err);
        if (rc == VIGEN_OK) rc = vigen_tableau_entry_eval(E->bt + i, E->bt_text[i], E->prec, err);
        for (slong j = 0; j < s && rc == VIGEN_OK; j++) {
            rc = vigen_tableau_entry_eval(arb_mat_entry(E->A, i, j), t->A_text[i * s + j], E->prec, err);
            if (rc == VIGEN_OK)
                rc = vigen_tableau_entry_eval(arb_mat_entry(E->At, i, j), E->At_text[i * s + j], E->prec, err);
        }
        if (rc != VIGEN_OK) return vigen_error_prefix(err, "%s: ", t->name ? t->name : "tableau");
    }
    return VIGEN_OK;
}

slong vigen_emit_spec_digits(int real) { return real == VIGEN_REAL_FLOAT128 ? 60 : 40; }

const vigen_emit_real_type vigen_emit_reals[VIGEN_EMIT_NREALS] = {
    [VIGEN_REAL_DOUBLE] = { "double", "double", "", 53 },
    [VIGEN_REAL_LONG_DOUBLE] = { "long-double", "long double", "_ld", 64 },
    [VIGEN_REAL_FLOAT128] = { "float128", "vigen_float128", "_q", 113 },
};

int vigen_emit_real_parse(int *real, const char *name)
{
    for (int k = 0; k < VIGEN_EMIT_NREALS; k++)
        if (strcmp(vigen_emit_reals[k].name, name) == 0) {
            *real = k;
            return VIGEN_OK;
        }
    return VIGEN_E_USAGE;
}

const char *vigen_emit_real_name(int real)
{
    return real >= 0 && real < VIGEN_EMIT_NREALS ? vigen_emit_reals[real].name : NULL;
}

/* Composed once from the table (a static buffer: the list is the same for
 * every caller). */
const char *vigen_emit_real_names(void)
{
    static char list[96];
    if (list[0] == '\0') {
        size_t n = 0;
        for (int k = 0; k < VIGEN_EMIT_NREALS; k++)
            n += (size_t)snprintf(list + n, sizeof list - n, "%s%s",
                                  k == 0 ? "" : k + 1 == VIGEN_EMIT_NREALS ? " or " : ", ", vigen_emit_reals[k].name);
    }
    return list;
}

/* How the messages name the input. */
static const char *input_name(const emit_ctx *E, const vigen_emit_options *opt)
{
    if (opt->input_label) return opt->input_label;
    return E->t->name ? E->t->name : "tableau";
}

void vigen_emit_precision_message(emit_ctx *E, const vigen_emit_options *opt, vigen_error *err)
{
    const vigen_tableau *t = E->t;
    char lab[64];
    const char *text = NULL;
    if (E->fail_ref >= 0) vigen_emit_entry_describe(E, E->fail_ref, lab, sizeof lab, &text, NULL);
    else snprintf(lab, sizeof lab, "%s", E->fail_label);
    char *shown = text ? vigen_emit_safe_text(text, 60) : NULL;
    char *what;
    if (shown) what = vigen_strdup_printf("%s = %s", lab, shown);
    else what = vigen_strdup_printf("%s (computed from entries given as rounded decimals)", lab);
    const char *why = E->fail_kind == 2 ? "is a ball around zero too wide to be rounded" : "is not known well enough to round it correctly";
    long bits = (long)E->bits, need = (long)vigen_emit_spec_digits(E->real);
    const char *rname = vigen_emit_reals[E->real].name;
    if (t->generated_now)
        vigen_error_set(err, VIGEN_E_INEXACT,
                        "%s %s to %ld bits (%s), even generated from the spec with %ld digits (the value lies "
                        "extremely close to a rounding boundary); pass --allow-inexact to round the decimals as "
                        "written", what, why, bits, rname, (long)t->digits);
    else if (t->digits > 0)
        vigen_error_set(err, VIGEN_E_INEXACT,
                        "%s %s to %ld bits (%s): the tableau was generated with %ld digits; regenerate it with "
                        "'vigen generate SPEC --digits %ld' (or more), or emit the spec itself (vigen emit then "
                        "generates enough digits); or give the entry exactly; or pass --allow-inexact to round the "
                        "decimals as written (the stepper's coefficients are then only as good as the decimals)",
                        what, why, bits, rname, (long)t->digits, need);
    else
        vigen_error_set(err, VIGEN_E_INEXACT,
                        "%s %s to %ld bits (%s): give the entry exactly (an expression such as 1/3 or sqrt(3)/6) "
                        "or with %ld or more significant digits (a tableau from vigen generate: regenerate it with "
                        "'vigen generate SPEC --digits %ld'); or pass --allow-inexact to round the decimals as "
                        "written (the stepper's coefficients are then only as good as the decimals)",
                        what, why, bits, rname, need, need);
    free(shown);
    free(what);
}

void vigen_emit_report_marks(emit_ctx *E, const vigen_emit_options *opt)
{
    const char *in = input_name(E, opt);
    slong n = vigen_emit_n_entries(E->s), ninexact = 0;
    vigen_strbuf names;
    vigen_strbuf_init(&names);
    vigen_strbuf_append(&names, "");
    for (slong r = 0; r < n; r++) {
        if (!E->marks[r]) continue;
        char lab[64];
        arb_srcptr v;
        vigen_emit_entry_describe(E, r, lab, sizeof lab, NULL, &v);
        if (E->marks[r] & MARK_ZERO)
            vigen_warn("%s: %s is only known to lie within %.3g of zero; emitted as an exact 0", in, lab,
                       mag_get_d(arb_radref(v)));
        if (E->marks[r] & MARK_INEXACT) {
            if (ninexact < 5) vigen_strbuf_printf(&names, "%s%s", ninexact ? ", " : "", lab);
            ninexact++;
        }
    }
    if (ninexact > 0 || E->inexact_derived > 0) {
        char more[64] = "", derived[96] = "";
        if (ninexact > 5) snprintf(more, sizeof more, " and %ld more", (long)(ninexact - 5));
        if (E->inexact_derived > 0)
            snprintf(derived, sizeof derived, "; and %ld coefficient%s computed from them", (long)E->inexact_derived,
                     E->inexact_derived == 1 ? "" : "s");
        vigen_warn("%s: --allow-inexact: rounded %ld entr%s to %s (%ld bits) from %s decimals as written (%s%s%s): "
                   "too few digits to round %s correctly, so the stepper's coefficients are only as good as these "
                   "decimals",
                   in, (long)ninexact, ninexact == 1 ? "y" : "ies", vigen_emit_reals[E->real].name, (long)E->bits,
                   ninexact == 1 ? "its" : "their", ninexact ? names.data : "none", more, derived,
                   ninexact == 1 ? "it" : "them");
    }
    vigen_strbuf_clear(&names);
}
