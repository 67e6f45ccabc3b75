/* test_galerkin.c — the generator against truths from independent sources:
 *   - Gauss methods s = 2, 3: closed forms of Hairer, Lubich & Wanner
 *     (GNI, Table II.1.1 / Butcher), with At = A;
 *   - Lobatto s = 3: Lobatto IIIA (A) and IIIB (At) from GNI Table II.2.1;
 *   - Radau IIA s = 2 (A) from Hairer & Wanner II, Table IV.5.5;
 *   - the trig(s) family (its own closed forms, arb_sin_cos_pi) against the
 *     same functions written as expression strings (the generic exact
 *     antiderivative of sin/cos of linear arguments in src/core/expr_integrate.c) and as Lua
 *     functions (acb_calc_integrate through Lua): three independent routes;
 *   - identities every generated method satisfies: ct_i = sum_j at_ij,
 *     symplecticity, sum b = 1, and the B(p) quadrature order of b.
 * The Leok & Zhang closed forms are checked in test_leok_zhang.c. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "core/decimal.h"
#include "method/galerkin.h"
#include "method/spec.h"
#include "testlib.h"

static int write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    if (!f) return 0;
    fputs(text, f);
    fclose(f);
    return 1;
}

static int generate(vigen_tableau *t, const char *path, slong digits)
{
    vigen_error err;
    vigen_error_init(&err);
    vigen_spec *spec = NULL;
    int rc = vigen_spec_load(&spec, path, NULL, &err);
    if (rc == VIGEN_OK) {
        rc = vigen_galerkin_generate(t, spec, digits, &err);
        vigen_spec_free(spec);
    }
    if (rc != VIGEN_OK) fprintf(stderr, "%s: %s\n", path, err.message);
    vigen_error_clear(&err);
    return rc == VIGEN_OK;
}

static void expect_entry(const arb_t x, const char *closed_form, slong digits, const char *what)
{
    arb_t y;
    arb_init(y);
    vigen_error err;
    vigen_error_init(&err);
    int rc = vigen_expr_eval_string(y, closed_form, 4 * digits + 64, &err);
    CHECK_MSG(rc == VIGEN_OK, "%s: %s", closed_form, err.message);
    if (!testlib_arb_close(x, y, digits, 4 * digits + 64)) {
        fprintf(stderr, "%s: expected %s\n", what, closed_form);
        CHECK_CLOSE(x, y, digits, 4 * digits + 64);
    }
    vigen_error_clear(&err);
    arb_clear(y);
}

static void expect_matrix(const arb_mat_t m, const char *const *forms, slong s, slong digits, const char *what)
{
    for (slong i = 0; i < s; i++)
        for (slong j = 0; j < s; j++) {
            char label[64];
            snprintf(label, sizeof label, "%s[%ld][%ld]", what, (long)(i + 1), (long)(j + 1));
            expect_entry(arb_mat_entry(m, i, j), forms[i * s + j], digits, label);
        }
}

static void expect_vector(arb_srcptr v, const char *const *forms, slong s, slong digits, const char *what)
{
    for (slong i = 0; i < s; i++) {
        char label[64];
        snprintf(label, sizeof label, "%s[%ld]", what, (long)(i + 1));
        expect_entry(v + i, forms[i], digits, label);
    }
}

/* Identities of Theorem 3: ct = At 1, b_i at_ij + b_j a_ji = b_i b_j, sum b = 1,
 * and sum_i b_i c_i^(k-1) = 1/k for k <= p (quadrature order p). */
static void check_identities(const vigen_tableau *t, slong quad_order, const char *name)
{
    slong s = t->s, prec = t->prec;
    arb_t r, q, ck;
    arb_init(r); arb_init(q); arb_init(ck);
    for (slong i = 0; i < s; i++) {
        arb_zero(r);
        for (slong j = 0; j < s; j++) arb_add(r, r, arb_mat_entry(t->At, i, j), prec);
        CHECK_MSG(arb_overlaps(r, t->ct + i), "%s: ct_%ld != sum_j at_ij", name, (long)(i + 1));
    }
    vigen_tableau_symplectic_residual(r, t, prec);
    CHECK_MSG(arb_contains_zero(r), "%s: symplecticity residual excludes 0", name);
    for (slong k = 1; k <= quad_order; k++) {
        arb_zero(r);
        for (slong i = 0; i < s; i++) {
            arb_pow_ui(ck, t->c + i, (ulong)(k - 1), prec);
            arb_addmul(r, t->b + i, ck, prec);
        }
        arb_one(q);
        arb_div_ui(q, q, (ulong)k, prec);
        CHECK_MSG(arb_overlaps(r, q), "%s: sum b_i c_i^%ld != 1/%ld", name, (long)(k - 1), (long)k);
    }
    arb_clear(r); arb_clear(q); arb_clear(ck);
}

