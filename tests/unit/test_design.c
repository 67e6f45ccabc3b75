/* test_design.c — vigen design (src/design): the order conditions of
 * compositions, the search, the Krawczyk proof and the certified solutions.
 *
 * Independent sources:
 *  - the conditions of the symmetric 3-stage composition of a symmetric
 *    second-order method, 2 x1 + x2 = 1 and 2 x1^3 + x2^3 = 0 (Yoshida,
 *    Phys. Lett. A 150 (1990) 262, eq. (4.4); HLW GNI sec. II.4), compared
 *    here with the polynomials built from the BCH series at rational points;
 *  - the number of conditions of symmetric compositions of a symmetric
 *    second-order method, 1, 2, 4, 8, 16 for orders 2, 4, 6, 8, 10
 *    (McLachlan, SIAM J. Sci. Comput. 16 (1995) 151, Table 2; the minimal
 *    stage counts 3, 7, 15, 31 of Yoshida's and Kahan-Li's families), and 3
 *    for non-symmetric compositions of order 4 (HLW GNI sec. V.3.2);
 *  - the triple jump gamma_1 = gamma_3 = 1/(2 - 2^(1/3)), gamma_2 = 1 - 2
 *    gamma_1 (Yoshida 1990, Suzuki 1990), computed here in arb: the digits
 *    written are a correct rounding of it;
 *  - Yoshida's three solutions A, B, C of the sixth-order 7-stage family as
 *    he printed them (Table 1, 15 digits): each found, certified of order 6
 *    exactly (not 7) and within 2e-14 of the printed digits (Yoshida's own
 *    digits are off by up to 1.2e-14, docs/design.md);
 *  - the number of conditions of splittings in the drifts A and the kicks B,
 *    the dimensions of the free Lie algebra on two generators (Witt);
 *  - order 6 from 5 symmetric stages has no solution (McLachlan 1995: the
 *    minimal symmetric sixth-order composition has 7 stages);
 *  - minimize on the 5-stage symmetric order-4 family: Suzuki's fractal
 *    composition (Phys. Lett. A 146 (1990) 319) is a member, so the best
 *    point found has an error constant no larger than the checker's on the
 *    library's suzuki_4;
 *  - the numbers of RKN conditions, McLachlan's RKN method of order 4 and
 *    the effective-order condition of the two-kick kernel (each test's
 *    comment gives its source);
 *  - the Krawczyk test refuses a box that holds no root: the triple jump
 *    moved by 1e-10 with a box of radius 1e-20, and a point far from every
 *    root.
 */
#define _GNU_SOURCE /* asprintf */
#include <stdlib.h>
#include <string.h>
#include "design/design_internal.h"
#include "core/decimal.h"
#include "vigen/check.h"
#include "vigen/design.h"
#include "vigen/library.h"
#include "vigen/method.h"
#include "testlib.h"

#define PREC 256

static void test_triple_jump_conditions(void)
{
    vigen_error err;
    vigen_error_init(&err);
    design_system sys;
    CHECK(design_composition_conditions(&sys, 3, 1, 2, 4, &err) == VIGEN_OK);
    CHECK(sys.k == 2 && sys.n == 2);
    arb_t v, want, t;
    arb_init(v);
    arb_init(want);
    arb_init(t);
    arb_ptr x = _arb_vec_init(2);
    for (int a = -3; a <= 3; a++)
        for (int b = 1; b <= 4; b++) {
            arb_set_si(x + 0, a);
            arb_div_si(x + 0, x + 0, b, PREC);
            arb_set_si(x + 1, 2 * b - a);
            arb_div_si(x + 1, x + 1, 3, PREC);
            /* 2 x1 + x2 - 1 */
            design_poly_eval_arb(v, &sys.cond[0], x, PREC);
            arb_mul_si(want, x + 0, 2, PREC);
            arb_add(want, want, x + 1, PREC);
            arb_sub_si(want, want, 1, PREC);
            arb_sub(t, v, want, PREC);
            CHECK(arb_contains_zero(t) && mag_cmp_2exp_si(arb_radref(t), -200) < 0);
            /* 2 x1^3 + x2^3 */
            design_poly_eval_arb(v, &sys.cond[1], x, PREC);
            arb_pow_ui(want, x + 0, 3, PREC);
            arb_mul_si(want, want, 2, PREC);
            arb_pow_ui(t, x + 1, 3, PREC);
            arb_add(want, want, t, PREC);
            arb_sub(t, v, want, PREC);
            CHECK(arb_contains_zero(t) && mag_cmp_2exp_si(arb_radref(t), -200) < 0);
        }
    _arb_vec_clear(x, 2);
    arb_clear(v);
    arb_clear(want);
    arb_clear(t);
    design_system_clear(&sys);
}

