/* generalized.c — the classical and the generalized order of a splitting
 * with two named flows, for H = A + eps B (vigen_check_generalized,
 * check.h), and the check of the claim generalized_order.
 *
 * The log of one step (for a processed method C K C^-1, whose order is the
 * processed method's) is computed in the free associative algebra on
 * {A, B} (lie.c), B the flow that carries eps.  It is a Lie series, so its
 * part of degree d with j letters B vanishes exactly when each of its word
 * coefficients does: the verdicts come from those balls, and the leading
 * part of each power of eps is then written in the Lyndon basis.  Laskar &
 * Robutel, Celest. Mech. Dyn. Astron. 80 (2001) 39-62, and Blanes, Casas,
 * Farres, Laskar, Makazaga & Murua, Appl. Numer. Math. 68 (2013) 58-72,
 * write the generalized order (r1, r2, ...) for an error O(eps h^r1 + eps^2
 * h^r2 + ...) in the Hamiltonian (and over a fixed time): the terms of the
 * log of degree r + 1, which is h^r in the modified Hamiltonian.
 *
 * A term's verdict: exact coefficients: it does not vanish when its ball
 * excludes 0 at the round's precision or at twice it, and it vanishes when
 * both balls contain 0 with a radius below 2^-(prec/2) (the rule of the
 * other conditions of the report: a numerical confirmation); rounded
 * coefficients: it vanishes to the data's precision when its ball contains
 * 0 with a radius below 2^-VIGEN_CHECK_DATA_BITS; otherwise it is
 * undecided, and so is every order it would decide. */
#include <stdlib.h>
#include <string.h>
#include "check/check_internal.h"
#include "support/strbuf.h"

enum { DEFAULT_DEGREE = 12 };

/* (freed with the report: report_init.c) */
static vigen_check_generalized *gen_new(void)
{
    vigen_check_generalized *g = calloc(1, sizeof *g);
    if (g == NULL) abort();
    for (int j = 0; j <= VIGEN_GEN_MAX_DEGREE; j++) arb_init(g->terms[j].norm);
    return g;
}

static void gen_reset(vigen_check_generalized *g)
{
    for (int j = 0; j <= VIGEN_GEN_MAX_DEGREE; j++) chk_lie_error_clear(&g->terms[j]);
    g->computed = g->processed = g->degree = g->rounded = g->within_data = 0;
    g->classical = g->k = g->claim_k = 0;
    g->classical_state = VIGEN_GEN_UNDECIDED;
    free(g->letter_a);
    free(g->letter_b);
    g->why = NULL;
    g->letter_a = g->letter_b = NULL;
    g->claim_status = -1;
}

/* the verdict on one word coefficient from its balls at two precisions
 * (exact data) or one (rounded data) */
static int term_verdict(const arb_t x, const arb_t x2, int rounded, slong prec, int *within)
{
    if (!arb_contains_zero(x) || (!rounded && !arb_contains_zero(x2))) return FAILS;
    mag_t m, lim;
    mag_init(m);
    mag_init(lim);
    int v = UNDECIDED;
    if (rounded) {
        arb_get_mag(m, x);
        mag_one(lim);
        mag_mul_2exp_si(lim, lim, -VIGEN_CHECK_DATA_BITS);
        if (mag_cmp(m, lim) <= 0) {
            v = HOLDS;
            *within = 1;
        }
    } else {
        arb_get_mag(m, x);
        mag_one(lim);
        mag_mul_2exp_si(lim, lim, -(prec / 2));
        int ok = mag_cmp(m, lim) <= 0;
        arb_get_mag(m, x2);
        mag_mul_2exp_si(lim, lim, -(prec / 2));
        if (ok && mag_cmp(m, lim) <= 0) v = HOLDS;
    }
    mag_clear(m);
    mag_clear(lim);
    return v;
}

/* the verdict on the part of degree d with j letters B */
static int part_verdict(arb_srcptr lg, arb_srcptr lg2, slong d, int j, int rounded, slong prec, int *within)
{
    int v = HOLDS, w = 0;
    for (slong b = 0; b < ((slong)1 << d) && v != FAILS; b++) {
        if (__builtin_popcountl((unsigned long)b) != j) continue;
        slong idx = ((slong)1 << d) | b;
        int t = term_verdict(lg + idx, lg2 + idx, rounded, prec, &w);
        if (t != HOLDS) v = t;
    }
    if (v == HOLDS && w) *within = 1;
    return v;
}

