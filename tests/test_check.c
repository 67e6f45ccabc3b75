/* test_check.c — the certifying checker (generator/check.c) on methods whose
 * properties are known from the literature, and on deliberately broken copies.
 *
 * Sources of the expected values (never this code's own output):
 *  - Hairer, Norsett, Wanner I (II.1) classical RK4: order 4, not symplectic;
 *  - Hairer, Wanner II (IV.5, Tables 5.1-5.2, 5.7-5.9): Gauss methods of s
 *    stages have order 2s and satisfy B(2s), C(s), D(s) (stage order s);
 *    Lobatto IIIA and IIIB of s stages have order 2s - 2, IIIA satisfies C(s),
 *    D(s - 2), IIIB C(s - 2), D(s); closed forms of the tableaux from there;
 *  - Hairer, Lubich, Wanner, Geometric Numerical Integration (I.1, II.2, VI.4):
 *    symplectic Euler (order 1) and Stormer-Verlet = Lobatto IIIA-IIIB s = 2
 *    (order 2) as symplectic PRK pairs; Thm VI.4.6: for separable H the
 *    conditions b_i at_ij + bt_j a_ji = b_i bt_j suffice for symplecticity;
 *  - Ruth, IEEE Trans. Nucl. Sci. 30 (1983): the three-stage splitting
 *    (kicks 7/24, 3/4, -1/24; drifts 2/3, -2/3, 1) has order 3 for
 *    H = T(p) + V(q);
 *  - Gauss methods computed here independently as collocation methods
 *    (Legendre roots from arb, Lagrange polynomials integrated exactly).
 */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <arb_hypgeom.h>
#include <arb_poly.h>
#include "check.h"
#include "decimal.h"
#include "expr.h"
#include "testlib.h"

/* ---------------------------------------------------------------- helpers */

static char **texts(slong n, const char *const *src)
{
    if (src == NULL) return NULL;
    char **t = calloc((size_t)n, sizeof(char *));
    for (slong k = 0; k < n; k++) t[k] = vigen_strdup(src[k]);
    return t;
}

/* A tableau from entry texts, as a hand-written file would give it. */
static void make(vigen_tableau *t, const char *name, slong s, const char *const *c, const char *const *A,
                 const char *const *b, const char *const *At, const char *const *ct, const char *const *bt)
{
    vigen_tableau_init(t, s);
    t->name = vigen_strdup(name);
    t->c_text = texts(s, c);
    t->A_text = texts(s * s, A);
    t->b_text = texts(s, b);
    t->At_text = texts(s * s, At);
    t->ct_text = texts(s, ct);
    t->bt_text = texts(s, bt);
    t->has_At = At != NULL;
    t->has_ct = ct != NULL;
    t->has_bt = bt != NULL;
}

static int check(vigen_check_report *rep, vigen_tableau *t, vigen_tableau *against, int P)
{
    vigen_check_options opt;
    vigen_check_options_init(&opt);
    opt.max_order = P;
    opt.path = t->name;
    vigen_error err;
    vigen_error_init(&err);
    vigen_check_report_init(rep);
    int rc = vigen_check_tableau(rep, t, against, &opt, &err);
    if (rc != VIGEN_OK) fprintf(stderr, "check failed: %s\n", err.message ? err.message : "?");
    vigen_error_clear(&err);
    return rc;
}

static const vigen_check_level *order_of(const vigen_check_report *rep, int family)
{
    return &rep->orders[family].level;
}

#define CHECK_LEVEL(L, v, cap, und) CHECK_MSG((L)->value == (v) && (L)->capped == (cap) && (L)->undecided == (und), \
    "level %d capped %d undecided %d, expected %d %d %d", (L)->value, (L)->capped, (L)->undecided, (v), (cap), (und))

static char *render(const vigen_check_report *rep, int json)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    if (json) vigen_check_print_json(f, rep);
    else vigen_check_print_text(f, rep);
    fclose(f);
    return buf;
}

static const vigen_check_problem *find_problem(const vigen_check_report *rep, int kind, const char *matrix, slong row,
                                               slong col)
{
    for (slong k = 0; k < rep->nproblems; k++) {
        const vigen_check_problem *p = rep->problems + k;
        if (p->kind == kind && p->matrix && strcmp(p->matrix, matrix) == 0 && p->row == row && p->col == col) return p;
    }
    return NULL;
}

