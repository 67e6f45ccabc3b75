/* test_check_theorem.c — claims of high orders decided by the simplifying
 * assumptions (Butcher's theorem, colour-blind for b = bt, c = ct) and refuted
 * by the bushy trees (src/check/theorem.c, claims.c).
 *
 * Also: the order-1 tree and the row sum sum b = 1 are one condition with
 * one scale (the rule of check.h).
 *
 * Sources of the expected values (never this code's own output):
 *  - Hairer, Wanner II, sec. IV.5 (Tables 5.1, 5.7-5.9): the s-stage Gauss
 *    method has order exactly 2s and satisfies B(2s), C(s), D(s); Lobatto
 *    IIIA-IIIB pairs of s stages have order exactly 2s - 2, IIIA satisfies
 *    C(s), D(s - 2), IIIB C(s - 2), D(s), both B(2s - 2);
 *  - Hairer, Norsett, Wanner I, Table II.1.2 and sec. II.1: the classical RK4
 *    has order 4, not 5;
 *  - an s-point quadrature rule is exact at most to degree 2s - 1, so the
 *    bushy tree of order 2s + 1 fails for every s-stage method (Hairer,
 *    Norsett, Wanner I, sec. II.7), which bounds its order by 2s;
 *  - Butcher's theorem itself (Hairer, Norsett, Wanner I, Thm II.7.4) gives
 *    min(p, eta + zeta + 1, 2 eta + 2) from B(p), C(eta), D(zeta): for
 *    Lobatto IIIA-IIIB with the smaller eta = zeta = s - 2 of the two parts,
 *    2s - 3, one below the true order (the theorem is sufficient only).
 */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "vigen/check.h"
#include "testlib.h"
#include "test_check_load.h"

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static const char *claim_message(const vigen_check_report *rep)
{
    for (slong k = 0; k < rep->nfailures; k++)
        if (rep->failures[k].kind == VIGEN_CHECK_FAIL_CLAIM && strcmp(rep->failures[k].claim, "order") == 0)
            return rep->failures[k].message;
    return "";
}

/* Gauss s = 1..6 from the generated tableaux (50-digit rounded data): order
 * 2s holds within the precision of the data, 2s + 1 is false (certain: the
 * bushy tree of order 2s + 1 fails). */
static void test_gauss(void)
{
    for (int s = 1; s <= 6; s++) {
        char rel[128];
        snprintf(rel, sizeof(rel), "tableaux/generated/gauss_legendre_s%d.lua", s);
        vigen_check_report rep;
        double t0 = now();
        CHECK(check_file_claim(&rep, rel, 2 * s, 8) == VIGEN_OK);
        if (s == 6) printf("gauss s = 6, claim order = 12: %.3f s\n", now() - t0);
        CHECK_MSG(rep.claim_order_status == VIGEN_CHECK_YES && rep.exit_code == 0, "s = %d: %s", s, claim_message(&rep));
        CHECK(rep.claim_order_within_data);
        CHECK(!rep.claim_order_separable);
        CHECK(rep.theorem.applies && rep.theorem.order == 2 * s);
        CHECK(rep.theorem.B == 2 * s && rep.theorem.eta == s && rep.theorem.zeta == s);
        CHECK(rep.theorem.bushy_fail[0] == 2 * s + 1 && rep.theorem.bushy_fail[1] == 2 * s + 1);
        vigen_check_report_clear(&rep);

        CHECK(check_file_claim(&rep, rel, 2 * s + 1, 8) == VIGEN_OK);
        CHECK_MSG(rep.claim_order_status == VIGEN_CHECK_NO && rep.exit_code == 1, "s = %d", s);
        vigen_check_report_clear(&rep);

        /* a lower claim is false too: the order is at least 2s */
        if (s <= 4) {   /* (higher: orders up to 2s enumerated, slow) */
            CHECK(check_file_claim(&rep, rel, 2 * s - 1, 8) == VIGEN_OK);
            /* certain only when the order-2s conditions hold exactly; on
             * rounded data they hold within the data, which cannot refute */
            CHECK(rep.claim_order_status != VIGEN_CHECK_YES && rep.exit_code == 1);
            vigen_check_report_clear(&rep);
        }
    }
    /* the exact Gauss tableaux: order 2s proved, not within the data */
    for (int s = 1; s <= 3; s++) {
        char rel[128];
        snprintf(rel, sizeof(rel), "tableaux/published/gauss_%d.lua", s);
        vigen_check_report rep;
        CHECK(check_file_claim(&rep, rel, 2 * s, 8) == VIGEN_OK);
        CHECK(rep.claim_order_status == VIGEN_CHECK_YES && !rep.claim_order_within_data);
        CHECK(rep.theorem.applies && rep.theorem.order == 2 * s && !rep.theorem.within_data);
        vigen_check_report_clear(&rep);
        CHECK(check_file_claim(&rep, rel, 2 * s - 1, 8) == VIGEN_OK);
        CHECK(rep.claim_order_status == VIGEN_CHECK_NO);
        vigen_check_report_clear(&rep);
    }
}