static void test_gauss(void)
{
    vigen_tableau t;
    /* s = 2 (GNI Table II.1.1) */
    if (generate(&t, "tableaux/specs/gauss_legendre_s2.lua", 60)) {
        const char *c[] = {"1/2 - sqrt(3)/6", "1/2 + sqrt(3)/6"};
        const char *A[] = {"1/4", "1/4 - sqrt(3)/6", "1/4 + sqrt(3)/6", "1/4"};
        const char *b[] = {"1/2", "1/2"};
        expect_vector(t.c, c, 2, 55, "gauss2 c");
        expect_matrix(t.A, A, 2, 55, "gauss2 A");
        expect_matrix(t.At, A, 2, 55, "gauss2 At");
        expect_vector(t.b, b, 2, 55, "gauss2 b");
        expect_vector(t.ct, c, 2, 55, "gauss2 ct");
        check_identities(&t, 4, "gauss2");
        vigen_tableau_clear(&t);
    } else CHECK(0);
    /* s = 3 */
    if (generate(&t, "tableaux/specs/gauss_legendre_s3.lua", 60)) {
        const char *c[] = {"1/2 - sqrt(15)/10", "1/2", "1/2 + sqrt(15)/10"};
        const char *A[] = {"5/36", "2/9 - sqrt(15)/15", "5/36 - sqrt(15)/30",
                           "5/36 + sqrt(15)/24", "2/9", "5/36 - sqrt(15)/24",
                           "5/36 + sqrt(15)/30", "2/9 + sqrt(15)/15", "5/36"};
        const char *b[] = {"5/18", "4/9", "5/18"};
        expect_vector(t.c, c, 3, 55, "gauss3 c");
        expect_matrix(t.A, A, 3, 55, "gauss3 A");
        expect_matrix(t.At, A, 3, 55, "gauss3 At");
        expect_vector(t.b, b, 3, 55, "gauss3 b");
        check_identities(&t, 6, "gauss3");
        vigen_tableau_clear(&t);
    } else CHECK(0);
    /* s = 1..8: At = A (Gauss methods are symplectic RK methods) and order 2s quadrature */
    for (int s = 1; s <= 8; s++) {
        char path[128];
        snprintf(path, sizeof path, "tableaux/specs/gauss_legendre_s%d.lua", s);
        if (!generate(&t, path, 40)) { CHECK(0); continue; }
        for (slong i = 0; i < s; i++)
            for (slong j = 0; j < s; j++)
                CHECK_MSG(arb_overlaps(arb_mat_entry(t.A, i, j), arb_mat_entry(t.At, i, j)), "gauss %d: At != A", s);
        check_identities(&t, 2 * s, path);
        vigen_tableau_clear(&t);
    }
}

static void test_lobatto(void)
{
    vigen_tableau t;
    if (!generate(&t, "tableaux/specs/gauss_lobatto_s3.lua", 60)) { CHECK(0); return; }
    /* GNI Table II.2.1: Lobatto IIIA and IIIB, s = 3 */
    const char *c[] = {"0", "1/2", "1"};
    const char *A[] = {"0", "0", "0", "5/24", "1/3", "-1/24", "1/6", "2/3", "1/6"};
    const char *At[] = {"1/6", "-1/6", "0", "1/6", "1/3", "0", "1/6", "5/6", "0"};
    const char *b[] = {"1/6", "2/3", "1/6"};
    expect_vector(t.c, c, 3, 55, "lobatto3 c");
    expect_matrix(t.A, A, 3, 55, "lobatto3 A (IIIA)");
    expect_matrix(t.At, At, 3, 55, "lobatto3 At (IIIB)");
    expect_vector(t.b, b, 3, 55, "lobatto3 b");
    expect_vector(t.ct, c, 3, 55, "lobatto3 ct");
    /* structural zeros are exact, hence written "0" */
    for (slong i = 0; i < 3; i++) {
        CHECK(arb_is_zero(arb_mat_entry(t.A, 0, i)));
        CHECK(arb_is_zero(arb_mat_entry(t.At, i, 2)));
        CHECK(strcmp(t.At_text[i * 3 + 2], "0") == 0);
    }
    check_identities(&t, 4, "lobatto3");
    vigen_tableau_clear(&t);
    for (int s = 2; s <= 6; s++) {
        char path[128];
        snprintf(path, sizeof path, "tableaux/specs/gauss_lobatto_s%d.lua", s);
        if (!generate(&t, path, 40)) { CHECK(0); continue; }
        check_identities(&t, 2 * s - 2, path);
        vigen_tableau_clear(&t);
    }
}

