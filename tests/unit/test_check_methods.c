/* test_check_methods.c — the checker on published methods and their known properties: symplectic Euler, Stormer-Verlet,
 * Gauss, Lobatto IIIA-IIIB, RK4, Ruth-3; the claims of a file; collocation methods of many stages.
 * Sources of the expected values: test_check_support.h. */
#include "test_check_support.h"

static void test_symplectic_euler(void)
{
    /* p1 = p0 + h g(q0, p1), q1 = q0 + h f(q0, p1): explicit Euler for q,
     * implicit Euler for p */
    const char *c[] = {"0"}, *A[] = {"0"}, *b[] = {"1"}, *ct[] = {"1"}, *At[] = {"1"}, *bt[] = {"1"};
    vigen_tableau t;
    make(&t, "symplectic euler", 1, c, A, b, At, ct, bt);
    vigen_check_report rep;
    CHECK(check(&rep, &t, NULL, 8) == VIGEN_OK);
    CHECK(rep.consistent == VIGEN_CHECK_YES);
    CHECK(rep.symplectic == VIGEN_CHECK_YES);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_GENERAL), 1, 0, 0);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_SEPARABLE), 1, 0, 0);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_A_ALONE), 1, 0, 0);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_AT_ALONE), 1, 0, 0);
    CHECK(rep.exit_code == 0);
    CHECK(rep.nfailures == 0);
    /* order 2 has 4 trees, the first failing one is b[b] (sum b_i a_ij = 0 != 1/2) */
    CHECK(rep.orders[0].count[2] == 4);
    CHECK(rep.orders[0].fail_tree && strcmp(rep.orders[0].fail_tree, "b[b]") == 0);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);
}

static void test_stormer_verlet(void)
{
    const char *c[] = {"0", "1"}, *A[] = {"0", "0", "1/2", "1/2"}, *b[] = {"1/2", "1/2"};
    const char *ct[] = {"1/2", "1/2"}, *At[] = {"1/2", "0", "1/2", "0"};
    vigen_tableau t;
    make(&t, "stormer-verlet", 2, c, A, b, At, ct, NULL);
    vigen_check_report rep;
    CHECK(check(&rep, &t, NULL, 8) == VIGEN_OK);
    CHECK(rep.consistent == VIGEN_CHECK_YES && rep.symplectic == VIGEN_CHECK_YES);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_GENERAL), 2, 0, 0);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_SEPARABLE), 2, 0, 0);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_A_ALONE), 2, 0, 0);   /* trapezoidal rule */
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_AT_ALONE), 2, 0, 0);  /* Lobatto IIIB, s = 2 */
    /* per-order counts of every family (twice A000081 for the separable and
     * each monochromatic family) */
    CHECK(rep.orders[VIGEN_CHECK_GENERAL].count[3] == 14);
    CHECK(rep.orders[VIGEN_CHECK_SEPARABLE].count[3] == 4);
    CHECK(rep.orders[VIGEN_CHECK_A_ALONE].count[3] == 2);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);
}

