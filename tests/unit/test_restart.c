/* test_restart.c — saved states of emitted steppers (NAME_state_size, _get,
 * _set): a run saved after K steps and continued in a fresh workspace is the
 * uninterrupted run bit for bit.  Stormer-Verlet (explicit with first same as
 * last), Gauss-2 (implicit, extrapolated starts, the start-force option of
 * mechanical problems), Yoshida's triple jump, the implicit midpoint rule,
 * symplectic Euler and the 3-stage Lobatto IIIA-IIIB pair (a node at 1) are
 * emitted from their tableau files and run through
 * tests/data/emit/restart_driver.c on every path: explicit compensated and
 * plain, implicit by fixed point and by Newton, general and mechanical
 * problems, with and without extrapolation, for double, long double and
 * __float128, and with a static dimension.  Asserted, against the
 * uninterrupted run as the independent truth:
 *   - t, q, p and every counter of vigen_stats equal bit for bit (memcmp),
 *     through NAME_state_* and through the stepper type's function
 *     pointers, in one process and across processes (a state written to a
 *     file by one run and read by another program: the final states printed
 *     in hexadecimal are equal);
 *   - the first step after a restore reuses the cached first-same-as-last
 *     gradient (Verlet's explicit path: every step after the restore reuses
 *     one) and starts an extrapolated implicit step without a starting
 *     gradient (the same gradient count as the uninterrupted step);
 *   - the state matters: a fresh workspace continued without it ends
 *     elsewhere on the compensated paths (so equality is not vacuous);
 *   - a state of another stepper, real type, dimension, problem kind or
 *     options is VIGEN_ESTATE and leaves the workspace as it was; so is a
 *     state whose format number, runtime version or name is changed with the
 *     checksum recomputed here from the documented layout and hash
 *     (docs/emit.md: FNV-1a 64 over every byte before the trailer), every
 *     single-byte corruption and a truncated buffer; NULL is VIGEN_EINVAL. */
#include "test_emit_harness.h"
#include <stdint.h>
#include "vigen/runtime.h"
#include "support/strbuf.h"

enum { N = 60, K = 23, DIM = 3 };

/* One driver run: key=value output (heap string). */
static char *drive(const char *exe, const char *mode, const char *file, int sep, int mech, int solver, int kahan,
                   int extrap, int start_force, int dim)
{
    char *cmd = vigen_strdup_printf("%s %s %s %d %d %d %d %d %d %d %d %d", exe, mode, file ? file : "-", sep, mech,
                                    solver, kahan, extrap, start_force, dim, N, K);
    char *out = harness_capture(cmd);
    free(cmd);
    return out;
}

typedef struct { int sep, mech, solver, kahan, extrap, start_force; const char *what; } config;

/* What must hold for every configuration; fsal: the explicit path reuses
 * the cached gradient at every step. */
static void check_config(const char *name, const char *exe, const config *c, int fsal_path)
{
    char *out = drive(exe, "check", NULL, c->sep, c->mech, c->solver, c->kahan, c->extrap, c->start_force, DIM);
    const char *w = c->what;
    CHECK_MSG(harness_value(out, "status", -1) == 0, "%s, %s: a step failed", name, w);
    CHECK_MSG(harness_value(out, "set_status", -1) == 0, "%s, %s: state_set refused its own state", name, w);
    CHECK_MSG(harness_value(out, "size", 0) > 192, "%s, %s: no state", name, w);
    CHECK_MSG(harness_value(out, "equal", 0) == 1, "%s, %s: the restored run differs from the uninterrupted one", name, w);
    CHECK_MSG(harness_value(out, "type_equal", 0) == 1, "%s, %s: through the stepper type, the restored run differs",
              name, w);
    CHECK_MSG(harness_value(out, "roundtrip", 0) == 1, "%s, %s: state_get after state_set gives other bytes", name, w);
    CHECK_MSG(harness_value(out, "null_einval", 0) == 1, "%s, %s: a NULL argument is not VIGEN_EINVAL", name, w);
    CHECK_MSG(harness_value(out, "extrapolated", 0) == 1,
              "%s, %s: the first restored step took another number of gradients", name, w);
    if (fsal_path)
        CHECK_MSG(harness_value(out, "reuses", -1) == N - K, "%s, %s: %g first-same-as-last reuses after the restore, "
                  "expected %d", name, w, harness_value(out, "reuses", -1), N - K);
    /* with compensation the lost compensation moves the end point */
    if (c->kahan)
        CHECK_MSG(harness_value(out, "control_same_point", 1) == 0,
                  "%s, %s: continuing without the state ends at the same point: the test would not see a lost state",
                  name, w);
    free(out);
}