static void test_radau(void)
{
    vigen_tableau t;
    if (!generate(&t, "tableaux/specs/radau_right_s2.lua", 50)) { CHECK(0); return; }
    /* Hairer & Wanner II, Table IV.5.5: Radau IIA, s = 2 */
    const char *c[] = {"1/3", "1"};
    const char *A[] = {"5/12", "-1/12", "3/4", "1/4"};
    const char *b[] = {"3/4", "1/4"};
    expect_vector(t.c, c, 2, 45, "radau2 c");
    expect_matrix(t.A, A, 2, 45, "radau2 A");
    expect_vector(t.b, b, 2, 45, "radau2 b");
    check_identities(&t, 3, "radau2");
    vigen_tableau_clear(&t);
}

/* trig(3) by the family's closed forms vs the same basis as expressions (the
 * generic antiderivative, src/core/expr_integrate.c) vs Lua functions (acb_calc_integrate). */
static void test_three_routes(void)
{
    const char *dir = getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp";
    char p1[512], p2[512], p3[512];
    snprintf(p1, sizeof p1, "%s/vigen_test_trig_family.lua", dir);
    snprintf(p2, sizeof p2, "%s/vigen_test_trig_expr.lua", dir);
    snprintf(p3, sizeof p3, "%s/vigen_test_trig_lua.lua", dir);
    CHECK(write_text(p1, "return { name = 'f', basis = trig(3), nodes = { '1/5', '1/2', '4/5' } }\n"));
    CHECK(write_text(p2, "return { name = 'e', basis = { '1', 'cos(pi*t)', 'sin(pi*t)' }, nodes = { '1/5', '1/2', '4/5' } }\n"));
    CHECK(write_text(p3, "return { name = 'l', basis = { function(t) return t^0 end, function(t) return cos(pi*t) end,\n"
                         "  function(t) return sin(pi*t) end }, nodes = { '1/5', '1/2', '4/5' } }\n"));
    vigen_tableau t1, t2, t3;
    int ok1 = generate(&t1, p1, 50), ok2 = generate(&t2, p2, 50), ok3 = generate(&t3, p3, 50);
    CHECK(ok1 && ok2 && ok3);
    if (ok1 && ok2 && ok3) {
        for (slong i = 0; i < 3; i++) {
            CHECK_CLOSE(t1.b + i, t2.b + i, 48, 400);
            CHECK_CLOSE(t1.b + i, t3.b + i, 48, 400);
            for (slong j = 0; j < 3; j++) {
                CHECK_CLOSE(arb_mat_entry(t1.A, i, j), arb_mat_entry(t2.A, i, j), 48, 400);
                CHECK_CLOSE(arb_mat_entry(t1.A, i, j), arb_mat_entry(t3.A, i, j), 48, 400);
                CHECK_CLOSE(arb_mat_entry(t1.At, i, j), arb_mat_entry(t2.At, i, j), 48, 400);
            }
            /* same certified decimals, whichever route */
            CHECK(strcmp(t1.b_text[i], t2.b_text[i]) == 0 && strcmp(t1.b_text[i], t3.b_text[i]) == 0);
        }
        check_identities(&t1, 1, "trig3");
    }
    if (ok1) vigen_tableau_clear(&t1);
    if (ok2) vigen_tableau_clear(&t2);
    if (ok3) vigen_tableau_clear(&t3);
    remove(p1); remove(p2); remove(p3);
}

/* High precision: every digit certified at 1000 digits, and the 1000-digit
 * decimals agree with the 34-digit ones (the shorter is the rounding of the longer). */
static void test_high_precision(void)
{
    vigen_tableau lo, hi;
    int ok1 = generate(&lo, "tableaux/specs/gauss_legendre_s4.lua", 34);
    int ok2 = generate(&hi, "tableaux/specs/gauss_legendre_s4.lua", 1000);
    CHECK(ok1 && ok2);
    if (ok1 && ok2) {
        arb_t x;
        arb_init(x);
        for (slong k = 0; k < 16; k++) {
            /* the 34-digit ball must contain the 1000-digit ball */
            vigen_error err;
            vigen_error_init(&err);
            arb_t y;
            arb_init(y);
            vigen_tableau_entry_eval(x, lo.A_text[k], 4000, &err);
            vigen_tableau_entry_eval(y, hi.A_text[k], 4000, &err);
            CHECK(arb_contains(x, y));
            CHECK(vigen_decimal_significant_digits(hi.A_text[k]) == 1000);
            arb_clear(y);
        }
        arb_clear(x);
    }
    if (ok1) vigen_tableau_clear(&lo);
    if (ok2) vigen_tableau_clear(&hi);
}

