/* test_lagrangian_doc.c — the complete program of docs/lagrangian.md (the C
 * block under "## A complete program") compiles under the strict flags
 * against the runtime built from its sources, runs, and its output agrees
 * with the exact motion it describes: a charged particle in a uniform field
 * B = 2 from (1, 0) with velocity (0, 1) runs on the circle
 * x = 1.5 - 0.5 cos 2t, y = 0.5 sin 2t (the Lorentz force, solved by hand),
 * with canonical angular momentum conserved. */
#include "test_emit_harness.h"
#include "support/file.h"
#include "support/strbuf.h"

/* The first ```c block after the heading, as a heap string (NULL if none). */
static char *code_block(const char *text, const char *heading)
{
    const char *h = strstr(text, heading);
    const char *b = h ? strstr(h, "```c\n") : NULL;
    const char *e = b ? strstr(b + 5, "\n```") : NULL;
    if (!e) return NULL;
    b += 5;
    char *out = malloc((size_t)(e - b) + 2);
    memcpy(out, b, (size_t)(e - b));
    out[e - b] = '\n';
    out[e - b + 1] = '\0';
    return out;
}

int main(void)
{
    (void)harness_emit;     /* the harness's emitting half is not needed here */
    (void)harness_build;
    if (!harness_init("ldoc")) { CHECK(0); TEST_MAIN_END(); }
    char *text = NULL;
    size_t len = 0;
    vigen_error err;
    vigen_error_init(&err);
    int rc = vigen_read_file(&text, &len, "docs/lagrangian.md", 1 << 20, &err);
    CHECK_MSG(rc == VIGEN_OK, "%s", err.message ? err.message : "docs/lagrangian.md");
    vigen_error_clear(&err);
    char *code = text ? code_block(text, "## A complete program") : NULL;
    CHECK_MSG(code != NULL, "docs/lagrangian.md: no C block under \"## A complete program\"");
    if (code) {
        char *src = vigen_strdup_printf("%s/example.c", harness_dir), *exe = vigen_strdup_printf("%s/example", harness_dir);
        CHECK(harness_write(src, code));
        char *cmd = vigen_strdup_printf("gcc %s -O2 %s %s -lgsl -lgslcblas -lm -o %s", HARNESS_CFLAGS, src, harness_lib, exe);
        if (harness_run(cmd) == 0) {
            char *out = harness_capture(exe);
            double t = harness_value(out, "t", -1), x = harness_value(out, "x", 99), y = harness_value(out, "y", 99);
            CHECK_MSG(fabs(t - 10.0) < 1e-12, "t = %.17g", t);
            double ex = 1.5 - 0.5 * cos(2 * t), ey = 0.5 * sin(2 * t);
            CHECK_MSG(fabs(x - ex) < 1e-3 && fabs(y - ey) < 1e-3, "(%.9f, %.9f) vs exact (%.9f, %.9f)", x, y, ex, ey);
            CHECK_MSG(fabs(harness_value(out, "J_drift", 1)) < 1e-12, "J_drift = %g", harness_value(out, "J_drift", 1));
            CHECK(harness_value(out, "steps", 0) == 1000 && harness_value(out, "newton_iterations", 0) >= 1000);
            free(out);
        } else {
            CHECK_MSG(0, "the program of docs/lagrangian.md does not build");
        }
        free(cmd);
        free(src);
        free(exe);
    }
    free(code);
    free(text);
    harness_done();
    TEST_MAIN_END();
}
