/* test_emit_brackets.c — emitted splitting steppers with bracket flows
 * (`brackets = {...}` of a splitting file: a substep advances the flow of
 * the Poisson bracket of its k letters by coef h^k), emitted at build time
 * (tests/CMakeLists.txt).  The problem is the harmonic oscillator
 * H = A + eps B, A = p^2/2 (flow q += t p), B = q^2/2 (flow p -= t eps q),
 * whose brackets have closed-form flows ({F, G} = F_q G_p - F_p G_q):
 *   {{A, B}, B} = eps^2 q^2 (the "interaction_gradient" |dB/dq|^2):
 *     p -= 2 t eps^2 q;
 *   {A, B} = -eps p q: q *= exp(-eps t), p *= exp(eps t).
 * The truths are the exact solution q0 cos(w t) + (p0/w) sin(w t),
 * w = sqrt(eps), and the papers' orders:
 *   - SABAC_2 (Laskar & Robutel 2001) is of classical order 4 with exact
 *     flows: its error falls by 16 per halving of h, where SABA_2's (the
 *     same method without its correctors) falls by 4;
 *   - the Wisdom-Holman map with the modified kick: for small eps its
 *     error against SABA_1 (the same map with the plain kick) loses the
 *     eps^2 h^2 part: at eps = 1e-3 the bare map's error is
 *     eps h^2 (1/24 [A,[A,B]]) + eps^2 h^2 (1/12 [[A,B],B]); both are
 *     second order, and the modified kick's error falls by 4;
 *   - one bracket {A, B}: a for h, b for h, {a, b} for h^2/2 is of order 2
 *     (ratio 4; with the opposite sign convention it would be of order 1);
 *   - the bracket flow is called with coef h^3: -(g_2/2) h^3 with
 *     g_2 = (2 - sqrt 3)/24 (the paper's), twice per step;
 *   - the header: NFLOWS, the flow constants and the certified order. */
#include <math.h>
#include <stdlib.h>
#include "testlib.h"
#include <vigen/runtime.h>
#include "bx_sabac2.h"
#include "bx_saba2.h"
#include "bx_mk.h"
#include "bx_saba1.h"
#include "bx_ab.h"

typedef struct {
    double eps;
    long grad_calls;
    double last_tau;   /* the time the last gradient call was given */
} osc;

static int drift(double t, double h, double *q, double *p, void *ctx)
{
    (void)t; (void)ctx;
    q[0] += h * p[0];
    return VIGEN_SUCCESS;
}
static int kick(double t, double h, double *q, double *p, void *ctx)
{
    (void)t;
    p[0] -= h * ((osc *)ctx)->eps * q[0];
    return VIGEN_SUCCESS;
}
static int gradient(double t, double h, double *q, double *p, void *ctx)
{
    (void)t;
    osc *o = ctx;
    o->grad_calls++;
    o->last_tau = h;
    p[0] -= 2 * h * o->eps * o->eps * q[0];
    return VIGEN_SUCCESS;
}
static int bracket_ab(double t, double h, double *q, double *p, void *ctx)
{
    (void)t;
    const double e = ((osc *)ctx)->eps;
    q[0] *= exp(-e * h);
    p[0] *= exp(e * h);
    return VIGEN_SUCCESS;
}

static const vigen_flow_fn flows3[3] = { drift, kick, gradient };
static const vigen_flow_fn flows_ab[3] = { drift, kick, bracket_ab };

/* the oscillator with the first nflows of flows3 (drift, kick, gradient) */
static vigen_split_problem problem(osc *o, size_t nflows)
{
    vigen_split_problem sp = { 1, nflows, flows3, o, NULL, NULL };
    return sp;
}

/* the error at T = 1 of n steps from (q, p) = (1, 0.5) */
static double error_at_1(const vigen_stepper_type *T, void *w, const osc *o, int n)
{
    double t = 0, q = 1, p = 0.5;
    T->reset(w);
    CHECK(vigen_integrate(T, w, &t, &q, &p, 1.0 / n, (unsigned long)n, 0, NULL, NULL, NULL) == VIGEN_SUCCESS);
    const double om = sqrt(o->eps);
    const double qe = cos(om) + 0.5 / om * sin(om), pe = -om * sin(om) + 0.5 * cos(om);
    return hypot(q - qe, p - pe);
}

