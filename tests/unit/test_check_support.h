/* test_check_support.h — the helpers and tableaux of the checker's tests
 * (test_check_methods.c, test_check_exact.c, test_check_typos.c,
 * test_check_fields.c, test_check_extension.c): the certifying checker (src/check/) on methods whose
 * properties are known from the literature, and on deliberately broken
 * copies.  Each test is an executable of its own, so the tableaux are
 * defined here once per test.
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
 *    10^-k / 2 (docs/tableaux.md), and the rule for rounded data holds
 *    a condition only with a radius at most 2^-10 of its terms (check.h).
 * Deliberately broken copies change an entry by a known exact amount (1/10^45,
 * e^-110, 1/5 for 1/6, 0.51 for 1/2): the defects they cause follow.
 */
#ifndef VIGEN_TEST_CHECK_SUPPORT_H
#define VIGEN_TEST_CHECK_SUPPORT_H

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

static inline char **texts(slong n, const char *const *src)
{
    if (src == NULL) return NULL;
    char **t = calloc((size_t)n, sizeof(char *));
    for (slong k = 0; k < n; k++) t[k] = vigen_strdup(src[k]);
    return t;
}

/* A tableau from entry texts, as a hand-written file would give it. */
static inline void make(vigen_tableau *t, const char *name, slong s, const char *const *c, const char *const *A,
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

/* Checks t with a starting precision and a cap (0: defaults). */
static inline int check_prec(vigen_check_report *rep, vigen_tableau *t, vigen_tableau *against, int P, slong prec,
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

/* Checks t (against: NULL or a second tableau) with orders up to P at an
 * adequate starting precision. */
static inline int check(vigen_check_report *rep, vigen_tableau *t, vigen_tableau *against, int P)
{
    return check_prec(rep, t, against, P, 0, 0);
}

static inline const vigen_check_level *order_of(const vigen_check_report *rep, int family)
{
    return &rep->orders[family].level;
}

#define CHECK_LEVEL(L, v, cap, und) CHECK_MSG((L)->value == (v) && (L)->capped == (cap) && (L)->undecided == (und), \
    "level %d capped %d undecided %d, expected %d %d %d", (L)->value, (L)->capped, (L)->undecided, (v), (cap), (und))

static inline char *render(const vigen_check_report *rep, int json)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    if (json) vigen_check_print_json(f, rep);
    else vigen_check_print_text(f, rep);
    fclose(f);
    return buf;
}

static inline const vigen_check_failure *find_problem(const vigen_check_report *rep, int kind, const char *matrix, slong row,
                                               slong col)
{
    for (slong k = 0; k < rep->nfailures; k++) {
        const vigen_check_failure *p = rep->failures + k;
        if (p->kind == kind && p->matrix && strcmp(p->matrix, matrix) == 0 && p->row == row && p->col == col) return p;
    }
    return NULL;
}

/* The problem that lists one failed condition (not a diagnosis). */
static inline const vigen_check_failure *find_listed(const vigen_check_report *rep, int kind, const char *matrix, slong row,
                                              slong col)
{
    for (slong k = 0; k < rep->nfailures; k++) {
        const vigen_check_failure *p = rep->failures + k;
        if (p->kind == kind && !p->diagnosed && p->matrix && strcmp(p->matrix, matrix) == 0 && p->row == row &&
            p->col == col)
            return p;
    }
    return NULL;
}

static inline const vigen_check_failure *find_diagnosis(const vigen_check_report *rep, int kind)
{
    for (slong k = 0; k < rep->nfailures; k++)
        if (rep->failures[k].kind == kind && rep->failures[k].diagnosed) return rep->failures + k;
    return NULL;
}

/* The defect printed in a message of a failed condition ("defect 0.01",
 * "defect in [0.005, 0.015]", "... = -0.0277778, not 0", "... is in [lo, hi],
 * not 0"): 1 when the printed numbers exclude 0, 0 when they do not, -1 when
 * nothing can be read. */