static void test_gauss_exact(void)
{
    const char *const *cs[] = {gauss1_c, gauss2_c, gauss3_c};
    const char *const *As[] = {gauss1_A, gauss2_A, gauss3_A};
    const char *const *bs[] = {gauss1_b, gauss2_b, gauss3_b};
    for (int s = 1; s <= 3; s++) {
        vigen_tableau t;
        make(&t, "gauss", s, cs[s - 1], As[s - 1], bs[s - 1], NULL, NULL, NULL);
        vigen_check_report rep;
        CHECK(check(&rep, &t, NULL, 8) == VIGEN_OK);
        CHECK_MSG(rep.consistent == VIGEN_CHECK_YES && rep.symplectic == VIGEN_CHECK_YES, "gauss%d", s);
        CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_GENERAL), 2 * s, 0, 0);
        CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_SEPARABLE), 2 * s, 0, 0);
        CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_A_ALONE), 2 * s, 0, 0);
        CHECK_LEVEL(&rep.B[0], 2 * s, 0, 0);
        CHECK_LEVEL(&rep.C[0], s, 0, 0);
        CHECK_LEVEL(&rep.D[0], s, 0, 0);
        CHECK_LEVEL(&rep.stage_order[0], s, 0, 0);
        CHECK(rep.exit_code == 0 && rep.nfailures == 0);
        /* all 2 + 4 + 14 + 52 + ... conditions up to 2s hold */
        static const slong counts[] = {0, 2, 4, 14, 52, 214, 916, 4116};
        for (int n = 1; n <= 2 * s; n++) CHECK(rep.orders[0].hold[n] == counts[n]);
        CHECK(rep.orders[0].fail[2 * s + 1] > 0);
        /* entries in Q (s = 1: dyadic, every ball exact) or Q(sqrt 3), Q(sqrt
         * 15): every hold is exact or proved at the first precision, no
         * confirmation round */
        CHECK_MSG((s == 1 || rep.proved > 0) && rep.rounds == 1, "gauss%d: %ld proved, %ld rounds", s,
                  (long)rep.proved, (long)rep.rounds);
        vigen_check_report_clear(&rep);
        vigen_tableau_clear(&t);
    }
}

static void test_lobatto3(void)
{
    vigen_tableau t;
    make(&t, "lobatto IIIA-IIIB 3", 3, lob3_c, lob3A_A, lob3_b, lob3B_A, lob3B_c, NULL);
    vigen_check_report rep;
    CHECK(check(&rep, &t, NULL, 8) == VIGEN_OK);
    CHECK(rep.consistent == VIGEN_CHECK_YES && rep.symplectic == VIGEN_CHECK_YES);
    /* rational entries (lcm of the denominators 24): the holds are proofs, at
     * the first precision, no confirmation at 1024 bits needed */
    CHECK(rep.rational_denominator != NULL && strcmp(rep.rational_denominator, "24") == 0);
    CHECK(rep.proved > 0 && rep.rounds == 1);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_GENERAL), 4, 0, 0);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_SEPARABLE), 4, 0, 0);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_A_ALONE), 4, 0, 0);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_AT_ALONE), 4, 0, 0);
    CHECK_LEVEL(&rep.B[0], 4, 0, 0);
    CHECK_LEVEL(&rep.C[0], 3, 0, 0);
    CHECK_LEVEL(&rep.D[0], 1, 0, 0);
    CHECK_LEVEL(&rep.B[1], 4, 0, 0);
    CHECK_LEVEL(&rep.C[1], 1, 0, 0);
    CHECK_LEVEL(&rep.D[1], 3, 0, 0);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);

    /* IIIA alone and IIIB alone, each an RK method for both parts: 2s - 2 */
    vigen_tableau a, b;
    make(&a, "lobatto IIIA 3", 3, lob3_c, lob3A_A, lob3_b, NULL, NULL, NULL);
    make(&b, "lobatto IIIB 3", 3, lob3B_c, lob3B_A, lob3_b, NULL, NULL, NULL);
    CHECK(check(&rep, &a, NULL, 8) == VIGEN_OK);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_GENERAL), 4, 0, 0);
    CHECK(rep.symplectic == VIGEN_CHECK_NO);   /* IIIA alone is not symplectic */
    CHECK(rep.exit_code == 0);                 /* nothing was claimed */
    vigen_check_report_clear(&rep);
    CHECK(check(&rep, &b, NULL, 8) == VIGEN_OK);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_GENERAL), 4, 0, 0);
    CHECK(rep.symplectic == VIGEN_CHECK_NO);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&a);
    vigen_tableau_clear(&b);

    /* typo in At[2][1] (1/5 for 1/6): row sum of At and symplecticity both
     * point at it and ask for 1/6 */
    const char *bad[9];
    memcpy(bad, lob3B_A, sizeof(bad));
    bad[3] = "1/5";
    vigen_tableau u;
    make(&u, "lobatto IIIA-IIIB 3, typo", 3, lob3_c, lob3A_A, lob3_b, bad, lob3B_c, NULL);
    CHECK(check(&rep, &u, NULL, 8) == VIGEN_OK);
    CHECK(rep.consistent == VIGEN_CHECK_NO && rep.symplectic == VIGEN_CHECK_NO);
    CHECK(rep.exit_code == 1);
    const vigen_check_failure *p = find_problem(&rep, VIGEN_CHECK_FAIL_ROWSUM, "At", 2, 1);
    CHECK(p != NULL && p->diagnosed);
    if (p) {
        arb_t sixth;
        arb_init(sixth);
        arb_set_ui(sixth, 1);
        arb_div_ui(sixth, sixth, 6, 256);
        CHECK_CLOSE(p->expected, sixth, 35, 256);   /* checked at 128 bits */
        CHECK(strstr(p->message, "At[2][1]") != NULL);
        arb_clear(sixth);
    }
    p = find_diagnosis(&rep, VIGEN_CHECK_FAIL_SYMPLECTIC);   /* the diagnosis names it for both */
    CHECK(p != NULL && p->row == 2 && p->col == 1 && strcmp(p->matrix, "At") == 0);
    /* and every failed condition is listed: row 2 of At sums to 1/5 + 1/3 =
     * 8/15, not ct_2 = 1/2; the only pair involving at_21 is (2, 1), with
     * b_2 at_21 + b_1 a_12 - b_2 b_1 = (2/3)(1/5) + 0 - (2/3)(1/6) = 1/45 */
    p = find_listed(&rep, VIGEN_CHECK_FAIL_ROWSUM, "At", 2, 0);
    CHECK(p != NULL && !p->undecided);
    if (p) {
        arb_t d, want;
        arb_init(d);
        arb_init(want);
        arb_sub(d, p->value, p->expected, 256);
        arb_set_ui(want, 1);
        arb_div_ui(want, want, 30, 256);   /* 8/15 - 1/2 */
        CHECK_CLOSE(d, want, 35, 256);
        CHECK(printed_defect_excludes_zero(p->message) == 1);
        arb_clear(d);
        arb_clear(want);
    }
    p = find_listed(&rep, VIGEN_CHECK_FAIL_SYMPLECTIC, "At", 2, 1);
    CHECK(p != NULL && !p->undecided);
    if (p) {
        arb_t want;
        arb_init(want);
        arb_set_ui(want, 1);
        arb_div_ui(want, want, 45, 256);
        CHECK_CLOSE(p->value, want, 35, 256);
        CHECK(printed_defect_excludes_zero(p->message) == 1);
        arb_clear(want);
    }
    CHECK(rep.row_fail == 1 && rep.sym_fail == 1);
    CHECK(rep.nfailures == 4);   /* two diagnoses (row sum, symplecticity), two listed failures */
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&u);
}

