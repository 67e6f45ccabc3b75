/* test_emit_split.c — splitting steppers with exact flows (`vigen emit
 * --variant split`, NAME_alloc_split), emitted at build time
 * (tests/CMakeLists.txt) from Stormer-Verlet, drift-kick-drift (Strang), and
 * Yoshida's fourth-order triple jump, whose flows are "drift" (flow 0) and
 * "kick" (flow 1).  The truths are closed forms and an independent
 * integrator:
 *   - the harmonic oscillator H = p^2/2 + q^2/2 split into the drift
 *     q += h p and the kick p -= h q (both exact): the error against
 *     q0 cos t + p0 sin t falls by 4 (Strang) and 16 (Yoshida) per halving
 *     of h;
 *   - two oscillators split into their rotations (exact flows that
 *     commute): every step is the exact solution, to round-off, at any h;
 *   - the free rigid body, split into its three axis rotations (H1 and
 *     H2 + H3, the flow of the latter a step of the same method over the
 *     rotations about axes 2 and 3: a flow of the method's order), and body angular momentum m, H = sum m_i^2 / (2 I_i)
 *     = c1 m1^2 / 2 + c3 m3^2 / 2 + |m|^2 / (2 I2) with c1 = 1/I1 - 1/I2,
 *     c3 = 1/I3 - 1/I2: the Casimir |m|^2 has no flow, so H splits into
 *     rotations about body axes 1 and 3 (exact flows); against classical
 *     RK4 in long double with a step 10^-4 (a method of another kind), the
 *     error falls by 4 and 16 per halving; the Casimir is kept to round-off
 *     and the energy error stays within O(h^p);
 *   - a file with named flows is emitted as the split variant by default,
 *     its substeps merged (a zero coefficient dropped, two of one flow
 *     added): Strang's bits;
 *   - a flow that fails or leaves a NaN: its status (VIGEN_ENONFINITE for
 *     the NaN), t, q, p unchanged bit for bit, failed_steps counted;
 *   - flow calls per step: Strang 2 drifts and 1 kick (the drifts of a step
 *     are not merged with the next step's), Yoshida 4 kicks and 3 drifts;
 *   - a saved state continues bit for bit in a fresh workspace; a damaged
 *     or foreign state is refused (VIGEN_ESTATE) with the workspace kept;
 *   - vigen_integrate_ensemble with the workspace as prototype gives every
 *     trajectory the bits of a run alone (vigen_integrate);
 *   - output at any time through the problem's vector field converges
 *     (error / 4 per halving for Strang); without a vector field output at
 *     any time and events refuse with VIGEN_EINVAL;
 *   - alloc refuses a wrong number of flows, a NULL flow, dim 0;
 *   - the long double stepper agrees with the double one to double
 *     round-off on the oscillator;
 *   - the emitter: byte-identical output for identical input, the flows
 *     named in the header, a tableau that is no splitting and --batch
 *     refused with a message; the golden split stepper
 *     (tests/data/emit/golden/rotations_strang.*) unchanged. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "testlib.h"
#include "vigen/emit.h"
#include "vigen/method.h"
#include <vigen/ensemble.h>
#include "sx_strang.h"
#include "sx_yoshida.h"
#include "sx_strang_ld.h"
#include "sx_rot.h"

/* ---- the harmonic oscillator: dim 1 (or 2 for the two rotations) -------- */
typedef struct {
    long calls;        /* flow calls so far */
    long fail_at;      /* the call (1-based) that fails; 0 never */
    int fail_nan;      /* that call leaves a NaN instead of returning an error */
} ho_ctx;

/* a failure injected at one call: VIGEN_EUNSUPPORTED or a NaN in p, q and p
 * changed either way (the stepper must put them back) */
static int inject(ho_ctx *c, double *q, double *p)
{
    if (c == NULL) return 0;
    c->calls++;
    if (c->calls != c->fail_at) return 0;
    q[0] += 1;
    if (c->fail_nan) { p[0] = NAN; return 0; }
    return VIGEN_EUNSUPPORTED;
}