static int consistent(arb_srcptr lg, arb_srcptr lg2, int rounded, slong prec, int *within)
{
    int ok = 1;
    arb_t x, x2;
    arb_init(x);
    arb_init(x2);
    for (slong w = 2; w <= 3; w++) {   /* the words A and B: their coefficients are the sums */
        arb_sub_ui(x, lg + w, 1, prec);
        arb_sub_ui(x2, lg2 + w, 1, 2 * prec);
        ok &= term_verdict(x, x2, rounded, prec, within) == HOLDS;
    }
    arb_clear(x);
    arb_clear(x2);
    return ok;
}

static void orders_text(vigen_strbuf *sb, const int *r, int k)
{
    vigen_strbuf_append(sb, "(");
    for (int j = 0; j < k; j++) vigen_strbuf_printf(sb, "%s%d", j ? "," : "", r[j]);
    vigen_strbuf_append(sb, ")");
}

/* The claim {c_1, ..., c_m} cut after its first least entry (the terms
 * beyond are dominated): r_j = c_j for j <= m and r_j >= c_m beyond. */
static int claim_verdict(const vigen_check_generalized *g, const int *c, int m, int N)
{
    int v = VIGEN_CHECK_YES;
    for (int j = 1; j < N && v != VIGEN_CHECK_NO; j++) {
        int want = j <= m ? c[j - 1] : c[m - 1];
        int exact = j <= m;
        if (g->state[j] == VIGEN_GEN_DECIDED) {
            if (exact ? g->r[j] != want : g->r[j] < want) v = VIGEN_CHECK_NO;
        } else if (want < g->r[j]) {
            if (exact) v = VIGEN_CHECK_NO;
        } else if (exact || want > g->r[j]) v = VIGEN_CHECK_UNDECIDED;
    }
    return v;
}

static void file_claim(vigen_check_report *rep, vigen_check_generalized *g)
{
    vigen_strbuf said, found;
    vigen_strbuf_init(&said);
    vigen_strbuf_init(&found);
    orders_text(&said, g->claim, g->claim_k);
    orders_text(&found, g->r + 1, g->k);
    vigen_check_failure *p = chk_failure_new(rep, VIGEN_CHECK_FAIL_CLAIM);
    p->claim = "generalized_order";
    p->undecided = g->claim_status == VIGEN_CHECK_UNDECIDED;
    if (g->why)
        p->message = vigen_strdup_printf("claim generalized_order = %s: undecided: %s", said.data, g->why);
    else if (p->undecided)
        p->message = vigen_strdup_printf("claim generalized_order = %s: undecided: the terms computed (to degree %d) "
                                         "give %s%s", said.data, g->degree, found.data,
                                         " with some entries only bounds from below");
    else
        p->message = vigen_strdup_printf("claim generalized_order = %s is false: the generalized order for H = %s + "
                                         "eps %s is %s (terms to degree %d)", said.data, g->letter_a, g->letter_b,
                                         found.data, g->degree);
    vigen_strbuf json;
    vigen_strbuf_init(&json);
    vigen_strbuf_append(&json, "[");
    for (int j = 0; j < g->claim_k; j++) vigen_strbuf_printf(&json, "%s%d", j ? ", " : "", g->claim[j]);
    vigen_strbuf_append(&json, "]");
    p->expected_json = json.data;
    vigen_strbuf_init(&json);
    vigen_strbuf_append(&json, "[");
    for (int j = 1; j <= g->k; j++) vigen_strbuf_printf(&json, "%s%d", j > 1 ? ", " : "", g->r[j]);
    vigen_strbuf_append(&json, "]");
    p->value_json = json.data;
    vigen_strbuf_clear(&said);
    vigen_strbuf_clear(&found);
}