static void test_counts(void)
{
    static const int want[] = {1, 2, 4, 8, 16};
    for (int i = 0; i < 5; i++) CHECK_MSG(design_composition_count(1, 2, 2 * i + 2) == want[i], "order %d", 2 * i + 2);
    CHECK(design_composition_count(0, 2, 4) == 3);
    /* splittings: Witt's dimensions 2, 1, 2, 3, 6 of the free Lie algebra on
     * two generators in degrees 1..5 (Reutenauer, Free Lie Algebras, 0.4.2):
     * odd degrees only when symmetric */
    CHECK(design_splitting_count(1, 4) == 4);
    CHECK(design_splitting_count(1, 6) == 10);
    CHECK(design_splitting_count(0, 4) == 8);
    /* the polynomials agree with the count: none vanishes identically */
    vigen_error err;
    vigen_error_init(&err);
    design_system sys;
    CHECK(design_composition_conditions(&sys, 15, 1, 2, 8, &err) == VIGEN_OK);
    CHECK(sys.n == 8 && sys.k == 8);
    design_system_clear(&sys);
}

/* The conditions for Nystrom H (T = p^2/2, V(q)): the free Lie algebra on
 * A, B modulo the relations of T and V ([B,[B,[B,A]]] = 0 first, a new one
 * at degree 8, where the ideal of [B,[B,[B,A]]] alone would leave 15) has
 * dimensions 2, 1, 2, 2, 4, 5, 10, 14 in degrees 1..8, the numbers of RKN
 * order conditions per order
 * (McLachlan, SIAM J. Sci. Comput. 16 (1995) 151; Blanes & Moan, J. Comput.
 * Appl. Math. 142 (2002) 313; Blanes & Casas, A Concise Introduction to
 * Geometric Numerical Integration, sec. 3.4), against Witt's 2, 1, 2, 3, 6,
 * 9, 18, 30 for separable H: symmetric order 4 asks 4 conditions of both,
 * order 6 asks 8 against 10.  A kernel of effective order 4 asks dim Lie_3 -
 * dim Lie_2 = 1 condition at h^3 instead of 2 (Blanes, Casas & Ros, SIAM J.
 * Sci. Comput. 21 (1999) 711): 3 in all. */
static void test_nystrom_counts(void)
{
    static const slong dim[] = {2, 1, 2, 2, 4, 5, 10, 14};
    slong below = 0;
    for (int p = 1; p <= 8; p++) {
        slong n = design_quotient_count(p, 0, DESIGN_MOD_NYSTROM);
        CHECK_MSG(n - below == dim[p - 1], "degree %d: %ld conditions, want %ld", p, (long)(n - below),
                  (long)dim[p - 1]);
        below = n;
    }
    CHECK(design_quotient_count(4, 1, DESIGN_MOD_NYSTROM) == 4 && design_splitting_count(1, 4) == 4);
    CHECK(design_quotient_count(6, 1, DESIGN_MOD_NYSTROM) == 8 && design_splitting_count(1, 6) == 10);
    CHECK(design_quotient_count(8, 1, DESIGN_MOD_NYSTROM) == 2 + 2 + 4 + 10);
    CHECK(design_quotient_count(4, 1, DESIGN_MOD_PROCESSED) == 3);
    CHECK(design_quotient_count(4, 1, DESIGN_MOD_PROCESSED | DESIGN_MOD_NYSTROM) == 3);
    /* the plain quotient (mods 0) is the Lyndon count */
    CHECK(design_quotient_count(6, 0, 0) == design_splitting_count(0, 6));
    /* the polynomials agree with the count: 7 kicks, order 6 */
    vigen_error err;
    vigen_error_init(&err);
    design_system sys;
    CHECK(design_splitting_conditions(&sys, 7, 1, 6, DESIGN_MOD_NYSTROM, &err) == VIGEN_OK);
    CHECK(sys.n == 8 && sys.k == 8);
    design_system_clear(&sys);
}

