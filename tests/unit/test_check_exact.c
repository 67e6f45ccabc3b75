/* test_check_exact.c — the checker on proofs on exact entries: rational tableaux (the denominator bound), one
 * real quadratic field (the conjugate tableau), the refinement of exact conditions, small parts of entries.
 * Sources of the expected values: test_check_support.h. */
#include "test_check_support.h"

/* A rational perturbation far below the first precision: at_11 = 1/6 +
 * 10^-60 = (5 10^59 + 3)/(3 10^60).  The common denominator (with 24 from
 * the other entries) becomes 3 10^60, so no condition on the
 * perturbed entry can be proved 0 at low precision; the precision rises until
 * the row sum of At and the symplecticity pairs through at_11 fail, and the
 * untouched conditions (A's row sums, sum b = 1) are still proved. */
#define ZEROS10 "0000000000"
#define ZEROS60 ZEROS10 ZEROS10 ZEROS10 ZEROS10 ZEROS10 ZEROS10
static void test_rational_tiny_perturbation(void)
{
    const char *bad[9];
    memcpy(bad, lob3B_A, sizeof(bad));
    bad[0] = "1/6 + 10^-60";
    vigen_tableau u;
    make(&u, "lobatto IIIA-IIIB 3, 1e-60 off", 3, lob3_c, lob3A_A, lob3_b, bad, lob3B_c, NULL);
    vigen_check_report rep;
    CHECK(check(&rep, &u, NULL, 4) == VIGEN_OK);
    CHECK(rep.rational_denominator != NULL && strcmp(rep.rational_denominator, "3" ZEROS60) == 0);
    CHECK(rep.consistent == VIGEN_CHECK_NO && rep.symplectic == VIGEN_CHECK_NO && rep.exit_code == 1);
    const vigen_check_failure *p = find_listed(&rep, VIGEN_CHECK_FAIL_ROWSUM, "At", 1, 0);
    if (p == NULL) p = find_problem(&rep, VIGEN_CHECK_FAIL_ROWSUM, "At", 1, 1);
    CHECK(p != NULL && !p->undecided);
    CHECK(rep.proved > 0 && rep.row_fail >= 1 && rep.sym_fail >= 1);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&u);
}

/* Entries in one real quadratic field: holds are proved with the conjugate
 * tableau (v v' (D^k g)^2 is an integer).  Gauss-2 lies in Q(sqrt 3) with
 * common denominator 12 (of 1/4, 1/6, 1/2), Gauss-3 in Q(sqrt 15) with 360 =
 * lcm(36, 9, 15, 30, 24, 10, 18).  Perturbed copies must fail exactly where
 * the perturbation enters: row 1 of A and the pair (1, 1), each by eps
 * (b_1 = 1/2: 2 b_1 (a_11 + eps) - b_1^2 = eps). */