/* 2000 digits (the largest digits tested): the 3-stage Gauss closed forms hold to
 * 1990 digits and every entry carries 2000 certified digits. */
static void test_2000_digits(void)
{
    vigen_tableau t;
    if (!generate(&t, "tableaux/specs/gauss_legendre_s3.lua", 2000)) { CHECK(0); return; }
    const char *A[] = {"5/36", "2/9 - sqrt(15)/15", "5/36 - sqrt(15)/30",
                       "5/36 + sqrt(15)/24", "2/9", "5/36 - sqrt(15)/24",
                       "5/36 + sqrt(15)/30", "2/9 + sqrt(15)/15", "5/36"};
    expect_matrix(t.A, A, 3, 1990, "gauss3 A at 2000 digits");
    for (slong k = 0; k < 9; k++) CHECK(vigen_decimal_significant_digits(t.A_text[k]) == 2000);
    vigen_tableau_clear(&t);
}

/* A tiny but non-zero weight is legal: nodes {0, 1/2 + 10^-70} with the
 * Lagrange basis give b_1 = int_0^1 (t - c_2)/(0 - c_2) = (c_2 - 1/2)/c_2. */
static void test_tiny_weight(void)
{
    const char *dir = getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp";
    char path[512];
    snprintf(path, sizeof path, "%s/vigen_test_tiny_weight.lua", dir);
    CHECK(write_text(path, "return { name = 'tiny', basis = 'lagrange', nodes = { '0', '1/2 + 1/10^70' } }\n"));
    vigen_tableau t;
    if (generate(&t, path, 40)) {
        /* relative comparison: scale b_1 by 10^70 (an absolute one would pass for 0) */
        arb_t scaled, p10;
        arb_init(scaled);
        arb_init(p10);
        arb_ui_pow_ui(p10, 10, 70, t.prec);
        arb_mul(scaled, t.b + 0, p10, t.prec);
        expect_entry(scaled, "1 / (1/2 + 1/10^70)", 38, "tiny b_1 * 10^70");
        arb_clear(scaled);
        arb_clear(p10);
        expect_entry(t.b + 1, "(1/2) / (1/2 + 1/10^70)", 38, "tiny b_2");
        vigen_tableau_clear(&t);
    } else CHECK(0);
    remove(path);
}

/* A rounding tie: Lagrange at equispaced(5) has a_43 = int_0^(3/4) l_3 = 9/40
 * exactly (Newton–Cotes weights, computed by hand with fractions), which lies
 * halfway between 0.22 and 0.23.  At --digits 2 it is written with the one
 * extra digit that makes it certified, "0.225", instead of failing. */
static void test_tie(void)
{
    const char *dir = getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp";
    char path[512];
    snprintf(path, sizeof path, "%s/vigen_test_tie.lua", dir);
    CHECK(write_text(path, "return { name = 'tie', basis = 'lagrange', nodes = equispaced(5) }\n"));
    vigen_tableau t;
    if (generate(&t, path, 2)) {
        CHECK_MSG(strcmp(t.A_text[3 * 5 + 2], "0.225") == 0, "a_43 written as %s", t.A_text[3 * 5 + 2]);
        /* every entry, read back as a rounded decimal, contains its exact value */
        vigen_error err;
        vigen_error_init(&err);
        arb_t x;
        arb_init(x);
        for (slong i = 0; i < 5; i++)
            for (slong j = 0; j < 5; j++) {
                CHECK(vigen_tableau_entry_eval(x, t.A_text[i * 5 + j], 256, &err) == VIGEN_OK);
                CHECK(arb_contains(x, arb_mat_entry(t.A, i, j)));
            }
        arb_clear(x);
        vigen_tableau_clear(&t);
    } else CHECK(0);
    remove(path);
}

int main(void)
{
    test_tie();
    test_tiny_weight();
    test_2000_digits();
    test_gauss();
    test_lobatto();
    test_radau();
    test_three_routes();
    test_high_precision();
    TEST_MAIN_END();
}