/* The final state lines of a driver output ("final_..." lines joined). */
static char *finals(const char *out)
{
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    vigen_strbuf_append(&sb, "");
    for (const char *p = out; p && *p;) {
        const char *e = strchr(p, '\n');
        size_t len = e ? (size_t)(e - p) : strlen(p);
        if (strncmp(p, "final_", 6) == 0) { vigen_strbuf_appendn(&sb, p, len); vigen_strbuf_append(&sb, ";"); }
        p = e ? e + 1 : NULL;
    }
    return sb.data;
}

/* Save in one process, continue in another: the final state is the
 * uninterrupted run's. */
static void check_across(const char *name, const char *exe, const config *c)
{
    char *file = vigen_strdup_printf("%s/%s_state.bin", harness_dir, name);
    char *o1 = drive(exe, "save", file, c->sep, c->mech, c->solver, c->kahan, c->extrap, c->start_force, DIM);
    char *o2 = drive(exe, "load", file, c->sep, c->mech, c->solver, c->kahan, c->extrap, c->start_force, DIM);
    char *o3 = drive(exe, "full", NULL, c->sep, c->mech, c->solver, c->kahan, c->extrap, c->start_force, DIM);
    char *f2 = finals(o2), *f3 = finals(o3);
    CHECK_MSG(harness_value(o1, "saved", 0) == 1, "%s, %s: the state was not saved", name, c->what);
    CHECK_MSG(harness_value(o2, "set_status", -1) == 0 && harness_value(o2, "status", -1) == 0,
              "%s, %s: the saved state was not taken or a step failed", name, c->what);
    CHECK_MSG(*f3 && strcmp(f2, f3) == 0, "%s, %s: restarted in another process: %s, uninterrupted: %s", name,
              c->what, f2, f3);
    free(o1); free(o2); free(o3); free(f2); free(f3); free(file);
}

/* A state saved by exe_save (with save's setup and dimension) is refused
 * by exe_load (with load's): VIGEN_ESTATE, the workspace unchanged. */
static void check_refused(const char *what, const char *exe_save, const config *save, int dim_save,
                          const char *exe_load, const config *load, int dim_load)
{
    char *file = vigen_strdup_printf("%s/refused.bin", harness_dir);
    char *o1 = drive(exe_save, "save", file, save->sep, save->mech, save->solver, save->kahan, save->extrap,
                     save->start_force, dim_save);
    char *o2 = drive(exe_load, "load", file, load->sep, load->mech, load->solver, load->kahan, load->extrap,
                     load->start_force, dim_load);
    CHECK_MSG(harness_value(o1, "saved", 0) == 1, "%s: the state was not saved", what);
    CHECK_MSG(harness_value(o2, "estate", 0) == 1, "%s: not refused with VIGEN_ESTATE (status %g)", what,
              harness_value(o2, "set_status", -1));
    CHECK_MSG(harness_value(o2, "unchanged", 0) == 1, "%s: the refusing workspace changed", what);
    free(o1); free(o2); free(file);
}

/* ---- the documented layout, independently: patch a field, re-hash ------- */

static uint64_t fnv1a(const unsigned char *b, size_t n)
{
    uint64_t hash = UINT64_C(0xcbf29ce484222325);
    for (size_t i = 0; i < n; i++) hash = (hash ^ b[i]) * UINT64_C(0x100000001b3);
    return hash;
}

/* The file of restart_driver save: size_t bytes, the state, then t, q, p.
 * patch(state, size) edits the state; the trailer is recomputed. */