static void test_quadratic_proofs(void)
{
    vigen_check_report rep;
    vigen_tableau t;
    make(&t, "gauss2", 2, gauss2_c, gauss2_A, gauss2_b, gauss2_A, gauss2_c, NULL);
    t.claim_order = 4;
    t.claim_symplectic = 1;
    CHECK(check(&rep, &t, NULL, 8) == VIGEN_OK);
    CHECK(in_field(&rep, "3", "12"));
    CHECK(rep.rounds == 1 && rep.prec == 128 && rep.proved > 0);
    CHECK(rep.consistent == VIGEN_CHECK_YES && rep.symplectic == VIGEN_CHECK_YES && rep.exit_code == 0);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_GENERAL), 4, 0, 0);
    CHECK(rep.orders[0].hold[4] == 52 && rep.orders[0].fail[5] > 0);
    char *text = render(&rep, 0), *json = render(&rep, 1);
    CHECK(strstr(text, "in Q(sqrt(3))") != NULL && strstr(text, "D = 12") != NULL &&
          strstr(text, "conjugate tableau") != NULL);
    CHECK(strstr(json, "\"quadratic_field\": \"sqrt(3)\", \"denominator\": \"12\", \"proved\": ") != NULL);
    CHECK(strstr(json, "rational_denominator") == NULL);
    free(text);
    free(json);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);

    make(&t, "gauss3", 3, gauss3_c, gauss3_A, gauss3_b, NULL, NULL, NULL);
    CHECK(check(&rep, &t, NULL, 8) == VIGEN_OK);
    CHECK(in_field(&rep, "15", "360"));   /* order, B, C, D: test_gauss_exact */
    CHECK(rep.rounds == 1 && rep.proved > 0 && rep.symplectic == VIGEN_CHECK_YES);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_GENERAL), 6, 0, 0);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);

    /* Radau IIA, s = 3 (Hairer-Wanner II, Table IV.5.6), in Q(sqrt 6) with D
     * = lcm(10, 360, 1800, 225, 36, 9) = 1800: order 2s - 1 = 5, B(5), C(3),
     * D(2); not symplectic (b_i a_ij + b_j a_ji = b_i b_j fails) */
    {
        const char *c[] = {"(4 - sqrt(6))/10", "(4 + sqrt(6))/10", "1"};
        const char *A[] = {"(88 - 7*sqrt(6))/360", "(296 - 169*sqrt(6))/1800", "(-2 + 3*sqrt(6))/225",
                           "(296 + 169*sqrt(6))/1800", "(88 + 7*sqrt(6))/360", "(-2 - 3*sqrt(6))/225",
                           "(16 - sqrt(6))/36", "(16 + sqrt(6))/36", "1/9"};
        const char *b[] = {"(16 - sqrt(6))/36", "(16 + sqrt(6))/36", "1/9"};
        make(&t, "radau IIA 3", 3, c, A, b, NULL, NULL, NULL);
        CHECK(check(&rep, &t, NULL, 8) == VIGEN_OK);
        CHECK(in_field(&rep, "6", "1800"));
        CHECK(rep.rounds == 1 && rep.proved > 0);
        CHECK(rep.consistent == VIGEN_CHECK_YES && rep.symplectic == VIGEN_CHECK_NO);
        CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_GENERAL), 5, 0, 0);
        CHECK_LEVEL(&rep.B[0], 5, 0, 0);
        CHECK_LEVEL(&rep.C[0], 3, 0, 0);
        CHECK_LEVEL(&rep.D[0], 2, 0, 0);
        vigen_check_report_clear(&rep);
        vigen_tableau_clear(&t);
    }

    /* a_11 + eps.  1/10^60 (rational) and sqrt(3)/10^60 keep the field and
     * raise D to 3 10^60.  (2 - sqrt 3)^100 ~ 6e-58 is an algebraic integer
     * (D stays 12) whose conjugate (2 + sqrt 3)^100 ~ 2e57 is large: the
     * denominator bound alone would take its ball at 128 bits for 0, the
     * conjugate's bound must not.  From 128 bits none of them is visible at
     * first. */
    static const char *const eps_texts[] = {"1/10^60", "sqrt(3)/10^60", "(2 - sqrt(3))^100"};
    static const char *const dens[] = {"3" ZEROS60, "3" ZEROS60, "12"};
    arb_t eps;
    arb_init(eps);
    for (int e = 0; e < 3; e++)
        for (int start = 0; start < 2; start++) {
            char *a11 = vigen_strdup_printf("1/4 + %s", eps_texts[e]);
            const char *A[] = {a11, gauss2_A[1], gauss2_A[2], gauss2_A[3]};
            make(&t, "gauss2, a11 + eps", 2, gauss2_c, A, gauss2_b, NULL, NULL, NULL);
            t.claim_order = 4;
            t.claim_symplectic = 1;
            CHECK(check_prec(&rep, &t, NULL, 6, start ? 128 : 0, 0) == VIGEN_OK);
            CHECK_MSG(in_field(&rep, "3", dens[e]), "%s: field %s, D = %s", a11,
                      rep.quadratic_d ? rep.quadratic_d : "none",
                      rep.quadratic_denominator ? rep.quadratic_denominator : "none");
            CHECK_MSG(rep.consistent == VIGEN_CHECK_NO && rep.symplectic == VIGEN_CHECK_NO && rep.exit_code == 1,
                      "%s from %s", a11, start ? "128 bits" : "the default");
            CHECK(rep.row_fail == 1 && rep.sym_fail == 1 && rep.row_undecided == 0 && rep.sym_undecided == 0);
            CHECK(rep.claim_order_status == VIGEN_CHECK_NO && rep.claim_symplectic_status == VIGEN_CHECK_NO);
            CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_GENERAL), 1, 0, 0);   /* b[b]: sum b_i a_ij = 1/2 + eps/2 */
            eval_text(eps, eps_texts[e], 2048);
            check_a11_defects(&rep, eps);
            /* what does not involve a_11 is still proved */
            CHECK(rep.proved > 0);
            vigen_check_report_clear(&rep);
            vigen_tableau_clear(&t);
            free(a11);
        }

    /* The same unit eps = (2 - sqrt 3)^100 where every other condition is
     * exact or fails visibly, so that nothing else asks for a second round:
     * the midpoint rule (c, A, b) = (1/2, 1/2, 1) with at_11 = 1 + eps, ct_1
     * = bt_1 = 1.  Only the row sum of At (at_11 - ct_1 = eps) and C(1) of
     * (ct, At, bt), the same sum, have a tiny value, 2^-190; no order
     * condition involving at_11 is near 0 (bt at_11 = 1 + eps against 1/2,
     * and at order 3 powers of 1/2 against 1/3 and 1/6), the pair (1, 1) is
     * 1/2 + eps.  At 128 bits the row sum's ball contains 0; were it taken
     * for 0 (as |v| D^k g < 1 alone would, D = 2), the round would end there
     * with the row sums holding. */
    {
        const char *c[] = {"1/2"}, *A[] = {"1/2"}, *b[] = {"1"};
        const char *At[] = {"1 + (2 - sqrt(3))^100"}, *ct[] = {"1"}, *bt[] = {"1"};
        make(&t, "midpoint, at11 = 1 + (2 - sqrt 3)^100", 1, c, A, b, At, ct, bt);
        CHECK(check_prec(&rep, &t, NULL, 3, 128, 0) == VIGEN_OK);
        CHECK(in_field(&rep, "3", "2"));
        CHECK(rep.consistent == VIGEN_CHECK_NO && rep.row_fail == 1 && rep.row_undecided == 0);
        CHECK(rep.rounds >= 2 && rep.prec >= 256);
        eval_text(eps, "(2 - sqrt(3))^100", 2048);
        check_rowsum_defect(&rep, "At", 1, eps);
        CHECK_LEVEL(&rep.C[1], 0, 0, 0);
        CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_A_ALONE), 2, 0, 0);   /* the midpoint rule */
        vigen_check_report_clear(&rep);
        vigen_tableau_clear(&t);
    }

    /* Gauss-2 written with sqrt(2) as well (sqrt(6)/sqrt(2) = sqrt(3)): no
     * single field is recognised, so no proof; the numeric rule still finds
     * order 4 and symplecticity, confirmed at a second precision of >= 1024
     * bits.  With a_11 + sqrt(2)/10^60 it fails where it must. */
    const char *Amix[] = {gauss2_A[0], "1/4 - sqrt(6)/(6*sqrt(2))", gauss2_A[2], gauss2_A[3]};
    make(&t, "gauss2, sqrt(2) and sqrt(3)", 2, gauss2_c, Amix, gauss2_b, NULL, NULL, NULL);
    CHECK(check(&rep, &t, NULL, 6) == VIGEN_OK);
    CHECK(rep.quadratic_d == NULL && rep.rational_denominator == NULL && rep.proved == 0);
    CHECK(rep.rounds >= 2 && rep.prec >= 1024);
    CHECK(rep.consistent == VIGEN_CHECK_YES && rep.symplectic == VIGEN_CHECK_YES);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_GENERAL), 4, 0, 0);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);
    const char *A2[] = {"1/4 + sqrt(2)/10^60", gauss2_A[1], gauss2_A[2], gauss2_A[3]};
    make(&t, "gauss2, a11 + sqrt(2)/10^60", 2, gauss2_c, A2, gauss2_b, NULL, NULL, NULL);
    CHECK(check(&rep, &t, NULL, 6) == VIGEN_OK);
    CHECK(rep.quadratic_d == NULL && rep.rational_denominator == NULL && rep.proved == 0);
    CHECK(rep.consistent == VIGEN_CHECK_NO && rep.symplectic == VIGEN_CHECK_NO);
    CHECK(rep.row_fail == 1 && rep.sym_fail == 1);
    eval_text(eps, "sqrt(2)/10^60", 2048);
    check_a11_defects(&rep, eps);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);
    arb_clear(eps);
}

