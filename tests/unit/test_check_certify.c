/* test_check_certify.c — the certification of generated tableaux
 * (vigen_check_certify): Butcher's theorem on the generator's balls
 * (src/check/certify_theorem.c) against the walk over every tree
 * (VIGEN_CERTIFY_TREES=1) on the specs of the library and on the published
 * tableaux with exact entries, and what the theorem decides on its own.
 *
 * Sources of the expected values (never this code's own output):
 *  - Hairer, Wanner II, sec. IV.5 (Tables 5.1, 5.5, 5.7-5.9): the s-stage
 *    Gauss method has order exactly 2s, B(2s), C(s), D(s); Radau IIA order
 *    2s - 1 with B(2s - 1), C(s), D(s - 1); Lobatto IIIA order 2s - 2 with
 *    B(2s - 2), C(s), D(s - 2);
 *  - Butcher's theorem (Hairer, Norsett, Wanner I, Thm II.7.4): B(p), C(eta),
 *    D(zeta), p <= eta + zeta + 1, p <= 2 eta + 2 give order p; for a PRK
 *    pair with the smaller eta, zeta of its parts (colour-blind), Lobatto
 *    IIIA-IIIB (eta = zeta = s - 2) gets 2s - 3 only, below its order 2s - 2
 *    (Hairer, Lubich, Wanner, GNI sec. II.2.2): the theorem does not decide
 *    it and the trees must;
 *  - an s-point quadrature is exact at most to degree 2s - 1: B(2s + 1) fails
 *    for every s-stage method;
 *  - the walk over every tree (orders.c) is the other method the theorem
 *    path must agree with.
 */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "check/check_internal.h"
#include "vigen/method.h"
#include "testlib.h"

typedef struct {
    int order, sep, nys, symplectic;
} claims;

static int generate(vigen_tableau *t, const char *path, slong digits)
{
    vigen_error err;
    vigen_error_init(&err);
    vigen_method *m = NULL;
    int rc = vigen_method_load(&m, path, NULL, &err);
    if (rc == VIGEN_OK) rc = vigen_method_tableau(t, m, digits, &err);
    vigen_method_free(m);
    if (rc != VIGEN_OK) fprintf(stderr, "%s: %s\n", path, err.message ? err.message : "?");
    vigen_error_clear(&err);
    return rc;
}

/* The claims vigen_check_certify records on a copy of t, by the theorem
 * path (trees = 0, where it decides) or by the walk over the trees. */
static claims certify(const vigen_tableau *t, int trees)
{
    vigen_tableau u;
    vigen_tableau_copy(&u, t);
    if (trees) setenv("VIGEN_CERTIFY_TREES", "1", 1);
    else unsetenv("VIGEN_CERTIFY_TREES");
    vigen_error err;
    vigen_error_init(&err);
    claims c = {-9, -9, -9, -9};
    if (vigen_check_certify(&u, "test", &err) == VIGEN_OK)
        c = (claims){u.claim_order, u.claim_order_sep, u.claim_order_nys, u.claim_symplectic};
    else fprintf(stderr, "certify: %s\n", err.message ? err.message : "?");
    unsetenv("VIGEN_CERTIFY_TREES");
    vigen_error_clear(&err);
    vigen_tableau_clear(&u);
    return c;
}

static int claims_eq(claims a, claims b)
{
    return a.order == b.order && a.sep == b.sep && a.nys == b.nys && a.symplectic == b.symplectic;
}

/* Every spec of the library (tableaux/specs) at the digits it ships with:
 * where the theorem decides, its claims are those of the tree walk; where
 * it does not, certification falls back to the walk.  Returns how many the
 * theorem decided. */