static int patch_file(const char *file, void (*patch)(unsigned char *, size_t), int rehash_only_check)
{
    FILE *f = fopen(file, "rb");
    if (!f) return 0;
    unsigned char all[1 << 14];
    size_t len = fread(all, 1, sizeof all, f);
    fclose(f);
    size_t size;
    memcpy(&size, all, sizeof size);
    if (size + sizeof size > len || size < 200) return 0;
    unsigned char *st = all + sizeof size;
    uint64_t stored, mine = fnv1a(st, size - 8);
    memcpy(&stored, st + size - 8, 8);
    if (rehash_only_check) return stored == mine;
    patch(st, size);
    mine = fnv1a(st, size - 8);
    memcpy(st + size - 8, &mine, 8);
    f = fopen(file, "wb");
    if (!f) return 0;
    int ok = fwrite(all, 1, len, f) == len;
    return fclose(f) == 0 && ok;
}

/* Header offsets (docs/emit.md): magic 0, byte order 8, format 16,
 * runtime version 24 (16 bytes), name 40 (32 bytes), identity 72, ... */
static void patch_format(unsigned char *s, size_t n) { (void)n; uint64_t v = 2; memcpy(s + 16, &v, 8); }
static void patch_version(unsigned char *s, size_t n) { (void)n; s[24 + 4] = (unsigned char)(s[24 + 4] + 1); }
static void patch_name(unsigned char *s, size_t n) { (void)n; s[40] = (unsigned char)(s[40] ^ 0x20); }
static void patch_nothing(unsigned char *s, size_t n) { (void)s; (void)n; }

static void check_patched(const char *exe, const config *c)
{
    struct { const char *what; void (*patch)(unsigned char *, size_t); int accepted; } cases[] = {
        { "the state re-hashed unchanged", patch_nothing, 1 },
        { "another format number", patch_format, 0 },
        { "another runtime version", patch_version, 0 },
        { "another stepper name", patch_name, 0 },
    };
    char *file = vigen_strdup_printf("%s/patched.bin", harness_dir);
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        char *o1 = drive(exe, "save", file, c->sep, c->mech, c->solver, c->kahan, c->extrap, c->start_force, DIM);
        CHECK_MSG(patch_file(file, NULL, 1), "the saved trailer is not the FNV-1a 64 hash of the bytes before it");
        CHECK_MSG(patch_file(file, cases[i].patch, 0), "cannot patch %s", file);
        char *o2 = drive(exe, "load", file, c->sep, c->mech, c->solver, c->kahan, c->extrap, c->start_force, DIM);
        if (cases[i].accepted)
            CHECK_MSG(harness_value(o2, "set_status", -1) == 0, "%s: refused (%g)", cases[i].what,
                      harness_value(o2, "set_status", -1));
        else
            CHECK_MSG(harness_value(o2, "estate", 0) == 1 && harness_value(o2, "unchanged", 0) == 1,
                      "%s: not refused with VIGEN_ESTATE, or the workspace changed", cases[i].what);
        free(o1);
        free(o2);
    }
    free(file);
}

static void check_damage(const char *name, const char *exe, const config *c)
{
    char *out = drive(exe, "damage", NULL, c->sep, c->mech, c->solver, c->kahan, c->extrap, c->start_force, DIM);
    double tried = harness_value(out, "tried", 0), refused = harness_value(out, "refused", -1);
    CHECK_MSG(tried > 200 && refused == tried, "%s: %g of %g damaged states refused", name, refused, tried);
    CHECK_MSG(harness_value(out, "unchanged", 0) == 1, "%s: a refused state changed the workspace", name);
    CHECK_MSG(harness_value(out, "intact", 0) == 1, "%s: the intact state was refused afterwards", name);
    free(out);
}

/* ---- the steppers --------------------------------------------------------- */

static const config GEN_EXPLICIT = { 1, 0, 0, 1, 1, 0, "explicit compensated" };
static const config GEN_PLAIN = { 1, 0, 0, 0, 1, 0, "explicit plain" };
static const config GEN_FP = { 0, 0, 0, 1, 1, 0, "implicit fixed point" };
static const config GEN_NEWTON = { 0, 0, 1, 1, 1, 0, "implicit Newton" };
static const config GEN_FP_PLAIN = { 0, 0, 0, 0, 1, 0, "implicit fixed point, plain" };
static const config GEN_NO_EXTRAP = { 0, 0, 0, 1, 0, 0, "implicit fixed point, no extrapolation" };
static const config MECH = { 1, 1, 0, 1, 1, 0, "mechanical" };
static const config MECH_PLAIN = { 1, 1, 0, 0, 1, 0, "mechanical plain" };
static const config MECH_NEWTON = { 1, 1, 1, 1, 1, 0, "mechanical Newton" };
static const config MECH_START = { 1, 1, 0, 1, 1, 1, "mechanical, start force" };

