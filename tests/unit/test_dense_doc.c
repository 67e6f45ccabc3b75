/* test_dense_doc.c — the complete program of docs/simulation.md (the C
 * block under "## A complete program") is built under the strict flags
 * against the runtime compiled from its sources and a stepper emitted from
 * the tableau it names (tableaux/published/forest_ruth_4.lua as fr4),
 * run, and its output checked against Kepler's problem solved through
 * Kepler's equation (test_dense_kepler.h): the states at the eight output
 * times, the periapsis passages at multiples of 2 pi (three of them), the
 * energy, and the bit-for-bit restart.
 *
 * The program uses the problem check (<vigen/diagnostics.h>) and the saved
 * states of emitted steppers (NAME_state_get/_set).  Where this tree lacks
 * one of them, the test cuts that part out of the program (the statement
 * that calls it) and checks the rest; with both present the whole program
 * is built and checked. */
#include "test_emit_harness.h"
#include "support/file.h"
#define KEPLER_DOUBLE_ONLY
#include "test_dense_kepler.h"
#include "support/strbuf.h"

/* Removes from code the lines from the one holding `from` through the
 * one where the next match of `to` ends (the same line when to is NULL).  Returns 0 when
 * `from` or `to` is not found. */
static int cut_lines(char *code, const char *from, const char *to)
{
    char *a = strstr(code, from);
    if (a == NULL) return 0;
    while (a > code && a[-1] != '\n') a--;
    char *z = to ? strstr(a, to) : a;
    if (z == NULL) return 0;
    if (to) z += strlen(to) - 1;   /* the line where the match ends */
    char *nl = strchr(z, '\n');
    z = nl ? nl + 1 : z + strlen(z);
    memmove(a, z, strlen(z) + 1);
    return 1;
}

/* The C block after `heading` in the markdown text (heap string). */
static char *doc_program(const char *text, const char *heading)
{
    const char *h = strstr(text, heading), *b = h ? strstr(h, "```c\n") : NULL;
    const char *e = b ? strstr(b, "\n```\n") : NULL;
    return e ? vigen_strdup_printf("%.*s\n", (int)(e - b - 5), b + 5) : NULL;
}

static void check_output(const char *out, int with_restart)
{
    const double e = 0.6;
    double worst = 0;
    for (int k = 0; k < 8; k++) {
        char key[32];
        double got[5], q[2], p[2];
        static const char *const names[5] = { "t", "q0", "q1", "p0", "p1" };
        for (int i = 0; i < 5; i++) {
            snprintf(key, sizeof key, "out_%d_%s", k, names[i]);
            got[i] = harness_value(out, key, NAN);
        }
        CHECK_MSG(fabs(got[0] - 0.37 * (k + 1)) < 1e-15, "output time %d is %.17g", k, got[0]);
        kepler_exact(e, got[0], q, p);
        for (int i = 0; i < 2; i++) worst = fmax(worst, fmax(fabs(got[1 + i] - q[i]), fabs(got[3 + i] - p[i])));
    }
    CHECK_MSG(worst < 1e-6, "outputs off the exact solution by %.3e", worst);
    const double n = harness_value(out, "periapsis_count", -1);
    CHECK_MSG(n == 3, "%g periapsis passages, expected 3", n);
    for (int k = 0; k < 3; k++) {
        char key[32];
        snprintf(key, sizeof key, "periapsis_%d", k);
        const double tp = harness_value(out, key, NAN);
        CHECK_MSG(fabs(tp - 2 * (double)KEPLER_PI * (k + 1)) < 1e-5, "periapsis %d at %.17g, expected %.17g", k, tp,
                  2 * (double)KEPLER_PI * (k + 1));
    }
    CHECK_MSG(harness_value(out, "energy_error", 1) < 1e-6, "energy error %g", harness_value(out, "energy_error", 1));
    if (with_restart)
        CHECK_MSG(harness_value(out, "restart_identical", 0) == 1, "the restarted run differs from the uninterrupted");
}

int main(void)
{
    (void)harness_build;
    if (!harness_init("simdoc")) { CHECK(0); TEST_MAIN_END(); }
    char *text = NULL, *stepper = NULL;
    size_t len = 0;
    vigen_error err;
    vigen_error_init(&err);
    CHECK_MSG(vigen_read_file(&text, &len, "docs/simulation.md", 1 << 20, &err) == VIGEN_OK, "%s",
              err.message ? err.message : "docs/simulation.md");
    vigen_error_clear(&err);
    char *code = text ? doc_program(text, "## A complete program") : NULL;
    CHECK_MSG(code != NULL, "docs/simulation.md: no C block under \"## A complete program\"");
    CHECK(strstr(text ? text : "", "vigen emit tableaux/published/forest_ruth_4.lua --name fr4") != NULL);
    int ok = code && harness_emit("tableaux/published/forest_ruth_4.lua", "fr4", VIGEN_REAL_DOUBLE, &stepper);
    const int have_check = access("runtime/include/vigen/diagnostics.h", F_OK) == 0;
    const int have_restart = stepper && strstr(stepper, "fr4_state_get") != NULL;
    if (ok && !have_check) {
        fprintf(stderr, "  note: no <vigen/diagnostics.h> here; the program is built without its problem check\n");
        CHECK(cut_lines(code, "#include <vigen/diagnostics.h>", NULL) &&
              cut_lines(code, "vigen_problem_report rep;", "        return 1;\n    }"));
    }
    if (ok && !have_restart) {
        fprintf(stderr, "  note: the emitted stepper has no saved states here; built without the restart\n");
        CHECK(cut_lines(code, "void *saved = malloc", "free(saved);"));
    }
    if (ok) {
        char *src = vigen_strdup_printf("%s/kepler_sim.c", harness_dir);
        char *exe = vigen_strdup_printf("%s/kepler_sim", harness_dir);
        const char *diag = have_check ? "runtime/diagnostics/*.c" : "";   /* the checks' sources */
        char *cmd = vigen_strdup_printf("gcc %s -O2 -I%s %s %s/fr4.c %s %s -lgsl -lgslcblas -lm -o %s", HARNESS_CFLAGS,
                                        harness_dir, src, harness_dir, diag, harness_lib, exe);
        CHECK(harness_write(src, code));
        if (harness_run(cmd) == 0) {
            char *out = harness_capture(exe);
            check_output(out, have_restart);
            free(out);
        } else {
            CHECK_MSG(0, "the program of docs/simulation.md does not build");
        }
        free(cmd);
        free(src);
        free(exe);
    }
    free(stepper);
    free(code);
    free(text);
    harness_done();
    TEST_MAIN_END();
}