static void run(vigen_design_result *res, const char *file, long digits)
{
    vigen_error err;
    vigen_error_init(&err);
    vigen_design_spec d;
    char *path = NULL;
    int rc = asprintf(&path, "%s/tests/data/design/%s", VIGEN_SOURCE_DIR, file);
    CHECK(rc > 0);
    CHECK_MSG(vigen_design_read(&d, path, &err) == VIGEN_OK, "%s", err.message ? err.message : "");
    vigen_design_options opt;
    vigen_design_options_init(&opt);
    opt.outdir = "/nonexistent";
    opt.digits = digits;
    CHECK_MSG(vigen_design_run(res, &d, &opt, &err) == VIGEN_OK, "%s", err.message ? err.message : "");
    vigen_error_clear(&err);
    vigen_design_spec_clear(&d);
    free(path);
}

/* the decimal text, read as the ball of half a unit in its last digit,
 * contains x */
static int rounds(const char *text, const arb_t x)
{
    arb_t b;
    arb_init(b);
    int ok = text && vigen_decimal_parse_rounded(b, text, 4 * PREC) && arb_contains(b, x) &&
             vigen_decimal_significant_digits(text) >= 60;
    arb_clear(b);
    return ok;
}

static void test_triple_jump(void)
{
    vigen_design_result res;
    run(&res, "triple_jump.lua", 60);
    CHECK(res.nsol == 1);
    if (res.nsol == 1) {
        const vigen_design_solution *s = &res.sol[0];
        CHECK(s->proved && s->certified && s->order == 4);
        arb_t g1, g2, c;
        arb_init(g1);
        arb_init(g2);
        arb_init(c);
        arb_set_ui(c, 2);
        arb_root_ui(c, c, 3, 4 * PREC);
        arb_set_ui(g1, 2);
        arb_sub(g1, g1, c, 4 * PREC);
        arb_inv(g1, g1, 4 * PREC);   /* 1/(2 - 2^(1/3)) */
        arb_mul_2exp_si(g2, g1, 1);
        arb_sub_ui(g2, g2, 1, 4 * PREC);
        arb_neg(g2, g2);             /* 1 - 2 gamma_1 */
        CHECK_MSG(rounds(s->digits[0], g1), "gamma_1 = %s", s->digits[0] ? s->digits[0] : "-");
        CHECK_MSG(rounds(s->digits[1], g2), "gamma_2 = %s", s->digits[1] ? s->digits[1] : "-");
        CHECK(s->text && strstr(s->text, "order = 4") && strstr(s->text, "symplectic = true"));
        arb_clear(g1);
        arb_clear(g2);
        arb_clear(c);
    }
    vigen_design_result_clear(&res);
}

static void test_yoshida6(void)
{
    /* Yoshida (1990), Table 1: w1, w2, w3 of solutions A, B, C */
    static const double printed[3][3] = {
        {-1.17767998417887, 0.235573213359357, 0.784513610477560},
        {-2.13228522200144, 0.426068187079180e-2, 1.43984816797678},
        {0.152886228424922e-2, -2.14403531630539, 1.44778256239930},
    };
    vigen_design_result res;
    run(&res, "yoshida6.lua", 40);
    CHECK(res.nsol == 3 && res.nconditions == 4 && res.nunknowns == 4);
    int matched[3] = {0, 0, 0};
    for (slong i = 0; i < res.nsol; i++) {
        const vigen_design_solution *s = &res.sol[i];
        CHECK(s->proved && s->certified && s->order == 6);
        if (!s->proved) continue;
        /* the unknowns are (gamma_1, ..., gamma_4) = (w3, w2, w1, w0) */
        for (int a = 0; a < 3; a++) {
            int close = 1;
            for (int j = 0; j < 3; j++) {
                arb_t x, y;
                arb_init(x);
                arb_init(y);
                vigen_decimal_parse_rounded(x, s->digits[2 - j], PREC);
                arb_set_d(y, printed[a][j]);
                arb_sub(x, x, y, PREC);
                arb_abs(x, x);
                close &= arf_cmpabs_d(arb_midref(x), 2e-14) < 0;
                arb_clear(x);
                arb_clear(y);
            }
            matched[a] += close;
        }
    }
    CHECK(matched[0] == 1 && matched[1] == 1 && matched[2] == 1);
    vigen_design_result_clear(&res);
}

