/* test_emit_hostile.c — emitted steppers refuse non-finite numbers, on every
 * path and for every real type.  Stormer-Verlet, Yoshida's triple jump
 * (a composition) and symplectic Euler (explicit for separable H, implicit
 * otherwise), Gauss-2 and the midpoint rule (implicit) from tests/data/emit
 * are emitted for double, long double and __float128 (where gcc has it),
 * built with tests/data/emit/hostile_driver.c and run on the harmonic
 * oscillator through the explicit path (compensated and plain), fixed-point
 * iteration and Newton.  Asserted, for each:
 *   - a NaN gradient on the first call, a NaN dH/dq or dH/dp and a +inf
 *     dH/dq mid-run, a NaN initial q and a NaN initial p: VIGEN_ENONFINITE,
 *     with t, q, p bit for bit what they were before the call, and in the
 *     step where the gradient first returned the bad value (the implicit
 *     path of Lobatto IIIA-IIIB, whose last dH/dq enters only the update of
 *     p, used to accept that step with a NaN p and fail one step later);
 *   - t = NaN, h = NaN, +inf, -inf, and t = h = 1e308 (t + h overflows; the
 *     type's own overflow for long double and float128), on a first call and
 *     continuing a trajectory: VIGEN_EINVAL with t, q, p unchanged;
 *   - h = 1e300 from t = 0 (the new state overflows): an error status with
 *     the state unchanged, VIGEN_ENONFINITE on the explicit path;
 *   - after a refused step, the repaired gradient gives the same bits as a
 *     run that never failed (the compensation and the cached gradients are
 *     not disturbed by the refusal);
 *   - Newton: a genuinely singular I - h J (midpoint, H = q p, h = 2:
 *     I - h J = diag(0, 2)) is VIGEN_ESINGULAR, a NaN gradient on the first
 *     call (a NaN Hessian) VIGEN_ENONFINITE.
 * The emitted code compiles warning-free under the harness's flags. */
#include "test_emit_harness.h"
#include "support/strbuf.h"

/* status codes of the runtime (vigen/runtime.h; the values are stable) */
enum { VIGEN_EINVAL = 1, VIGEN_ESINGULAR = 5, VIGEN_ENONFINITE = 6 };

typedef struct {
    const char *file, *tag;
    int explicit_path;   /* the tableau is explicit for separable H */
    int singular;        /* run the singular-matrix case too */
} tableau_case;

typedef struct { int sep, kahan, solver; const char *label; } mode;

static const char *const nonfinite_cases[] = { "nan_first", "nan_mid", "nanp_mid", "inf_mid", "nan_q", "nan_p" };
static const char *const einval_cases[] = { "t_nan", "h_nan", "h_inf", "h_minf", "tover_first", "tover_mid" };

static double key(const char *out, const char *c, const char *suffix)
{
    char k[64];
    snprintf(k, sizeof k, "%s_%s", c, suffix);
    return harness_value(out, k, -99);
}

static void check_mode(const char *what, const char *out, int explicit_path)
{
    for (size_t i = 0; i < sizeof nonfinite_cases / sizeof *nonfinite_cases; i++) {
        const char *c = nonfinite_cases[i];
        CHECK_MSG(key(out, c, "status") == VIGEN_ENONFINITE && key(out, c, "unchanged") == 1,
                  "%s: %s: status %g (want %d), state unchanged %g", what, c, key(out, c, "status"),
                  VIGEN_ENONFINITE, key(out, c, "unchanged"));
        /* refused in the very step that met the bad value, not later */
        if (strstr(c, "_mid"))
            CHECK_MSG(key(out, c, "step") >= 2 && key(out, c, "step") == key(out, c, "fired"),
                      "%s: %s: refused at step %g, the gradient turned bad at step %g", what, c, key(out, c, "step"),
                      key(out, c, "fired"));
    }
    CHECK_MSG(harness_value(out, "recover_same", 0) == 1, "%s: the step retried after a refusal differs", what);
    for (size_t i = 0; i < sizeof einval_cases / sizeof *einval_cases; i++) {
        const char *c = einval_cases[i];
        CHECK_MSG(key(out, c, "status") == VIGEN_EINVAL && key(out, c, "unchanged") == 1,
                  "%s: %s: status %g (want %d), state unchanged %g", what, c, key(out, c, "status"), VIGEN_EINVAL,
                  key(out, c, "unchanged"));
    }
    double hs = key(out, "h_huge", "status");
    CHECK_MSG(hs > 0 && key(out, "h_huge", "unchanged") == 1, "%s: h_huge: status %g, unchanged %g", what, hs,
              key(out, "h_huge", "unchanged"));
    if (explicit_path) CHECK_MSG(hs == VIGEN_ENONFINITE, "%s: h_huge: status %g on the explicit path", what, hs);
}

