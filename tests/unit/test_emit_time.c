/* test_emit_time.c — emitted steppers on a time-dependent Hamiltonian and on
 * non-uniform grids.  The forced oscillator
 *     H(t, q, p) = p^2/2 + q^2/2 - q F cos(w t),   F = 0.8, w = 2.3,
 * has the exact solution derived in tests/data/emit/forced_driver.c
 * (variation of constants):
 *     q(t) = q0 cos t + p0 sin t + F (cos w t - cos t) / (1 - w^2).
 * Gauss-2 (implicit path, fixed point and Newton), Stormer-Verlet and
 * Yoshida's triple jump (explicit paths for separable H, compensated and
 * plain, and their implicit paths) are emitted from tests/data/emit, built
 * with gcc and run through that driver.  Asserted:
 *   - the empirical order (largest error over the trajectory, between every
 *     pair of successive halvings of h) is 4 / 2 / 4 within 0.2, on a
 *     uniform grid, on a grid alternating h and 1.7 h, and on a smoothly
 *     varying grid (steps between 0.7 and 1.3 times the mean): the stage
 *     times t0 + c_i h carry the time dependence to full order, and each
 *     call's own h is used;
 *   - every gradient is called at t0 or at t0 + c_i h of its step, with c_i
 *     the nodes computed here from their closed forms, and every node occurs
 *     (t is a position-like variable: the nodes of A, not of At, which
 *     differ for Verlet);
 *   - t advances by exactly the sum of the step sizes: bit for bit over 10^5
 *     alternating dyadic steps; within one unit in the last place of the exact
 *     sum over 10^5 alternating steps 0.001, 0.0017 with compensated
 *     summation (the naive double sum is thousands of units off there), and
 *     bit for bit equal to that naive sum without compensation. */
#include "test_emit_harness.h"
#include "support/strbuf.h"

typedef struct {
    const char *file, *name;
    int order;
    int has_explicit;      /* the tableau has an explicit path for separable H */
    long n0;               /* step counts n0 2^k, k = 0..K, over [0, 10] */
    int K;
    int nnodes;
    double nodes[4];       /* distinct c_i, from the closed forms */
} method;

static void check_orders(const char *what, const char *out, int K, int p)
{
    char key[32];
    double prev = -1;
    for (int k = 0; k <= K; k++) {
        snprintf(key, sizeof key, "status_%d", k);
        CHECK_MSG(harness_value(out, key, -1) == 0, "%s: a step failed at k = %d", what, k);
        snprintf(key, sizeof key, "err_%d", k);
        double e = harness_value(out, key, -1);
        CHECK_MSG(e > 0, "%s: no error measured at k = %d", what, k);
        /* asymptotic regime, above round-off */
        if (k == 0) CHECK_MSG(e < 1e-2, "%s: first error %.3e: too coarse a grid", what, e);
        if (k == K) CHECK_MSG(e > 1e-11, "%s: last error %.3e: round-off level", what, e);
        if (k > 0 && prev > 0 && e > 0) {
            double o = log2(prev / e);
            CHECK_MSG(fabs(o - p) < 0.2, "%s: order %.3f between halvings %d and %d (errors %.3e, %.3e), expected %d",
                      what, o, k - 1, k, prev, e, p);
            if (k == K) fprintf(stderr, "  %s: errors %.3e .. %.3e, last order %.3f\n", what,
                                harness_value(out, "err_0", -1), e, o);
        }
        prev = e;
    }
}