static int ho_drift(double t, double h, double *q, double *p, void *ctx)
{
    (void)t;
    q[0] += h * p[0];
    return inject(ctx, q, p);
}
static int ho_kick(double t, double h, double *q, double *p, void *ctx)
{
    (void)t;
    p[0] -= h * q[0];
    return inject(ctx, q, p);
}
static int ho_field(double t, const double *q, const double *p, double *dq, double *dp, void *ctx)
{
    (void)t; (void)ctx;
    dq[0] = p[0];
    dp[0] = -q[0];
    return VIGEN_SUCCESS;
}
static int ho_drift_ld(long double t, long double h, long double *q, long double *p, void *ctx)
{
    (void)t; (void)ctx;
    q[0] += h * p[0];
    return VIGEN_SUCCESS;
}
static int ho_kick_ld(long double t, long double h, long double *q, long double *p, void *ctx)
{
    (void)t; (void)ctx;
    p[0] -= h * q[0];
    return VIGEN_SUCCESS;
}

static const vigen_flow_fn ho_flows[2] = { ho_drift, ho_kick };

static vigen_split_problem ho_problem(ho_ctx *ctx)
{
    vigen_split_problem sp = { 1, 2, ho_flows, ctx, ho_field, NULL };
    return sp;
}

/* The error at T = 1 of n steps of a stepper type from (q, p) = (1, 0.5). */
static double ho_error(const vigen_stepper_type *T, void *w, int n)
{
    double t = 0, q = 1, p = 0.5;
    T->reset(w);
    CHECK(vigen_integrate(T, w, &t, &q, &p, 1.0 / n, (unsigned long)n, 0, NULL, NULL, NULL) == VIGEN_SUCCESS);
    const double qe = cos(1.0) + 0.5 * sin(1.0), pe = -sin(1.0) + 0.5 * cos(1.0);
    CHECK(fabs(t - 1) < 1e-14);
    return hypot(q - qe, p - pe);
}

/* Error ratios per halving of h, from n0 steps on. */
static void check_ratio(const vigen_stepper_type *T, void *w, int n0, double want, const char *what)
{
    double e0 = ho_error(T, w, n0), e1 = ho_error(T, w, 2 * n0), e2 = ho_error(T, w, 4 * n0);
    const double r1 = e0 / e1, r2 = e1 / e2;
    CHECK_MSG(fabs(r1 / want - 1) < 0.1 && fabs(r2 / want - 1) < 0.1, "%s: error ratios %g %g, want %g (errors %g %g %g)",
              what, r1, r2, want, e0, e1, e2);
}

static void test_oscillator_order(void)
{
    vigen_split_problem sp = ho_problem(NULL);
    sx_strang_workspace *ws = sx_strang_alloc_split(&sp, NULL);
    sx_yoshida_workspace *wy = sx_yoshida_alloc_split(&sp, NULL);
    CHECK(ws != NULL && wy != NULL);
    CHECK(SX_STRANG_NFLOWS == 2 && SX_STRANG_FLOW_DRIFT == 0 && SX_STRANG_FLOW_KICK == 1);
    CHECK(SX_STRANG_ORDER == 2 && SX_YOSHIDA_ORDER == 4 && sx_strang_type.order == 2 && sx_yoshida_type.order == 4);
    check_ratio(&sx_strang_type, ws, 10, 4, "Strang, oscillator");
    check_ratio(&sx_yoshida_type, wy, 10, 16, "Yoshida, oscillator");
    /* flow calls: per step Strang 2 drifts + 1 kick, Yoshida 3 drifts + 4 kicks */
    sx_strang_reset(ws);
    sx_yoshida_reset(wy);
    double t = 0, q = 1, p = 0;
    for (int k = 0; k < 10; k++) CHECK(sx_strang_step(ws, &t, &q, &p, 0.1) == VIGEN_SUCCESS);
    CHECK(sx_strang_flow_calls(ws, 0) == 20 && sx_strang_flow_calls(ws, 1) == 10);
    CHECK(sx_strang_stats(ws)->steps == 10 && sx_strang_stats(ws)->failed_steps == 0);
    t = 0; q = 1; p = 0;
    for (int k = 0; k < 10; k++) CHECK(sx_yoshida_step(wy, &t, &q, &p, 0.1) == VIGEN_SUCCESS);
    CHECK(sx_yoshida_flow_calls(wy, 0) == 30 && sx_yoshida_flow_calls(wy, 1) == 40);
    CHECK(sx_yoshida_flow_calls(wy, 2) == 0 && sx_yoshida_flow_calls(wy, -1) == 0);
    /* the long double stepper: the same method, double round-off apart */
    const vigen_flow_fn_ld fl[2] = { ho_drift_ld, ho_kick_ld };
    vigen_split_problem_ld spl = { 1, 2, fl, NULL, NULL, NULL };
    sx_strang_ld_workspace *wl = sx_strang_ld_alloc_split(&spl, NULL);
    CHECK(wl != NULL);
    long double tl = 0, ql = 1, pl = 0.5;
    for (int k = 0; k < 100; k++) CHECK(sx_strang_ld_step(wl, &tl, &ql, &pl, 0.01L) == VIGEN_SUCCESS);
    t = 0; q = 1; p = 0.5;
    sx_strang_reset(ws);
    for (int k = 0; k < 100; k++) CHECK(sx_strang_step(ws, &t, &q, &p, 0.01) == VIGEN_SUCCESS);
    CHECK(fabsl(ql - q) < 1e-13L && fabsl(pl - p) < 1e-13L && fabsl(tl - 1) < 1e-17L);
    sx_strang_ld_free(wl);
    sx_strang_free(ws);
    sx_yoshida_free(wy);
}