/* ----------------------------------------------------- published tableaux */

static const char *const gauss1_c[] = {"1/2"}, *const gauss1_A[] = {"1/2"}, *const gauss1_b[] = {"1"};

static const char *const gauss2_c[] = {"1/2 - sqrt(3)/6", "1/2 + sqrt(3)/6"};
static const char *const gauss2_A[] = {"1/4", "1/4 - sqrt(3)/6", "1/4 + sqrt(3)/6", "1/4"};
static const char *const gauss2_b[] = {"1/2", "1/2"};

static const char *const gauss3_c[] = {"1/2 - sqrt(15)/10", "1/2", "1/2 + sqrt(15)/10"};
static const char *const gauss3_A[] = {
    "5/36", "2/9 - sqrt(15)/15", "5/36 - sqrt(15)/30",
    "5/36 + sqrt(15)/24", "2/9", "5/36 - sqrt(15)/24",
    "5/36 + sqrt(15)/30", "2/9 + sqrt(15)/15", "5/36"};
static const char *const gauss3_b[] = {"5/18", "4/9", "5/18"};

static const char *const lob3_c[] = {"0", "1/2", "1"};
static const char *const lob3A_A[] = {"0", "0", "0", "5/24", "1/3", "-1/24", "1/6", "2/3", "1/6"};
static const char *const lob3B_A[] = {"1/6", "-1/6", "0", "1/6", "1/3", "0", "1/6", "5/6", "0"};
static const char *const lob3B_c[] = {"0", "1/2", "1"};
static const char *const lob3_b[] = {"1/6", "2/3", "1/6"};

static const char *const rk4_c[] = {"0", "1/2", "1/2", "1"};
static const char *const rk4_A[] = {"0", "0", "0", "0", "1/2", "0", "0", "0", "0", "1/2", "0", "0", "0", "0", "1", "0"};
static const char *const rk4_b[] = {"1/6", "1/3", "1/3", "1/6"};

/* Gauss method of s stages as a collocation method, balls only. */
static void gauss_balls(vigen_tableau *t, slong s, slong prec)
{
    vigen_tableau_init(t, s);
    t->name = vigen_strdup_printf("gauss%ld (collocation)", (long)s);
    arb_t x;
    arb_init(x);
    for (slong k = 0; k < s; k++) {
        arb_hypgeom_legendre_p_ui_root(x, NULL, (ulong)s, (ulong)k, prec);
        arb_add_ui(x, x, 1, prec);
        arb_mul_2exp_si(t->c + k, x, -1);
    }
    arb_poly_t l, lin, F;
    arb_poly_init(l);
    arb_poly_init(lin);
    arb_poly_init(F);
    arb_t d, one;
    arb_init(d);
    arb_init(one);
    arb_one(one);
    for (slong j = 0; j < s; j++) {
        arb_poly_one(l);
        for (slong m = 0; m < s; m++) {
            if (m == j) continue;
            arb_sub(d, t->c + j, t->c + m, prec);
            arb_inv(d, d, prec);
            arb_poly_zero(lin);
            arb_poly_set_coeff_arb(lin, 1, d);            /* (t - c_m) / (c_j - c_m) */
            arb_mul(x, t->c + m, d, prec);
            arb_neg(x, x);
            arb_poly_set_coeff_arb(lin, 0, x);
            arb_poly_mul(l, l, lin, prec);
        }
        arb_poly_integral(F, l, prec);
        arb_poly_evaluate(t->b + j, F, one, prec);
        for (slong i = 0; i < s; i++) arb_poly_evaluate(arb_mat_entry(t->A, i, j), F, t->c + i, prec);
    }
    _arb_vec_set(t->bt, t->b, s);
    t->prec = prec;
    arb_poly_clear(l);
    arb_poly_clear(lin);
    arb_poly_clear(F);
    arb_clear(d);
    arb_clear(one);
    arb_clear(x);
}

static double now(void) { return (double)clock() / CLOCKS_PER_SEC; }

