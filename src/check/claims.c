/* claims.c — the check of the claims a file states: order = p (the order is
 * exactly p) and symplectic = true or false.
 */
#include <limits.h>
#include <stdlib.h>
#include "check/check_internal.h"
#include "support/strbuf.h"

/* What a level says about "the order is exactly p": 2 certainly, 1 possibly, 0 not. */
static int level_is(const vigen_check_level *L, int p)
{
    if (L->capped) return p >= L->value ? 1 : 0;       /* the order is >= value */
    if (L->undecided) return p == L->value ? 1 : p > L->value ? 1 : 0;   /* >= value, value + 1 undecided */
    return p == L->value ? 2 : 0;
}

/* With level_is(L, claim) = 0: is "the order is claim" certainly false?  Yes
 * when a condition of order <= claim fails (level below claim), or when every
 * condition of order claim + 1 holds exactly; not when some of these hold
 * only within the precision of the data (the exact values may fail them). */
static int order_refutes(const vigen_check_orders *o, int claim)
{
    if (o->level.value < claim) return 1;
    return claim + 1 > VIGEN_TREE_MAX_ORDER || o->hold_data[claim + 1] == 0;
}

/* What the simplifying assumptions and the bushy trees (theorem.c) say about
 * "the order for family f (general 0, separable 1) is exactly p", with the
 * levels of the enumerated trees: YES, NO or UNDECIDED; *within: a YES rests
 * on holds within the precision of the data. */
static int theorem_says(const vigen_check_report *rep, int f, int p, int *within)
{
    const vigen_check_theorem *th = &rep->theorem;
    const vigen_check_level *L = &rep->orders[f ? VIGEN_CHECK_SEPARABLE : VIGEN_CHECK_GENERAL].level;
    int lo = L->value, lo_within = L->within_data;
    if (th->applies && th->order > lo) {
        lo = th->order;
        lo_within = th->within_data;
    }
    int hi = INT_MAX;
    if (!L->capped && !L->undecided) hi = L->value;
    if (th->bushy_fail[f] && th->bushy_fail[f] - 1 < hi) hi = th->bushy_fail[f] - 1;
    *within = 0;
    if (hi < p || (lo > p && !lo_within)) return VIGEN_CHECK_NO;
    if (lo >= p && hi <= p) {
        *within = lo_within;
        return VIGEN_CHECK_YES;
    }
    return VIGEN_CHECK_UNDECIDED;
}

