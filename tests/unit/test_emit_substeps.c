/* test_emit_substeps.c — the mechanical steppers of splitting and
 * composition tableaux (NAME_alloc_mechanical stepping the substeps in
 * place): McLachlan's SB3A (tableaux/published/mclachlan_rkn_4.lua: drift
 * first and last), Yoshida's triple jump of velocity Verlet (yoshida_4.lua)
 * and velocity Verlet (stormer_verlet_velocity.lua: kick first and last,
 * first same as last) are emitted and run through a driver written here.
 *
 * The reference is the splitting applied directly, in long double, with
 * its coefficients computed in the driver from the closed forms of the
 * sources (McLachlan 1995: a1, a2 from sqrt(722025967665), b1 = -3/73,
 * b2 = 17/59; Yoshida 1990: x1 = 1/(2 - 2^(1/3)), x0 = -2^(1/3) x1 composing
 * kick-drift-kick; Verlet: 1/2, 1, 1/2), unmerged, with no vigen code:
 *   - harmonic oscillators (f = -k q, k = 1 and 3, masses 1 and 2.5, and
 *     unit masses): the kick and drift maps multiplied out into one 2 x 2
 *     matrix per component, iterated;
 *   - Kepler, e = 0.6 from the pericentre (the maps applied in turn).
 * Asserted:
 *   - the emitted stepper (compensated and plain) stays within round-off
 *     of the reference: max |difference| <= 16 N eps over N steps (a few
 *     ulps per step; the states are of size 0.4 to 2), while the same stepper
 *     against another method's reference (Yoshida's for McLachlan's) is far
 *     outside it (the comparison can fail);
 *   - the general-H stepper of the same tableau (dH/dq = -f, dH/dp =
 *     M^-1 p, its PRK stage sums) agrees with the mechanical one to the
 *     same round-off;
 *   - force evaluations: 5 per step for McLachlan, 3 for Yoshida, 1 for
 *     Verlet (plus 1 at the first step for the two with first same as
 *     last), no dH/dp call;
 *   - a force that turns NaN mid-step (its 7th call): VIGEN_ENONFINITE with
 *     t, q, p unchanged (tests/data/emit/mech_driver.c, nan), also with a
 *     static dimension (--dim 2: vectorised passes, finiteness by an OR of
 *     bits), and with --dim 8 the same bits as without on a chain of 8
 *     unequal masses (mech_driver.c, final);
 *   - a state saved mid-run and restored into a fresh workspace continues
 *     bit for bit (tests/data/emit/restart_driver.c, check: a chain with
 *     unequal masses, compensated and plain);
 *   - the emitted code is warning-free under the strict flags (gcc, clang). */
#include "test_emit_harness.h"
#include "support/strbuf.h"
#include <float.h>