/* ------------------------------------------------------------------ tests */

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
    CHECK(rep.nproblems == 0);
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
        CHECK(rep.exit_code == 0 && rep.nproblems == 0);
        /* all 2 + 4 + 14 + 52 + ... conditions up to 2s hold */
        static const slong counts[] = {0, 2, 4, 14, 52, 214, 916, 4116};
        for (int n = 1; n <= 2 * s; n++) CHECK(rep.orders[0].hold[n] == counts[n]);
        CHECK(rep.orders[0].fail[2 * s + 1] > 0);
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
    const vigen_check_problem *p = find_problem(&rep, VIGEN_PROBLEM_ROWSUM, "At", 2, 1);
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
    p = find_problem(&rep, VIGEN_PROBLEM_SYMPLECTIC, "At", 2, 1);   /* the diagnosis names it for both */
    CHECK(p != NULL && p->diagnosed);
    CHECK(rep.nproblems == 2);
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
    for (slong k = 0; k < rep.nproblems; k++) {
        claims += rep.problems[k].kind == VIGEN_PROBLEM_CLAIM;
        symp += rep.problems[k].kind == VIGEN_PROBLEM_SYMPLECTIC;
    }
    CHECK(claims == 1 && symp > 0);
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
    const vigen_check_problem *p = find_problem(&rep, VIGEN_PROBLEM_ROWSUM, "A", 2, 3);
    const vigen_check_problem *q = find_problem(&rep, VIGEN_PROBLEM_SYMPLECTIC, "A", 2, 3);
    const vigen_check_problem *r = find_problem(&rep, VIGEN_PROBLEM_AGAINST, "A", 2, 3);
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
    CHECK(rep.against_differences == 0 && rep.nproblems == 0 && rep.exit_code == 0);
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
    const vigen_check_problem *p = find_problem(&rep, VIGEN_PROBLEM_ROWSUM, "b", 1, 0);
    CHECK(p != NULL && p->diagnosed);
    if (p) CHECK_CLOSE(p->expected, half, 35, 256);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);

    /* c[1] of Gauss-2 is 1/2 - sqrt(3)/5: only the row sum, only c[1] */
    const char *c[] = {"1/2 - sqrt(3)/5", "1/2 + sqrt(3)/6"};
    make(&t, "gauss2, c typo", 2, c, gauss2_A, gauss2_b, NULL, NULL, NULL);
    CHECK(check(&rep, &t, NULL, 6) == VIGEN_OK);
    p = find_problem(&rep, VIGEN_PROBLEM_ROWSUM, "c", 1, 0);
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
    for (slong k = 0; k < rep.nproblems; k++) diagnosed |= rep.problems[k].diagnosed;
    CHECK(!diagnosed);
    CHECK(find_problem(&rep, VIGEN_PROBLEM_ROWSUM, "A", 2, 0) != NULL);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);
    vigen_error_clear(&err);
    arb_clear(half);
    arb_clear(x);
}

static void test_undecided_and_refinement(void)
{
    vigen_check_report rep;
    vigen_tableau t;
    /* Gauss-2 to 6 digits: every condition that holds has a ball of radius
     * ~1e-6 > 2^-30 around 0: undecided, and more precision cannot help */
    const char *c[] = {"0.211325", "0.788675"};
    const char *A[] = {"0.25", "-0.0386751", "0.538675", "0.25"};
    const char *b[] = {"0.5", "0.5"};
    make(&t, "gauss2, 6 digits", 2, c, A, b, NULL, NULL, NULL);
    CHECK(check(&rep, &t, NULL, 6) == VIGEN_OK);
    CHECK(rep.consistent == VIGEN_CHECK_UNDECIDED);
    CHECK(rep.orders[0].level.undecided);
    CHECK(rep.exit_code == 1);
    CHECK(rep.rounds <= 2);
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);

    /* an exact entry that 128 bits cannot resolve: c = exp(100) + 1/2 - exp(100)
     * is decided after raising the precision */
    const char *c1[] = {"exp(100) + 1/2 - exp(100)"};
    make(&t, "gauss1, cancellation", 1, c1, gauss1_A, gauss1_b, NULL, NULL, NULL);
    CHECK(check(&rep, &t, NULL, 4) == VIGEN_OK);
    CHECK(rep.rounds >= 2 && rep.prec >= 256);
    CHECK(rep.consistent == VIGEN_CHECK_YES);
    CHECK_LEVEL(order_of(&rep, VIGEN_CHECK_GENERAL), 2, 0, 0);
    CHECK_LEVEL(&rep.C[0], 1, 0, 0);
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
    test_perturbed_gauss3();
    test_other_typos();
    test_undecided_and_refinement();
    test_claims();
    test_collocation_and_speed();
    TEST_MAIN_END();
}
