/* test_emit_harness.h — what the tests that run emitted steppers share
 * (test_emit_precision.c, test_emit_time.c): a scratch directory, the runtime
 * compiled from its sources, emitting a tableau file into the scratch
 * directory, building a driver from tests/data/emit against it, and reading
 * the driver's key=value output.  Static functions only: each test includes
 * it once.  Paths are relative to the source root (ctest sets the working
 * directory; VIGEN_SOURCE_DIR is the fallback). */
#ifndef VIGEN_TEST_EMIT_HARNESS_H
#define VIGEN_TEST_EMIT_HARNESS_H

#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "vigen/emit.h"
#include "vigen/method.h"
#include "vigen/tableau.h"
#include "support/strbuf.h"
#include "testlib.h"

/* What every emitted stepper must compile under (strict C11, warnings as errors). */
#define HARNESS_CFLAGS "-std=c11 -Wall -Wextra -Wpedantic -Werror -Iruntime/include"

static char harness_dir[256];
static char *harness_lib;   /* the runtime as a static library in harness_dir */

static int harness_run(const char *cmd)
{
    int rc = system(cmd);
    if (rc != 0) fprintf(stderr, "command failed (%d): %s\n", rc, cmd);
    return rc;
}

/* Standard output of cmd (heap string, "" when it cannot be run). */
static char *harness_capture(const char *cmd)
{
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    vigen_strbuf_append(&sb, "");
    FILE *f = popen(cmd, "r");
    if (!f) return sb.data;
    char buf[512];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, f)) > 0) vigen_strbuf_appendn(&sb, buf, n);
    int rc = pclose(f);
    if (rc != 0) fprintf(stderr, "command exited with %d: %s\n", rc, cmd);
    return sb.data;
}

/* The value of the line "key=..." in out, or def when there is none. */
static double harness_value(const char *out, const char *key, double def)
{
    size_t k = strlen(key);
    for (const char *p = out; p && *p;) {
        if (strncmp(p, key, k) == 0 && p[k] == '=') return strtod(p + k + 1, NULL);
        p = strchr(p, '\n');
        if (p) p++;
    }
    return def;
}

static int harness_write(const char *path, const char *text)
{
    FILE *f = fopen(path, "wb");
    if (!f) return 0;
    fputs(text, f);
    return fclose(f) == 0;
}

/* Creates the scratch directory and compiles the runtime from its sources
 * (the way a user without CMake would).  Returns 0 on failure. */
static int harness_init(const char *tag)
{
#ifdef VIGEN_SOURCE_DIR
    if (access("tests/data/emit", F_OK) != 0 && chdir(VIGEN_SOURCE_DIR) != 0) return 0;
#endif
    snprintf(harness_dir, sizeof harness_dir, "/tmp/vigen-test-%s-XXXXXX", tag);
    if (mkdtemp(harness_dir) == NULL) { perror("mkdtemp"); return 0; }
    vigen_strbuf cmd;
    vigen_strbuf_init(&cmd);
    vigen_strbuf_append(&cmd, "");
    /* the runtime's core and drivers, and the Lagrangian integrators for
     * drivers that compare them with emitted steppers */
    vigen_strbuf_printf(&cmd, "for f in runtime/core/*.c runtime/drive/*.c runtime/lagrangian/*.c; do "
                        "gcc %s -O2 -c \"$f\" -o %s/rt_$(basename \"$f\" .c).o || exit 1; done && ",
                        HARNESS_CFLAGS, harness_dir);
    vigen_strbuf_printf(&cmd, "ar rcs %s/librt.a %s/rt_*.o", harness_dir, harness_dir);
    int ok = harness_run(cmd.data) == 0;
    vigen_strbuf_clear(&cmd);
    harness_lib = vigen_strdup_printf("%s/librt.a", harness_dir);
    if (!ok) fprintf(stderr, "cannot prepare the scratch directory and the runtime\n");
    /* warnings of vigen emit are expected in these tests, not noise */
    vigen_warning_set_handler(NULL, NULL);
    return ok;
}

