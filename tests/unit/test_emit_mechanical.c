/* test_emit_mechanical.c — emitted steppers on mechanical problems
 * (NAME_alloc_mechanical, Nystrom form) and with a static dimension
 * (vigen_emit_options.dim, `vigen emit --dim`).  Gauss-2, Stormer-Verlet and
 * Yoshida's triple jump are emitted from tests/data/emit and run through
 * tests/data/emit/mech_driver.c, built with gcc and clang under the strict
 * flags (-std=c11 -Wall -Wextra -Wpedantic -Werror).  Asserted, on Kepler
 * (e = 0.6) and on a driven FPUT chain with unequal masses:
 *   - the mechanical and the general stepper (the same H with dH/dq = -f,
 *     dH/dp = M^-1 p) give the same trajectory: bit for bit on the explicit
 *     paths (negating a force is exact, so p - h b (-f) = p + h b f), and to
 *     round-off for Gauss-2 (both solve the same stage equations to
 *     round-off; the bound 1e-11 relative over 1000 steps is checked to lie
 *     far below the difference between two different methods, Gauss-2 and
 *     Verlet, on the same run);
 *   - the mechanical Verlet against the Stormer-Verlet formula written in
 *     the driver (kick, drift, kick) agrees to round-off, and Gauss-2 does
 *     not (the comparison can fail);
 *   - force evaluations: no dH/dp call ever; Verlet 1 per step and
 *     Yoshida's triple jump 3 per step (the minimum: one per distinct kick,
 *     Yoshida 1990), plus one at the first step (first same as last);
 *     Gauss-2 with fixed point 2 per sweep (one per stage) plus the first
 *     step's starting force;
 *   - a NaN force gives VIGEN_ENONFINITE with t, q, p unchanged (explicit
 *     path, fixed point, Newton);
 *   - a static-dimension stepper reports its dimension (NAME_dim), refuses a
 *     problem of another dimension (NULL from both allocs) and gives the
 *     same bits as the dynamic one;
 *   - the long double Gauss-2 agrees with its general stepper to its
 *     round-off;
 *   - the solver option start_force (the force at the step's start joins
 *     the extrapolated starting forces) leaves the Gauss-2 trajectory as it
 *     is to round-off and costs exactly one force per step;
 *   - Gauss-3 and Lobatto IIIA-IIIB 3 (tableaux/published) agree with their
 *     general steppers too, with and without start_force, by fixed point
 *     and by Newton (the Nystrom form's s n unknowns against the general
 *     stepper's 2 s n), and their force statistics equal the calls the
 *     driver counts. */
#include "test_emit_harness.h"
#include "support/strbuf.h"

static char *run(const char *exe, const char *args)
{
    char *cmd = vigen_strdup_printf("%s %s", exe, args);
    char *out = harness_capture(cmd);
    free(cmd);
    return out;
}

static char *build(const char *cc, const char *name, const char *extra)
{
    char *flags = vigen_strdup_printf("-DSTEPPER_NAME=%s_ %s", name, extra);
    char *exe_name = vigen_strdup_printf("mech_%s_%s", name, cc);
    char *exe = harness_build(cc, "mech_driver.c", name, flags, exe_name);
    free(flags);
    free(exe_name);
    return exe;
}

/* The first component of a final state line "final_<m>_0=<q> <p>". */
static double final_q0(const char *out, char which)
{
    char key[32];
    snprintf(key, sizeof key, "final_%c_0=", which);
    const char *p = strstr(out, key);
    return p ? strtod(p + strlen(key), NULL) : NAN;
}

static const char *const H = "0.031415926535897934";   /* 2 pi / 200 */