int main(void)
{
    if (!harness_init("emit-hostile")) return 1;
    const tableau_case tableaux[] = {
        { "tests/data/emit/verlet.lua", "sv", 1, 0 },
        { "tests/data/emit/yoshida4.lua", "y4", 1, 0 },
        { "tests/data/emit/symplectic_euler.lua", "se", 1, 0 },
        { "tests/data/emit/gauss2.lua", "g2", 0, 0 },
        { "tests/data/emit/midpoint.lua", "mp", 0, 1 },
    };
    const mode modes[] = {
        { 1, 1, 0, "separable, compensated" },   /* the explicit path where there is one */
        { 1, 0, 0, "separable, plain" },
        { 0, 1, 0, "fixed point" },
        { 0, 0, 0, "fixed point, plain" },
        { 0, 1, 1, "Newton" },
    };
    const struct { int real; const char *define, *label; } reals[] = {
        { VIGEN_REAL_DOUBLE, "", "double" },
        { VIGEN_REAL_LONG_DOUBLE, "-DREAL_LD", "long double" },
        { VIGEN_REAL_FLOAT128, "-DREAL_Q", "float128" },
    };
    int have_float128 = system("echo | gcc -dM -E - | grep -q __SIZEOF_FLOAT128__") == 0;
    if (!have_float128) fprintf(stderr, "note: gcc has no __float128 here; float128 not tested\n");
    for (size_t r = 0; r < 3; r++) {
        if (reals[r].real == VIGEN_REAL_FLOAT128 && !have_float128) continue;
        for (size_t k = 0; k < sizeof tableaux / sizeof *tableaux; k++) {
            const tableau_case *tc = &tableaux[k];
            char *name = vigen_strdup_printf("h_%s_%zu", tc->tag, r);
            char *exe_name = vigen_strdup_printf("drv_%s", name);
            char *exe = harness_emit(tc->file, name, reals[r].real, NULL)
                            ? harness_build("gcc", "hostile_driver.c", name, reals[r].define, exe_name)
                            : NULL;
            for (size_t m = 0; exe && m < sizeof modes / sizeof *modes; m++) {
                char *cmd = vigen_strdup_printf("%s %d %d %d", exe, modes[m].sep, modes[m].kahan, modes[m].solver);
                char *out = harness_capture(cmd);
                char *what = vigen_strdup_printf("%s, %s, %s", tc->file, reals[r].label, modes[m].label);
                check_mode(what, out, tc->explicit_path && modes[m].sep && modes[m].solver == 0);
                free(what);
                free(out);
                free(cmd);
            }
            if (exe && tc->singular) {
                char *cmd = vigen_strdup_printf("%s singular", exe);
                char *out = harness_capture(cmd);
                CHECK_MSG(harness_value(out, "singular_status", -1) == VIGEN_ESINGULAR &&
                              harness_value(out, "singular_unchanged", 0) == 1,
                          "%s, %s: singular I - h J: status %g", tc->file, reals[r].label,
                          harness_value(out, "singular_status", -1));
                CHECK_MSG(harness_value(out, "singular_nan_status", -1) == VIGEN_ENONFINITE &&
                              harness_value(out, "singular_nan_unchanged", 0) == 1,
                          "%s, %s: Newton with a NaN gradient: status %g", tc->file, reals[r].label,
                          harness_value(out, "singular_nan_status", -1));
                free(out);
                free(cmd);
            }
            free(exe);
            free(exe_name);
            free(name);
        }
    }
    harness_done();
    TEST_MAIN_END();
}