/* ---- two oscillators of frequencies 1 and 3, split into their rotations -- */
static void rotate(double w, double h, double *q, double *p)
{
    const double c = cos(w * h), s = sin(w * h), q0 = *q, p0 = *p;
    *q = c * q0 + s * p0;
    *p = -s * q0 + c * p0;
}
static int rot1(double t, double h, double *q, double *p, void *ctx)
{
    (void)t; (void)ctx;
    rotate(1, h, q, p);
    return VIGEN_SUCCESS;
}
static int rot2(double t, double h, double *q, double *p, void *ctx)
{
    (void)t; (void)ctx;
    rotate(3, h, q + 1, p + 1);
    return VIGEN_SUCCESS;
}

static void test_commuting_rotations(void)
{
    const vigen_flow_fn fl[2] = { rot1, rot2 };
    vigen_split_problem sp = { 2, 2, fl, NULL, NULL, NULL };
    sx_yoshida_workspace *w = sx_yoshida_alloc_split(&sp, NULL);
    double t = 0, q[2] = { 1, 0.3 }, p[2] = { -0.2, 0.7 };
    const double h = 0.7;
    for (int k = 0; k < 100; k++) CHECK(sx_yoshida_step(w, &t, q, p, h) == VIGEN_SUCCESS);
    const double T = t;
    const double qe0 = cos(T) + -0.2 * sin(T), pe0 = -sin(T) - 0.2 * cos(T);
    const double qe1 = 0.3 * cos(3 * T) + 0.7 * sin(3 * T), pe1 = -0.3 * sin(3 * T) + 0.7 * cos(3 * T);
    CHECK_MSG(fabs(q[0] - qe0) + fabs(p[0] - pe0) + fabs(q[1] - qe1) + fabs(p[1] - pe1) < 1e-11,
              "commuting rotations: %g %g %g %g", q[0] - qe0, p[0] - pe0, q[1] - qe1, p[1] - pe1);
    sx_yoshida_free(w);
}

/* ---- the free rigid body ------------------------------------------------- */
static const double I1 = 1, I2 = 2, I3 = 3;

/* rotation of m about body axis i by the angle c m_i h (the flow of c m_i^2 / 2) */
static void axis_flow(int i, double c, double h, double *m)
{
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const double th = c * m[i] * h, co = cos(th), si = sin(th), mj = m[j], mk = m[k];
    m[j] = co * mj + si * mk;
    m[k] = -si * mj + co * mk;
}
/* the state m is q (p is carried along untouched) */
static int rb_axis1(double t, double h, double *q, double *p, void *ctx)
{
    (void)t; (void)p; (void)ctx;
    axis_flow(0, 1 / I1 - 1 / I2, h, q);
    return VIGEN_SUCCESS;
}
static int rb_axis3(double t, double h, double *q, double *p, void *ctx)
{
    (void)t; (void)p; (void)ctx;
    axis_flow(2, 1 / I3 - 1 / I2, h, q);
    return VIGEN_SUCCESS;
}

/* Euler's equations m' = m x omega, omega_i = m_i / I_i */
static void euler_rhs(const long double *m, long double *dm)
{
    const long double w1 = m[0] / I1, w2 = m[1] / I2, w3 = m[2] / I3;
    dm[0] = m[1] * w3 - m[2] * w2;
    dm[1] = m[2] * w1 - m[0] * w3;
    dm[2] = m[0] * w2 - m[1] * w1;
}