static void test_rk4(void)
{
    vigen_tableau t;
    make(&t, "rk4", 4, rk4_c, rk4_A, rk4_b, NULL, NULL, NULL);
    vigen_check_report rep;
    CHECK(check(&rep, &t, NULL, 8) == VIGEN_OK);
    CHECK(rep.consistent == VIGEN_CHECK_YES);
    CHECK(rep.symplectic == VIGEN_CHECK_NO);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_GENERAL), 4, 0, 0);
    /* one RK method for both parts: every bicoloured condition is the RK
     * condition of its uncoloured tree, so the separable order is 4 as well */
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_SEPARABLE), 4, 0, 0);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_A_ALONE), 4, 0, 0);
    CHECK(rep.exit_code == 0);
    vigen_check_report_clear(&rep);

    /* the same with a false claim of symplecticity: exit 1, claim problem */
    t.claim_symplectic = 1;
    t.claim_order = 4;
    CHECK(check(&rep, &t, NULL, 8) == VIGEN_OK);
    CHECK(rep.claim_order_status == VIGEN_CHECK_YES);
    CHECK(rep.claim_symplectic_status == VIGEN_CHECK_NO);
    CHECK(rep.exit_code == 1);
    int claims = 0, symp = 0;
    for (slong k = 0; k < rep.nfailures; k++) {
        claims += rep.failures[k].kind == VIGEN_CHECK_FAIL_CLAIM;
        symp += rep.failures[k].kind == VIGEN_CHECK_FAIL_SYMPLECTIC;
    }
    CHECK(claims == 1 && symp > 0);
    vigen_check_report_clear(&rep);

    /* without any claim, every failing pair is still named (the report
     * names each failing pair): with At = A the pairs are i <= j, and for RK4 all
     * ten defects b_i a_ij + b_j a_ji - b_i b_j are nonzero (-1/36, 1/9,
     * -1/18, -1/36, -1/9, 1/18, -1/18, -1/9, 1/9, -1/36) */
    t.claim_symplectic = -1;
    t.claim_order = -1;
    CHECK(check(&rep, &t, NULL, 4) == VIGEN_OK);
    CHECK(rep.exit_code == 0 && rep.sym_fail == 10);
    arb_t aij, aji, bi, bj, want;
    arb_init(aij);
    arb_init(aji);
    arb_init(bi);
    arb_init(bj);
    arb_init(want);
    int pairs = 0;
    for (slong i = 0; i < 4; i++)
        for (slong j = i; j < 4; j++) {
            eval_text(aij, rk4_A[i * 4 + j], 256);
            eval_text(aji, rk4_A[j * 4 + i], 256);
            eval_text(bi, rk4_b[i], 256);
            eval_text(bj, rk4_b[j], 256);
            arb_mul(want, bi, aij, 256);
            arb_addmul(want, bj, aji, 256);
            arb_submul(want, bi, bj, 256);
            CHECK(!arb_contains_zero(want));
            const vigen_check_failure *p = find_listed(&rep, VIGEN_CHECK_FAIL_SYMPLECTIC, "A", i + 1, j + 1);
            CHECK_MSG(p != NULL, "pair (%ld, %ld) not listed", (long)(i + 1), (long)(j + 1));
            if (p) {
                pairs++;
                CHECK_CLOSE(p->value, want, 35, 256);
                CHECK(p->has_expected && arb_is_zero(p->expected));
                CHECK(printed_defect_excludes_zero(p->message) == 1);
            }
        }
    CHECK(pairs == 10);
    char *text = render(&rep, 0);
    CHECK(strstr(text, "pair (1, 1)") != NULL && strstr(text, "pair (4, 4)") != NULL);
    free(text);
    char *json = render(&rep, 1);
    CHECK(strstr(json, "\"kind\": \"symplectic\", \"matrix\": \"A\", \"row\": 3, \"col\": 4") != NULL);
    free(json);
    vigen_check_report_clear(&rep);
    arb_clear(aij);
    arb_clear(aji);
    arb_clear(bi);
    arb_clear(bj);
    arb_clear(want);
    vigen_tableau_clear(&t);

    /* 7 stages with A = 0 and b_i = 1/7: every pair has the defect
     * -b_i b_j = -1/49, 28 pairs; the text names 20 and says how many more,
     * the JSON names all 28 */
    const char *c7[7], *A7[49], *b7[7];
    for (int k = 0; k < 7; k++) c7[k] = "0", b7[k] = "1/7";
    for (int k = 0; k < 49; k++) A7[k] = "0";
    make(&t, "seven zero stages", 7, c7, A7, b7, NULL, NULL, NULL);
    CHECK(check(&rep, &t, NULL, 2) == VIGEN_OK);
    CHECK(rep.sym_fail == 28);
    slong listed = 0;
    for (slong k = 0; k < rep.nfailures; k++) listed += rep.failures[k].kind == VIGEN_CHECK_FAIL_SYMPLECTIC;
    CHECK(listed == 28);
    text = render(&rep, 0);
    slong lines = 0;
    for (const char *q = strstr(text, "  pair ("); q; q = strstr(q + 1, "  pair (")) lines++;
    CHECK_MSG(lines == 20, "%ld pair lines", (long)lines);
    CHECK(strstr(text, "and 8 more pairs") != NULL);
    free(text);
    json = render(&rep, 1);
    slong in_json = 0;
    for (const char *q = strstr(json, "\"kind\": \"symplectic\""); q; q = strstr(q + 1, "\"kind\": \"symplectic\""))
        in_json++;
    CHECK(in_json == 28);
    free(json);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);
}