static void check_ratio(const vigen_stepper_type *T, void *w, const osc *o, int n0, double want, const char *what)
{
    const double e0 = error_at_1(T, w, o, n0), e1 = error_at_1(T, w, o, 2 * n0), e2 = error_at_1(T, w, o, 4 * n0);
    const double r1 = e0 / e1, r2 = e1 / e2;
    CHECK_MSG(fabs(r1 / want - 1) < 0.1 && fabs(r2 / want - 1) < 0.1, "%s: error ratios %g %g, want %g (errors %g %g %g)",
              what, r1, r2, want, e0, e1, e2);
}

static void test_sabac(void)
{
    osc o = { 1.0, 0, 0 };
    vigen_split_problem sp3 = problem(&o, 3), sp2 = problem(&o, 2);
    bx_sabac2_workspace *wc = bx_sabac2_alloc_split(&sp3, NULL);
    bx_saba2_workspace *ws = bx_saba2_alloc_split(&sp2, NULL);
    CHECK(wc != NULL && ws != NULL);
    CHECK(bx_sabac2_alloc_split(&sp2, NULL) == NULL);   /* three flows wanted */
    CHECK(BX_SABAC2_NFLOWS == 3 && BX_SABAC2_FLOW_KEPLER == 0 && BX_SABAC2_FLOW_INTERACTION == 1 &&
          BX_SABAC2_FLOW_INTERACTION_GRADIENT == 2);
    CHECK(BX_SABAC2_ORDER == 4 && bx_sabac2_type.order == 4 && BX_SABA2_ORDER == 2);
    check_ratio(&bx_sabac2_type, wc, &o, 8, 16, "SABAC_2");
    check_ratio(&bx_saba2_type, ws, &o, 8, 4, "SABA_2");
    /* the corrector: called twice a step with -(g_2/2) h^3 */
    bx_sabac2_reset(wc);
    o.grad_calls = 0;
    double t = 0, q = 1, p = 0;
    const double h = 0.5, g2 = (2 - sqrt(3)) / 24;
    CHECK(bx_sabac2_step(wc, &t, &q, &p, h) == VIGEN_SUCCESS);
    CHECK(o.grad_calls == 2 && bx_sabac2_flow_calls(wc, 2) == 2 && bx_sabac2_flow_calls(wc, 0) == 3);
    CHECK_MSG(fabs(o.last_tau / (-g2 / 2 * h * h * h) - 1) < 1e-15, "tau %.17g, want %.17g", o.last_tau,
              -g2 / 2 * h * h * h);
    bx_sabac2_free(wc);
    bx_saba2_free(ws);
}

/* the modified kick removes the eps^2 h^2 part of the map's error */
static void test_modified_kick(void)
{
    osc o = { 1.0, 0, 0 };
    vigen_split_problem sp3 = problem(&o, 3), sp2 = problem(&o, 2);
    bx_mk_workspace *wm = bx_mk_alloc_split(&sp3, NULL);
    bx_saba1_workspace *w1 = bx_saba1_alloc_split(&sp2, NULL);
    CHECK(wm != NULL && w1 != NULL);
    CHECK(BX_MK_ORDER == 2);
    check_ratio(&bx_mk_type, wm, &o, 8, 4, "modified kick");
    /* eps small: the map's error is eps h^2 e1 + eps^2 h^2 e2 over the time 1,
     * and the modified kick leaves eps h^2 e1 alone: the difference of the
     * errors is of order eps^2 h^2, far below eps h^2 */
    o.eps = 1e-2;
    const double em = error_at_1(&bx_mk_type, wm, &o, 4), e1 = error_at_1(&bx_saba1_type, w1, &o, 4);
    CHECK_MSG(em > 0 && fabs(em - e1) < 0.1 * e1 && fabs(em - e1) > 1e-4 * e1,
              "eps = 1e-2: modified kick %g, plain kick %g", em, e1);
    bx_mk_free(wm);
    bx_saba1_free(w1);
}

/* one bracket {A, B}: its sign convention decides the order */
static void test_one_bracket(void)
{
    osc o = { 1.0, 0, 0 };
    vigen_split_problem sp = { 1, 3, flows_ab, &o, NULL, NULL };
    bx_ab_workspace *w = bx_ab_alloc_split(&sp, NULL);
    CHECK(w != NULL);
    CHECK(BX_AB_ORDER == 2);
    check_ratio(&bx_ab_type, w, &o, 16, 4, "a, b, {a, b} h^2/2");
    bx_ab_free(w);
}

int main(void)
{
    test_sabac();
    test_modified_kick();
    test_one_bracket();
    return testlib_failures != 0;
}