/* Exact entries: a condition holds only when its ball is tight and the same
 * verdicts come out at two precisions. */
static void test_exact_refinement(void)
{
    vigen_check_report rep;
    vigen_tableau t, ref;
    /* an exact entry that 128 bits cannot resolve: c = exp(100) + 1/2 - exp(100)
     * is decided after raising the precision */
    const char *c1[] = {"exp(100) + 1/2 - exp(100)"};
    make(&t, "gauss1, cancellation", 1, c1, gauss1_A, gauss1_b, NULL, NULL, NULL);
    CHECK(check(&rep, &t, NULL, 4) == VIGEN_OK);
    CHECK(rep.rounds >= 2 && rep.prec >= 256);
    CHECK(rep.consistent == VIGEN_CHECK_YES);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_GENERAL), 2, 0, 0);
    CHECK_LEVEL(&rep.C[0], 1, 0, 0);
    CHECK(rep.holds[VIGEN_CHECK_SECT_ROWSUM].exact == 2 && rep.holds[VIGEN_CHECK_SECT_ROWSUM].data == 0);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);

    /* Gauss-2 with a_11 = 1/4 + 1/10^45: the row sum of row 1 and the pair
     * (1, 1) (2 b_1 a_11 - b_1^2 = 1/10^45) are off by exactly 1/10^45; found
     * from the default start, and from --prec 128 (where every ball contains
     * 0 with a radius near 2^-128) by confirming at higher precision */
    const char *A45[] = {"1/4 + 1/10^45", "1/4 - sqrt(3)/6", "1/4 + sqrt(3)/6", "1/4"};
    arb_t eps;
    arb_init(eps);
    eval_text(eps, "1/10^45", 512);
    make(&ref, "gauss2", 2, gauss2_c, gauss2_A, gauss2_b, NULL, NULL, NULL);
    for (int start = 0; start < 2; start++) {
        make(&t, "gauss2, a11 + 1e-45", 2, gauss2_c, A45, gauss2_b, NULL, NULL, NULL);
        t.claim_order = 4;
        t.claim_symplectic = 1;
        CHECK(check_prec(&rep, &t, NULL, 6, start ? 128 : 0, 0) == VIGEN_OK);
        CHECK_MSG(rep.consistent == VIGEN_CHECK_NO && rep.symplectic == VIGEN_CHECK_NO, "start %d", start);
        CHECK(rep.exit_code == 1);
        check_a11_defects(&rep, eps);
        CHECK(rep.claim_order_status == VIGEN_CHECK_NO && rep.claim_symplectic_status == VIGEN_CHECK_NO);
        CHECK(rep.prec > 150);   /* 10^-45 is about 2^-149.5 */
        if (start) CHECK(rep.rounds >= 2);
        vigen_check_report_clear(&rep);

        /* --against has the same blind spot: the exact Gauss-2 differs in A[1][1] */
        CHECK(check_prec(&rep, &ref, &t, 6, start ? 128 : 0, 0) == VIGEN_OK);
        CHECK(rep.against_differences == 1 && rep.exit_code == 1);
        CHECK(find_listed(&rep, VIGEN_CHECK_FAIL_AGAINST, "A", 1, 1) != NULL);
        vigen_check_report_clear(&rep);
        vigen_tableau_clear(&t);
    }
    /* the exact Gauss-2 agrees with itself, exactly */
    vigen_tableau ref2;
    make(&ref2, "gauss2", 2, gauss2_c, gauss2_A, gauss2_b, NULL, NULL, NULL);
    CHECK(check(&rep, &ref, &ref2, 6) == VIGEN_OK);
    CHECK(rep.against_differences == 0 && rep.against_undecided == 0 && rep.exit_code == 0);
    CHECK(rep.holds[VIGEN_CHECK_SECT_AGAINST].exact == 8);   /* c, A, b */
    /* the holding exact conditions were confirmed at a second precision, of 1024 bits or more */
    CHECK(rep.rounds >= 2 && rep.prec >= 1024);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&ref2);

    /* a_11 = 1/4 + e^-110 (about 1.7e-48 = 2^-158.7): no literal shows the
     * size, but the starting precision covers the span of the entry's parts
     * (2^2 down to 2^-159), so the first round already sees the defect */
    const char *Ae[] = {"1/4 + exp(-110)", "1/4 - sqrt(3)/6", "1/4 + sqrt(3)/6", "1/4"};
    make(&t, "gauss2, a11 + exp(-110)", 2, gauss2_c, Ae, gauss2_b, NULL, NULL, NULL);
    CHECK(check(&rep, &t, NULL, 6) == VIGEN_OK);
    CHECK(rep.prec_first >= 160 + 64);
    CHECK(rep.consistent == VIGEN_CHECK_NO && rep.symplectic == VIGEN_CHECK_NO);
    eval_text(eps, "exp(-110)", 1024);
    check_rowsum_defect(&rep, "A", 1, eps);
    vigen_check_report_clear(&rep);
    CHECK(check(&rep, &ref, &t, 6) == VIGEN_OK);
    CHECK(rep.against_differences == 1);
    vigen_check_report_clear(&rep);

    /* with the refinement capped at 256 bits the round at 256 bits cannot be
     * confirmed: the failure is certain, what held at 128 bits only is
     * reported undecided (never "holds") */
    CHECK(check_prec(&rep, &t, NULL, 4, 128, 128) == VIGEN_OK);
    CHECK(rep.prec == 256 && rep.consistent == VIGEN_CHECK_NO);
    CHECK(find_listed(&rep, VIGEN_CHECK_FAIL_ROWSUM, "A", 1, 0) != NULL);
    CHECK(rep.undecided_left > 0 && rep.undecided_reason && strstr(rep.undecided_reason, "cap") != NULL);
    /* row 2 (a_21 + a_22 = 1/2 + sqrt(3)/6 = c_2, true but with a radius) is
     * undecided; sum b = 1/2 + 1/2 is exact (radius 0) and holds */
    CHECK(rep.row_fail == 1 && rep.row_undecided == 1 && rep.holds[VIGEN_CHECK_SECT_ROWSUM].exact == 1);
    CHECK(rep.exit_code == 1);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);
    vigen_tableau_clear(&ref);
    arb_clear(eps);
}

/* b = 1/2 +- exp(-2000) (about 2^-2886): the starting precision covers the
 * span of the entries' parts, so the defects of sum b c = 1/2 and of
 * symplecticity (~1e-869) are found instead of being taken for holds at the
 * 1024-bit confirmation (which a reviewer showed happened before). */
static void test_hidden_small_part(void)
{
    const char *b[] = {"1/2 + exp(-2000)", "1/2 - exp(-2000)"};
    vigen_tableau t;
    make(&t, "gauss2, b +- exp(-2000)", 2, gauss2_c, gauss2_A, b, NULL, NULL, NULL);
    t.claim_symplectic = 1;   /* refuted: exit status 1 */
    vigen_check_report rep;
    CHECK(check(&rep, &t, NULL, 6) == VIGEN_OK);
    CHECK(rep.prec_first >= 2886);
    CHECK(rep.symplectic == VIGEN_CHECK_NO && rep.exit_code == 1);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_GENERAL), 1, 0, 0);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);
}

int main(void)
{
    test_rational_tiny_perturbation();
    test_quadratic_proofs();
    test_exact_refinement();
    test_hidden_small_part();
    TEST_MAIN_END();
}