static void test_ruth3(void)
{
    /* kicks p += bt_j h g(Q_j) with bt = (7/24, 3/4, -1/24), then drifts
     * q += b_j h f(P_j) with b = (2/3, -2/3, 1): at_ij = bt_j for j <= i,
     * a_ij = b_j for j < i */
    const char *b[] = {"2/3", "-2/3", "1"}, *bt[] = {"7/24", "3/4", "-1/24"};
    const char *A[] = {"0", "0", "0", "2/3", "0", "0", "2/3", "-2/3", "0"};
    const char *c[] = {"0", "2/3", "0"};
    const char *At[] = {"7/24", "0", "0", "7/24", "3/4", "0", "7/24", "3/4", "-1/24"};
    const char *ct[] = {"7/24", "25/24", "1"};
    vigen_tableau t;
    make(&t, "ruth3", 3, c, A, b, At, ct, bt);
    t.claim_order = 3;
    t.claim_symplectic = 1;
    vigen_check_report rep;
    CHECK(check(&rep, &t, NULL, 8) == VIGEN_OK);
    CHECK(rep.consistent == VIGEN_CHECK_YES);
    CHECK(rep.symplectic == VIGEN_CHECK_NO);              /* bt != b */
    CHECK(rep.symplectic_separable == VIGEN_CHECK_YES);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_SEPARABLE), 3, 0, 0);
    CHECK(order_of(&rep, VIGEN_CHECK_GENERAL)->value <= 3);
    CHECK(rep.claim_order_status == VIGEN_CHECK_YES);
    CHECK(rep.claim_symplectic_status == VIGEN_CHECK_YES && rep.claim_symplectic_separable);
    CHECK(rep.exit_code == 0);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);
}

