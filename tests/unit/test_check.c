/* test_check.c — the certifying checker (src/check/) on methods whose
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
 *    (Legendre roots from arb, Lagrange polynomials integrated exactly);
 *  - the symplecticity defect of a pair is b_i a~_ij + b~_j a_ji - b_i b~_j by
 *    definition (GNI Thm VI.4.6), computed here from the exact entries.
 *  - an s-stage Runge-Kutta method has order <= 2s: its weights and nodes
 *    form an s-point quadrature rule (the bushy trees), exact at most up to
 *    degree 2s - 1 (Hairer, Norsett, Wanner I, sec. II.7);
 *  - a decimal with k digits after the point is read as the ball of radius
 *    10^-k / 2 (README, "Tableau files"), and the rule for rounded data holds
 *    a condition only with a radius at most 2^-10 of its terms (check.h).
 * Deliberately broken copies change an entry by a known exact amount (1/10^45,
 * e^-110, 1/5 for 1/6, 0.51 for 1/2): the defects they cause follow.
 */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <arb_hypgeom.h>
#include <arb_poly.h>
#include "vigen/check.h"
#include "core/decimal.h"
#include "core/expr.h"
#include "testlib.h"
#include "support/strbuf.h"

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

/* check() with a starting precision and a cap (0: defaults). */
static int check_prec(vigen_check_report *rep, vigen_tableau *t, vigen_tableau *against, int P, slong prec,
                      slong max_prec)
{
    vigen_check_options opt;
    vigen_check_options_init(&opt);
    opt.max_order = P;
    opt.path = t->name;
    if (prec) opt.prec = prec;
    if (max_prec) opt.max_prec = max_prec;
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

/* The problem that lists one failed condition (not a diagnosis). */
static const vigen_check_problem *find_listed(const vigen_check_report *rep, int kind, const char *matrix, slong row,
                                              slong col)
{
    for (slong k = 0; k < rep->nproblems; k++) {
        const vigen_check_problem *p = rep->problems + k;
        if (p->kind == kind && !p->diagnosed && p->matrix && strcmp(p->matrix, matrix) == 0 && p->row == row &&
            p->col == col)
            return p;
    }
    return NULL;
}

static const vigen_check_problem *find_diagnosis(const vigen_check_report *rep, int kind)
{
    for (slong k = 0; k < rep->nproblems; k++)
        if (rep->problems[k].kind == kind && rep->problems[k].diagnosed) return rep->problems + k;
    return NULL;
}

/* The defect printed in a message of a failed condition ("defect 0.01",
 * "defect in [0.005, 0.015]", "... = -0.0277778, not 0", "... is in [lo, hi],
 * not 0"): 1 when the printed numbers exclude 0, 0 when they do not, -1 when
 * nothing can be read. */
static int printed_defect_excludes_zero(const char *msg)
{
    const char *p = strstr(msg, "defect ");
    if (p) p += 7;
    else {
        const char *q = strstr(msg, " is in ");
        const char *r = NULL;
        for (const char *x = strstr(msg, " = "); x; x = strstr(x + 1, " = ")) r = x;
        if (q) p = q + 7;
        else if (r) p = r + 3;
        else return -1;
    }
    if (strncmp(p, "in ", 3) == 0) p += 3;
    double lo, hi;
    if (*p == '[') {
        if (sscanf(p, "[%lf, %lf]", &lo, &hi) != 2) return -1;
    } else {
        if (sscanf(p, "%lf", &lo) != 1) return -1;
        hi = lo;
    }
    return lo > 0 || hi < 0;
}

/* x = the value of the exact expression text. */
static void eval_text(arb_t x, const char *text, slong prec)
{
    vigen_error err;
    vigen_error_init(&err);
    if (vigen_expr_eval_string(x, text, prec, &err) != VIGEN_OK) {
        fprintf(stderr, "%s: %s\n", text, err.message ? err.message : "?");
        arb_indeterminate(x);
    }
    vigen_error_clear(&err);
}

/* The listed failure of the row sum of row `row` of `matrix` (c or ct the
 * other side) is eps, certified to 30 digits. */
static void check_rowsum_defect(const vigen_check_report *rep, const char *matrix, slong row, const arb_t eps)
{
    const vigen_check_problem *p = find_listed(rep, VIGEN_PROBLEM_ROWSUM, matrix, row, 0);
    CHECK_MSG(p != NULL, "row %ld of %s is not listed", (long)row, matrix);
    if (p == NULL) return;
    arb_t d;
    arb_init(d);
    arb_sub(d, p->value, p->expected, 2048);
    CHECK_CLOSE(d, eps, 30, 2048);
    arb_clear(d);
}

/* The report names the field Q(sqrt d) and the common denominator D. */
static int in_field(const vigen_check_report *rep, const char *d, const char *D)
{
    return rep->quadratic_d && strcmp(rep->quadratic_d, d) == 0 && rep->quadratic_denominator &&
           strcmp(rep->quadratic_denominator, D) == 0 && rep->rational_denominator == NULL;
}

/* Gauss-2 (b_1 = 1/2) with a_11 + eps: row 1 of A and the pair (1, 1),
 * 2 b_1 (a_11 + eps) - b_1^2 = eps, are listed as failing by eps. */
static void check_a11_defects(const vigen_check_report *rep, const arb_t eps)
{
    check_rowsum_defect(rep, "A", 1, eps);
    const vigen_check_problem *p = find_listed(rep, VIGEN_PROBLEM_SYMPLECTIC, "A", 1, 1);
    CHECK(p != NULL);
    if (p) CHECK_CLOSE(p->value, eps, 30, 2048);
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
    p = find_diagnosis(&rep, VIGEN_PROBLEM_SYMPLECTIC);   /* the diagnosis names it for both */
    CHECK(p != NULL && p->row == 2 && p->col == 1 && strcmp(p->matrix, "At") == 0);
    /* and every failed condition is listed: row 2 of At sums to 1/5 + 1/3 =
     * 8/15, not ct_2 = 1/2; the only pair involving at_21 is (2, 1), with
     * b_2 at_21 + b_1 a_12 - b_2 b_1 = (2/3)(1/5) + 0 - (2/3)(1/6) = 1/45 */
    p = find_listed(&rep, VIGEN_PROBLEM_ROWSUM, "At", 2, 0);
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
    p = find_listed(&rep, VIGEN_PROBLEM_SYMPLECTIC, "At", 2, 1);
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
    CHECK(rep.nproblems == 4);   /* two diagnoses (row sum, symplecticity), two listed failures */
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&u);
}

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
    const vigen_check_problem *p = find_listed(&rep, VIGEN_PROBLEM_ROWSUM, "At", 1, 0);
    if (p == NULL) p = find_problem(&rep, VIGEN_PROBLEM_ROWSUM, "At", 1, 1);
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
            const vigen_check_problem *p = find_listed(&rep, VIGEN_PROBLEM_SYMPLECTIC, "A", i + 1, j + 1);
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
    for (slong k = 0; k < rep.nproblems; k++) listed += rep.problems[k].kind == VIGEN_PROBLEM_SYMPLECTIC;
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

    /* b[1] of Gauss-2 typed as the short decimal 0.51 (the ball [0.505,
     * 0.515]): sum b = 1 and symplecticity fail; solved with b[1] as an exact
     * unknown they ask for 1/2 (b[2] = 1/2 is exact), whereas b[2] cannot
     * explain the pairs (b_2 = 1 - b_1 leaves the pair (1, 2) at about -0.003
     * .. -0.008 over the whole ball) */
    const char *b051[] = {"0.51", "1/2"};
    make(&t, "gauss2, b = 0.51", 2, gauss2_c, gauss2_A, b051, NULL, NULL, NULL);
    CHECK(check(&rep, &t, NULL, 6) == VIGEN_OK);
    CHECK(rep.consistent == VIGEN_CHECK_NO && rep.symplectic == VIGEN_CHECK_NO);
    p = find_diagnosis(&rep, VIGEN_PROBLEM_ROWSUM);
    CHECK(p != NULL && strcmp(p->matrix, "b") == 0 && p->row == 1);
    if (p) {
        CHECK_CLOSE(p->expected, half, 35, 256);
        CHECK(strstr(p->message, "b[1] = 0.51;") != NULL);
    }
    /* the messages of failed conditions print defects that visibly exclude 0 */
    for (slong k = 0; k < rep.nproblems; k++) {
        const vigen_check_problem *q = rep.problems + k;
        if (q->kind == VIGEN_PROBLEM_CLAIM || q->diagnosed) continue;
        CHECK_MSG(printed_defect_excludes_zero(q->message) == 1, "%s", q->message);
        CHECK_MSG(strstr(q->message, "+/-") == NULL, "%s", q->message);
    }
    /* the pair (1, 1), 2 b_1 a_11 - b_1^2 = b_1 (1/2 - b_1), ranges over
     * [-0.007725, -0.002525] for b_1 in [0.505, 0.515]: it fails (b_1 occurs
     * three times, but is one number) */
    p = find_listed(&rep, VIGEN_PROBLEM_SYMPLECTIC, "A", 1, 1);
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
    p = find_listed(&rep, VIGEN_PROBLEM_ROWSUM, "b", 0, 0);
    CHECK(p != NULL && strstr(p->message, "defect in [0.00499, 0.0151]") != NULL);
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
    const vigen_check_problem *p = find_listed(&rep, VIGEN_PROBLEM_ROWSUM, "b", 0, 0);
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
        CHECK(find_listed(&rep, VIGEN_PROBLEM_AGAINST, "A", 1, 1) != NULL);
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
    CHECK(find_listed(&rep, VIGEN_PROBLEM_ROWSUM, "A", 1, 0) != NULL);
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
    const vigen_check_problem *p = NULL;
    for (slong k = 0; k < rep.nproblems; k++)
        if (rep.problems[k].kind == VIGEN_PROBLEM_CLAIM) p = rep.problems + k;
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
    test_rational_tiny_perturbation();
    test_quadratic_proofs();
    test_rk4();
    test_ruth3();
    test_perturbed_gauss3();
    test_other_typos();
    test_rounded_data();
    test_short_data();
    test_exact_refinement();
    test_hidden_small_part();
    test_claims();
    test_collocation_and_speed();
    TEST_MAIN_END();
}
