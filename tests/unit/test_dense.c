/* test_dense.c — output at any time (vigen_integrate_at and its _sys, _ld
 * and _q variants) with the golden Gauss-2 and Stormer-Verlet steppers of
 * tests/data/emit/golden and the long double and __float128 triple jump of
 * test_dense_kepler.h.  Asserted against independent truths:
 *   - Kepler (e = 0.5, 0.9) at output times between grid points agrees with
 *     the solution of Kepler's equation, and the error falls by 2^4 under
 *     step halving for the 4th-order Gauss-2 and triple jump (the cubic
 *     Hermite extension is O(h^4)) and by 2^2 for Verlet (the method's
 *     O(h^2) dominates);
 *   - the extension alone: one step from an exact state, evaluated mid-step,
 *     has the interpolation error of a cubic, falling by 2^4 per halving;
 *   - steps and final state equal vigen_integrate's bit for bit whatever
 *     the output times, and output times on the grid give the grid states
 *     bit for bit;
 *   - slopes are evaluated only for steps that hold an output time: one
 *     dH/dq and one dH/dp per step end (2 per isolated step, n + 1 for n
 *     consecutive steps, none for grid times);
 *   - a mechanical workspace (Nystrom form) gives the general one's outputs;
 *   - backward steps (h < 0) and refused arguments (nothing stepped). */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <vigen/runtime.h>
#include "testlib.h"
#include "test_dense_kepler.h"
#include "../data/emit/golden/gauss2.c"
#include "../data/emit/golden/verlet.c"

#define NOUT 40

/* Largest deviation of the outputs from the exact solution. */
static double kepler_error(double e, const double *t_out, size_t n, const double *q_out, const double *p_out)
{
    double worst = 0;
    for (size_t k = 0; k < n; k++) {
        double q[2], p[2];
        kepler_exact(e, t_out[k], q, p);
        for (int i = 0; i < 2; i++) {
            worst = fmax(worst, fabs(q_out[2 * k + i] - q[i]));
            worst = fmax(worst, fabs(p_out[2 * k + i] - p[i]));
        }
    }
    return worst;
}

/* The largest deviation from the exact solution at the grid points. */
typedef struct { double e, worst; } grid_error;
static int grid_error_obs(unsigned long step, double t, const double *q, const double *p, void *ctx)
{
    grid_error *g = ctx;
    double qe[2], pe[2];
    (void)step;
    kepler_exact(g->e, t, qe, pe);
    for (int i = 0; i < 2; i++) g->worst = fmax(g->worst, fmax(fabs(q[i] - qe[i]), fabs(p[i] - pe[i])));
    return 0;
}

/* Error at NOUT times spread over `periods` periods, off the grid of
 * h = 2 pi / steps_per_period; *on_grid receives the method's own error at
 * the grid points of the same steps (vigen_integrate). */
static double run_kepler(const vigen_stepper_type *T, double e, unsigned long steps_per_period, double periods,
                         double *on_grid)
{
    vigen_hamiltonian sys = kepler_problem();
    void *w = T->alloc(&sys, NULL);
    double t = 0, q[2], p[2], t_out[NOUT], q_out[2 * NOUT], p_out[2 * NOUT];
    const double h = 2 * M_PI / (double)steps_per_period, span = 2 * M_PI * periods;
    kepler_start(e, q, p);
    for (int k = 0; k < NOUT; k++) t_out[k] = span * (k + 0.6180339887) / NOUT;
    unsigned long done = 0;
    int status = vigen_integrate_at(T, w, &t, q, p, h, t_out, NOUT, q_out, p_out, &done);
    CHECK_MSG(status == VIGEN_SUCCESS, "%s: status %d", T->name, status);
    CHECK_MSG(t >= t_out[NOUT - 1] && t - h < t_out[NOUT - 1], "%s: stopped at %g, last output %g", T->name, t,
              t_out[NOUT - 1]);
    T->free(w);
    grid_error g = { e, 0 };
    t = 0;
    kepler_start(e, q, p);
    w = T->alloc(&sys, NULL);
    CHECK(vigen_integrate(T, w, &t, q, p, h, done, 1, grid_error_obs, &g, NULL) == VIGEN_SUCCESS);
    T->free(w);
    *on_grid = g.worst;
    return kepler_error(e, t_out, NOUT, q_out, p_out);
}