static const char *const driver_lines[] = {
    "#include <math.h>",
    "#include <stdio.h>",
    "#include <stdlib.h>",
    "#include <string.h>",
    "#include STEPPER_HEADER",
    "#define CAT_(a, b) a##b",
    "#define CAT(a, b) CAT_(a, b)",
    "#define FN(x) CAT(STEPPER_NAME, x)",
    "typedef long double ld;",
    "static int nsub, kind[40];   /* 1 drift, 0 kick */",
    "static ld coef[40];",
    "static void add(int d, ld c) { kind[nsub] = d; coef[nsub++] = c; }",
    "static int setup(const char *m)",
    "{",
    "    if (strcmp(m, \"verlet\") == 0) { add(0, 0.5L); add(1, 1); add(0, 0.5L); return 1; }",
    "    if (strcmp(m, \"yoshida\") == 0) {",
    "        const ld x1 = 1 / (2 - cbrtl(2)), x0 = -cbrtl(2) * x1, w[3] = { x1, x0, x1 };",
    "        for (int i = 0; i < 3; i++) { add(0, w[i] / 2); add(1, w[i]); add(0, w[i] / 2); }",
    "        return 1;",
    "    }",
    "    if (strcmp(m, \"mclachlan\") == 0) {",
    "        const ld r = sqrtl(722025967665.0L);",
    "        const ld a1 = (1095 * r - 229483763) / 1729961856, a2 = (315354233 - 1081 * r) / 2100667968;",
    "        const ld a3 = 0.5L - a1 - a2, b1 = -3.0L / 73, b2 = 17.0L / 59, b3 = 1 - 2 * (b1 + b2);",
    "        const ld a[6] = { a1, a2, a3, a3, a2, a1 }, b[5] = { b1, b2, b3, b2, b1 };",
    "        for (int i = 0; i < 6; i++) { add(1, a[i]); if (i < 5) add(0, b[i]); }",
    "        return 1;",
    "    }",
    "    return 0;",
    "}",
    "static const double K[2] = { 1, 3 }, IM[2] = { 1, 0.4 };",
    "static int unit, kepler;",
    "static long dhdp_calls;",
    "static void force(double t, const double *q, double *f, void *ctx)",
    "{",
    "    (void)t; (void)ctx;",
    "    if (kepler) {",
    "        const double r2 = q[0] * q[0] + q[1] * q[1], r3 = r2 * sqrt(r2);",
    "        f[0] = -q[0] / r3; f[1] = -q[1] / r3;",
    "    } else {",
    "        f[0] = -K[0] * q[0]; f[1] = -K[1] * q[1];",
    "    }",
    "}",
    "static void dhdq(double t, const double *q, const double *p, double *g, void *ctx)",
    "{",
    "    (void)p;",
    "    force(t, q, g, ctx);",
    "    g[0] = -g[0]; g[1] = -g[1];",
    "}",
    "static void dhdp(double t, const double *q, const double *p, double *g, void *ctx)",
    "{",
    "    (void)t; (void)q; (void)ctx;",
    "    dhdp_calls++;",
    "    for (int k = 0; k < 2; k++) g[k] = unit ? p[k] : IM[k] * p[k];",
    "}",
    "/* one step of the splitting applied directly, in long double */",
    "static void ref_step(ld *q, ld *p, ld h)",
    "{",
    "    for (int s = 0; s < nsub; s++) {",
    "        if (kind[s]) {",
    "            for (int k = 0; k < 2; k++) q[k] += coef[s] * h * (unit ? 1 : (ld)IM[k]) * p[k];",
    "        } else if (kepler) {",
    "            const ld r2 = q[0] * q[0] + q[1] * q[1], r3 = r2 * sqrtl(r2);",
    "            const ld f0 = -q[0] / r3, f1 = -q[1] / r3;",
    "            p[0] += coef[s] * h * f0; p[1] += coef[s] * h * f1;",
    "        } else {",
    "            for (int k = 0; k < 2; k++) p[k] -= coef[s] * h * (ld)K[k] * q[k];",
    "        }",
    "    }",
    "}",
    "/* usage: driver PROBLEM(ho|hounit|kepler) SPLITTING KAHAN N H */",
    "int main(int argc, char **argv)",
    "{",
    "    if (argc != 6 || !setup(argv[2])) return 2;",
    "    kepler = strcmp(argv[1], \"kepler\") == 0;",
    "    unit = kepler || strcmp(argv[1], \"hounit\") == 0;",
    "    const int kahan = atoi(argv[3]);",
    "    const long n = atol(argv[4]);",
    "    const double h = strtod(argv[5], NULL);",
    "    /* the oscillators: each component's one-step matrix, multiplied out */",
    "    ld M[2][2][2];",
    "    for (int k = 0; k < 2; k++) {",
    "        ld a = 1, b = 0, c = 0, d = 1;   /* [[a, b], [c, d]] acting on (q, p) */",
    "        for (int s = 0; s < nsub; s++) {",
    "            const ld x = coef[s] * h;",
    "            if (kind[s]) { const ld m = x * (unit ? 1 : (ld)IM[k]); a += m * c; b += m * d; }",
    "            else { const ld m = -x * (ld)K[k]; c += m * a; d += m * b; }",
    "        }",
    "        M[k][0][0] = a; M[k][0][1] = b; M[k][1][0] = c; M[k][1][1] = d;",
    "    }",
    "    vigen_solver_options opt;",
    "    vigen_solver_options_default(&opt);",
    "    opt.kahan = kahan;",
    "    vigen_mechanical ms = { 2, force, NULL, NULL, unit ? NULL : IM };",
    "    vigen_hamiltonian gs = { 2, dhdq, dhdp, NULL, NULL, 1, NULL };",
    "    FN(workspace) *wm = FN(alloc_mechanical)(&ms, &opt), *wg = FN(alloc)(&gs, &opt);",
    "    if (wm == NULL || wg == NULL) return 3;",
    "    double t = 0, tg = 0;",
    "    double q[2] = { 0.4, 0 }, p[2] = { 0, 2 };",
    "    if (!kepler) { q[0] = 1; q[1] = -0.5; p[0] = 0.3; p[1] = 1.25; }",
    "    double qg[2] = { q[0], q[1] }, pg[2] = { p[0], p[1] };",
    "    ld qr[2] = { q[0], q[1] }, pr[2] = { p[0], p[1] };",
    "    ld dmax = 0, gmax = 0;",
    "    int st = VIGEN_SUCCESS, sg = VIGEN_SUCCESS;",
    "    for (long i = 0; i < n && st == VIGEN_SUCCESS && sg == VIGEN_SUCCESS; i++) {",
    "        st = FN(step)(wm, &t, q, p, h);",
    "        sg = FN(step)(wg, &tg, qg, pg, h);",
    "        if (kepler) {",
    "            ref_step(qr, pr, h);",
    "        } else {",
    "            for (int k = 0; k < 2; k++) {",
    "                const ld x = M[k][0][0] * qr[k] + M[k][0][1] * pr[k], y = M[k][1][0] * qr[k] + M[k][1][1] * pr[k];",
    "                qr[k] = x; pr[k] = y;",
    "            }",
    "        }",
    "        for (int k = 0; k < 2; k++) {",
    "            const ld e[4] = { q[k] - qr[k], p[k] - pr[k], (ld)q[k] - qg[k], (ld)p[k] - pg[k] };",
    "            for (int j = 0; j < 2; j++) if (!(fabsl(e[j]) <= dmax)) dmax = fabsl(e[j]);",
    "            for (int j = 2; j < 4; j++) if (!(fabsl(e[j]) <= gmax)) gmax = fabsl(e[j]);",
    "        }",
    "    }",
    "    const vigen_stats *s = FN(stats)(wm);",
    "    printf(\"status=%d\\nstatus_g=%d\\nsteps=%lu\\nforces=%lu\\nreuses=%lu\\ndhdp=%lu\\n\", st, sg, s->steps,",
    "           s->dHdq_evals, s->fsal_reuses, s->dHdp_evals);",
    "    printf(\"refdiff=%.6Le\\ngendiff=%.6Le\\ndriver_dhdp=%ld\\n\", dmax, gmax, dhdp_calls);",
    "    FN(free)(wm);",
    "    FN(free)(wg);",
    "    return 0;",
    "}",
    NULL,
};