static int test_library(void)
{
    static const char *names[] = {
        "exponential_lua", "gauss_legendre_s1", "gauss_legendre_s2", "gauss_legendre_s3", "gauss_legendre_s4",
        "gauss_legendre_s5", "gauss_legendre_s6", "gauss_legendre_s7", "gauss_legendre_s8", "gauss_lobatto_s2",
        "gauss_lobatto_s3", "gauss_lobatto_s4", "gauss_lobatto_s5", "gauss_lobatto_s6", "leok_zhang_ex2_c0",
        "leok_zhang_ex2_c1", "leok_zhang_ex2_c12", "leok_zhang_ex3", "leok_zhang_ex4", "leok_zhang_ex5_s1",
        "leok_zhang_ex5_s2", "leok_zhang_ex5_s3", "radau_right_s2", "radau_right_s3", "radau_right_s4",
        "trig_gauss5"};
    int decided = 0;
    for (size_t k = 0; k < sizeof(names) / sizeof(names[0]); k++) {
        char path[1024];
        snprintf(path, sizeof(path), "%s/tableaux/specs/%s.lua", VIGEN_SOURCE_DIR, names[k]);
        vigen_tableau t;
        if (generate(&t, path, 50) != VIGEN_OK) {
            CHECK_MSG(0, "%s: not generated", names[k]);
            continue;
        }
        chk_theorem_verdict v;
        int by_theorem = chk_certify_theorem(&v, &t);
        claims a = certify(&t, 0), b = certify(&t, 1);
        CHECK_MSG(claims_eq(a, b), "%s: theorem path %d/%d/%d/%d, trees %d/%d/%d/%d", names[k], a.order, a.sep,
                  a.nys, a.symplectic, b.order, b.sep, b.nys, b.symplectic);
        if (by_theorem) {
            decided++;
            CHECK_MSG(v.order == b.order && b.order == b.sep && b.order == b.nys, "%s: theorem %d, trees %d",
                      names[k], v.order, b.order);
        }
        /* the Lobatto IIIA-IIIB pair: the colour-blind theorem gives 2s - 3 */
        if (strncmp(names[k], "gauss_lobatto", 13) == 0) CHECK_MSG(!by_theorem, "%s: decided by the theorem", names[k]);
        /* Gauss: 2s; Radau IIA with its symplectic partner: 2s - 1 */
        int s = (int)t.s;
        if (strncmp(names[k], "gauss_legendre", 14) == 0) CHECK_MSG(by_theorem && v.order == 2 * s, "%s", names[k]);
        if (strncmp(names[k], "radau_right", 11) == 0) CHECK_MSG(by_theorem && v.order == 2 * s - 1, "%s", names[k]);
        vigen_tableau_clear(&t);
    }
    return decided;
}

/* The published tableaux with exact entries, their balls at 2048 bits
 * standing for the generator's (they contain the exact values), claims
 * cleared: the theorem path agrees with the tree walk on their texts.
 * Rounded data (16-digit decimals) are the tree walk's alone.  Returns how
 * many the theorem decided. */
