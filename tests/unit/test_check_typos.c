/* test_check_typos.c — the checker on misprinted and rounded entries: a perturbed entry found and
 * repaired (the diagnosis), other typos, rounded decimals held within the precision of the data, data too short.
 * Sources of the expected values: test_check_support.h. */
#include "test_check_support.h"

/* 40-digit Gauss-3 with a perturbation of 1e-30 in A[2][3]. */
static void test_perturbed_gauss3(void)
{
    slong prec = 256, s = 3;
    char *c40[3], *A40[9], *b40[3];
    arb_t x, eps;
    arb_init(x);
    arb_init(eps);
    vigen_error err;
    vigen_error_init(&err);
    for (slong k = 0; k < s; k++) {
        CHECK(vigen_expr_eval_string(x, gauss3_c[k], prec, &err) == VIGEN_OK);
        c40[k] = vigen_decimal_format(x, 40);
        CHECK(vigen_expr_eval_string(x, gauss3_b[k], prec, &err) == VIGEN_OK);
        b40[k] = vigen_decimal_format(x, 40);
    }
    for (slong k = 0; k < s * s; k++) {
        CHECK(vigen_expr_eval_string(x, gauss3_A[k], prec, &err) == VIGEN_OK);
        if (k == 1 * 3 + 2) {
            arb_set_str(eps, "1e-30", prec);
            arb_add(x, x, eps, prec);
        }
        A40[k] = vigen_decimal_format(x, 40);
    }
    for (slong k = 0; k < s; k++) CHECK(c40[k] && b40[k]);
    for (slong k = 0; k < s * s; k++) CHECK(A40[k] != NULL);

    vigen_tableau t, exact;
    make(&t, "gauss3, 40 digits, perturbed", 3, (const char *const *)c40, (const char *const *)A40,
         (const char *const *)b40, NULL, NULL, NULL);
    t.claim_order = 6;
    t.claim_symplectic = 1;
    make(&exact, "gauss3", 3, gauss3_c, gauss3_A, gauss3_b, NULL, NULL, NULL);
    vigen_check_report rep;
    CHECK(check(&rep, &t, &exact, 8) == VIGEN_OK);
    CHECK(rep.consistent == VIGEN_CHECK_NO);
    CHECK(rep.symplectic == VIGEN_CHECK_NO);
    CHECK(rep.exit_code == 1);
    const vigen_check_failure *p = find_problem(&rep, VIGEN_CHECK_FAIL_ROWSUM, "A", 2, 3);
    const vigen_check_failure *q = find_problem(&rep, VIGEN_CHECK_FAIL_SYMPLECTIC, "A", 2, 3);
    const vigen_check_failure *r = find_problem(&rep, VIGEN_CHECK_FAIL_AGAINST, "A", 2, 3);
    CHECK(p != NULL && p->diagnosed);
    CHECK(q != NULL && q->diagnosed);
    CHECK(r != NULL);
    CHECK(rep.against_differences == 1);
    if (p) {
        /* the value asked for is the exact a_23 to the precision of the file */
        CHECK(vigen_expr_eval_string(x, gauss3_A[5], prec, &err) == VIGEN_OK);
        CHECK_CLOSE(p->expected, x, 38, prec);
        CHECK(!testlib_arb_close(p->value, x, 31, prec));
        CHECK(strstr(p->message, "A[2][3] = ") != NULL && strstr(p->message, "both ask for") != NULL);
    }
    /* claims: the order fell to 1, the symplecticity claim fails */
    CHECK(rep.claim_order_status == VIGEN_CHECK_NO && rep.claim_symplectic_status == VIGEN_CHECK_NO);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_GENERAL), 1, 0, 0);
    char *text = render(&rep, 0);
    printf("--- text report of the perturbed 40-digit Gauss-3 ---\n%s", text);
    CHECK(strstr(text, "A[2][3]") != NULL);
    free(text);
    char *json = render(&rep, 1);
    CHECK(strstr(json, "\"kind\": \"rowsum\", \"matrix\": \"A\", \"row\": 2, \"col\": 3") != NULL);
    CHECK(strstr(json, "\"kind\": \"against\"") != NULL);
    CHECK(strstr(json, "\"consistent\": false") != NULL);
    free(json);
    vigen_check_report_clear(&rep);

    /* unperturbed 40 digits: everything holds to the precision of the file,
     * and agrees with the exact tableau */
    vigen_tableau good;
    CHECK(vigen_expr_eval_string(x, gauss3_A[5], prec, &err) == VIGEN_OK);
    free(A40[5]);
    A40[5] = vigen_decimal_format(x, 40);
    make(&good, "gauss3, 40 digits", 3, (const char *const *)c40, (const char *const *)A40,
         (const char *const *)b40, NULL, NULL, NULL);
    good.claim_order = 6;
    good.claim_symplectic = 1;
    CHECK(check(&rep, &good, &exact, 8) == VIGEN_OK);
    CHECK(rep.consistent == VIGEN_CHECK_YES && rep.symplectic == VIGEN_CHECK_YES);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_GENERAL), 6, 0, 0);
    CHECK(rep.against_differences == 0 && rep.nfailures == 0 && rep.exit_code == 0);
    json = render(&rep, 1);
    CHECK(strstr(json, "\"order\": 6,") != NULL && strstr(json, "\"symplectic\": true") != NULL);
    CHECK(strstr(json, "\"problems\": []") != NULL);
    free(json);
    vigen_check_report_clear(&rep);

    vigen_tableau_clear(&good);
    vigen_tableau_clear(&t);
    vigen_tableau_clear(&exact);
    for (slong k = 0; k < s; k++) { free(c40[k]); free(b40[k]); }
    for (slong k = 0; k < s * s; k++) free(A40[k]);
    arb_clear(x);
    arb_clear(eps);
    vigen_error_clear(&err);
}