static void test_claims(void)
{
    vigen_check_report rep;
    vigen_tableau t;
    make(&t, "gauss2", 2, gauss2_c, gauss2_A, gauss2_b, NULL, NULL, NULL);
    t.claim_order = 3;   /* wrong label: the order is 4 */
    CHECK(check(&rep, &t, NULL, 8) == VIGEN_OK);
    CHECK(rep.claim_order_status == VIGEN_CHECK_NO && rep.exit_code == 1);
    vigen_check_report_clear(&rep);
    t.claim_order = 4;
    CHECK(check(&rep, &t, NULL, 2) == VIGEN_OK);   /* max_order raised to 5 for the claim */
    CHECK(rep.max_order == 5);
    CHECK(rep.claim_order_status == VIGEN_CHECK_YES && rep.exit_code == 0);
    /* exact entries: certain, nothing within the precision of data */
    CHECK(!rep.claim_order_within_data && !order_of(&rep, VIGEN_CHECK_GENERAL)->within_data);
    vigen_check_report_clear(&rep);
    t.claim_order = 5;   /* Gauss-2 has order 4 */
    CHECK(check(&rep, &t, NULL, 2) == VIGEN_OK);
    CHECK(rep.claim_order_status == VIGEN_CHECK_NO && rep.exit_code == 1);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);

    /* order = p means the order is p, so order p + 1 must be seen to fail.
     * Gauss-6 has order 12 (Hairer-Wanner II, IV.5): a claim of order 10 is
     * refuted only by conditions of order 11 holding, which for balls with a
     * radius (not exact data) is not certain: the claim is undecided, exit 1 */
    gauss_balls(&t, 6, 192);
    t.claim_order = 10;
    double t0 = now();
    CHECK(check(&rep, &t, NULL, 8) == VIGEN_OK);
    printf("gauss6, claim order = 10 (orders <= 11): %.3f s\n", now() - t0);
    CHECK(rep.max_order == 11);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_GENERAL), 11, 1, 0);
    CHECK(rep.claim_order_status == VIGEN_CHECK_UNDECIDED && !rep.claim_order_beyond && rep.exit_code == 1);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);

    /* Gauss-4 has order 8.  A claim of order 16 is refuted although orders
     * up to --max-order 8 hold: the bushy tree of order 9 fails (a 4-point
     * quadrature is exact to degree 7 at most); with --max-order 10 the order
     * 8 is found by the trees and the claim is false */
    gauss_balls(&t, 4, 192);
    t.claim_order = 16;
    CHECK(check(&rep, &t, NULL, 8) == VIGEN_OK);
    CHECK(rep.max_order == 8);
    CHECK(rep.claim_order_status == VIGEN_CHECK_NO && !rep.claim_order_beyond && rep.exit_code == 1);
    CHECK(rep.theorem.bushy_fail[0] == 9 && rep.theorem.bushy_fail[1] == 9);
    const vigen_check_failure *p = NULL;
    for (slong k = 0; k < rep.nfailures; k++)
        if (rep.failures[k].kind == VIGEN_CHECK_FAIL_CLAIM) p = rep.failures + k;
    CHECK(p != NULL && !p->undecided && strstr(p->message, "bushy tree of order 9") != NULL);
    vigen_check_report_clear(&rep);
    CHECK(check(&rep, &t, NULL, 10) == VIGEN_OK);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_GENERAL), 8, 0, 0);
    CHECK(rep.claim_order_status == VIGEN_CHECK_NO && !rep.claim_order_beyond);
    vigen_check_report_clear(&rep);
    t.claim_order = 8;   /* true: order 9 fails */
    CHECK(check(&rep, &t, NULL, 2) == VIGEN_OK);
    CHECK(rep.max_order == 9 && rep.claim_order_status == VIGEN_CHECK_YES && rep.exit_code == 0);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);
}