static int test_published(void)
{
    static const char *names[] = {
        "blanes_moan_s10_6", "blanes_moan_s6_4", "candy_rozmus_4", "forest_ruth_4", "gauss_1", "gauss_2",
        "gauss_3", "leok_zhang_ex2_i", "leok_zhang_ex2_ii", "leok_zhang_ex2_iii", "leok_zhang_ex3",
        "leok_zhang_ex4", "leok_zhang_ex5_i", "leok_zhang_ex5_ii", "leok_zhang_ex5_iii", "lobatto_iiia_iiib_2",
        "lobatto_iiia_iiib_3", "lobatto_iiia_iiib_4", "mclachlan_atela_2", "mclachlan_atela_3", "mclachlan_rkn_4",
        "ruth_3", "stormer_verlet_position", "stormer_verlet_velocity", "suzuki_4", "symplectic_euler_p_first",
        "symplectic_euler_q_first", "yoshida_4", "yoshida_6"};
    int decided = 0, exact = 0;
    for (size_t k = 0; k < sizeof(names) / sizeof(names[0]); k++) {
        char path[1024];
        snprintf(path, sizeof(path), "%s/tableaux/published/%s.lua", VIGEN_SOURCE_DIR, names[k]);
        vigen_tableau t;
        if (generate(&t, path, 0) != VIGEN_OK) {
            CHECK_MSG(0, "%s: not loaded", names[k]);
            continue;
        }
        exactness x;
        chk_exactness_init(&x, &t);
        int rounded = x.any_rounded;
        chk_exactness_clear(&x);
        vigen_error err;
        vigen_error_init(&err);
        if (!rounded && vigen_tableau_evaluate(&t, 2048, &err) == VIGEN_OK) {
            exact++;
            t.generated_now = 1;
            t.claim_order = t.claim_order_sep = t.claim_order_nys = t.claim_symplectic = -1;
            chk_theorem_verdict v;
            int by_theorem = chk_certify_theorem(&v, &t);
            claims a = certify(&t, 0), b = certify(&t, 1);
            CHECK_MSG(claims_eq(a, b), "%s: theorem path %d/%d/%d/%d, trees %d/%d/%d/%d", names[k], a.order, a.sep,
                      a.nys, a.symplectic, b.order, b.sep, b.nys, b.symplectic);
            if (by_theorem) {
                decided++;
                CHECK_MSG(v.order == b.order, "%s: theorem %d, trees %d", names[k], v.order, b.order);
            }
        }
        vigen_error_clear(&err);
        vigen_tableau_clear(&t);
    }
    printf("%d published tableaux with exact entries, %d decided by the theorem\n", exact, decided);
    return decided;
}

/* Gauss s = 1..10 at 1000 digits: order exactly 2s by the theorem. */
static void test_gauss(void)
{
    char dir[] = "/tmp/vigen_certify_XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    for (int s = 1; s <= 10; s++) {
        char path[256];
        snprintf(path, sizeof(path), "%s/gauss%d.lua", dir, s);
        FILE *f = fopen(path, "w");
        CHECK(f != NULL);
        if (f == NULL) continue;
        fprintf(f, "return { name = \"gauss%d\", basis = \"lagrange\", nodes = gauss_legendre(%d) }\n", s, s);
        fclose(f);
        vigen_tableau t;
        CHECK(generate(&t, path, 1000) == VIGEN_OK);
        chk_theorem_verdict v;
        CHECK_MSG(chk_certify_theorem(&v, &t) && v.order == 2 * s && v.symplectic == 1, "s = %d", s);
        claims a = certify(&t, 0);
        CHECK_MSG(a.order == 2 * s && a.sep == 2 * s && a.nys == 2 * s && a.symplectic == 1, "s = %d: %d", s, a.order);
        vigen_tableau_clear(&t);
        remove(path);
    }
    rmdir(dir);
}

/* Gauss s = 16 at 16 digits: B(33) fails by (16!)^4 / (33 (32!)^2) = 8.4e-20
 * (the quadrature error of x^32), which 16 digits do not show: the theorem
 * path declines, as `vigen check` of the written file could not confirm
 * order 32, and certification reports what the tree walk does. */
static void test_short_digits(void)
{
    char dir[] = "/tmp/vigen_certify_XXXXXX", path[256];
    CHECK(mkdtemp(dir) != NULL);
    snprintf(path, sizeof(path), "%s/gauss16.lua", dir);
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (f == NULL) return;
    fputs("return { name = \"gauss16\", basis = \"lagrange\", nodes = gauss_legendre(16) }\n", f);
    fclose(f);
    vigen_tableau t;
    CHECK(generate(&t, path, 16) == VIGEN_OK);
    chk_theorem_verdict v;
    CHECK(!chk_certify_theorem(&v, &t));
    CHECK(claims_eq(certify(&t, 0), certify(&t, 1)));
    vigen_tableau_clear(&t);
    /* at 100 digits it shows: order 32 */
    CHECK(generate(&t, path, 100) == VIGEN_OK);
    CHECK(chk_certify_theorem(&v, &t) && v.order == 32);
    vigen_tableau_clear(&t);
    remove(path);
    rmdir(dir);
}