static void test_other_typos(void)
{
    vigen_check_report rep;
    arb_t half, x;
    arb_init(half);
    arb_init(x);
    arb_set_ui(half, 1);
    arb_mul_2exp_si(half, half, -1);

    /* b[1] of Gauss-2 is 3/5: sum b and symplecticity (quadratic in b_1 on the
     * diagonal) agree on 1/2 */
    const char *b[] = {"3/5", "1/2"};
    vigen_tableau t;
    make(&t, "gauss2, b typo", 2, gauss2_c, gauss2_A, b, NULL, NULL, NULL);
    CHECK(check(&rep, &t, NULL, 6) == VIGEN_OK);
    const vigen_check_failure *p = find_problem(&rep, VIGEN_CHECK_FAIL_ROWSUM, "b", 1, 0);
    CHECK(p != NULL && p->diagnosed);
    if (p) CHECK_CLOSE(p->expected, half, 35, 256);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);

    /* b[1] of Gauss-2 typed as the short decimal 0.51 (the ball [0.505,
     * 0.515]): sum b = 1 and symplecticity fail; solved with b[1] as an exact
     * unknown they ask for 1/2 (b[2] = 1/2 is exact), whereas b[2] cannot
     * explain the pairs (b_2 = 1 - b_1 leaves the pair (1, 2) at about -0.003
     * .. -0.008 over the whole ball) */
    const char *b051[] = {"0.51", "1/2"};
    make(&t, "gauss2, b = 0.51", 2, gauss2_c, gauss2_A, b051, NULL, NULL, NULL);
    CHECK(check(&rep, &t, NULL, 6) == VIGEN_OK);
    CHECK(rep.consistent == VIGEN_CHECK_NO && rep.symplectic == VIGEN_CHECK_NO);
    p = find_diagnosis(&rep, VIGEN_CHECK_FAIL_ROWSUM);
    CHECK(p != NULL && strcmp(p->matrix, "b") == 0 && p->row == 1);
    if (p) {
        CHECK_CLOSE(p->expected, half, 35, 256);
        CHECK(strstr(p->message, "b[1] = 0.51;") != NULL);
    }
    /* the messages of failed conditions print defects that visibly exclude 0 */
    for (slong k = 0; k < rep.nfailures; k++) {
        const vigen_check_failure *q = rep.failures + k;
        if (q->kind == VIGEN_CHECK_FAIL_CLAIM || q->diagnosed) continue;
        CHECK_MSG(printed_defect_excludes_zero(q->message) == 1, "%s", q->message);
        CHECK_MSG(strstr(q->message, "+/-") == NULL, "%s", q->message);
    }
    /* the pair (1, 1), 2 b_1 a_11 - b_1^2 = b_1 (1/2 - b_1), ranges over
     * [-0.007725, -0.002525] for b_1 in [0.505, 0.515]: it fails (b_1 occurs
     * three times, but is one number) */
    p = find_listed(&rep, VIGEN_CHECK_FAIL_SYMPLECTIC, "A", 1, 1);
    CHECK(p != NULL);
    if (p) {
        arb_t lo, hi;
        arb_init(lo);
        arb_init(hi);
        arb_set_str(lo, "-0.007725", 128);
        arb_set_str(hi, "-0.002525", 128);
        CHECK(!arb_contains_zero(p->value) && arb_contains(p->value, lo) && arb_contains(p->value, hi));
        arb_clear(lo);
        arb_clear(hi);
    }
    /* sum b = 0.51 + 1/2 lies in [1.005, 1.015]: its defect in [0.005, 0.015] */
    p = find_listed(&rep, VIGEN_CHECK_FAIL_ROWSUM, "b", 0, 0);
    CHECK(p != NULL && strstr(p->message, "defect in [0.00499, 0.0151]") != NULL);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);

    /* c[1] of Gauss-2 is 1/2 - sqrt(3)/5: only the row sum, only c[1] */
    const char *c[] = {"1/2 - sqrt(3)/5", "1/2 + sqrt(3)/6"};
    make(&t, "gauss2, c typo", 2, c, gauss2_A, gauss2_b, NULL, NULL, NULL);
    CHECK(check(&rep, &t, NULL, 6) == VIGEN_OK);
    p = find_problem(&rep, VIGEN_CHECK_FAIL_ROWSUM, "c", 1, 0);
    CHECK(p != NULL && p->diagnosed);
    vigen_error err;
    vigen_error_init(&err);
    CHECK(vigen_expr_eval_string(x, gauss2_c[0], 256, &err) == VIGEN_OK);
    if (p) CHECK_CLOSE(p->expected, x, 35, 256);
    CHECK(rep.symplectic == VIGEN_CHECK_YES);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);

    /* two typos: no single entry explains them; the failures are listed */
    const char *A2[] = {"1/4", "1/4 - sqrt(3)/6", "1/4 + sqrt(3)/5", "1/3"};
    make(&t, "gauss2, two typos", 2, gauss2_c, A2, gauss2_b, NULL, NULL, NULL);
    CHECK(check(&rep, &t, NULL, 6) == VIGEN_OK);
    int diagnosed = 0;
    for (slong k = 0; k < rep.nfailures; k++) diagnosed |= rep.failures[k].diagnosed;
    CHECK(!diagnosed);
    CHECK(find_problem(&rep, VIGEN_CHECK_FAIL_ROWSUM, "A", 2, 0) != NULL);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);
    vigen_error_clear(&err);
    arb_clear(half);
    arb_clear(x);
}