static void compare_runs(const char *exe, const char *name, int explicit_path, int per_step)
{
    static const char *const problems[] = { "kepler", "fput" };
    for (int pr = 0; pr < 2; pr++)
        for (int solver = 0; solver <= (explicit_path ? 0 : 1); solver++)
            for (int kahan = 1; kahan >= (explicit_path ? 0 : 1); kahan--) {
                char *args = vigen_strdup_printf("compare %s %d %d 1000 %s", problems[pr], solver, kahan, H);
                char *out = run(exe, args);
                double steps = harness_value(out, "steps", -1), fq = harness_value(out, "m_dHdq", -1);
                CHECK_MSG(harness_value(out, "status_g", -1) == 0 && harness_value(out, "status_m", -1) == 0 &&
                              steps == 1000, "%s %s: a run failed", name, args);
                CHECK_MSG(harness_value(out, "m_dHdp", -1) == 0, "%s %s: %g dH/dp calls in the mechanical run", name,
                          args, harness_value(out, "m_dHdp", -1));
                if (explicit_path) {
                    CHECK_MSG(harness_value(out, "bitequal", 0) == 1, "%s %s: mechanical and general differ (%g)", name,
                              args, harness_value(out, "maxdiff", -1));
                    CHECK_MSG(fq == per_step * steps + 1, "%s %s: %g force evaluations in %g steps, expected %d per "
                              "step + 1", name, args, fq, steps, per_step);
                } else {
                    double d = harness_value(out, "maxdiff", 1);
                    CHECK_MSG(d < 1e-11, "%s %s: mechanical and general differ by %.3e (relative)", name, args, d);
                    if (solver == 0)
                        CHECK_MSG(fq == 2 * harness_value(out, "m_iter", -1) + 1, "%s %s: %g forces for %g sweeps", name,
                                  args, fq, harness_value(out, "m_iter", -1));
                    fprintf(stderr, "  %s %s: sweeps per step %.3f (mechanical) %.3f (general), forces %.2f, "
                            "gradients %.2f per step, difference %.2e\n", name, args,
                            harness_value(out, "m_iter", 0) / steps, harness_value(out, "g_iter", 0) / steps, fq / steps,
                            (harness_value(out, "g_dHdq", 0) + harness_value(out, "g_dHdp", 0)) / steps, d);
                }
                free(out);
                free(args);
            }
}

static void check_nan(const char *exe, const char *name, int solver)
{
    char *args = vigen_strdup_printf("nan %d", solver);
    char *out = run(exe, args);
    CHECK_MSG(harness_value(out, "nan_enonfinite", 0) == 1, "%s %s: status %g, expected VIGEN_ENONFINITE", name, args,
              harness_value(out, "nan_status", -1));
    CHECK_MSG(harness_value(out, "nan_unchanged", 0) == 1, "%s %s: the state changed in the failing step", name, args);
    free(out);
    free(args);
}