int chk_claims(chk_round *rd, vigen_error *err)
{
    (void)err;
    vigen_check_report *rep = rd->rep;
    if (rep->claim_order >= 0) {
        const vigen_check_orders *go = &rep->orders[VIGEN_CHECK_GENERAL], *so = &rep->orders[VIGEN_CHECK_SEPARABLE];
        const vigen_check_level *g = &go->level;
        const vigen_check_level *sp = &so->level;
        int claim = rep->claim_order, st;
        int data_above = 0;      /* undecided: order claim + 1 holds only within the data's precision */
        /* order = p means the order is p: every condition up to p holds and
         * one of order p + 1 fails (for general H, or for separable H: the
         * separable order is at least the general one) */
        int ig = level_is(g, claim), is = level_is(sp, claim);
        rep->claim_order_separable = 0;
        rep->claim_order_beyond = 0;
        rep->claim_order_within_data = 0;
        rep->claim_order_too_short = 0;
        if (ig == 2) {
            st = VIGEN_CHECK_YES;
            rep->claim_order_within_data = g->within_data;
        } else if (is == 2) {
            st = VIGEN_CHECK_YES;
            rep->claim_order_separable = 1;
            rep->claim_order_within_data = sp->within_data;
        } else if (ig || is) {
            st = VIGEN_CHECK_UNDECIDED;
            /* possible only because nothing up to max_order fails and order
             * claim + 1 is beyond what can be evaluated */
            rep->claim_order_beyond = (g->capped || sp->capped) && claim + 1 > rep->max_order &&
                                      !(g->undecided || sp->undecided);
            /* or because the conditions that decide are undecided for short data */
            rep->claim_order_too_short = !rep->claim_order_beyond && (!ig || (g->undecided && g->too_short)) &&
                                         (!is || (sp->undecided && sp->too_short)) &&
                                         ((ig && g->undecided) || (is && sp->undecided));
        } else if (!(order_refutes(go, claim) && order_refutes(so, claim))) {
            /* the order looks higher than claimed only because conditions of
             * order claim + 1 hold within the precision of rounded data: that
             * does not refute the claim (the exact values may fail them) */
            st = VIGEN_CHECK_UNDECIDED;
            data_above = 1;
        } else st = VIGEN_CHECK_NO;
        /* what the enumerated trees leave open, the simplifying assumptions
         * and the bushy trees may decide (orders above those enumerated) */
        rep->claim_order_theorem = 0;
        if (st == VIGEN_CHECK_UNDECIDED) {
            int wg, ws;
            int tg = theorem_says(rep, 0, claim, &wg), ts = theorem_says(rep, 1, claim, &ws);
            if (tg == VIGEN_CHECK_YES || ts == VIGEN_CHECK_YES) {
                st = VIGEN_CHECK_YES;
                rep->claim_order_separable = tg != VIGEN_CHECK_YES;
                rep->claim_order_within_data = tg == VIGEN_CHECK_YES ? wg : ws;
            } else if (tg == VIGEN_CHECK_NO && ts == VIGEN_CHECK_NO) st = VIGEN_CHECK_NO;
            if (st != VIGEN_CHECK_UNDECIDED) {
                rep->claim_order_theorem = 1;
                rep->claim_order_beyond = rep->claim_order_too_short = 0;
                data_above = 0;
            }
        }
        rep->claim_order_status = st;
        if (st != VIGEN_CHECK_YES) {
            vigen_check_failure *p = chk_failure_new(rep, VIGEN_CHECK_FAIL_CLAIM);
            p->claim = "order";
            p->undecided = st == VIGEN_CHECK_UNDECIDED;
            p->value_json = vigen_strdup_printf("%d", g->value);
            p->expected_json = vigen_strdup_printf("%d", claim);
            const vigen_check_theorem *th = &rep->theorem;
            if (rep->claim_order_theorem && th->bushy_fail[0] && th->bushy_fail[0] <= claim)
                p->message = vigen_strdup_printf(
                    "claim order = %d is false: the bushy tree of order %d fails (the quadrature condition "
                    "B(%d) on the row sums), so the order is at most %d", claim, th->bushy_fail[0], th->bushy_fail[0],
                    th->bushy_fail[0] - 1);
            else if (rep->claim_order_theorem)
                p->message = vigen_strdup_printf(
                    "claim order = %d is false: B(%d), C(%d), D(%d) for both parts with b = bt and c = ct give "
                    "order %d or more (Butcher's theorem)", claim, th->B, th->eta, th->zeta, th->order);
            else if (rep->claim_order_beyond && th->bushy_to > claim && !th->bushy_fail[0])
                p->message = vigen_strdup_printf(
                    "claim order = %d: undecided: every condition up to order %d holds and the simplifying "
                    "assumptions give order %d only (B(%d), C(%d), D(%d)%s); the bushy tree of order %d holds, and "
                    "the other conditions of order %d are beyond the %d that can be enumerated",
                    claim, rep->max_order, th->applies ? th->order : 0, th->B, th->eta, th->zeta,
                    th->applies ? "" : "; Butcher's theorem does not apply",
                    claim + 1, claim + 1, VIGEN_TREE_MAX_ORDER);
            else if (rep->claim_order_beyond)
                p->message = vigen_strdup_printf(
                    "claim order = %d: undecided: every condition up to order %d holds, and confirming that the "
                    "order is exactly %d needs the conditions of order %d (at most %d supported%s)",
                    claim, rep->max_order, claim, claim + 1, VIGEN_TREE_MAX_ORDER,
                    rep->max_order < VIGEN_TREE_MAX_ORDER ? "; --max-order 12 looks further for a lower order" : "");
            else if (data_above) {
                char *r = vigen_mag_str(rep->holds[VIGEN_CHECK_SECT_ORDER].radius);
                p->message = vigen_strdup_printf(
                    "claim order = %d: undecided: the conditions of order %d hold within the precision of the data "
                    "(radius <= %s), so the order looks higher, but their exact values may fail them",
                    claim, claim + 1, r);
                free(r);
            } else if (rep->claim_order_too_short)
                p->message = vigen_strdup_printf("claim order = %d: undecided, the data are too short to decide "
                                                 "(order >= %d; the conditions of order %d that are undecided have "
                                                 "balls containing 0 wider than 2^-%d of their terms)",
                                                 claim, g->value, g->value + 1, VIGEN_CHECK_DATA_BITS);
            else if (st == VIGEN_CHECK_UNDECIDED)
                p->message = vigen_strdup_printf("claim order = %d: undecided at this precision (order >= %d, "
                                                 "order %d undecided)", claim, g->value, g->value + 1);
            else if (g->capped)
                p->message = vigen_strdup_printf("claim order = %d is false: every condition up to order %d holds, "
                                                 "so the order is at least %d", claim, g->value, g->value);
            else if (sp->value != g->value || sp->capped != g->capped)
                p->message = vigen_strdup_printf("claim order = %d is false: the order is %d (%d%s for separable H)",
                                                 claim, g->value, sp->value, sp->capped ? " or more" : "");
            else
                p->message = vigen_strdup_printf("claim order = %d is false: the order is %d", claim, g->value);
        }
    }
    /* order_separable = p, order_nystrom = p: the certified order of the
     * family (its trees, Butcher's theorem beyond) is exactly p */
    static const int families[2] = {VIGEN_CHECK_SEPARABLE, VIGEN_CHECK_NYSTROM};
    static const char *const family_names[2] = {"order_separable", "order_nystrom"};
    for (int f = 0; f < 2; f++) {
        int claim = rep->claim_order_family[f];
        if (claim < 0) continue;
        int at_least, undecided;
        int q = vigen_check_certified_order(rep, families[f], &at_least, &undecided);
        int st = !at_least && !undecided ? (q == claim ? VIGEN_CHECK_YES : VIGEN_CHECK_NO)
                 : claim < q ? VIGEN_CHECK_NO : VIGEN_CHECK_UNDECIDED;
        rep->claim_order_family_status[f] = st;
        if (st != VIGEN_CHECK_YES) {
            vigen_check_failure *p = chk_failure_new(rep, VIGEN_CHECK_FAIL_CLAIM);
            p->claim = family_names[f];
            p->undecided = st == VIGEN_CHECK_UNDECIDED;
            p->value_json = vigen_strdup_printf("%d", q);
            p->expected_json = vigen_strdup_printf("%d", claim);
            p->message = st == VIGEN_CHECK_NO
                             ? vigen_strdup_printf("claim %s = %d is false: the order for %s is %s%d", family_names[f],
                                                   claim, f ? "Nystrom H" : "separable H", at_least ? "at least " : "", q)
                             : vigen_strdup_printf("claim %s = %d: undecided (order %s%d for %s)", family_names[f], claim,
                                                   at_least ? "at least " : "", q, f ? "Nystrom H" : "separable H");
        }
    }
    if (rep->claim_symplectic >= 0) {
        int want = rep->claim_symplectic, st;
        rep->claim_symplectic_separable = 0;
        if (want) {
            if (rep->symplectic == VIGEN_CHECK_YES) st = VIGEN_CHECK_YES;
            else if (rep->symplectic_separable == VIGEN_CHECK_YES) {
                st = VIGEN_CHECK_YES;
                rep->claim_symplectic_separable = 1;
            } else if (rep->symplectic == VIGEN_CHECK_UNDECIDED || rep->symplectic_separable == VIGEN_CHECK_UNDECIDED)
                st = VIGEN_CHECK_UNDECIDED;
            else st = VIGEN_CHECK_NO;
        } else st = rep->symplectic == VIGEN_CHECK_UNDECIDED ? VIGEN_CHECK_UNDECIDED
                    : rep->symplectic == VIGEN_CHECK_NO ? VIGEN_CHECK_YES : VIGEN_CHECK_NO;
        rep->claim_symplectic_status = st;
        rep->claim_symplectic_within_data = st == VIGEN_CHECK_YES && want && rep->symplectic_within_data;
        if (st != VIGEN_CHECK_YES) {
            vigen_check_failure *p = chk_failure_new(rep, VIGEN_CHECK_FAIL_CLAIM);
            p->claim = "symplectic";
            p->undecided = st == VIGEN_CHECK_UNDECIDED;
            p->value_json = vigen_strdup(rep->symplectic == VIGEN_CHECK_YES ? "true"
                                         : rep->symplectic == VIGEN_CHECK_NO ? "false" : "null");
            p->expected_json = vigen_strdup(want ? "true" : "false");
            int short_data = rep->holds[VIGEN_CHECK_SECT_SYMPLECTIC].too_short > 0;
            p->message = st == VIGEN_CHECK_UNDECIDED
                             ? vigen_strdup_printf("claim symplectic = %s: undecided%s", want ? "true" : "false",
                                                   short_data ? ", the data are too short to decide"
                                                              : " at this precision")
                             : vigen_strdup_printf("claim symplectic = %s is false", want ? "true" : "false");
        }
    }
    return VIGEN_OK;
}