/* Rounded decimal data: a condition holds within the precision of the data
 * when its ball, which carries the half-ulp radii of the entries, contains 0. */
static void test_rounded_data(void)
{
    vigen_check_report rep;
    vigen_tableau t;
    /* Gauss-2 to 6 digits: the conditions of order <= 4 hold within the
     * precision of the data, those of order 5 fail (Gauss-2 has order 4) */
    const char *c[] = {"0.211325", "0.788675"};
    const char *A[] = {"0.250000", "-0.0386751", "0.538675", "0.250000"};
    const char *b[] = {"0.500000", "0.500000"};
    make(&t, "gauss2, 6 digits", 2, c, A, b, NULL, NULL, NULL);
    t.claim_order = 4;
    t.claim_symplectic = 1;
    CHECK(check(&rep, &t, NULL, 6) == VIGEN_OK);
    CHECK(rep.consistent == VIGEN_CHECK_YES && rep.symplectic == VIGEN_CHECK_YES);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_GENERAL), 4, 0, 0);
    CHECK(rep.claim_order_status == VIGEN_CHECK_YES && rep.claim_symplectic_status == VIGEN_CHECK_YES);
    CHECK(rep.exit_code == 0 && rep.rounds == 1 && rep.rounded_entries && !rep.exact_entries);
    /* ... and every verdict resting on such holds says so */
    CHECK(order_of(&rep, VIGEN_CHECK_GENERAL)->within_data && order_of(&rep, VIGEN_CHECK_SEPARABLE)->within_data);
    CHECK(rep.claim_order_within_data && rep.claim_symplectic_within_data);
    CHECK(rep.consistent_within_data && rep.symplectic_within_data);
    CHECK(rep.B[0].within_data && rep.stage_order[0].within_data && rep.nnotes == 0);
    /* decided within the data; the largest radius is at least the half-ulp
     * 5e-7 of c_1, which the row sum c_1 = a_11 + a_12 carries */
    CHECK(rep.holds[VIGEN_CHECK_SECT_ROWSUM].data == 3 && rep.holds[VIGEN_CHECK_SECT_ROWSUM].exact == 0);
    CHECK(mag_cmp_2exp_si(rep.holds[VIGEN_CHECK_SECT_ROWSUM].radius, -21) > 0);   /* 2^-21 = 4.8e-7 */
    CHECK(mag_cmp_2exp_si(rep.holds[VIGEN_CHECK_SECT_ROWSUM].radius, -16) < 0);
    char *text = render(&rep, 0);
    CHECK(strstr(text, "within the precision of the data") != NULL);
    free(text);
    char *json = render(&rep, 1);
    CHECK(strstr(json, "\"within_data_precision\": 3") != NULL);
    CHECK(strstr(json, "\"order_status\": \"within_data\"") != NULL);
    CHECK(strstr(json, "\"order_status\": \"exact\"") == NULL);
    free(json);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);

    /* Gauss-3 rounded to 9 digits, as `vigen generate --digits 9` writes it:
     * consistent, symplectic and of order 6 within the precision of the data
     * (the order-7 defects, such as b . c^6 - 1/7, are far above 1e-9) */
    char *c9[3], *A9[9], *b9[3];
    arb_t x;
    arb_init(x);
    for (int k = 0; k < 3; k++) {
        eval_text(x, gauss3_c[k], 256);
        c9[k] = vigen_decimal_format(x, 9);
        eval_text(x, gauss3_b[k], 256);
        b9[k] = vigen_decimal_format(x, 9);
    }
    for (int k = 0; k < 9; k++) {
        eval_text(x, gauss3_A[k], 256);
        A9[k] = vigen_decimal_format(x, 9);
    }
    make(&t, "gauss3, 9 digits", 3, (const char *const *)c9, (const char *const *)A9, (const char *const *)b9,
         (const char *const *)A9, (const char *const *)c9, NULL);
    t.claim_order = 6;
    t.claim_symplectic = 1;
    CHECK(check(&rep, &t, NULL, 8) == VIGEN_OK);
    CHECK(rep.consistent == VIGEN_CHECK_YES && rep.symplectic == VIGEN_CHECK_YES);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_GENERAL), 6, 0, 0);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_SEPARABLE), 6, 0, 0);
    CHECK(rep.claim_order_status == VIGEN_CHECK_YES && rep.exit_code == 0);
    CHECK(rep.holds[VIGEN_CHECK_SECT_ORDER].data > 0);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);
    for (int k = 0; k < 3; k++) { free(c9[k]); free(b9[k]); }
    for (int k = 0; k < 9; k++) free(A9[k]);
    arb_clear(x);
}