int main(void)
{
    if (!harness_init("emit-mech")) return 1;
    int ok = harness_emit("tests/data/emit/gauss2.lua", "g2", VIGEN_REAL_DOUBLE, NULL) &&
             harness_emit("tests/data/emit/verlet.lua", "sv", VIGEN_REAL_DOUBLE, NULL) &&
             harness_emit("tests/data/emit/yoshida4.lua", "y4", VIGEN_REAL_DOUBLE, NULL) &&
             harness_emit_dim("tests/data/emit/gauss2.lua", "g2s", VIGEN_REAL_DOUBLE, 2, NULL) &&
             harness_emit_dim("tests/data/emit/verlet.lua", "svs", VIGEN_REAL_DOUBLE, 2, NULL) &&
             harness_emit("tests/data/emit/gauss2.lua", "g2l", VIGEN_REAL_LONG_DOUBLE, NULL);
    if (!ok) { harness_done(); TEST_MAIN_END(); }
    char *g2 = build("gcc", "g2", ""), *sv = build("gcc", "sv", ""), *y4 = build("gcc", "y4", "");
    char *g2s = build("gcc", "g2s", ""), *svs = build("gcc", "svs", ""), *g2l = build("gcc", "g2l", "-DREAL_LD");
    /* the strict flags with clang too (build only: the code is the same) */
    static const char *const clang_names[] = { "g2", "sv", "y4", "g2s", "g2l" };
    for (size_t k = 0; k < sizeof clang_names / sizeof clang_names[0]; k++) {
        char *e = build("clang", clang_names[k], strcmp(clang_names[k], "g2l") == 0 ? "-DREAL_LD" : "");
        CHECK_MSG(e != NULL, "%s: not warning-free with clang", clang_names[k]);
        free(e);
    }
    if (!g2 || !sv || !y4 || !g2s || !svs || !g2l) goto done;

    /* mechanical against general */
    compare_runs(g2, "gauss2", 0, 0);
    compare_runs(sv, "verlet", 1, 1);
    compare_runs(y4, "yoshida4", 1, 3);
    {
        /* the round-off bound is far below a method's difference */
        char *args = vigen_strdup_printf("final kepler 0 1000 %s", H);
        char *a = run(g2, args), *b = run(sv, args);
        double d = fabs(final_q0(a, 'm') - final_q0(b, 'g'));
        CHECK_MSG(d > 1e-6, "Gauss-2 and Verlet end only %.3e apart: the round-off bound cannot tell", d);
        free(a);
        free(b);
        free(args);
    }
    {
        char *args = vigen_strdup_printf("compare kepler 0 1 1000 %s", H);
        char *out = run(g2l, args);
        double d = harness_value(out, "maxdiff", 1);
        CHECK_MSG(harness_value(out, "status_m", -1) == 0 && d < 1e-14,
                  "long double Gauss-2: mechanical and general differ by %.3e", d);
        free(out);
        free(args);
    }

    /* the start force (solver option start_force): the same trajectory (only
     * the starting values of the iteration change), one more force per step
     * (its own count: 2 per sweep plus 1 per step, the first step's start
     * included) */
    for (int pr = 0; pr < 2; pr++) {
        const char *prob = pr ? "fput" : "kepler";
        char *args = vigen_strdup_printf("compare %s 0 1 1000 %s 1", prob, H);
        char *base = vigen_strdup_printf("compare %s 0 1 1000 %s 0", prob, H);
        char *out = run(g2, args), *ref = run(g2, base);
        double d = harness_value(out, "maxdiff", 1), it = harness_value(out, "m_iter", -1);
        CHECK_MSG(harness_value(out, "status_m", -1) == 0 && d < 1e-11, "gauss2 %s: start_force changes the "
                  "trajectory by %.3e", args, d);
        CHECK_MSG(harness_value(out, "m_dHdq", -1) == 2 * it + 1000, "gauss2 %s: %g forces for %g sweeps in 1000 steps",
                  args, harness_value(out, "m_dHdq", -1), it);
        fprintf(stderr, "  gauss2 %s, start force: sweeps per step %.3f (extrapolated: %.3f), forces %.2f (%.2f)\n",
                prob, it / 1000, harness_value(ref, "m_iter", 0) / 1000, harness_value(out, "m_dHdq", 0) / 1000,
                harness_value(ref, "m_dHdq", 0) / 1000);
        free(out);
        free(ref);
        free(args);
        free(base);
    }

    /* more shapes: Gauss-3 (an odd number of nodes: the sign of the start
     * force's weight) and Lobatto IIIA-IIIB 3 (implicit, a node at 1: no
     * start force) agree with their general steppers, with and without the
     * option */
    static const char *const more[] = { "gauss_3", "lobatto_iiia_iiib_3" };
    for (size_t k = 0; k < 2; k++) {
        char *path = vigen_strdup_printf("tableaux/published/%s.lua", more[k]);
        char *nm = vigen_strdup_printf("m%zu", k);
        char *exe = harness_emit(path, nm, VIGEN_REAL_DOUBLE, NULL) ? build("gcc", nm, "") : NULL;
        for (int sf = 0; exe && sf <= 3; sf++) {
            /* sf 0, 1: fixed point without and with the start force; 2, 3:
             * simplified Newton (in Nystrom form, s n unknowns, against the
             * general stepper's 2 s n) */
            char *args = vigen_strdup_printf("compare kepler %d 1 500 %s %d", sf / 2, H, sf % 2);
            char *out = run(exe, args);
            double d = harness_value(out, "maxdiff", 1);
            CHECK_MSG(harness_value(out, "status_m", -1) == 0 && harness_value(out, "m_dHdp", -1) == 0 && d < 1e-11,
                      "%s %s: mechanical and general differ by %.3e", more[k], args, d);
            /* the statistics count every force the stepper called, no more
             * (Lobatto's first stage, at q, is evaluated once per step) */
            CHECK_MSG(harness_value(out, "m_dHdq", -1) == harness_value(out, "m_calls", -2),
                      "%s %s: %g forces counted, %g called", more[k], args, harness_value(out, "m_dHdq", -1),
                      harness_value(out, "m_calls", -2));
            free(out);
            free(args);
        }
        CHECK_MSG(exe != NULL, "%s: not built", more[k]);
        free(exe);
        free(nm);
        free(path);
    }

    /* the Stormer-Verlet formula */
    {
        char *args = vigen_strdup_printf("verlet 1000 %s", H);
        char *out = run(sv, args), *other = run(g2, args);
        double d = harness_value(out, "verlet_maxdiff", 1), o = harness_value(other, "verlet_maxdiff", 0);
        CHECK_MSG(harness_value(out, "verlet_status", -1) == 0 && d < 1e-10,
                  "mechanical Verlet and the Stormer-Verlet formula differ by %.3e", d);
        CHECK_MSG(o > 1e-6, "Gauss-2 agrees with the Verlet formula to %.3e: the comparison cannot fail", o);
        free(out);
        free(other);
        free(args);
    }

    /* a NaN force */
    check_nan(sv, "verlet", 0);
    check_nan(y4, "yoshida4", 0);
    check_nan(g2, "gauss2", 0);
    check_nan(g2, "gauss2", 1);

    /* static dimension: refusal, and the same bits as the dynamic stepper */
    const struct { const char *name; const char *stat, *dyn; } st[] = { { "gauss2", g2s, g2 }, { "verlet", svs, sv } };
    for (size_t k = 0; k < 2; k++) {
        char *out = run(st[k].stat, "dim");
        CHECK_MSG(harness_value(out, "stepper_dim", -1) == 2, "%s --dim 2: NAME_dim() = %g", st[k].name,
                  harness_value(out, "stepper_dim", -1));
        CHECK_MSG(harness_value(out, "refused_g", 0) == 1 && harness_value(out, "refused_m", 0) == 1,
                  "%s --dim 2: a problem of dimension 3 was accepted", st[k].name);
        CHECK_MSG(harness_value(out, "accepted", 0) == 1, "%s --dim 2: a problem of dimension 2 was refused", st[k].name);
        free(out);
        out = run(st[k].dyn, "dim");
        CHECK_MSG(harness_value(out, "stepper_dim", -1) == 0 && harness_value(out, "refused_g", 1) == 0 &&
                      harness_value(out, "refused_m", 1) == 0, "%s: the dynamic stepper refused a dimension", st[k].name);
        free(out);
        for (int solver = 0; solver <= 1; solver++) {
            char *args = vigen_strdup_printf("final kepler %d 500 %s", solver, H);
            char *a = run(st[k].stat, args), *b = run(st[k].dyn, args);
            CHECK_MSG(strstr(a, "final_m_1=") != NULL && strcmp(a, b) == 0,
                      "%s %s: static and dynamic dimension differ:\n%s---\n%s", st[k].name, args, a, b);
            free(a);
            free(b);
            free(args);
        }
    }
done:
    free(g2);
    free(sv);
    free(y4);
    free(g2s);
    free(svs);
    free(g2l);
    harness_done();
    TEST_MAIN_END();
}