/* An RK tableau from exact texts, its balls at prec (they contain the exact
 * values, as the generator's do). */
static void rk_exact(vigen_tableau *t, slong s, const char *const *c, const char *const *A, const char *const *b)
{
    vigen_tableau_init(t, s);
    t->c_text = calloc((size_t)s, sizeof(char *));
    t->b_text = calloc((size_t)s, sizeof(char *));
    t->A_text = calloc((size_t)(s * s), sizeof(char *));
    for (slong i = 0; i < s; i++) {
        t->c_text[i] = strdup(c[i]);
        t->b_text[i] = strdup(b[i]);
        for (slong j = 0; j < s; j++) t->A_text[i * s + j] = strdup(A[i * s + j]);
    }
    vigen_error err;
    vigen_error_init(&err);
    CHECK(vigen_tableau_evaluate(t, 2048, &err) == VIGEN_OK);
    vigen_error_clear(&err);
    t->generated_now = 1;
}

/* Radau IIA s = 2 (order 3) and Lobatto IIIA s = 3 (order 4), one RK
 * method each (Hairer, Wanner II, Tables 5.5 and 5.7). */
static void test_radau_lobatto(void)
{
    static const char *rc[] = {"1/3", "1"}, *rA[] = {"5/12", "-1/12", "3/4", "1/4"}, *rb[] = {"3/4", "1/4"};
    static const char *lc[] = {"0", "1/2", "1"}, *lA[] = {"0", "0", "0", "5/24", "1/3", "-1/24", "1/6", "2/3", "1/6"},
                      *lb[] = {"1/6", "2/3", "1/6"};
    vigen_tableau t;
    chk_theorem_verdict v;
    rk_exact(&t, 2, rc, rA, rb);
    CHECK(chk_certify_theorem(&v, &t) && v.order == 3);
    CHECK(claims_eq(certify(&t, 0), certify(&t, 1)));
    vigen_tableau_clear(&t);
    rk_exact(&t, 3, lc, lA, lb);
    CHECK(chk_certify_theorem(&v, &t) && v.order == 4);
    CHECK(claims_eq(certify(&t, 0), certify(&t, 1)));
    vigen_tableau_clear(&t);
}

/* Gauss s = 3 at 50 digits with a_11 moved by one unit of its last digit:
 * C(1) (the row sum) fails on the balls, the theorem path declines, and
 * certification reports what the tree walk does. */
static void test_perturbed(void)
{
    char path[1024];
    snprintf(path, sizeof(path), "%s/tableaux/specs/gauss_legendre_s3.lua", VIGEN_SOURCE_DIR);
    vigen_tableau t;
    CHECK(generate(&t, path, 50) == VIGEN_OK);
    chk_theorem_verdict v;
    CHECK(chk_certify_theorem(&v, &t));
    arb_t d;
    arb_init(d);
    arb_set_ui(d, 10);
    arb_pow_ui(d, d, 50, t.prec);
    arb_inv(d, d, t.prec);
    arb_ptr a = arb_mat_entry(t.A, 0, 0);
    arb_mul(d, d, a, t.prec);
    arb_add(a, a, d, t.prec);
    arb_clear(d);
    CHECK(!chk_certify_theorem(&v, &t));
    CHECK(claims_eq(certify(&t, 0), certify(&t, 1)));
    vigen_tableau_clear(&t);
}

int main(void)
{
    int decided = test_library();
    printf("%d specs of the library decided by the theorem\n", decided);
    /* Gauss 1..8 and Radau IIA 2..4 at least */
    CHECK_MSG(decided >= 11, "%d decided by the theorem", decided);
    /* Gauss 1..3 at least */
    CHECK(test_published() >= 3);
    test_gauss();
    test_radau_lobatto();
    test_perturbed();
    test_short_digits();
    flint_cleanup();
    if (testlib_failures) fprintf(stderr, "%d failures\n", testlib_failures);
    return testlib_failures != 0;
}
