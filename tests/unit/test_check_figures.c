/* test_check_figures.c — the figures of `vigen check`: principal error
 * constants, the linear stability interval, the cost of a step
 * (src/check/error_cost.c, stability.c).
 *
 * Sources of the expected values (never this code's own output):
 *  - error coefficients e(t) = (Phi(t) - 1/gamma(t)) / sigma(t) worked by
 *    hand for the implicit midpoint rule (Phi = 1/4 for every tree of order
 *    3: e = -1/24 for the bushy trees with two equal leaves, -1/12 with two
 *    different ones, 1/12 for the chains) and for the Lobatto IIIA-IIIB pair
 *    of 2 stages (Stormer-Verlet; docs/analysis.md has the table of its four
 *    alternating trees: -1/24, -1/6, 1/12, 1/12, so 5/24);
 *  - stability on q'' = -omega^2 q: Stormer-Verlet and symplectic Euler have
 *    tr R = 2 - x^2, stable for x < 2 (HLW GNI sec. I.5 / closed form); RK4
 *    has R = r(ix), r(z) = 1 + z + z^2/2 + z^3/6 + z^4/24, and
 *    |r(ix)|^2 = 1 - x^6/72 + x^8/576 <= 1 iff x <= 2 sqrt 2 (HNW II sec.
 *    IV.2); Gauss methods are A-stable with |r(ix)| = 1: unbounded;
 *    Forest-Ruth is the composition of three Verlet steps theta h,
 *    (1 - 2 theta) h, theta h, whose 2x2 matrices [[1 - y/2, x], [-x (1 -
 *    y/4), 1 - y/2]] (y = x^2, closed form) are multiplied here: the trace of
 *    the product crosses 2 at the checker's x* (about 1.573, the value
 *    quoted for this method in the literature on the linear stability of
 *    splitting methods; the assertion is the composed trace);
 *  - cost: Forest-Ruth uses 3 force evaluations per step (Forest & Ruth
 *    1990), velocity Verlet 1 (the last force is the next step's first).
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "vigen/check.h"
#include "testlib.h"
#include "test_check_load.h"

#define PREC 256

static int check_file(vigen_check_report *rep, const char *rel)
{
    return check_file_claim(rep, rel, -2, 0);
}

/* x = sqrt(num) / den, as a ball */
static void sqrt_over(arb_t x, ulong num, ulong den)
{
    arb_sqrt_ui(x, num, PREC);
    arb_div_ui(x, x, den, PREC);
}

static void test_error_constants(void)
{
    vigen_check_report rep;
    arb_t want;
    arb_init(want);

    /* implicit midpoint: 14 general trees of order 3: 4 at -1/24, 2 at
     * -1/12, 8 at 1/12: sum 11/144; separable: 2 at -1/24, 2 at 1/12: 5/288;
     * Nystrom (no black vertex with two children): -1/24, 1/12, 1/12: 9/576 */
    CHECK(check_file(&rep, "tableaux/published/gauss_1.lua") == VIGEN_OK);
    const vigen_check_error_constant *e = rep.error_constant;
    CHECK(e[VIGEN_CHECK_EC_GENERAL].available && e[VIGEN_CHECK_EC_GENERAL].order == 2);
    CHECK(e[VIGEN_CHECK_EC_GENERAL].ntrees == 14 && e[VIGEN_CHECK_EC_SEPARABLE].ntrees == 4 &&
          e[VIGEN_CHECK_EC_NYSTROM].ntrees == 3);
    sqrt_over(want, 11, 12);
    CHECK_CLOSE(e[VIGEN_CHECK_EC_GENERAL].value, want, 30, PREC);
    arb_set_ui(want, 5);
    arb_div_ui(want, want, 288, PREC);
    arb_sqrt(want, want, PREC);
    CHECK_CLOSE(e[VIGEN_CHECK_EC_SEPARABLE].value, want, 30, PREC);
    arb_set_ui(want, 3);
    arb_div_ui(want, want, 24, PREC);
    CHECK_CLOSE(e[VIGEN_CHECK_EC_NYSTROM].value, want, 30, PREC);
    vigen_check_report_clear(&rep);

    /* Lobatto IIIA-IIIB s = 2 (velocity Verlet): separable 5/24; Nystrom
     * without b[w,w] (-1/24): sqrt(24/576) = 1/sqrt(24) */
    CHECK(check_file(&rep, "tableaux/published/lobatto_iiia_iiib_2.lua") == VIGEN_OK);
    e = rep.error_constant;
    CHECK(e[VIGEN_CHECK_EC_SEPARABLE].available && e[VIGEN_CHECK_EC_SEPARABLE].order == 2);
    arb_set_ui(want, 5);
    arb_div_ui(want, want, 24, PREC);
    CHECK_CLOSE(e[VIGEN_CHECK_EC_SEPARABLE].value, want, 30, PREC);
    arb_rsqrt_ui(want, 24, PREC);
    CHECK_CLOSE(e[VIGEN_CHECK_EC_NYSTROM].value, want, 30, PREC);
    vigen_check_report_clear(&rep);

    /* an order above the trees evaluated: no constant (Gauss-6, order 12) */
    CHECK(check_file(&rep, "tableaux/generated/gauss_legendre_s6.lua") == VIGEN_OK);
    CHECK(!rep.error_constant[VIGEN_CHECK_EC_GENERAL].available);
    vigen_check_report_clear(&rep);
    arb_clear(want);
}