/* The error between grid points falls like h^order (ratio lo .. hi per
 * halving) and stays within `factor` of the method's own error at the grid. */
static void test_kepler_order(const vigen_stepper_type *T, double e, unsigned long n0, double lo, double hi,
                              double factor)
{
    double g1, g2, g3;
    const double e1 = run_kepler(T, e, n0, 2, &g1), e2 = run_kepler(T, e, 2 * n0, 2, &g2),
                 e3 = run_kepler(T, e, 4 * n0, 2, &g3);
    fprintf(stderr, "  %s e = %.1f: errors %.3e %.3e %.3e (grid %.3e %.3e %.3e), ratios %.2f %.2f\n", T->name, e,
            e1, e2, e3, g1, g2, g3, e1 / e2, e2 / e3);
    CHECK_MSG(e2 / e3 > lo && e2 / e3 < hi, "%s e = %g: error ratio %.2f under halving, expected %g .. %g", T->name, e,
              e2 / e3, lo, hi);
    CHECK_MSG(e1 < factor * g1 && e2 < factor * g2 && e3 < factor * g3,
              "%s e = %g: between grid points %.3e %.3e %.3e, at the grid %.3e %.3e %.3e", T->name, e, e1, e2, e3, g1,
              g2, g3);
}

/* One step from the exact state at t0, the extension at mid-step. */
static double midstep_error(double e, double t0, double h)
{
    vigen_hamiltonian sys = kepler_problem();
    void *w = gauss2_type.alloc(&sys, NULL);
    double t = t0, q[2], p[2], qo[2], po[2], qe[2], pe[2], tm = t0 + h / 2;
    kepler_exact(e, t0, q, p);
    CHECK(vigen_integrate_at(&gauss2_type, w, &t, q, p, h, &tm, 1, qo, po, NULL) == VIGEN_SUCCESS);
    kepler_exact(e, tm, qe, pe);
    gauss2_type.free(w);
    return fmax(fmax(fabs(qo[0] - qe[0]), fabs(qo[1] - qe[1])), fmax(fabs(po[0] - pe[0]), fabs(po[1] - pe[1])));
}

static void test_extension_order(void)
{
    double err[4];
    for (int k = 0; k < 4; k++) err[k] = midstep_error(0.5, 0.7, 0.1 / (1 << k));
    fprintf(stderr, "  mid-step errors %.3e %.3e %.3e %.3e\n", err[0], err[1], err[2], err[3]);
    for (int k = 1; k < 4; k++)
        CHECK_MSG(err[k - 1] / err[k] > 13 && err[k - 1] / err[k] < 19, "mid-step error ratio %.2f, expected ~16",
                  err[k - 1] / err[k]);
}

static int grid_obs(unsigned long step, double t, const double *q, const double *p, void *ctx)
{
    double *rec = (double *)ctx + 5 * step;
    rec[0] = t;
    memcpy(rec + 1, q, 2 * sizeof *q);
    memcpy(rec + 3, p, 2 * sizeof *p);
    return 0;
}

static unsigned long evals(const vigen_stepper_type *T, const void *w)
{
    const vigen_stats *s = T->stats(w);
    return s->dHdq_evals + s->dHdp_evals + s->iterations;
}

/* The steps of vigen_integrate_at are those of vigen_integrate, and it
 * evaluates slopes for the steps that hold output times only. */
