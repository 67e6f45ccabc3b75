/* diagnose.c — the typo diagnosis: failed row sums and symplecticity pairs
 * that all involve one entry are traced back to it and the value they ask for
 * is solved for; and the problems these conditions file into the report.
 */
#include <stdlib.h>
#include <string.h>
#include "core/decimal.h"
#include "check/check_internal.h"
#include "support/strbuf.h"

/* Solves condition c for entry e: writes x with c(x) = 0 nearest the current
 * value (the condition is at most quadratic in one entry); 0 if it cannot. */
static int solve_for(arb_t x, const ctx_t *cx, const cond *c, entry e)
{
    slong prec = cx->prec;
    arb_t x0, r0, rp, rm, xp, alpha, beta, disc, t;
    arb_init(x0); arb_init(r0); arb_init(rp); arb_init(rm); arb_init(xp);
    arb_init(alpha); arb_init(beta); arb_init(disc); arb_init(t);
    /* the entry is the unknown: expand around its midpoint, taken as exact, so
     * that the value found carries the radii of the other entries only */
    arb_set_arf(x0, arb_midref(chk_entry_value(cx, e)));
    override ov0 = chk_ov1(e, x0), ov = chk_ov1(e, xp);
    chk_cond_eval(r0, cx, c, &ov0);
    arb_add_ui(xp, x0, 1, prec);
    chk_cond_eval(rp, cx, c, &ov);
    arb_sub_ui(xp, x0, 1, prec);
    chk_cond_eval(rm, cx, c, &ov);
    /* r(x0 + d) = r0 + alpha d + beta d^2 */
    arb_sub(alpha, rp, rm, prec);
    arb_mul_2exp_si(alpha, alpha, -1);
    arb_add(beta, rp, rm, prec);
    arb_mul_2exp_si(beta, beta, -1);
    arb_sub(beta, beta, r0, prec);
    int ok = 0;
    if (arb_contains_zero(beta)) {
        if (!arb_contains_zero(alpha)) {
            arb_div(t, r0, alpha, prec);
            arb_sub(x, x0, t, prec);
            ok = 1;
        }
    } else {
        /* the root nearest d = 0: d = -2 r0 / (alpha + sign(alpha) sqrt(alpha^2 - 4 beta r0)) */
        arb_sqr(disc, alpha, prec);
        arb_mul(t, beta, r0, prec);
        arb_mul_2exp_si(t, t, 2);
        arb_sub(disc, disc, t, prec);
        if (arb_is_nonnegative(disc) && !arb_contains_zero(alpha)) {
            arb_sqrt(disc, disc, prec);
            if (arb_is_negative(alpha)) arb_neg(disc, disc);
            arb_add(t, alpha, disc, prec);
            arb_mul_2exp_si(xp, r0, 1);
            arb_div(t, xp, t, prec);
            arb_sub(x, x0, t, prec);
            ok = arb_is_finite(x);
        }
    }
    arb_clear(x0); arb_clear(r0); arb_clear(rp); arb_clear(rm); arb_clear(xp);
    arb_clear(alpha); arb_clear(beta); arb_clear(disc); arb_clear(t);
    return ok;
}

static void mid_vec(arb_ptr out, arb_srcptr x, slong s)
{
    for (slong i = 0; i < s; i++) arb_set_arf(out + i, arb_midref(x + i));
}

void chk_midpoints_init(midpoints *m, const ctx_t *cx)
{
    slong s = cx->s;
    arb_mat_init(m->A, s, s);
    arb_mat_init(m->At, s, s);
    m->b = _arb_vec_init(s);
    m->bt = _arb_vec_init(s);
    m->c = _arb_vec_init(s);
    m->ct = _arb_vec_init(s);
    for (slong i = 0; i < s; i++)
        for (slong j = 0; j < s; j++) {
            arb_set_arf(arb_mat_entry(m->A, i, j), arb_midref(arb_mat_entry(cx->A, i, j)));
            arb_set_arf(arb_mat_entry(m->At, i, j), arb_midref(arb_mat_entry(cx->At, i, j)));
        }
    mid_vec(m->b, cx->b, s);
    mid_vec(m->bt, cx->bt, s);
    mid_vec(m->c, cx->c, s);
    mid_vec(m->ct, cx->ct, s);
    m->cx = *cx;
    m->cx.A = m->A;
    m->cx.At = m->At;
    m->cx.b = m->b;
    m->cx.bt = m->bt;
    m->cx.c = m->c;
    m->cx.ct = m->ct;
}