/* The Verlet matrix of a step gamma h on q'' = -omega^2 q, in (q, p/omega),
 * kick-drift-kick: [[1 - z/2, g x], [-g x (1 - z/4), 1 - z/2]], z = (g x)^2. */
static void verlet(arb_t m[4], const arb_t gx)
{
    arb_t z;
    arb_init(z);
    arb_sqr(z, gx, PREC);
    arb_mul_2exp_si(m[0], z, -1);
    arb_sub_ui(m[0], m[0], 1, PREC);
    arb_neg(m[0], m[0]);
    arb_set(m[3], m[0]);
    arb_set(m[1], gx);
    arb_mul_2exp_si(m[2], z, -2);
    arb_sub_ui(m[2], m[2], 1, PREC);
    arb_mul(m[2], m[2], gx, PREC);   /* -g x (1 - z/4) = g x (z/4 - 1) */
    arb_clear(z);
}

static void mat_mul(arb_t out[4], arb_t a[4], arb_t b[4])
{
    arb_t r[4];
    for (int k = 0; k < 4; k++) arb_init(r[k]);
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++) {
            arb_mul(r[2 * i + j], a[2 * i], b[j], PREC);
            arb_addmul(r[2 * i + j], a[2 * i + 1], b[2 + j], PREC);
        }
    for (int k = 0; k < 4; k++) {
        arb_swap(out[k], r[k]);
        arb_clear(r[k]);
    }
}

/* The trace of the Forest-Ruth step at x: three Verlet steps theta, 1 - 2
 * theta, theta (theta = 1/(2 - 2^(1/3))). */
static void forest_ruth_trace(arb_t tr, const arb_t x)
{
    arb_t th, g, m[4], p[4];
    arb_init(th);
    arb_init(g);
    for (int k = 0; k < 4; k++) {
        arb_init(m[k]);
        arb_init(p[k]);
    }
    arb_set_ui(th, 2);
    arb_root_ui(th, th, 3, PREC);
    arb_sub_ui(th, th, 2, PREC);
    arb_neg(th, th);
    arb_inv(th, th, PREC);
    arb_mul(g, th, x, PREC);
    verlet(p, g);
    arb_mul_2exp_si(g, th, 1);
    arb_sub_ui(g, g, 1, PREC);
    arb_neg(g, g);
    arb_mul(g, g, x, PREC);
    verlet(m, g);
    mat_mul(p, m, p);
    arb_mul(g, th, x, PREC);
    verlet(m, g);
    mat_mul(p, m, p);
    arb_add(tr, p[0], p[3], PREC);
    arb_clear(th);
    arb_clear(g);
    for (int k = 0; k < 4; k++) {
        arb_clear(m[k]);
        arb_clear(p[k]);
    }
}

/* 1 when x > d certainly, -1 when x < d certainly, 0 otherwise */
static int cmp_d(const arb_t x, double d)
{
    arb_t y;
    arb_init(y);
    arb_set_d(y, d);
    int r = arb_gt(x, y) ? 1 : arb_lt(x, y) ? -1 : 0;
    arb_clear(y);
    return r;
}

static void test_stability(void)
{
    vigen_check_report rep;
    arb_t want;
    arb_init(want);
    const char *two[] = {"tableaux/published/stormer_verlet_position.lua",
                         "tableaux/published/stormer_verlet_velocity.lua",
                         "tableaux/published/symplectic_euler_p_first.lua",
                         "tableaux/published/symplectic_euler_q_first.lua"};
    for (int k = 0; k < 4; k++) {
        CHECK(check_file(&rep, two[k]) == VIGEN_OK);
        CHECK_MSG(rep.stability.status == VIGEN_CHECK_STAB_BOUNDED, "%s", two[k]);
        arb_set_ui(want, 2);
        CHECK(arb_contains(rep.stability.x, want));
        CHECK_CLOSE(rep.stability.x, want, 30, PREC);
        vigen_check_report_clear(&rep);
    }
    /* RK4: 2 sqrt 2 */
    CHECK(check_file(&rep, "tests/data/check/rk4.lua") == VIGEN_OK);
    CHECK(rep.stability.status == VIGEN_CHECK_STAB_BOUNDED);
    sqrt_over(want, 8, 1);
    CHECK(arb_overlaps(rep.stability.x, want));
    CHECK_CLOSE(rep.stability.x, want, 30, PREC);
    vigen_check_report_clear(&rep);
    /* Gauss: unbounded (exact s = 1..3, rounded s = 4..6) */
    const char *gauss[] = {"tableaux/published/gauss_1.lua", "tableaux/published/gauss_2.lua",
                           "tableaux/published/gauss_3.lua", "tableaux/generated/gauss_legendre_s4.lua",
                           "tableaux/generated/gauss_legendre_s6.lua"};
    for (int k = 0; k < 5; k++) {
        CHECK(check_file(&rep, gauss[k]) == VIGEN_OK);
        CHECK_MSG(rep.stability.status == VIGEN_CHECK_STAB_UNBOUNDED, "%s", gauss[k]);
        vigen_check_report_clear(&rep);
    }
    /* Forest-Ruth: the composed Verlet trace is within (-2, 2) just below x*
     * and above 2 just above it */
    CHECK(check_file(&rep, "tableaux/published/forest_ruth_4.lua") == VIGEN_OK);
    CHECK(rep.stability.status == VIGEN_CHECK_STAB_BOUNDED);
    {
        arb_t x, tr, eps;
        arb_init(x);
        arb_init(tr);
        arb_init(eps);
        arb_set_d(eps, 1e-12);
        arb_sub(x, rep.stability.x, eps, PREC);
        forest_ruth_trace(tr, x);
        CHECK(cmp_d(tr, -2) > 0 && cmp_d(tr, 2) < 0);
        arb_add(x, rep.stability.x, eps, PREC);
        forest_ruth_trace(tr, x);
        CHECK(cmp_d(tr, 2) > 0);
        /* published: about 1.573 */
        arb_set_d(want, 1.573);
        arb_sub(x, rep.stability.x, want, PREC);
        arb_abs(x, x);
        CHECK(cmp_d(x, 1e-3) < 0);
        arb_clear(x);
        arb_clear(tr);
        arb_clear(eps);
    }
    vigen_check_report_clear(&rep);
    arb_clear(want);
}