static void test_same_steps(const vigen_stepper_type *T)
{
    enum { N = 300 };
    static double grid[5 * (N + 1)];
    const double h = 2 * M_PI / 200, e = 0.6;
    vigen_hamiltonian sys = kepler_problem();
    double t_ref = 0, q_ref[2], p_ref[2];
    kepler_start(e, q_ref, p_ref);
    void *w = T->alloc(&sys, NULL);
    CHECK(vigen_integrate(T, w, &t_ref, q_ref, p_ref, h, N, 1, grid_obs, grid, NULL) == VIGEN_SUCCESS);
    const unsigned long ref_evals = evals(T, w);
    T->free(w);

    /* three kinds of output times, all ending in step N */
    double sparse[3] = { 10.5 * h, 100.25 * h, (N - 0.5) * h };
    double consecutive[11], on_grid[6];
    for (int k = 0; k < 10; k++) consecutive[k] = (250.3 + k) * h;
    consecutive[10] = (N - 0.2) * h;
    for (int k = 0; k < 6; k++) on_grid[k] = grid[5 * (k * 60)];
    struct { const double *t; size_t n; unsigned long slopes; } cases[] = {
        { sparse, 3, 6 },             /* three isolated steps: both ends each */
        { consecutive, 11, 11 + 2 },  /* steps 251 .. 260 share ends (11), step 300 alone (2) */
        { on_grid, 6, 0 },            /* the start and grid times: the states themselves */
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        double t = 0, q[2], p[2], q_out[22], p_out[22];
        vigen_dense_stats st;
        unsigned long done = 0;
        kepler_start(e, q, p);
        w = T->alloc(&sys, NULL);
        CHECK(vigen_integrate_at_sys(T, w, NULL, &t, q, p, h, cases[c].t, cases[c].n, q_out, p_out, &done, &st) ==
              VIGEN_SUCCESS);
        CHECK_MSG(done == N && st.steps == N, "%s case %zu: %lu steps, expected %d", T->name, c, done, N);
        CHECK_MSG(memcmp(&t, &t_ref, sizeof t) == 0 && memcmp(q, q_ref, sizeof q) == 0 &&
                      memcmp(p, p_ref, sizeof p) == 0, "%s case %zu: final state differs from vigen_integrate's",
                  T->name, c);
        CHECK_MSG(evals(T, w) == ref_evals, "%s case %zu: the stepper's work changed", T->name, c);
        CHECK_MSG(st.dHdq_evals == cases[c].slopes && st.dHdp_evals == cases[c].slopes,
                  "%s case %zu: %lu + %lu slope evaluations, expected %lu each", T->name, c, st.dHdq_evals,
                  st.dHdp_evals, cases[c].slopes);
        if (c == 2)
            for (int k = 0; k < 6; k++)
                CHECK_MSG(memcmp(q_out + 2 * k, grid + 5 * (k * 60) + 1, 2 * sizeof(double)) == 0 &&
                              memcmp(p_out + 2 * k, grid + 5 * (k * 60) + 3, 2 * sizeof(double)) == 0,
                          "%s: output at grid time %d is not the grid state", T->name, k * 60);
        T->free(w);
    }
}

static void kepler_force(double t, const double *q, double *f, void *ctx)
{
    kepler_dHdq(t, q, NULL, f, ctx);
    f[0] = -f[0];
    f[1] = -f[1];
}