void chk_midpoints_clear(midpoints *m)
{
    slong s = m->cx.s;
    arb_mat_clear(m->A);
    arb_mat_clear(m->At);
    _arb_vec_clear(m->b, s);
    _arb_vec_clear(m->bt, s);
    _arb_vec_clear(m->c, s);
    _arb_vec_clear(m->ct, s);
}

/* Encloses condition c over the balls of its entries without the dependency
 * problem of plain ball arithmetic (an entry that occurs twice varies once):
 *   r(mid) +- (sum_u |dr/du| rad_u + 2 (sum_u rad_u)^2),
 * r and its derivatives taken at the midpoints of every entry u.  This is a
 * rigorous enclosure for these conditions, which are polynomials of degree <= 2
 * in the entries with coefficients of size 1 (the central difference gives
 * dr/du exactly, and the quadratic remainder is at most 2 (sum_u rad_u)^2).
 * When e is not NULL, entry e takes the value fix instead (midpoint f,
 * radius rad(fix)). */
void chk_cond_enclose(arb_t out, const ctx_t *cx, const ctx_t *mx, const cond *c, const entry *e,
                      const arb_t fix)
{
    slong prec = cx->prec;
    arb_t f, up, dn, u;
    arb_init(f);
    arb_init(up);
    arb_init(dn);
    arb_init(u);
    override ov = {0, {{0, 0, 0}, {0, 0, 0}}, {NULL, NULL}};
    if (e) {
        arb_set_arf(f, arb_midref(fix));
        ov = chk_ov1(*e, f);
    }
    chk_cond_eval(out, mx, c, &ov);
    entry buf[4];
    entry *list = chk_cond_is_rowsum(c) ? flint_malloc(sizeof(entry) * (size_t)(cx->s + 1)) : buf;
    slong n = chk_cond_entries(list, cx, c);
    mag_t tol, sum, g, rad;
    mag_init(tol);
    mag_init(sum);
    mag_init(g);
    mag_init(rad);
    for (slong k = 0; k < n; k++) {
        int dup = 0;
        for (slong q = 0; q < k; q++) dup |= chk_entry_eq(list[q], list[k]);
        if (dup) continue;
        int is_e = e && chk_entry_eq(list[k], *e);
        mag_set(rad, arb_radref(is_e ? fix : chk_entry_value(cx, list[k])));
        if (mag_is_zero(rad)) continue;
        /* dr/du by a central difference (exact: r is at most quadratic in u) */
        override o2 = ov;
        int slot = is_e ? 0 : o2.n;
        o2.e[slot] = list[k];
        if (!is_e) o2.n++;
        arb_srcptr base = is_e ? f : chk_get(mx, list[k].mat, list[k].i, list[k].j, NULL);
        arb_add_ui(u, base, 1, prec);
        o2.value[slot] = u;
        chk_cond_eval(up, mx, c, &o2);
        arb_sub_ui(u, base, 1, prec);
        o2.value[slot] = u;
        chk_cond_eval(dn, mx, c, &o2);
        arb_sub(up, up, dn, prec);
        arb_mul_2exp_si(up, up, -1);
        arb_get_mag(g, up);
        mag_mul(g, g, rad);
        mag_add(tol, tol, g);
        mag_add(sum, sum, rad);
    }
    mag_mul(sum, sum, sum);
    mag_mul_2exp_si(sum, sum, 1);
    mag_add(tol, tol, sum);
    arb_add_error_mag(out, tol);
    if (list != buf) flint_free(list);
    mag_clear(tol);
    mag_clear(sum);
    mag_clear(g);
    mag_clear(rad);
    arb_clear(f);
    arb_clear(up);
    arb_clear(dn);
    arb_clear(u);
}