typedef struct {
    const char *file, *name;
    int explicit_fsal;       /* explicit path with first same as last */
    int has_explicit;
} method;

static char *build(const method *m, int real, size_t dim, const char *exe, const char *extra)
{
    if (!(dim ? harness_emit_dim(m->file, m->name, real, dim, NULL) : harness_emit(m->file, m->name, real, NULL)))
        return NULL;
    char *flags = vigen_strdup_printf("-DSTEPPER_NAME=%s_ %s %s", m->name,
                                      real == VIGEN_REAL_LONG_DOUBLE ? "-DREAL_LD" : real == VIGEN_REAL_FLOAT128 ? "-DREAL_Q" : "",
                                      extra ? extra : "");
    char *path = harness_build("gcc", "restart_driver.c", m->name, flags, exe);
    free(flags);
    return path;
}

static void run_configs(const method *m, const char *exe, const config *const *cs, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        const int explicit_path = m->has_explicit && cs[i]->sep;
        check_config(m->name, exe, cs[i], explicit_path && m->explicit_fsal);
    }
}

int main(void)
{
    if (!harness_init("restart")) return 1;
    const method verlet = { "tests/data/emit/verlet.lua", "verlet", 1, 1 };
    const method gauss2 = { "tests/data/emit/gauss2.lua", "gauss2", 0, 0 };
    const method yoshida = { "tests/data/emit/yoshida4.lua", "yoshida4", 0, 1 };
    const method midpoint = { "tests/data/emit/midpoint.lua", "midpoint", 0, 0 };
    const method euler = { "tests/data/emit/symplectic_euler.lua", "symplectic_euler", 0, 1 };
    const method lobatto = { "tableaux/published/lobatto_iiia_iiib_3.lua", "lobatto3", 0, 0 };
    const config *const all[] = { &GEN_EXPLICIT, &GEN_PLAIN, &GEN_FP, &GEN_NEWTON, &GEN_FP_PLAIN, &GEN_NO_EXTRAP,
                                  &MECH, &MECH_PLAIN, &MECH_NEWTON, &MECH_START };
    const size_t nall = sizeof all / sizeof all[0];

    /* double: every configuration of every stepper */
    char *g2 = build(&gauss2, VIGEN_REAL_DOUBLE, 0, "restart_gauss2", NULL);
    if (g2) {
        run_configs(&gauss2, g2, all, nall);
        check_across("gauss2", g2, &GEN_FP);
        check_across("gauss2", g2, &MECH_START);
        check_damage("gauss2", g2, &GEN_FP);
        check_patched(g2, &GEN_FP);
        /* another dimension, problem kind or options */
        check_refused("gauss2: dimension 3 into 4", g2, &GEN_FP, 3, g2, &GEN_FP, 4);
        check_refused("gauss2: mechanical into general", g2, &MECH, 3, g2, &GEN_FP, 3);
        check_refused("gauss2: general into mechanical", g2, &GEN_FP, 3, g2, &MECH, 3);
        check_refused("gauss2: compensated into plain", g2, &GEN_FP, 3, g2, &GEN_FP_PLAIN, 3);
        check_refused("gauss2: fixed point into Newton", g2, &GEN_FP, 3, g2, &GEN_NEWTON, 3);
        check_refused("gauss2: extrapolating into not", g2, &GEN_FP, 3, g2, &GEN_NO_EXTRAP, 3);
        check_refused("gauss2: start force into none", g2, &MECH_START, 3, g2, &MECH, 3);
    }
    /* Verlet linked with Gauss-2, whose states it must refuse */
    char *extra = vigen_strdup_printf("-DOTHER_HEADER='\"gauss2.h\"' -DOTHER_NAME=gauss2_ %s/gauss2.c", harness_dir);
    char *vl = build(&verlet, VIGEN_REAL_DOUBLE, 0, "restart_verlet", extra);
    free(extra);
    if (vl) {
        run_configs(&verlet, vl, all, nall);
        char *out = drive(vl, "check", NULL, 0, 0, 0, 1, 1, 0, DIM);
        CHECK_MSG(harness_value(out, "other", -1) == VIGEN_ESTATE, "verlet took a state of gauss2 (status %g)",
                  harness_value(out, "other", -1));
        free(out);
        check_across("verlet", vl, &GEN_EXPLICIT);
        check_across("verlet", vl, &MECH_PLAIN);
        check_damage("verlet", vl, &GEN_EXPLICIT);
        check_refused("verlet: explicit into implicit (separable flag)", vl, &GEN_EXPLICIT, 3, vl, &GEN_FP, 3);
    }
    const method *others[] = { &yoshida, &midpoint, &euler, &lobatto };
    for (size_t i = 0; i < sizeof others / sizeof others[0]; i++) {
        char *exe_name = vigen_strdup_printf("restart_%s", others[i]->name);
        char *exe = build(others[i], VIGEN_REAL_DOUBLE, 0, exe_name, NULL);
        if (exe) run_configs(others[i], exe, all, nall);
        free(exe);
        free(exe_name);
    }

    /* long double: Gauss-2 and Verlet, and a state of another real type
     * (gauss2 emitted for long double) refused by the double build */
    const config *const some[] = { &GEN_EXPLICIT, &GEN_FP, &GEN_NEWTON, &MECH, &MECH_START };
    char *g2l = build(&gauss2, VIGEN_REAL_LONG_DOUBLE, 0, "restart_gauss2_ld", NULL);
    if (g2l) {
        run_configs(&gauss2, g2l, some, sizeof some / sizeof some[0]);
        check_across("gauss2_ld", g2l, &GEN_FP);
        check_damage("gauss2_ld", g2l, &GEN_FP);
        if (g2) {
            check_refused("gauss2: long double into double", g2l, &GEN_FP, 3, g2, &GEN_FP, 3);
            check_refused("gauss2: double into long double", g2, &GEN_FP, 3, g2l, &GEN_FP, 3);
        }
    }
    char *vll = build(&verlet, VIGEN_REAL_LONG_DOUBLE, 0, "restart_verlet_ld", NULL);
    if (vll) run_configs(&verlet, vll, some, sizeof some / sizeof some[0]);
#ifdef __SIZEOF_FLOAT128__
    char *g2q = build(&gauss2, VIGEN_REAL_FLOAT128, 0, "restart_gauss2_q", NULL);
    if (g2q) {
        run_configs(&gauss2, g2q, some, sizeof some / sizeof some[0]);
        check_across("gauss2_q", g2q, &MECH);
        if (g2l) check_refused("gauss2: float128 into long double", g2q, &GEN_FP, 3, g2l, &GEN_FP, 3);
    }
    char *vlq = build(&verlet, VIGEN_REAL_FLOAT128, 0, "restart_verlet_q", NULL);
    if (vlq) run_configs(&verlet, vlq, some, sizeof some / sizeof some[0]);
    free(g2q);
    free(vlq);
#endif
    /* a static dimension (--dim 3) */
    const method gauss2s = { "tests/data/emit/gauss2.lua", "gauss2s", 0, 0 };
    const method verlets = { "tests/data/emit/verlet.lua", "verlets", 1, 1 };
    char *g2s = build(&gauss2s, VIGEN_REAL_DOUBLE, DIM, "restart_gauss2s", NULL);
    if (g2s) {
        run_configs(&gauss2s, g2s, all, nall);
        check_across("gauss2s", g2s, &GEN_NEWTON);
    }
    char *vls = build(&verlets, VIGEN_REAL_DOUBLE, DIM, "restart_verlets", NULL);
    if (vls) run_configs(&verlets, vls, all, nall);
    free(g2);
    free(vl);
    free(g2l);
    free(vll);
    free(g2s);
    free(vls);
    harness_done();
    TEST_MAIN_END();
}