static void run_method(const method *m)
{
    if (!harness_emit(m->file, m->name, VIGEN_REAL_DOUBLE, NULL)) return;
    char *exe_name = vigen_strdup_printf("forced_%s", m->name);
    char *exe = harness_build("gcc", "forced_driver.c", m->name, "", exe_name);
    free(exe_name);
    if (exe == NULL) return;
    static const char *const grids[] = { "uniform", "alternating h, 1.7h", "smooth" };
    /* runs: grid, separable, kahan, solver */
    struct { int grid, sep, kahan, solver; } runs[] = {
        { 0, 1, 1, 0 }, { 1, 1, 1, 0 }, { 2, 1, 1, 0 },   /* explicit path if any, compensated */
        { 1, 1, 0, 0 },                                   /* plain (no compensation) */
        { 1, 0, 1, 0 },                                   /* implicit path, fixed point */
        { 1, 0, 1, 1 },                                   /* implicit path, Newton */
    };
    for (size_t r = 0; r < sizeof runs / sizeof runs[0]; r++) {
        char *cmd = vigen_strdup_printf("%s order %d %d %d %d 10 %ld %d", exe, runs[r].grid, runs[r].sep, runs[r].kahan,
                                        runs[r].solver, m->n0, m->K);
        char *out = harness_capture(cmd);
        char *what = vigen_strdup_printf("%s, %s grid, %s path%s%s", m->name, grids[runs[r].grid],
                                         runs[r].sep && m->has_explicit ? "explicit" : "implicit",
                                         runs[r].kahan ? "" : ", no compensation", runs[r].solver ? ", Newton" : "");
        check_orders(what, out, m->K, m->order);
        free(what);
        free(out);
        free(cmd);
    }

    /* the times of the gradient calls, on both paths */
    for (int sep = 1; sep >= 0; sep--) {
        vigen_strbuf cmd;
        vigen_strbuf_init(&cmd);
        vigen_strbuf_printf(&cmd, "%s stagetimes %d", exe, sep);
        for (int i = 0; i < m->nnodes; i++) vigen_strbuf_printf(&cmd, " %.17g", m->nodes[i]);
        char *out = harness_capture(cmd.data);
        CHECK_MSG(harness_value(out, "stagetime_calls", 0) >= 20, "%s: gradient calls not recorded", m->name);
        CHECK_MSG(harness_value(out, "stagetime_bad", -1) == 0, "%s (separable %d): %g gradient calls at times other "
                  "than t0 + c_i h", m->name, sep, harness_value(out, "stagetime_bad", -1));
        CHECK_MSG(harness_value(out, "stagetime_nodes", -1) == m->nnodes, "%s (separable %d): %g of the %d nodes used",
                  m->name, sep, harness_value(out, "stagetime_nodes", -1), m->nnodes);
        free(out);
        vigen_strbuf_clear(&cmd);
    }

    /* t is the sum of the step sizes */
    for (int kahan = 1; kahan >= 0; kahan--) {
        char *cmd = vigen_strdup_printf("%s tsum %d 100000", exe, kahan);
        char *out = harness_capture(cmd);
        CHECK_MSG(harness_value(out, "tsum_status", -1) == 0 && harness_value(out, "tsum_status2", -1) == 0,
                  "%s: tsum run failed", m->name);
        CHECK_MSG(harness_value(out, "tsum_dyadic_diff", 1) == 0, "%s (kahan %d): t - sum of dyadic steps = %g",
                  m->name, kahan, harness_value(out, "tsum_dyadic_diff", 1));
        double naive_ulps = harness_value(out, "tsum_naive_ulps", 0);
        CHECK_MSG(naive_ulps > 10, "%s: the naive sum is only %g ulps off: the test cannot tell", m->name, naive_ulps);
        if (kahan) {
            CHECK_MSG(harness_value(out, "tsum_ulps", 99) <= 1, "%s: compensated t is %g ulps from the exact sum",
                      m->name, harness_value(out, "tsum_ulps", 99));
        } else {
            CHECK_MSG(harness_value(out, "tsum_vs_naive", 1) == 0, "%s: uncompensated t differs from the naive sum by %g",
                      m->name, harness_value(out, "tsum_vs_naive", 1));
        }
        free(out);
        free(cmd);
    }
    free(exe);
}

int main(void)
{
    if (!harness_init("emit-time")) return 1;
    /* nodes: Gauss-2 1/2 -+ sqrt(3)/6; Verlet (Lobatto IIIA) 0, 1; Yoshida's
     * triple jump with g = 1/(2 - 2^(1/3)): 0, g, 1 - g, 1 (the q stages of
     * the three Verlet substeps of sizes g h, (1 - 2g) h, g h) */
    double g = 1 / (2 - cbrt(2.0));
    const method methods[] = {
        { "tests/data/emit/gauss2.lua", "gauss2", 4, 0, 32, 5, 2, { 0.5 - sqrt(3.0) / 6, 0.5 + sqrt(3.0) / 6 } },
        { "tests/data/emit/verlet.lua", "verlet", 2, 1, 128, 5, 2, { 0, 1 } },
        { "tests/data/emit/yoshida4.lua", "yoshida4", 4, 1, 64, 5, 4, { 0, g, 1 - g, 1 } },
    };
    for (size_t k = 0; k < sizeof methods / sizeof methods[0]; k++) run_method(&methods[k]);
    harness_done();
    TEST_MAIN_END();
}