static char *driver_exe(const char *cc, const char *name)
{
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    for (size_t k = 0; driver_lines[k]; k++) vigen_strbuf_printf(&sb, "%s\n", driver_lines[k]);
    char *src = vigen_strdup_printf("%s/split_driver.c", harness_dir);
    char *exe = vigen_strdup_printf("%s/split_%s_%s", harness_dir, name, cc);
    int ok = harness_write(src, sb.data);
    vigen_strbuf_clear(&sb);
    char *cmd = vigen_strdup_printf("%s %s -O2 -I%s -DSTEPPER_HEADER='\"%s.h\"' -DSTEPPER_NAME=%s_ %s %s/%s.c %s -lgsl "
                                    "-lgslcblas -lm -o %s", cc, HARNESS_CFLAGS, harness_dir, name, name, src,
                                    harness_dir, name, harness_lib, exe);
    ok = ok && harness_run(cmd) == 0;
    CHECK_MSG(ok, "%s: building the splitting driver with %s failed", name, cc);
    free(cmd);
    free(src);
    if (!ok) { free(exe); return NULL; }
    return exe;
}

typedef struct {
    const char *file, *name, *split;
    int per_step, fsal;
} method;

static char *drive(const char *exe, const char *problem, const char *split, int kahan, long n, const char *h)
{
    char *cmd = vigen_strdup_printf("%s %s %s %d %ld %s", exe, problem, split, kahan, n, h);
    char *out = harness_capture(cmd);
    free(cmd);
    return out;
}