static inline int printed_defect_excludes_zero(const char *msg)
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
static inline void eval_text(arb_t x, const char *text, slong prec)
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
static inline void check_rowsum_defect(const vigen_check_report *rep, const char *matrix, slong row, const arb_t eps)
{
    const vigen_check_failure *p = find_listed(rep, VIGEN_CHECK_FAIL_ROWSUM, matrix, row, 0);
    CHECK_MSG(p != NULL, "row %ld of %s is not listed", (long)row, matrix);
    if (p == NULL) return;
    arb_t d;
    arb_init(d);
    arb_sub(d, p->value, p->expected, 2048);
    CHECK_CLOSE(d, eps, 30, 2048);
    arb_clear(d);
}

/* The report names the field Q(sqrt d) and the common denominator D. */
static inline int in_field(const vigen_check_report *rep, const char *d, const char *D)
{
    return rep->quadratic_d && strcmp(rep->quadratic_d, d) == 0 && rep->quadratic_denominator &&
           strcmp(rep->quadratic_denominator, D) == 0 && rep->rational_denominator == NULL;
}

/* Gauss-2 (b_1 = 1/2) with a_11 + eps: row 1 of A and the pair (1, 1),
 * 2 b_1 (a_11 + eps) - b_1^2 = eps, are listed as failing by eps. */
static inline void check_a11_defects(const vigen_check_report *rep, const arb_t eps)
{
    check_rowsum_defect(rep, "A", 1, eps);
    const vigen_check_failure *p = find_listed(rep, VIGEN_CHECK_FAIL_SYMPLECTIC, "A", 1, 1);
    CHECK(p != NULL);
    if (p) CHECK_CLOSE(p->value, eps, 30, 2048);
}

/* ----------------------------------------------------- published tableaux */

const char *const gauss1_c[] = {"1/2"}, *const gauss1_A[] = {"1/2"}, *const gauss1_b[] = {"1"};

const char *const gauss2_c[] = {"1/2 - sqrt(3)/6", "1/2 + sqrt(3)/6"};
const char *const gauss2_A[] = {"1/4", "1/4 - sqrt(3)/6", "1/4 + sqrt(3)/6", "1/4"};
const char *const gauss2_b[] = {"1/2", "1/2"};

const char *const gauss3_c[] = {"1/2 - sqrt(15)/10", "1/2", "1/2 + sqrt(15)/10"};
const char *const gauss3_A[] = {
    "5/36", "2/9 - sqrt(15)/15", "5/36 - sqrt(15)/30",
    "5/36 + sqrt(15)/24", "2/9", "5/36 - sqrt(15)/24",
    "5/36 + sqrt(15)/30", "2/9 + sqrt(15)/15", "5/36"};
const char *const gauss3_b[] = {"5/18", "4/9", "5/18"};

const char *const lob3_c[] = {"0", "1/2", "1"};
const char *const lob3A_A[] = {"0", "0", "0", "5/24", "1/3", "-1/24", "1/6", "2/3", "1/6"};
const char *const lob3B_A[] = {"1/6", "-1/6", "0", "1/6", "1/3", "0", "1/6", "5/6", "0"};
const char *const lob3B_c[] = {"0", "1/2", "1"};
const char *const lob3_b[] = {"1/6", "2/3", "1/6"};

const char *const rk4_c[] = {"0", "1/2", "1/2", "1"};
const char *const rk4_A[] = {"0", "0", "0", "0", "1/2", "0", "0", "0", "0", "1/2", "0", "0", "0", "0", "1", "0"};
const char *const rk4_b[] = {"1/6", "1/3", "1/3", "1/6"};

/* Gauss method of s stages as a collocation method, balls only. */
static inline void gauss_balls(vigen_tableau *t, slong s, slong prec)
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

static inline double now(void) { return (double)clock() / CLOCKS_PER_SEC; }

#endif