/* the orders from the log (lg at prec, lg2 at twice it) */
static void decide_orders(vigen_check_generalized *g, arb_srcptr lg, arb_srcptr lg2, int N, slong prec)
{
    int lo = N;
    for (int j = 1; j < N; j++) {
        g->r[j] = N;
        g->state[j] = VIGEN_GEN_AT_LEAST;
        for (int d = j + 1; d <= N; d++) {
            int v = part_verdict(lg, lg2, d, j, g->rounded, prec, &g->within_data);
            if (v == HOLDS) continue;
            g->r[j] = d - 1;
            g->state[j] = v == FAILS ? VIGEN_GEN_DECIDED : VIGEN_GEN_UNDECIDED;
            break;
        }
        if (g->r[j] < lo) lo = g->r[j];
    }
    g->classical = lo;
    g->classical_state = VIGEN_GEN_AT_LEAST;
    for (int j = 1; j < N; j++)
        if (g->r[j] == lo && g->state[j] != VIGEN_GEN_AT_LEAST &&
            (g->classical_state == VIGEN_GEN_AT_LEAST || g->state[j] == VIGEN_GEN_DECIDED))
            g->classical_state = g->state[j];
    /* at least (r1, r2): the literature's form, (2,2) for Stormer-Verlet */
    g->k = 1;
    while (g->k < N - 1 && g->r[g->k] != lo) g->k++;
    if (g->k < 2 && N > 2) g->k = 2;
}

int chk_generalized(chk_round *rd, vigen_error *err)
{
    vigen_check_report *rep = rd->rep;
    const vigen_tableau *t = rd->t;
    if (t->flows == NULL || t->nsubsteps == 0 || rd->cx->skip_generalized) return VIGEN_OK;
    if (rep->generalized == NULL) rep->generalized = gen_new();
    vigen_check_generalized *g = rep->generalized;
    gen_reset(g);
    const vigen_flows *fl = t->flows;
    g->computed = 1;
    g->processed = fl->ncorrector > 0;
    g->brackets = 0;
    for (slong j = 0; j < fl->nflows && fl->degree; j++) g->brackets += fl->degree[j] > 1;
    int flip = fl->perturbation == 0;
    g->flipped = flip;
    g->letter_a = vigen_strdup(fl->names[flip ? 1 : 0]);
    g->letter_b = vigen_strdup(fl->names[flip ? 0 : 1]);
    int N = DEFAULT_DEGREE;
    for (int j = 0; j < fl->ngeneralized; j++)
        if (fl->generalized[j] + 1 > N) N = fl->generalized[j] + 1;
    if (N > VIGEN_GEN_MAX_DEGREE) N = VIGEN_GEN_MAX_DEGREE;
    g->degree = N;
    for (slong k = 0; k < chk_lie_step_count(t); k++)
        g->rounded |= vigen_tableau_entry_is_rounded(chk_lie_step_coef(t, k));
    slong prec = rd->cx->prec < 128 ? 128 : rd->cx->prec, size = (slong)1 << (N + 1);
    arb_ptr lg = _arb_vec_init(size), lg2 = _arb_vec_init(size);
    int rc = chk_lie_log(lg, t, N, flip, prec, err);
    if (rc == VIGEN_OK && !g->rounded) rc = chk_lie_log(lg2, t, N, flip, 2 * prec, err);
    if (rc == VIGEN_OK && !consistent(lg, g->rounded ? lg : lg2, g->rounded, prec, &g->within_data))
        g->why = "the coefficients of a flow do not add up to 1 (not consistent)";
    if (rc == VIGEN_OK && g->why == NULL) {
        decide_orders(g, lg, lg2, N, prec);
        for (int j = 1; j <= g->k; j++)
            if (g->state[j] == VIGEN_GEN_DECIDED) chk_lie_lyndon(&g->terms[j], lg, N, g->r[j] + 1, j, prec);
    }
    if (rc == VIGEN_OK && fl->ngeneralized > 0) {
        int m = 0, least = fl->generalized[0];
        for (int j = 0; j < fl->ngeneralized; j++)
            if (fl->generalized[j] < least) least = fl->generalized[j];
        while (fl->generalized[m] != least) m++;
        g->claim_k = fl->ngeneralized;
        memcpy(g->claim, fl->generalized, sizeof g->claim);
        g->claim_status = g->why ? VIGEN_CHECK_UNDECIDED : claim_verdict(g, fl->generalized, m + 1, N);
        if (g->claim_status != VIGEN_CHECK_YES) file_claim(rep, g);
    }
    _arb_vec_clear(lg, size);
    _arb_vec_clear(lg2, size);
    return rc;
}