static void check_reference(const method *m, const char *exe)
{
    static const char *const problems[] = { "ho", "hounit", "kepler" };
    const long n = 1000;
    /* 16 ulps of 1 per step (the states are of size 0.4 to 2): plain sums
     * on Kepler reach about 2.7e-12 over the 1000 steps (the orbit shears
     * the rounding errors), compensated ones 1e-13, the oscillators 1e-14 */
    const double bound = 16.0 * (double)n * DBL_EPSILON;
    for (int pr = 0; pr < 3; pr++)
        for (int kahan = 1; kahan >= 0; kahan--) {
            char *out = drive(exe, problems[pr], m->split, kahan, n, "0.031415926535897934");
            const double rd = harness_value(out, "refdiff", 1), gd = harness_value(out, "gendiff", 1);
            const double f = harness_value(out, "forces", -1);
            CHECK_MSG(harness_value(out, "status", -1) == 0 && harness_value(out, "status_g", -1) == 0 &&
                          harness_value(out, "steps", -1) == n, "%s %s kahan %d: a run failed", m->name, problems[pr],
                      kahan);
            CHECK_MSG(rd <= bound, "%s %s kahan %d: %.3e from the splitting applied directly (bound %.3e)", m->name,
                      problems[pr], kahan, rd, bound);
            CHECK_MSG(gd <= bound, "%s %s kahan %d: the general-H stepper differs by %.3e (bound %.3e)", m->name,
                      problems[pr], kahan, gd, bound);
            CHECK_MSG(f == (double)(m->per_step * n + m->fsal), "%s %s: %g forces in %ld steps, expected %d per step%s",
                      m->name, problems[pr], f, n, m->per_step, m->fsal ? " + 1" : "");
            CHECK_MSG(harness_value(out, "dhdp", -1) == 0, "%s: dH/dp counted on a mechanical problem", m->name);
            if (m->fsal)
                CHECK_MSG(harness_value(out, "reuses", -1) == n - 1, "%s %s: %g first-same-as-last reuses in %ld steps",
                          m->name, problems[pr], harness_value(out, "reuses", -1), n);
            fprintf(stderr, "  %s %s kahan %d: %.2e from the direct splitting, %.2e from the general stepper\n",
                    m->name, problems[pr], kahan, rd, gd);
            free(out);
        }
}