/* Is condition c consistent with the data once entry e is given the value
 * fix (midpoint f, radius rho)?  Its enclosure over the data's balls (with e
 * in [f - rho, f + rho]) must contain 0. */
static int consistent_with_data(const ctx_t *cx, const ctx_t *mx, const cond *c, entry e, const arb_t fix)
{
    arb_t r;
    arb_init(r);
    chk_cond_enclose(r, cx, mx, c, &e, fix);
    int ok = arb_is_finite(r) && arb_contains_zero(r);
    arb_clear(r);
    return ok;
}

/* Among the conditions with in_scope[k], the failed ones all involve exactly
 * one entry whose change can satisfy every in-scope condition involving it?
 * Returns 1 with *culprit and fix when that entry is unique.  The value asked
 * for is solved with the entry as an exact unknown around its midpoint (its
 * radius comes from the other entries only), and the candidate must make every
 * in-scope condition involving it consistent with the data (see
 * consistent_with_data). */
static int diagnose(entry *culprit, arb_t fix, ctx_t *cx, const ctx_t *mx, cond *conds, slong n,
                    const int *in_scope)
{
    slong first = -1;
    for (slong k = 0; k < n; k++)
        if (in_scope[k] && conds[k].status == FAILS) { first = k; break; }
    if (first < 0) return 0;
    entry *cand = flint_malloc(sizeof(entry) * (size_t)(cx->s + 4));   /* s + 1 or 4 entries */
    slong ncand = chk_cond_entries(cand, cx, conds + first);
    /* deduplicate and intersect with every other failed condition */
    slong m = 0;
    for (slong a = 0; a < ncand; a++) {
        int dup = 0;
        for (slong q = 0; q < m; q++) dup |= chk_entry_eq(cand[q], cand[a]);
        if (dup) continue;
        int all = 1;
        for (slong k = first + 1; k < n && all; k++)
            if (in_scope[k] && conds[k].status == FAILS) all = chk_cond_involves(cx, conds + k, cand[a]);
        if (all) cand[m++] = cand[a];
    }
    int found = 0;
    arb_t x;
    arb_init(x);
    for (slong a = 0; a < m; a++) {
        /* the value asked by the first failed condition that can be solved */
        int solved = 0;
        for (slong k = first; k < n && !solved; k++)
            if (in_scope[k] && conds[k].status == FAILS) solved = solve_for(x, cx, conds + k, cand[a]);
        if (!solved) continue;
        /* every in-scope condition involving the entry must then hold */
        int ok = 1;
        for (slong k = 0; k < n && ok; k++) {
            if (!in_scope[k] || !chk_cond_involves(cx, conds + k, cand[a])) continue;
            ok = consistent_with_data(cx, mx, conds + k, cand[a], x);
        }
        if (!ok) continue;
        found++;
        if (found == 1) {
            *culprit = cand[a];
            arb_set(fix, x);
        }
    }
    arb_clear(x);
    flint_free(cand);
    return found == 1;
}

/* Significant digits of a decimal literal ("-0.01250e-3" has 4), 0 when it
 * is not one. */
static slong decimal_sig_digits(const char *text)
{
    slong n = 0, lead = 1;
    for (const char *c = text; *c && *c != 'e' && *c != 'E'; c++) {
        if (*c < '0' || *c > '9') continue;
        if (lead && *c == '0') continue;
        lead = 0;
        n++;
    }
    return n;
}

/* The problems of the row sums and symplecticity: when the failed conditions
 * all involve one entry, one problem per kind naming it with the value they
 * ask for; then every failed or undecided condition. */