/* Lobatto IIIA-IIIB, s = 2, 3, 4 (exact): order 2s - 2 exactly; the
 * colour-blind theorem gives 2s - 3 only, and says no more than that. */
static void test_lobatto(void)
{
    for (int s = 2; s <= 4; s++) {
        char rel[128];
        snprintf(rel, sizeof(rel), "tableaux/published/lobatto_iiia_iiib_%d.lua", s);
        vigen_check_report rep;
        CHECK(check_file_claim(&rep, rel, 2 * s - 2, 8) == VIGEN_OK);
        CHECK_MSG(rep.claim_order_status == VIGEN_CHECK_YES && rep.exit_code == 0, "s = %d: %s", s,
                  claim_message(&rep));
        if (s == 2) {
            /* IIIB of 2 stages satisfies C(0) only: its row sums (1/2, 1/2) are
             * not the nodes (0, 1), so ct != c and the theorem does not apply */
            CHECK(!rep.theorem.applies && rep.theorem.why_not && strcmp(rep.theorem.why_not, "c != ct") == 0);
        } else {
            CHECK(rep.theorem.applies && rep.theorem.eta == s - 2 && rep.theorem.zeta == s - 2);
            CHECK(rep.theorem.B == 2 * s - 2 && rep.theorem.order == 2 * s - 3);
        }
        CHECK(rep.theorem.bushy_fail[0] == 2 * s - 1);
        vigen_check_report_clear(&rep);
        CHECK(check_file_claim(&rep, rel, 2 * s - 1, 8) == VIGEN_OK);
        CHECK(rep.claim_order_status == VIGEN_CHECK_NO && rep.exit_code == 1);
        vigen_check_report_clear(&rep);
    }
}

/* RK4: order 4, not 5; its quadrature is Simpson's rule, exact to degree 3:
 * B(4) but not B(5) */
static void test_rk4(void)
{
    vigen_check_report rep;
    CHECK(check_file_claim(&rep, "tests/data/check/rk4.lua", 4, 8) == VIGEN_OK);
    CHECK(rep.claim_order_status == VIGEN_CHECK_YES && !rep.claim_order_within_data);
    CHECK(rep.theorem.applies && rep.theorem.B == 4 && rep.theorem.eta == 1 && rep.theorem.zeta == 1);
    CHECK(rep.theorem.order == 3);   /* eta + zeta + 1 */
    CHECK(rep.theorem.bushy_fail[0] == 5);
    vigen_check_report_clear(&rep);
    CHECK(check_file_claim(&rep, "tests/data/check/rk4.lua", 5, 8) == VIGEN_OK);
    CHECK(rep.claim_order_status == VIGEN_CHECK_NO);
    vigen_check_report_clear(&rep);
}

/* One size of the terms for every verdict within the precision of the data:
 * sum b = 1 as a row sum and as the order-1 tree (tests/data/check/
 * short_among_long.lua: radius 0.00505, terms 3 + 2 + 1 = 6, 2^-10 * 6 =
 * 0.00586, so it holds within the data, by the rule of check.h) */
static void test_one_scale(void)
{
    vigen_check_report rep;
    CHECK(check_file_claim(&rep, "tests/data/check/short_among_long.lua", -1, 2) == VIGEN_OK);
    CHECK(rep.consistent == VIGEN_CHECK_YES && rep.consistent_within_data);
    const vigen_check_orders *g = &rep.orders[VIGEN_CHECK_GENERAL];
    CHECK(g->count[1] == 2 && g->hold[1] == 2 && g->hold_data[1] == 2 && g->undecided[1] == 0);
    vigen_check_report_clear(&rep);
}

int main(void)
{
    test_one_scale();
    test_gauss();
    test_lobatto();
    test_rk4();
    TEST_MAIN_END();
}