int main(void)
{
    if (!harness_init("emit-sub")) return 1;
    const method ms[] = {
        { "tableaux/published/mclachlan_rkn_4.lua", "mcl", "mclachlan", 5, 0 },
        { "tableaux/published/yoshida_4.lua", "yo4", "yoshida", 3, 1 },
        { "tableaux/published/stormer_verlet_velocity.lua", "svv", "verlet", 1, 1 },
    };
    for (size_t i = 0; i < sizeof ms / sizeof ms[0]; i++) {
        const method *m = ms + i;
        char *c = NULL;
        if (!harness_emit(m->file, m->name, VIGEN_REAL_DOUBLE, &c)) continue;
        char *sub = vigen_strdup_printf("%s_substeps", m->name);
        CHECK_MSG(strstr(c, sub) != NULL, "%s: no substep path in the emitted stepper", m->name);
        free(sub);
        free(c);
        char *exe = driver_exe("gcc", m->name), *cl = driver_exe("clang", m->name);
        CHECK_MSG(cl != NULL, "%s: not warning-free with clang", m->name);
        free(cl);
        if (exe) check_reference(m, exe);

        /* the comparison can fail: another method's reference */
        if (exe && i == 0) {
            char *out = drive(exe, "kepler", "yoshida", 1, 1000, "0.031415926535897934");
            CHECK_MSG(harness_value(out, "refdiff", 0) > 1e-6, "McLachlan's stepper is within %.3e of Yoshida's "
                      "splitting: the reference cannot tell methods apart", harness_value(out, "refdiff", 0));
            free(out);
        }
        free(exe);

        /* a NaN force mid-step */
        char *flags = vigen_strdup_printf("-DSTEPPER_NAME=%s_", m->name);
        char *mexe_name = vigen_strdup_printf("mech_%s", m->name), *rexe_name = vigen_strdup_printf("rst_%s", m->name);
        char *mexe = harness_build("gcc", "mech_driver.c", m->name, flags, mexe_name);
        if (mexe) {
            char *cmd = vigen_strdup_printf("%s nan 0", mexe);
            char *out = harness_capture(cmd);
            CHECK_MSG(harness_value(out, "nan_enonfinite", 0) == 1, "%s: a NaN force gave status %g", m->name,
                      harness_value(out, "nan_status", -1));
            CHECK_MSG(harness_value(out, "nan_unchanged", 0) == 1, "%s: the failing step changed the state", m->name);
            free(out);
            free(cmd);
        }

        /* a static dimension (--dim): the passes are vectorised and
         * finiteness is folded in by an OR of bits; the NaN force again
         * (Kepler, --dim 2), and on the chain of 8 unequal masses (--dim 8)
         * the same bits as the stepper without --dim */
        for (size_t d = 2; mexe && d <= 8; d += 6) {
            char *sname = vigen_strdup_printf("%s%zu", m->name, d);
            char *sflags = vigen_strdup_printf("-DSTEPPER_NAME=%s_", sname);
            char *sexe_name = vigen_strdup_printf("mech_%s", sname);
            char *sexe = harness_emit_dim(m->file, sname, VIGEN_REAL_DOUBLE, d, NULL)
                             ? harness_build("gcc", "mech_driver.c", sname, sflags, sexe_name)
                             : NULL;
            char *cmd = sexe == NULL ? NULL
                        : d == 2    ? vigen_strdup_printf("%s nan 0", sexe)
                                    : vigen_strdup_printf("%s final fput 0 300 0.05", sexe);
            char *out = cmd ? harness_capture(cmd) : NULL;
            if (out && d == 2) {
                CHECK_MSG(harness_value(out, "nan_enonfinite", 0) == 1, "%s --dim 2: a NaN force gave status %g",
                          m->name, harness_value(out, "nan_status", -1));
                CHECK_MSG(harness_value(out, "nan_unchanged", 0) == 1, "%s --dim 2: the failing step changed the state",
                          m->name);
            } else if (out) {
                char *dcmd = vigen_strdup_printf("%s final fput 0 300 0.05", mexe);
                char *dout = harness_capture(dcmd);
                CHECK_MSG(strstr(out, "final_m_7=") != NULL && harness_value(out, "final_status_m", -1) == 0 &&
                              dout && strcmp(out, dout) == 0,
                          "%s --dim 8: static and dynamic dimension differ:\n%s---\n%s", m->name, out,
                          dout ? dout : "");
                free(dout);
                free(dcmd);
            }
            CHECK_MSG(out != NULL, "%s --dim %zu: not built", m->name, d);
            free(out);
            free(cmd);
            free(sexe);
            free(sexe_name);
            free(sflags);
            free(sname);
        }

        /* restart bit for bit, mechanical (unequal masses), compensated and plain */
        char *rexe = harness_build("gcc", "restart_driver.c", m->name, flags, rexe_name);
        for (int kahan = 1; rexe && kahan >= 0; kahan--) {
            char *cmd = vigen_strdup_printf("%s check - 1 1 0 %d 1 0 3 60 23", rexe, kahan);
            char *out = harness_capture(cmd);
            CHECK_MSG(harness_value(out, "status", -1) == 0 && harness_value(out, "set_status", -1) == 0,
                      "%s kahan %d: a step failed or the state was refused", m->name, kahan);
            CHECK_MSG(harness_value(out, "equal", 0) == 1 && harness_value(out, "type_equal", 0) == 1,
                      "%s kahan %d: the restored run differs from the uninterrupted one", m->name, kahan);
            if (m->fsal)
                CHECK_MSG(harness_value(out, "reuses", -1) == 60 - 23, "%s kahan %d: %g reuses after the restore",
                          m->name, kahan, harness_value(out, "reuses", -1));
            if (kahan)
                CHECK_MSG(harness_value(out, "control_same_point", 1) == 0,
                          "%s: continuing without the state ends at the same point", m->name);
            free(out);
            free(cmd);
        }
        free(mexe);
        free(rexe);
        free(flags);
        free(mexe_name);
        free(rexe_name);
    }
    harness_done();
    TEST_MAIN_END();
}