int chk_diagnosis(chk_round *r, vigen_error *err)
{
    (void)err;
    vigen_check_report *rep = r->rep;
    ctx_t *cx = r->cx;
    cond *conds = r->conds;
    slong n = r->nconds;
    if (!r->have_mid) return VIGEN_OK;
    const ctx_t *mx = &r->mid.cx;
    int claim_symplectic = r->t->claim_symplectic;
    /* Diagnosis: over everything; then without bt = b (a splitting method
     * written as a PRK pair has bt != b by design); then over the row sums
     * alone (a method that is not symplectic says nothing about its typos). */
    int *scope = flint_malloc(sizeof(int) * (size_t)n);
    entry culprit = {0, 0, 0};
    arb_t fix;
    arb_init(fix);
    int diagnosed = 0;
    if (rep->row_fail + rep->sym_fail > 0) {
        for (slong k = 0; k < n; k++) scope[k] = 1;
        diagnosed = diagnose(&culprit, fix, cx, mx, conds, n, scope);
        if (!diagnosed && cx->has_bt) {
            for (slong k = 0; k < n; k++) scope[k] = conds[k].type != C_BT_EQ_B;
            diagnosed = diagnose(&culprit, fix, cx, mx, conds, n, scope);
        }
        if (!diagnosed && rep->row_fail > 0) {
            for (slong k = 0; k < n; k++) scope[k] = chk_cond_is_rowsum(conds + k);
            diagnosed = diagnose(&culprit, fix, cx, mx, conds, n, scope);
        }
    }
    /* every failed or undecided pair is a problem; bt != b is one when the
     * file claims symplecticity and the claim fails (a splitting method
     * written as a PRK pair has bt != b by design) */
    int list_bt = claim_symplectic == 1 && rep->symplectic != VIGEN_CHECK_YES &&
                  rep->symplectic_separable != VIGEN_CHECK_YES;

    if (diagnosed) {
        /* one problem per kind of failed condition, each naming the entry */
        char *name = chk_entry_name(culprit);
        int kinds_seen[2] = {0, 0};
        vigen_strbuf words;
        vigen_strbuf_init(&words);
        int nwords = 0;
        const char *seen_words[4] = {0};
        for (slong k = 0; k < n; k++) {
            if (!scope[k] || conds[k].status != FAILS) continue;
            const char *w = chk_cond_kind_words(conds[k].type);
            int dup = 0;
            for (int q = 0; q < nwords; q++) dup |= strcmp(seen_words[q], w) == 0;
            if (!dup && nwords < 4) seen_words[nwords++] = w;
        }
        for (int q = 0; q < nwords; q++) {
            if (q > 0) vigen_strbuf_append(&words, q + 1 == nwords ? " and " : ", ");
            vigen_strbuf_append(&words, seen_words[q]);
        }
        slong digits = vigen_ball_digits_to_separate(chk_entry_value(cx, culprit), fix, cx->prec);
        const char *text = chk_entry_text(cx, culprit);
        if (text && vigen_decimal_is_rounded(text)) {
            /* the repair as many digits long as the entry, where the data certify them */
            slong want = decimal_sig_digits(text), can = (slong)(arb_rel_accuracy_bits(fix) * 0.30103);
            if (want > can) want = can;
            if (want > digits) digits = want;
        }
        /* a rounded decimal is shown as the file gives it */
        char *v = text && vigen_decimal_is_rounded(text) ? vigen_strdup(text) : vigen_ball_str(chk_entry_value(cx, culprit), digits);
        char *f = vigen_ball_str(fix, digits);
        for (slong k = 0; k < n; k++) {
            if (!scope[k] || conds[k].status != FAILS) continue;
            int kind = chk_cond_is_rowsum(conds + k) ? VIGEN_CHECK_FAIL_ROWSUM : VIGEN_CHECK_FAIL_SYMPLECTIC;
            if (kinds_seen[kind]) continue;
            kinds_seen[kind] = 1;
            vigen_check_failure *p = chk_failure_new(rep, kind);
            p->matrix = chk_matrix_names[culprit.mat];
            p->row = culprit.i + 1;
            p->col = (culprit.mat == M_A || culprit.mat == M_AT) ? culprit.j + 1 : 0;
            p->diagnosed = 1;
            p->has_value = p->has_expected = 1;
            arb_set(p->value, chk_entry_value(cx, culprit));
            arb_set(p->expected, fix);
            p->message = vigen_strdup_printf("%s = %s; %s %s for %s", name, v, words.data,
                                             nwords > 1 ? (nwords > 2 ? "all ask" : "both ask") : "asks", f);
        }
        free(v);
        free(f);
        free(name);
        vigen_strbuf_clear(&words);
    }

    for (slong k = 0; k < n; k++) {
        cond *c = conds + k;
        if (c->status == HOLDS) continue;
        int rowsum = chk_cond_is_rowsum(c);
        if (c->type == C_BT_EQ_B && !list_bt) continue;
        vigen_check_failure *p = chk_failure_new(rep, rowsum ? VIGEN_CHECK_FAIL_ROWSUM : VIGEN_CHECK_FAIL_SYMPLECTIC);
        p->undecided = c->status == UNDECIDED;
        p->has_value = p->has_expected = 1;
        chk_cond_parts(p->value, p->expected, cx, c, NULL);
        if (c->type == C_SYMP) arb_set(p->value, c->r);   /* the enclosure decided on (expected 0) */
        slong digits = vigen_ball_digits_to_separate(p->value, p->expected, cx->prec);
        /* a failure: digits enough that the two sides differ in the text */
        char *v = p->undecided ? vigen_ball_str(p->value, digits) : vigen_ball_str_apart(p->value, p->expected, cx->prec);
        char *e = p->undecided ? vigen_ball_str(p->expected, digits)
                               : vigen_ball_str_apart(p->expected, p->value, cx->prec);
        char *d = vigen_ball_str(c->r, 6);
        const char *verdict = !p->undecided ? ""
                              : c->too_short ? "undecided, the data are too short to decide: "
                                             : "undecided at this precision: ";
        /* "defect 0.0100" or "defect in [0.00500, 0.0150]": the reader sees whether it excludes 0 */
        const char *in = d[0] == '[' ? "in " : "";
        switch (c->type) {
        case C_ROWSUM_A:
        case C_ROWSUM_AT:
            p->matrix = c->type == C_ROWSUM_A ? "A" : "At";
            p->row = c->i + 1;
            p->message = vigen_strdup_printf("%srow %ld of %s sums to %s%s but %s[%ld] = %s (defect %s%s)", verdict,
                                             (long)p->row, p->matrix, v[0] == '[' ? "a value in " : "", v,
                                             c->type == C_ROWSUM_A ? "c" : "ct", (long)p->row, e, in, d);
            break;
        case C_SUM_B:
        case C_SUM_BT:
            p->matrix = c->type == C_SUM_B ? "b" : "bt";
            p->message = vigen_strdup_printf("%ssum of %s is %s%s, not 1 (defect %s%s)", verdict, p->matrix,
                                             v[0] == '[' ? "in " : "", v, in, d);
            break;
        case C_BT_EQ_B:
            p->matrix = "bt";
            p->row = c->i + 1;
            p->message = vigen_strdup_printf("%sbt[%ld] = %s but b[%ld] = %s", verdict, (long)p->row, v,
                                             (long)p->row, e);
            break;
        default:
            p->matrix = cx->has_At ? "At" : "A";
            p->row = c->i + 1;
            p->col = c->j + 1;
            p->message = vigen_strdup_printf("%spair (%ld, %ld): b_i %s_ij + %s_j a_ji - b_i %s_j %s %s%s", verdict,
                                             (long)p->row, (long)p->col, cx->has_At ? "at" : "a",
                                             cx->has_bt ? "bt" : "b", cx->has_bt ? "bt" : "b",
                                             d[0] == '[' ? "is in" : "=", d, p->undecided ? "" : ", not 0");
            break;
        }
        free(v);
        free(e);
        free(d);
    }

    arb_clear(fix);
    flint_free(scope);
    return VIGEN_OK;
}