/* classical RK4 in long double, step 1e-4 (global error ~1e-16) */
static void rb_reference(const double *m0, double T, double *m)
{
    long double y[3] = { m0[0], m0[1], m0[2] }, k1[3], k2[3], k3[3], k4[3], z[3];
    const long n = lround(T / 1e-4);
    const long double h = (long double)T / n;
    for (long s = 0; s < n; s++) {
        euler_rhs(y, k1);
        for (int i = 0; i < 3; i++) z[i] = y[i] + h / 2 * k1[i];
        euler_rhs(z, k2);
        for (int i = 0; i < 3; i++) z[i] = y[i] + h / 2 * k2[i];
        euler_rhs(z, k3);
        for (int i = 0; i < 3; i++) z[i] = y[i] + h * k3[i];
        euler_rhs(z, k4);
        for (int i = 0; i < 3; i++) y[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
    }
    for (int i = 0; i < 3; i++) m[i] = (double)y[i];
}

static double rb_energy(const double *m) { return m[0] * m[0] / (2 * I1) + m[1] * m[1] / (2 * I2) + m[2] * m[2] / (2 * I3); }

static double rb_error(const vigen_stepper_type *T, void *w, int n, const double *ref, double *casimir, double *energy)
{
    const double m0[3] = { 0.4, 0.8, 0.6 };
    double t = 0, m[3] = { m0[0], m0[1], m0[2] }, p[3] = { 0, 0, 0 };
    T->reset(w);
    *casimir = *energy = 0;
    const double C0 = m0[0] * m0[0] + m0[1] * m0[1] + m0[2] * m0[2], E0 = rb_energy(m0);
    for (int k = 0; k < n; k++) {
        CHECK(T->step(w, &t, m, p, 2.0 / n) == VIGEN_SUCCESS);
        *casimir = fmax(*casimir, fabs(m[0] * m[0] + m[1] * m[1] + m[2] * m[2] - C0));
        *energy = fmax(*energy, fabs(rb_energy(m) - E0));
    }
    return sqrt((m[0] - ref[0]) * (m[0] - ref[0]) + (m[1] - ref[1]) * (m[1] - ref[1]) + (m[2] - ref[2]) * (m[2] - ref[2]));
}

/* Error ratios per halving on the rigid body from n0 steps over [0, 2], the
 * Casimir at every step and the energy error against the state error. */
static void rb_check_orders(const char *what, const vigen_stepper_type *T, void *w, double want, int n0,
                            const double *ref)
{
    double e[3], cas[3], en[3];
    for (int k = 0; k < 3; k++) e[k] = rb_error(T, w, n0 << k, ref, cas + k, en + k);
    const double r1 = e[0] / e[1], r2 = e[1] / e[2];
    CHECK_MSG(fabs(r1 / want - 1) < 0.15 && fabs(r2 / want - 1) < 0.15, "%s %s: ratios %g %g (errors %g %g %g)", what,
              T->name, r1, r2, e[0], e[1], e[2]);
    for (int k = 0; k < 3; k++) {
        CHECK_MSG(cas[k] < 1e-14, "%s %s: Casimir moved by %g", what, T->name, cas[k]);
        /* the energy error is of the order of the method, bounded by the error's size */
        CHECK_MSG(en[k] < 10 * e[k] + 1e-14, "%s %s: energy error %g, state error %g", what, T->name, en[k], e[k]);
    }
    T->free(w);
}

static void test_rigid_body(void)
{
    const vigen_flow_fn fl[2] = { rb_axis1, rb_axis3 };
    vigen_split_problem sp = { 3, 2, fl, NULL, NULL, NULL };
    const double m0[3] = { 0.4, 0.8, 0.6 };
    double ref[3];
    rb_reference(m0, 2.0, ref);
    struct { const vigen_stepper_type *T; void *w; double want; int n0; } cases[2] = {
        { &sx_strang_type, sx_strang_alloc_split(&sp, NULL), 4, 20 },
        { &sx_yoshida_type, sx_yoshida_alloc_split(&sp, NULL), 16, 10 },
    };
    for (int c = 0; c < 2; c++) rb_check_orders("rigid body", cases[c].T, cases[c].w, cases[c].want, cases[c].n0, ref);
}

/* The three axis rotations, H = H1 + (H2 + H3), H_i = m_i^2 / (2 I_i): flow 0
 * the rotation about axis 1, flow 1 that of H2 + H3 by one step of an
 * emitted stepper of the same method over the rotations about axes 2 and 3
 * (a flow of the method's order: the order holds). */
typedef struct { const vigen_stepper_type *T; void *inner; } nested_ctx;
static int rb_full1(double t, double h, double *q, double *p, void *ctx)
{
    (void)t; (void)p; (void)ctx;
    axis_flow(0, 1 / I1, h, q);
    return VIGEN_SUCCESS;
}
static int rb_full2(double t, double h, double *q, double *p, void *ctx)
{
    (void)t; (void)p; (void)ctx;
    axis_flow(1, 1 / I2, h, q);
    return VIGEN_SUCCESS;
}
static int rb_full3(double t, double h, double *q, double *p, void *ctx)
{
    (void)t; (void)p; (void)ctx;
    axis_flow(2, 1 / I3, h, q);
    return VIGEN_SUCCESS;
}
static int rb_nested(double t, double h, double *q, double *p, void *ctx)
{
    const nested_ctx *c = ctx;
    return c->T->step(c->inner, &t, q, p, h);
}

static void test_rigid_body_three_axes(void)
{
    const vigen_flow_fn inner_fl[2] = { rb_full2, rb_full3 }, outer_fl[2] = { rb_full1, rb_nested };
    vigen_split_problem inner = { 3, 2, inner_fl, NULL, NULL, NULL };
    const double m0[3] = { 0.4, 0.8, 0.6 };
    double ref[3];
    rb_reference(m0, 2.0, ref);
    nested_ctx cs = { &sx_strang_type, sx_strang_alloc_split(&inner, NULL) };
    nested_ctx cy = { &sx_yoshida_type, sx_yoshida_alloc_split(&inner, NULL) };
    vigen_split_problem outer_s = { 3, 2, outer_fl, &cs, NULL, NULL }, outer_y = { 3, 2, outer_fl, &cy, NULL, NULL };
    struct { const vigen_stepper_type *T; void *w; double want; int n0; } cases[2] = {
        { &sx_strang_type, sx_strang_alloc_split(&outer_s, NULL), 4, 20 },
        { &sx_yoshida_type, sx_yoshida_alloc_split(&outer_y, NULL), 16, 10 },
    };
    for (int c = 0; c < 2; c++) rb_check_orders("rigid body, three axes", cases[c].T, cases[c].w, cases[c].want, cases[c].n0, ref);
    cs.T->free(cs.inner);
    cy.T->free(cy.inner);
}

/* A file with named flows ("axis1", "axis3") is emitted as the split variant
 * without --variant; its Strang step (written with a zero and a repeated
 * substep, merged by the emitter) has order 2 on the rigid body. */
static void test_named_flows(void)
{
    CHECK(SX_ROT_NFLOWS == 2 && SX_ROT_FLOW_AXIS1 == 0 && SX_ROT_FLOW_AXIS3 == 1 && SX_ROT_SUBSTEPS == 3);
    CHECK(SX_ROT_ORDER == 2);
    const vigen_flow_fn fl[2] = { rb_axis1, rb_axis3 };
    vigen_split_problem sp = { 3, 2, fl, NULL, NULL, NULL };
    sx_rot_workspace *w = sx_rot_alloc_split(&sp, NULL);
    sx_strang_workspace *v = sx_strang_alloc_split(&sp, NULL);
    double t = 0, m[3] = { 0.4, 0.8, 0.6 }, p[3] = { 0 }, tv = 0, mv[3] = { 0.4, 0.8, 0.6 }, pv[3] = { 0 };
    for (int k = 0; k < 50; k++) {
        CHECK(sx_rot_step(w, &t, m, p, 0.04) == VIGEN_SUCCESS);
        CHECK(sx_strang_step(v, &tv, mv, pv, 0.04) == VIGEN_SUCCESS);
    }
    /* the same method as Stormer-Verlet's drift-kick-drift: the same bits */
    CHECK(memcmp(m, mv, sizeof m) == 0 && t == tv);
    CHECK(sx_rot_flow_calls(w, 0) == 100 && sx_rot_flow_calls(w, 1) == 50);
    sx_rot_free(w);
    sx_strang_free(v);
}

/* ---- failures: the flow's status, the state unchanged --------------------- */
static void test_failures(void)
{
    for (int nan = 0; nan < 2; nan++) {
        ho_ctx c = { 0, 0, nan };
        vigen_split_problem sp = ho_problem(&c);
        sx_yoshida_workspace *w = sx_yoshida_alloc_split(&sp, NULL);
        double t = 0, q = 1, p = 0.5;
        for (int k = 0; k < 3; k++) CHECK(sx_yoshida_step(w, &t, &q, &p, 0.1) == VIGEN_SUCCESS);
        c.fail_at = c.calls + 5;   /* midway through the next step */
        const double t0 = t, q0 = q, p0 = p;
        const int rc = sx_yoshida_step(w, &t, &q, &p, 0.1);
        CHECK_MSG(rc == (nan ? VIGEN_ENONFINITE : VIGEN_EUNSUPPORTED), "status %d", rc);
        CHECK(memcmp(&t, &t0, sizeof t) == 0 && memcmp(&q, &q0, sizeof q) == 0 && memcmp(&p, &p0, sizeof p) == 0);
        CHECK(sx_yoshida_stats(w)->failed_steps == 1 && sx_yoshida_stats(w)->steps == 3);
        /* the next step goes on from the unchanged state */
        CHECK(sx_yoshida_step(w, &t, &q, &p, 0.1) == VIGEN_SUCCESS);
        CHECK(isfinite(q) && isfinite(p));
        double bad = NAN;
        CHECK(sx_yoshida_step(w, &t, &q, &p, bad) == VIGEN_EINVAL);
        CHECK(sx_yoshida_step(w, &t, &q, &p, INFINITY) == VIGEN_EINVAL);
        sx_yoshida_free(w);
    }
}

/* ---- restart, ensembles -------------------------------------------------- */
static void test_restart(void)
{
    vigen_split_problem sp = ho_problem(NULL);
    sx_yoshida_workspace *a = sx_yoshida_alloc_split(&sp, NULL);
    double t = 0.125, q = 1, p = 0.5;
    const double h = 0.0123456789;
    for (int k = 0; k < 37; k++) CHECK(sx_yoshida_step(a, &t, &q, &p, h) == VIGEN_SUCCESS);
    const size_t size = sx_yoshida_state_size(a);
    unsigned char *buf = malloc(size);
    CHECK(sx_yoshida_state_get(a, buf) == VIGEN_SUCCESS);
    double ts = t, qs = q, ps = p;
    for (int k = 0; k < 500; k++) CHECK(sx_yoshida_step(a, &t, &q, &p, h) == VIGEN_SUCCESS);
    sx_yoshida_workspace *b = sx_yoshida_alloc_split(&sp, NULL);
    CHECK(sx_yoshida_state_set(b, buf) == VIGEN_SUCCESS);
    for (int k = 0; k < 500; k++) CHECK(sx_yoshida_step(b, &ts, &qs, &ps, h) == VIGEN_SUCCESS);
    CHECK(memcmp(&t, &ts, sizeof t) == 0 && memcmp(&q, &qs, sizeof q) == 0 && memcmp(&p, &ps, sizeof p) == 0);
    CHECK(sx_yoshida_flow_calls(a, 0) == sx_yoshida_flow_calls(b, 0) && sx_yoshida_stats(b)->steps == 537);
    /* the compensated time: 537 steps of h from 0.125 against the sum in long double */
    CHECK(fabsl(t - (0.125L + 537 * (long double)h)) <= 1e-15L);
    /* a damaged buffer, another stepper's state: refused, b unchanged */
    buf[size / 2] ^= 1;
    CHECK(sx_yoshida_state_set(b, buf) == VIGEN_ESTATE);
    CHECK(sx_yoshida_stats(b)->steps == 537);
    sx_strang_workspace *s = sx_strang_alloc_split(&sp, NULL);
    unsigned char *other = malloc(sx_strang_state_size(s));
    CHECK(sx_strang_state_get(s, other) == VIGEN_SUCCESS);
    CHECK(sx_yoshida_state_size(b) != sx_strang_state_size(s) || sx_yoshida_state_set(b, other) == VIGEN_ESTATE);
    CHECK(sx_yoshida_state_set(b, NULL) == VIGEN_EINVAL);
    free(other);
    free(buf);
    sx_strang_free(s);
    sx_yoshida_free(a);
    sx_yoshida_free(b);
}

static void test_ensemble(void)
{
    enum { N = 9 };
    vigen_split_problem sp = ho_problem(NULL);
    sx_yoshida_workspace *proto = sx_yoshida_alloc_split(&sp, NULL);
    double t[N], q[N], p[N];
    for (int i = 0; i < N; i++) {
        t[i] = 0.1 * i;
        q[i] = cos(i);
        p[i] = sin(2 * i);
    }
    double t1[N], q1[N], p1[N];
    memcpy(t1, t, sizeof t);
    memcpy(q1, q, sizeof q);
    memcpy(p1, p, sizeof p);
    vigen_ensemble e;
    memset(&e, 0, sizeof e);
    e.type = &sx_yoshida_type;
    e.prototype = proto;
    e.threads = 2;
    int status[N];
    CHECK(vigen_integrate_ensemble(&e, N, t, q, p, 0.05, 300, status, NULL) == VIGEN_SUCCESS);
    for (int i = 0; i < N; i++) {
        sx_yoshida_workspace *w = sx_yoshida_alloc_split(&sp, NULL);
        CHECK(vigen_integrate(&sx_yoshida_type, w, t1 + i, q1 + i, p1 + i, 0.05, 300, 0, NULL, NULL, NULL) ==
              VIGEN_SUCCESS);
        CHECK(status[i] == VIGEN_SUCCESS);
        CHECK(memcmp(t + i, t1 + i, sizeof(double)) == 0 && memcmp(q + i, q1 + i, sizeof(double)) == 0 &&
              memcmp(p + i, p1 + i, sizeof(double)) == 0);
        sx_yoshida_free(w);
    }
    sx_yoshida_free(proto);
}

/* ---- output at any time, events, alloc ----------------------------------- */
static double dense_error(int n)
{
    vigen_split_problem sp = ho_problem(NULL);
    sx_strang_workspace *w = sx_strang_alloc_split(&sp, NULL);
    const double tout[3] = { 0.3337, 1.01, 1.777 };
    double qo[3], po[3], t = 0, q = 1, p = 0.5;
    CHECK(vigen_integrate_at(&sx_strang_type, w, &t, &q, &p, 2.0 / n, tout, 3, qo, po, NULL) == VIGEN_SUCCESS);
    double e = 0;
    for (int k = 0; k < 3; k++)
        e = fmax(e, hypot(qo[k] - (cos(tout[k]) + 0.5 * sin(tout[k])), po[k] - (-sin(tout[k]) + 0.5 * cos(tout[k]))));
    sx_strang_free(w);
    return e;
}

static double ev_q(double t, const double *q, const double *p, void *ctx)
{
    (void)t; (void)p; (void)ctx;
    return q[0];
}

static void test_dense_events_alloc(void)
{
    const double e0 = dense_error(40), e1 = dense_error(80), e2 = dense_error(160);
    CHECK_MSG(e0 / e1 > 3.4 && e0 / e1 < 4.6 && e1 / e2 > 3.4 && e1 / e2 < 4.6, "output at any time: %g %g %g", e0, e1,
              e2);
    /* no vector field: output at any time and events refuse */
    vigen_split_problem sp = ho_problem(NULL);
    sp.vector_field = NULL;
    sx_strang_workspace *w = sx_strang_alloc_split(&sp, NULL);
    double t = 0, q = 1, p = 0.5, tout = 0.55, qo, po, tev[4];
    size_t nev = 0;
    int rc = vigen_integrate_at(&sx_strang_type, w, &t, &q, &p, 0.1, &tout, 1, &qo, &po, NULL);
    CHECK_MSG(rc == VIGEN_EINVAL, "%d", rc);
    CHECK(vigen_integrate_events(&sx_strang_type, w, &t, &q, &p, 0.1, 50, ev_q, 0, 0, NULL, tev, 4, &nev) ==
          VIGEN_EINVAL);
    sx_strang_free(w);
    /* with it, the events of q = 0: q = cos t + sin t / 2 vanishes at t = pi - atan(2) (mod pi), once in [0, 5] */
    sp.vector_field = ho_field;
    w = sx_strang_alloc_split(&sp, NULL);
    t = 0; q = 1; p = 0.5;
    CHECK(vigen_integrate_events(&sx_strang_type, w, &t, &q, &p, 0.01, 500, ev_q, 0, 0, NULL, tev, 4, &nev) ==
          VIGEN_SUCCESS);
    CHECK_MSG(nev == 1 && fabs(tev[0] - (3.14159265358979324 - atan(2))) < 1e-4, "%zu %g", nev, tev[0]);
    sx_strang_free(w);
    /* refusals */
    sp.nflows = 3;
    CHECK(sx_strang_alloc_split(&sp, NULL) == NULL);
    sp.nflows = 2;
    sp.dim = 0;
    CHECK(sx_strang_alloc_split(&sp, NULL) == NULL);
    sp.dim = 1;
    const vigen_flow_fn half[2] = { ho_drift, NULL };
    sp.flow = half;
    CHECK(sx_strang_alloc_split(&sp, NULL) == NULL);
    CHECK(sx_strang_alloc_split(NULL, NULL) == NULL);
    CHECK(sx_strang_type.alloc == NULL && sx_strang_type.clone != NULL);
}

/* ---- the emitter --------------------------------------------------------- */
static int render(const char *file, const char *variant, int batch, char **h, char **c, vigen_error *err)
{
    vigen_emit_options opt;
    memset(&opt, 0, sizeof opt);
    opt.name = "sx";
    opt.real = VIGEN_REAL_DOUBLE;
    opt.variant = variant;
    opt.batch = batch;
    opt.template_dir = VIGEN_SOURCE_DIR "/templates";
    opt.input_label = "x.lua";
    vigen_tableau t;
    int loaded = 0;
    char *ident = NULL;
    int rc = vigen_emit_load_render(&t, &loaded, file, &opt, h, c, &ident, err);
    if (loaded) vigen_tableau_clear(&t);
    free(ident);
    return rc;
}

static char *slurp(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (f == NULL) return NULL;
    fseek(f, 0, SEEK_END);
    const long n = ftell(f);
    fseek(f, 0, SEEK_SET);
    char *s = calloc((size_t)n + 1, 1);
    if (s && fread(s, 1, (size_t)n, f) != (size_t)n) s[0] = '\0';
    fclose(f);
    return s;
}

/* The golden split stepper (reviewed by hand; regenerate with
 *   vigen emit tests/data/emit/split/rotations_strang.lua --name rotations_strang -o tests/data/emit/golden
 * after a change of templates/split/) is what the emitter writes now. */
static void test_golden(void)
{
    vigen_error err;
    vigen_error_init(&err);
    vigen_emit_options opt;
    memset(&opt, 0, sizeof opt);
    opt.name = "rotations_strang";
    opt.real = VIGEN_REAL_DOUBLE;
    opt.template_dir = VIGEN_SOURCE_DIR "/templates";
    opt.input_label = "rotations_strang.lua";
    vigen_tableau t;
    int loaded = 0;
    char *h = NULL, *c = NULL, *ident = NULL;
    CHECK(vigen_emit_load_render(&t, &loaded, VIGEN_SOURCE_DIR "/tests/data/emit/split/rotations_strang.lua", &opt, &h,
                                 &c, &ident, &err) == VIGEN_OK);
    if (loaded) vigen_tableau_clear(&t);
    char *gh = slurp(VIGEN_SOURCE_DIR "/tests/data/emit/golden/rotations_strang.h");
    char *gc = slurp(VIGEN_SOURCE_DIR "/tests/data/emit/golden/rotations_strang.c");
    CHECK_MSG(h && gh && strcmp(h, gh) == 0, "golden rotations_strang.h differs from a fresh emission");
    CHECK_MSG(c && gc && strcmp(c, gc) == 0, "golden rotations_strang.c differs from a fresh emission");
    free(h); free(c); free(ident); free(gh); free(gc);
    vigen_error_clear(&err);
}

static void test_emitter(void)
{
    vigen_error err;
    vigen_error_init(&err);
    char *h1, *c1, *h2, *c2;
    const char *yo = VIGEN_SOURCE_DIR "/tableaux/published/yoshida_4.lua";
    CHECK(render(yo, "split", 0, &h1, &c1, &err) == VIGEN_OK);
    CHECK(render(yo, "split", 0, &h2, &c2, &err) == VIGEN_OK);
    CHECK(h1 && h2 && strcmp(h1, h2) == 0 && strcmp(c1, c2) == 0);
    CHECK(h1 && strstr(h1, "flow 0: \"drift\" (SX_FLOW_DRIFT), carries the time") != NULL);
    CHECK(c1 && strstr(c1, "--variant split") != NULL);
    free(h1); free(c1); free(h2); free(c2);
    h1 = c1 = NULL;
    CHECK(render(VIGEN_SOURCE_DIR "/tableaux/published/gauss_2.lua", "split", 0, &h1, &c1, &err) == VIGEN_E_USAGE);
    CHECK(err.message && strstr(err.message, "needs a splitting") != NULL);
    CHECK(h1 == NULL && c1 == NULL);
    vigen_error_clear(&err);
    vigen_error_init(&err);
    CHECK(render(yo, "split", 1, &h1, &c1, &err) == VIGEN_E_USAGE);
    vigen_error_clear(&err);
}

int main(void)
{
    test_oscillator_order();
    test_commuting_rotations();
    test_rigid_body();
    test_rigid_body_three_axes();
    test_named_flows();
    test_failures();
    test_restart();
    test_ensemble();
    test_dense_events_alloc();
    test_emitter();
    test_golden();
    TEST_MAIN_END();
}