/* Short data: a ball containing 0 holds within the precision of the data
 * only with a radius at most 2^-10 of its terms; wider, the data are too
 * short to decide. */
static void test_short_data(void)
{
    vigen_check_report rep;
    vigen_tableau t;
    /* the threshold: one stage, b = 1 written with 3 and 4 decimals.  sum b =
     * 1 compares terms of size |b| + 1 = 2; "1.000" is 1 +/- 5e-4, a radius
     * of 2.5e-4 of the terms (below 2^-10 = 9.8e-4): it holds within the data;
     * "1.00" is 1 +/- 5e-3, 2.5e-3 of the terms: undecided */
    const char *c1[] = {"1/2"}, *A1[] = {"1/2"}, *b4[] = {"1.000"}, *b3[] = {"1.00"};
    make(&t, "midpoint, b with 3 decimals", 1, c1, A1, b4, NULL, NULL, NULL);
    CHECK(check(&rep, &t, NULL, 2) == VIGEN_OK);
    CHECK(rep.consistent == VIGEN_CHECK_YES && rep.consistent_within_data);
    CHECK(rep.holds[VIGEN_CHECK_SECT_ROWSUM].too_short == 0);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);
    make(&t, "midpoint, b with 2 decimals", 1, c1, A1, b3, NULL, NULL, NULL);
    CHECK(check(&rep, &t, NULL, 2) == VIGEN_OK);
    CHECK(rep.consistent == VIGEN_CHECK_UNDECIDED && !rep.consistent_within_data && rep.exit_code == 1);
    CHECK(rep.holds[VIGEN_CHECK_SECT_ROWSUM].too_short == 1 && rep.undecided_short > 0);
    CHECK(rep.undecided_reason != NULL && strstr(rep.undecided_reason, "too short") != NULL);
    const vigen_check_failure *p = find_listed(&rep, VIGEN_CHECK_FAIL_ROWSUM, "b", 0, 0);
    CHECK(p != NULL && p->undecided && strstr(p->message, "too short") != NULL);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);

    /* Gauss-2 with b = "0.5" (0.5 +/- 0.05) and a11 = a22 = "0.25" among
     * 16-digit entries: no 2-stage method has order 5, so neither the order 5
     * nor the claim order = 5 may be reported; the true claim order = 4 may
     * not be refuted; the short entries are named with their fractions */
    const char *c[] = {"0.2113248654051871", "0.7886751345948129"};
    const char *A[] = {"0.25", "-0.03867513459481288", "0.5386751345948129", "0.25"};
    const char *b[] = {"0.5", "0.5"};
    make(&t, "gauss2, short b", 2, c, A, b, NULL, NULL, NULL);
    t.claim_order = 5;
    CHECK(check(&rep, &t, NULL, 8) == VIGEN_OK);
    CHECK(rep.claim_order_status != VIGEN_CHECK_YES && rep.exit_code == 1);
    CHECK(order_of(&rep, VIGEN_CHECK_GENERAL)->value < 5 && order_of(&rep, VIGEN_CHECK_A_ALONE)->value < 5);
    CHECK(rep.B[0].value < 5);
    /* sum b = 1 has terms of size 2 and a radius of 0.1: 5%, too short */
    CHECK(rep.consistent == VIGEN_CHECK_UNDECIDED && rep.claim_order_too_short);
    CHECK(rep.nnotes == 4);
    if (rep.nnotes == 4) {
        CHECK(strcmp(rep.notes[0].entry, "A[1][1]") == 0 && strcmp(rep.notes[0].fraction, "1/4") == 0 &&
              strcmp(rep.notes[0].radius, "0.005") == 0 && rep.notes[0].digits == 2);
        CHECK(strcmp(rep.notes[2].entry, "b[1]") == 0 && strcmp(rep.notes[2].fraction, "1/2") == 0 &&
              strcmp(rep.notes[2].radius, "0.05") == 0 && rep.notes[2].digits == 1);
        CHECK(strstr(rep.notes[2].message, "b[1] = \"0.5\"") != NULL &&
              strstr(rep.notes[2].message, "write \"1/2\"") != NULL);
    }
    char *text = render(&rep, 0);
    CHECK(strstr(text, "order = 5: holds") == NULL && strstr(text, "note: b[1] = \"0.5\" is read as 0.5 +/- 0.05") != NULL);
    free(text);
    char *json = render(&rep, 1);
    CHECK(strstr(json, "\"exact_value\": \"1/2\"") != NULL);
    free(json);
    vigen_check_report_clear(&rep);
    t.claim_order = 4;
    CHECK(check(&rep, &t, NULL, 8) == VIGEN_OK);
    CHECK(rep.claim_order_status == VIGEN_CHECK_UNDECIDED && rep.exit_code == 1);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);

    /* the same with b and the diagonal exact: order 4 within the precision of
     * the 16-digit data (order 5 fails: sum b c^4 = 7/36, not 1/5), the claim
     * holds, within the data, exit 0; nothing short is left to name */
    const char *Ae[] = {"1/4", "-0.03867513459481288", "0.5386751345948129", "1/4"};
    const char *be[] = {"1/2", "1/2"};
    make(&t, "gauss2, exact b", 2, c, Ae, be, NULL, NULL, NULL);
    t.claim_order = 4;
    CHECK(check(&rep, &t, NULL, 8) == VIGEN_OK);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_GENERAL), 4, 0, 0);
    CHECK(order_of(&rep, VIGEN_CHECK_GENERAL)->within_data);
    CHECK(rep.claim_order_status == VIGEN_CHECK_YES && rep.claim_order_within_data && rep.exit_code == 0);
    CHECK(rep.nnotes == 0);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);
}

int main(void)
{
    test_perturbed_gauss3();
    test_other_typos();
    test_rounded_data();
    test_short_data();
    TEST_MAIN_END();
}