static void test_no_solution(void)
{
    vigen_design_result res;
    run(&res, "no_solution.lua", 40);
    CHECK(res.nconditions == 4 && res.nunknowns == 3 && res.nsquare == 3);
    for (slong i = 0; i < res.nsol; i++) CHECK(!res.sol[i].certified && res.sol[i].excluded);
    vigen_design_result_clear(&res);
}

static void test_minimize(void)
{
    vigen_design_result res;
    run(&res, "s5_minimize.lua", 40);
    CHECK(res.minimized && res.nfree == 1 && res.nsol == 1);
    vigen_tableau t;
    vigen_error err;
    vigen_error_init(&err);
    char *path = NULL;
    CHECK(vigen_library_resolve(&path, "suzuki_4", &err) == VIGEN_OK);
    CHECK(vigen_source_load(&t, path, 34, &err) == VIGEN_OK);
    vigen_check_options opt;
    vigen_check_options_init(&opt);
    vigen_check_report rep;
    vigen_check_report_init(&rep);
    CHECK(vigen_check_tableau(&rep, &t, NULL, &opt, &err) == VIGEN_OK);
    CHECK(rep.error_constant[VIGEN_CHECK_EC_GENERAL].available);
    double suzuki = arf_get_d(arb_midref(rep.error_constant[VIGEN_CHECK_EC_GENERAL].value), ARF_RND_NEAR);
    if (res.nsol == 1) {
        const vigen_design_solution *s = &res.sol[0];
        CHECK(s->proved && s->certified && s->order == 4);
        CHECK_MSG(s->error_constant_d <= suzuki, "%g > Suzuki's %g", s->error_constant_d, suzuki);
    }
    vigen_check_report_clear(&rep);
    vigen_tableau_clear(&t);
    free(path);
    vigen_design_result_clear(&res);
}

/* McLachlan's RKN method of order 4 with five kicks (SIAM J. Sci. Comput.
 * 16 (1995) 151, SB3A; the library's mclachlan_rkn_4): with b1 = -3/73 and
 * b2 = 17/59 held, the drifts are a1 = (1095 sqrt(722025967665) -
 * 229483763)/1729961856 and a2 = (315354233 - 1081 sqrt(722025967665)) /
 * 2100667968, closed forms computed here in arb: one solution of the family
 * is them, certified of order 4 for Nystrom H. */
static void test_mclachlan_rkn(void)
{
    vigen_design_result res;
    run(&res, "mclachlan_rkn4.lua", 60);
    arb_t r, a1, a2, t;
    arb_init(r);
    arb_init(a1);
    arb_init(a2);
    arb_init(t);
    arb_set_str(r, "722025967665", 4 * PREC);
    arb_sqrt(r, r, 4 * PREC);
    arb_mul_ui(a1, r, 1095, 4 * PREC);
    arb_sub_ui(a1, a1, 229483763, 4 * PREC);
    arb_div_ui(a1, a1, 1729961856, 4 * PREC);
    arb_mul_ui(a2, r, 1081, 4 * PREC);
    arb_neg(a2, a2);
    arb_add_ui(a2, a2, 315354233, 4 * PREC);
    arb_div_ui(a2, a2, 2100667968, 4 * PREC);
    int found = 0;
    for (slong i = 0; i < res.nsol; i++) {
        const vigen_design_solution *s = &res.sol[i];
        CHECK(s->certified && s->order_nystrom == 4);
        if (s->digits && rounds(s->digits[0], a1) && rounds(s->digits[1], a2)) found++;
    }
    CHECK_MSG(found == 1, "%d solutions are McLachlan's", found);
    arb_clear(r);
    arb_clear(a1);
    arb_clear(a2);
    arb_clear(t);
    vigen_design_result_clear(&res);
}

/* The kernel drift a, kick 1/2, drift 1 - 2a, kick 1/2, drift a: its h^3
 * term lies in [A+B, Lie_2] exactly when a^2/2 - a/4 + 1/24 = 0 (the BCH
 * coefficients of the words AAB and ABB, summed, worked out independently
 * of this code), whose discriminant 1/16 - 1/12 is negative: no real
 * kernel of effective order 4 has two kicks, where Forest and Ruth's
 * order 4 needs three. */