static void test_collocation_and_speed(void)
{
    vigen_check_report rep;
    vigen_tableau t;
    /* Gauss-8 at 128 bits, orders 1..8: every condition is evaluated */
    gauss_balls(&t, 8, 128);
    double t0 = now();
    CHECK(check(&rep, &t, NULL, 8) == VIGEN_OK);
    double t1 = now();
    printf("gauss8 (8 stages), orders <= 8 at %ld bits: %.3f s (%ld evaluations)\n", (long)rep.prec, t1 - t0,
           (long)rep.rounds);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_GENERAL), 8, 1, 0);
    CHECK(rep.symplectic == VIGEN_CHECK_YES);
    CHECK_LEVEL(&rep.B[0], 16, 0, 0);
    CHECK_LEVEL(&rep.C[0], 8, 0, 0);
    CHECK_LEVEL(&rep.D[0], 8, 0, 0);
    CHECK(rep.orders[0].hold[8] == 18996);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);

    /* order 10: Gauss-4 has order exactly 8, Gauss-5 order 10 */
    gauss_balls(&t, 4, 192);
    t0 = now();
    CHECK(check(&rep, &t, NULL, 10) == VIGEN_OK);
    t1 = now();
    printf("gauss4, orders <= 10: %.3f s\n", t1 - t0);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_GENERAL), 8, 0, 0);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_SEPARABLE), 8, 0, 0);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);

    gauss_balls(&t, 5, 192);
    t0 = now();
    CHECK(check(&rep, &t, NULL, 10) == VIGEN_OK);
    t1 = now();
    printf("gauss5, orders <= 10 (all 570040 conditions): %.3f s\n", t1 - t0);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_GENERAL), 10, 1, 0);
    CHECK(rep.orders[0].hold[10] == 433196);
    CHECK(rep.orders[VIGEN_CHECK_SEPARABLE].hold[10] == 2 * 719);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);
}

int main(void)
{
    test_symplectic_euler();
    test_stormer_verlet();
    test_gauss_exact();
    test_lobatto3();
    test_rk4();
    test_ruth3();
    test_claims();
    test_collocation_and_speed();
    TEST_MAIN_END();
}