static void test_cost(void)
{
    vigen_check_report rep;
    CHECK(check_file(&rep, "tableaux/published/forest_ruth_4.lua") == VIGEN_OK);
    CHECK(rep.cost.stages == 6 && rep.cost.force == 3 && rep.cost.explicit_separable && !rep.cost.explicit_general);
    vigen_check_report_clear(&rep);
    CHECK(check_file(&rep, "tableaux/published/stormer_verlet_velocity.lua") == VIGEN_OK);
    CHECK(rep.cost.force == 1 && rep.cost.fsal && rep.cost.explicit_separable);
    vigen_check_report_clear(&rep);
    CHECK(check_file(&rep, "tests/data/check/rk4.lua") == VIGEN_OK);
    CHECK(rep.cost.force == 4 && rep.cost.explicit_separable && rep.cost.explicit_general);
    vigen_check_report_clear(&rep);
    CHECK(check_file(&rep, "tableaux/published/gauss_2.lua") == VIGEN_OK);
    CHECK(rep.cost.force == 2 && !rep.cost.explicit_separable && !rep.cost.explicit_general);
    vigen_check_report_clear(&rep);
}

/* The Nystrom trees counted independently: a white root has a multiset of
 * black-rooted children, a black root one white-rooted child, so with W(n)
 * and B(n) the white- and black-rooted Nystrom trees of order n, B(n) =
 * W(n - 1) and W(n) counts multisets of black trees of total order n - 1.
 * W = 1, 1, 2, 3, 6, 10, 20, 36 is the number of RKN conditions of each order
 * (Hairer, Norsett, Wanner I, sec. II.14). */
static void test_nystrom_trees(void)
{
    enum { NMAX = 8 };
    slong W[NMAX + 1] = {0}, Bt[NMAX + 1] = {0};
    W[1] = Bt[1] = 1;
    for (int n = 2; n <= NMAX; n++) {
        Bt[n] = W[n - 1];
        /* multisets of black trees of total n - 1: knapsack over sizes k with
         * Bt[k] kinds each (multisets of m trees among Bt[k] kinds) */
        slong ways[NMAX + 1] = {1};
        for (int k = 1; k <= n - 1; k++) {
            slong next[NMAX + 1] = {0};
            for (int t = 0; t <= n - 1; t++)
                for (int m = 0; m * k <= t; m++) {
                    /* C(Bt[k] + m - 1, m) */
                    slong c = 1;
                    for (int i = 0; i < m; i++) c = c * (Bt[k] + i) / (i + 1);
                    next[t] += ways[t - m * k] * c;
                }
            for (int t = 0; t <= NMAX; t++) ways[t] = next[t];
        }
        W[n] = ways[n - 1];
    }
    CHECK(W[5] == 6 && W[6] == 10 && W[7] == 20 && W[8] == 36);
    vigen_check_report rep;
    CHECK(check_file(&rep, "tableaux/generated/gauss_legendre_s4.lua") == VIGEN_OK);
    for (int n = 1; n <= NMAX; n++)
        CHECK_MSG(rep.orders[VIGEN_CHECK_NYSTROM].count[n] == W[n] + Bt[n], "order %d: %ld, want %ld", n,
                  (long)rep.orders[VIGEN_CHECK_NYSTROM].count[n], (long)(W[n] + Bt[n]));
    vigen_check_report_clear(&rep);
}

int main(void)
{
    test_nystrom_trees();
    test_error_constants();
    test_stability();
    test_cost();
    TEST_MAIN_END();
}