static void test_processed_two_kicks(void)
{
    vigen_error err;
    vigen_error_init(&err);
    design_system sys;
    CHECK(design_splitting_conditions(&sys, 2, 1, 4, DESIGN_MOD_PROCESSED, &err) == VIGEN_OK);
    CHECK(sys.n == 3 && sys.k == 3);
    arb_ptr x = _arb_vec_init(3);
    arb_t v, want, ratio, first;
    arb_init(v);
    arb_init(want);
    arb_init(ratio);
    arb_init(first);
    for (int num = -5; num <= 5; num++) {
        /* unknowns: drifts a1, a2, then the kick b1 */
        arb_set_si(x + 0, num);
        arb_div_si(x + 0, x + 0, 7, PREC);
        arb_mul_2exp_si(x + 1, x + 0, 1);
        arb_neg(x + 1, x + 1);
        arb_add_ui(x + 1, x + 1, 1, PREC);
        arb_set_d(x + 2, 0.5);
        design_poly_eval_arb(v, &sys.cond[2], x, PREC);
        arb_sqr(want, x + 0, PREC);
        arb_mul_2exp_si(want, want, -1);
        arb_mul_2exp_si(ratio, x + 0, -2);
        arb_sub(want, want, ratio, PREC);
        arb_set_ui(ratio, 1);
        arb_div_ui(ratio, ratio, 24, PREC);
        arb_add(want, want, ratio, PREC);
        arb_div(ratio, v, want, PREC);
        if (num == -5) arb_set(first, ratio);
        arb_sub(want, ratio, first, PREC);
        CHECK(!arb_contains_zero(first) && arb_contains_zero(want) && mag_cmp_2exp_si(arb_radref(want), -200) < 0);
    }
    _arb_vec_clear(x, 3);
    arb_clear(v);
    arb_clear(want);
    arb_clear(ratio);
    arb_clear(first);
    design_system_clear(&sys);
    vigen_design_result res;
    run(&res, "processed_2kicks.lua", 40);
    for (slong i = 0; i < res.nsol; i++) CHECK(!res.sol[i].certified);
    vigen_design_result_clear(&res);
}

static void test_krawczyk_refuses(void)
{
    vigen_error err;
    vigen_error_init(&err);
    design_system sys;
    CHECK(design_composition_conditions(&sys, 3, 1, 2, 4, &err) == VIGEN_OK);
    slong rows[2] = {0, 1};
    double g1 = 1.0 / (2.0 - 1.2599210498948731648), x0[2] = {g1, 1 - 2 * g1};
    arb_ptr box = _arb_vec_init(2), mid = _arb_vec_init(2), out = _arb_vec_init(2);
    CHECK(design_krawczyk_prove(box, &sys, rows, x0, PREC) == 1);
    /* the proved box, moved by 1e-10, at radius 1e-20: no root inside */
    mag_t rad;
    mag_init(rad);
    mag_set_d(rad, 1e-20);
    for (int j = 0; j < 2; j++) {
        arb_get_mid_arb(mid + j, box + j);
        arb_add_error_2exp_si(mid + j, -400);
        arb_get_mid_arb(mid + j, mid + j);
    }
    CHECK(design_krawczyk_test(out, &sys, rows, mid, rad, PREC) == 1);
    arb_set_d(out, 1e-10);
    arb_add(mid + 0, mid + 0, out, PREC);
    CHECK(design_krawczyk_test(out, &sys, rows, mid, rad, PREC) == 0);
    /* far from every root: refused at any radius tried */
    arb_set_d(mid + 0, 0.5);
    arb_set_d(mid + 1, 0.0);
    for (double r = 1e-12; r < 1; r *= 1e3) {
        mag_set_d(rad, r);
        CHECK(design_krawczyk_test(out, &sys, rows, mid, rad, PREC) == 0);
    }
    mag_clear(rad);
    _arb_vec_clear(box, 2);
    _arb_vec_clear(mid, 2);
    _arb_vec_clear(out, 2);
    design_system_clear(&sys);
}

int main(void)
{
    vigen_method_set_name_resolver(vigen_library_resolve);
    test_triple_jump_conditions();
    test_counts();
    test_nystrom_counts();
    test_krawczyk_refuses();
    test_triple_jump();
    test_yoshida6();
    test_no_solution();
    test_minimize();
    test_mclachlan_rkn();
    test_processed_two_kicks();
    TEST_MAIN_END();
}