/* Removes the scratch directory unless a check failed (then it is kept for
 * inspection). */
static void harness_done(void)
{
    if (testlib_failures == 0) {
        char *cmd = vigen_strdup_printf("rm -rf %s", harness_dir);
        if (system(cmd) != 0) fprintf(stderr, "note: could not remove %s\n", harness_dir);
        free(cmd);
    } else {
        fprintf(stderr, "emitted sources kept in %s\n", harness_dir);
    }
    free(harness_lib);
}

/* Emits the tableau file path as stepper `name` for the real type real into
 * the scratch directory (name.h, name.c); the C text is returned in *c_text
 * when c_text is not NULL.  Returns 0 on failure (reported). */
static int harness_emit_dim(const char *path, const char *name, int real, size_t dim, char **c_text);
static int harness_emit(const char *path, const char *name, int real, char **c_text)
{
    return harness_emit_dim(path, name, real, 0, c_text);
}

/* The same with a static dimension (vigen_emit_options.dim; 0: any). */
static int harness_emit_dim(const char *path, const char *name, int real, size_t dim, char **c_text)
{
    vigen_error err;
    vigen_error_init(&err);
    vigen_tableau t;
    if (c_text) *c_text = NULL;
    /* any method file as it states its tableau (splitting files too) */
    vigen_method *m = NULL;
    int loaded = vigen_method_load(&m, path, NULL, &err);
    if (loaded == VIGEN_OK) loaded = vigen_method_tableau(&t, m, 0, &err);
    vigen_method_free(m);
    if (loaded != VIGEN_OK) {
        CHECK_MSG(0, "%s: %s", path, err.message ? err.message : "");
        vigen_error_clear(&err);
        return 0;
    }
    vigen_emit_options opt = { name, real, path, 0, NULL, NULL, dim, 0 };
    char *h = NULL, *c = NULL, *id = NULL;
    int rc = vigen_emit_render(&t, &opt, &h, &c, &id, &err);
    vigen_tableau_clear(&t);
    CHECK_MSG(rc == VIGEN_OK, "%s: emit failed: %s", path, err.message ? err.message : "");
    vigen_error_clear(&err);
    int ok = rc == VIGEN_OK && strcmp(id, name) == 0;
    if (ok) {
        char *hp = vigen_strdup_printf("%s/%s.h", harness_dir, name), *cp = vigen_strdup_printf("%s/%s.c", harness_dir, name);
        ok = harness_write(hp, h) && harness_write(cp, c);
        CHECK_MSG(ok, "cannot write %s", cp);
        free(hp);
        free(cp);
    }
    if (ok && c_text) { *c_text = c; c = NULL; }
    free(h);
    free(c);
    free(id);
    return ok;
}

/* Builds tests/data/emit/<driver> against the emitted stepper `name` (with
 * STEPPER_HEADER and STEPPER_TYPE defined for it, and the extra flags) into
 * scratch/<exe>, with compiler cc (gcc or clang).  Returns the executable's
 * path (heap string), or NULL when the build fails (reported). */
static char *harness_build(const char *cc, const char *driver, const char *name, const char *extra, const char *exe)
{
    char *out = vigen_strdup_printf("%s/%s", harness_dir, exe);
    char *cmd = vigen_strdup_printf("%s %s -O2 -I%s -DSTEPPER_HEADER='\"%s.h\"' -DSTEPPER_TYPE=%s_type %s "
                                    "tests/data/emit/%s %s/%s.c %s -lgsl -lgslcblas -lm -o %s",
                                    cc, HARNESS_CFLAGS, harness_dir, name, name, extra, driver, harness_dir, name,
                                    harness_lib, out);
    int ok = harness_run(cmd) == 0;
    CHECK_MSG(ok, "%s: building %s with %s failed", name, driver, cc);
    free(cmd);
    if (!ok) { free(out); return NULL; }
    return out;
}

#endif