/* A workspace of NAME_alloc_mechanical: the problem comes from its force. */
static void test_mechanical(void)
{
    vigen_hamiltonian sys = kepler_problem();
    vigen_mechanical mech = { 2, kepler_force, NULL, NULL, NULL };
    double qa[2], pa[2], qb[2], pb[2], t_out[NOUT], q_a[2 * NOUT], p_a[2 * NOUT], q_b[2 * NOUT], p_b[2 * NOUT];
    double ta = 0, tb = 0, h = 2 * M_PI / 400;
    for (int k = 0; k < NOUT; k++) t_out[k] = 4 * M_PI * (k + 0.3) / NOUT;
    kepler_start(0.5, qa, pa);
    kepler_start(0.5, qb, pb);
    void *wa = gauss2_type.alloc(&sys, NULL), *wb = gauss2_alloc_mechanical(&mech, NULL);
    CHECK(vigen_integrate_at(&gauss2_type, wa, &ta, qa, pa, h, t_out, NOUT, q_a, p_a, NULL) == VIGEN_SUCCESS);
    CHECK(vigen_integrate_at(&gauss2_type, wb, &tb, qb, pb, h, t_out, NOUT, q_b, p_b, NULL) == VIGEN_SUCCESS);
    double d = 0;
    for (int k = 0; k < 2 * NOUT; k++) d = fmax(d, fmax(fabs(q_a[k] - q_b[k]), fabs(p_a[k] - p_b[k])));
    const double err = kepler_error(0.5, t_out, NOUT, q_b, p_b);
    CHECK_MSG(d < 1e-11 && err < 1e-5, "mechanical: differs from the general stepper by %.3e, error %.3e", d, err);
    gauss2_type.free(wa);
    gauss2_free(wb);
}

/* h < 0: output times decrease. */
static void test_backward(void)
{
    vigen_hamiltonian sys = kepler_problem();
    void *w = gauss2_type.alloc(&sys, NULL);
    double t = 0, q[2], p[2], t_out[NOUT], q_out[2 * NOUT], p_out[2 * NOUT];
    kepler_start(0.5, q, p);
    for (int k = 0; k < NOUT; k++) t_out[k] = -2 * M_PI * (k + 0.41) / NOUT;
    CHECK(vigen_integrate_at(&gauss2_type, w, &t, q, p, -2 * M_PI / 400, t_out, NOUT, q_out, p_out, NULL) ==
          VIGEN_SUCCESS);
    const double err = kepler_error(0.5, t_out, NOUT, q_out, p_out);
    CHECK_MSG(err < 1e-6 && t <= t_out[NOUT - 1], "backward: error %.3e, stopped at %g", err, t);
    gauss2_type.free(w);
}

static void test_refused(void)
{
    vigen_hamiltonian sys = kepler_problem(), none = { 2, NULL, NULL, NULL, NULL, 1, NULL };
    void *w = gauss2_type.alloc(&sys, NULL);
    double t = 1, q[2] = { 1, 0 }, p[2] = { 0, 1 }, qo[4], po[4];
    const double unordered[2] = { 2, 1.5 }, before[1] = { 0.5 }, ok[1] = { 2 };
    unsigned long done = 7;
    struct { const double *t_out; double h; const vigen_hamiltonian *sys; } bad[] = {
        { unordered, 0.1, NULL }, { before, 0.1, NULL }, { ok, 0, NULL }, { ok, NAN, NULL }, { ok, -0.1, NULL },
        { ok, 0.1, &none },
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        int status = vigen_integrate_at_sys(&gauss2_type, w, bad[k].sys, &t, q, p, bad[k].h, bad[k].t_out,
                                            bad[k].t_out == unordered ? 2 : 1, qo, po, &done, NULL);
        CHECK_MSG(status == VIGEN_EINVAL && t == 1 && q[0] == 1 && done == 0, "refused case %zu: status %d", k,
                  status);
    }
    CHECK(vigen_integrate_at(&gauss2_type, w, &t, q, p, 0.1, NULL, 1, qo, po, &done) == VIGEN_EINVAL);
    /* no output time: nothing to do */
    CHECK(vigen_integrate_at(&gauss2_type, w, &t, q, p, 0.1, NULL, 0, NULL, NULL, &done) == VIGEN_SUCCESS &&
          done == 0 && t == 1);
    gauss2_type.free(w);
}

/* The other real types through the triple jump: Kepler at off-grid times
 * and the O(h^4) ratio, and the final state of vigen_integrate. */
#define TEST_REAL(R, S)                                                                                   \
    static double run_kepler##S(unsigned long steps_per_period, int check_same)                           \
    {                                                                                                     \
        vigen_hamiltonian##S sys = { 2, kepler_dHdq##S, kepler_dHdp##S, kepler_H##S, NULL, 1, NULL };     \
        void *w = yoshida_type##S.alloc(&sys, NULL);                                                      \
        R t = 0, q[2], p[2], t_out[NOUT], q_out[2 * NOUT], p_out[2 * NOUT];                               \
        const R h = 2 * (R)KEPLER_PI / (R)steps_per_period;                                               \
        kepler_start##S((R)0.5, q, p);                                                                    \
        for (int k = 0; k < NOUT; k++) t_out[k] = 4 * (R)KEPLER_PI * (k + (R)0.6180339887) / NOUT;        \
        unsigned long done = 0;                                                                           \
        CHECK(vigen_integrate_at##S(&yoshida_type##S, w, &t, q, p, h, t_out, NOUT, q_out, p_out,          \
                                    &done) == VIGEN_SUCCESS);                                             \
        yoshida_type##S.free(w);                                                                          \
        if (check_same) {                                                                                 \
            R t2 = 0, q2[2], p2[2];                                                                       \
            kepler_start##S((R)0.5, q2, p2);                                                              \
            w = yoshida_type##S.alloc(&sys, NULL);                                                        \
            CHECK(vigen_integrate##S(&yoshida_type##S, w, &t2, q2, p2, h, done, 0, NULL, NULL, NULL) ==   \
                  VIGEN_SUCCESS);                                                                         \
            CHECK_MSG(t2 == t && q2[0] == q[0] && q2[1] == q[1] && p2[0] == p[0] && p2[1] == p[1],        \
                      #S ": final state differs from vigen_integrate's");                                 \
            yoshida_type##S.free(w);                                                                      \
        }                                                                                                 \
        R worst = 0;                                                                                      \
        for (int k = 0; k < NOUT; k++) {                                                                  \
            R qe[2], pe[2];                                                                               \
            kepler_exact##S((R)0.5, t_out[k], qe, pe);                                                    \
            for (int i = 0; i < 2; i++) {                                                                 \
                R dq = q_out[2 * k + i] - qe[i], dp = p_out[2 * k + i] - pe[i];                           \
                if (dq < 0) dq = -dq;                                                                     \
                if (dp < 0) dp = -dp;                                                                     \
                if (dq > worst) worst = dq;                                                               \
                if (dp > worst) worst = dp;                                                               \
            }                                                                                             \
        }                                                                                                 \
        return (double)worst;                                                                             \
    }                                                                                                     \
    static void test_real##S(void)                                                                        \
    {                                                                                                     \
        const double e1 = run_kepler##S(400, 1), e2 = run_kepler##S(800, 0), e3 = run_kepler##S(1600, 0); \
        fprintf(stderr, "  yoshida4" #S ": errors %.3e %.3e %.3e, ratios %.2f %.2f\n", e1, e2, e3,        \
                e1 / e2, e2 / e3);                                                                        \
        CHECK_MSG(e1 < 1e-3 && e2 / e3 > 13 && e2 / e3 < 19, #S ": error %.3e, ratio %.2f", e1,           \
                  e2 / e3);                                                                               \
    }

TEST_REAL(long double, _ld)
#ifdef VIGEN_HAVE_FLOAT128
TEST_REAL(vigen_float128, _q)
#endif

int main(void)
{
    test_kepler_order(&gauss2_type, 0.5, 200, 13, 19, 2);
    test_kepler_order(&gauss2_type, 0.9, 1000, 13, 19, 2);
    test_kepler_order(&verlet_type, 0.5, 400, 3.6, 4.4, 2);
    test_extension_order();
    test_same_steps(&gauss2_type);
    test_same_steps(&verlet_type);
    test_mechanical();
    test_backward();
    test_refused();
    test_real_ld();
#ifdef VIGEN_HAVE_FLOAT128
    test_real_q();
#endif
    TEST_MAIN_END();
}
