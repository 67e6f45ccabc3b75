/* test_emit_template.c — the template engine of `vigen emit` and its
 * contract: inline, block and flag slots render as template.h describes, and
 * every breach (a slot the template uses without declaring it, a declared
 * slot the emitter does not supply, a used slot without a value, a slot used
 * as the wrong kind, a malformed mark) is VIGEN_E_TEMPLATE with a message
 * naming the file, the line and the slot.  The shipped PRK templates declare
 * exactly the slots the PRK builder supplies (rendering them succeeds in
 * test_emit; here: every declared name is used).  From the emitter's side: a
 * slot the builder supplies that no template of the variant declares is
 * VIGEN_E_TEMPLATE naming the slot and the variant; a template that cannot be
 * read is VIGEN_E_TEMPLATE (a broken installation, not bad input); the
 * variant is chosen by its name in variants.def and an unknown name is
 * refused with the list of variants; the real types are parsed by name.
 * Included files (@include FILE@) render as templates of their own, in the
 * including file's folder only, and their output is what pasting them would
 * give. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <dirent.h>
#include <sys/stat.h>
#include <unistd.h>
#include "testlib.h"
#include "vigen/emit.h"
#include "support/file.h"
#include "emit/template.h"
#include "support/strbuf.h"


static void standard_slots(vigen_slots *S)
{
    vigen_slots_init(S);
    vigen_slots_text(S, "NAME", "gauss2");
    vigen_slots_text(S, "EMPTY", "");
    vigen_slots_flag(S, "ON", 1);
    vigen_slots_flag(S, "OFF", 0);
    vigen_slot *b = vigen_slots_lines(S, "BODY");
    vigen_slot_line(b, "x = 1;");
    vigen_slot_line(b, "if (x) {");
    vigen_slot_line(b, "    y = 2;");
    vigen_slot_line(b, "}");
    vigen_slots_lines(S, "NONE");
}

/* Renders text; returns the status, *out the text or the error message. */
static int render(const char *text, char **out)
{
    vigen_slots S;
    standard_slots(&S);
    vigen_error err;
    vigen_error_init(&err);
    int rc = vigen_template_render(out, text, "t.in", &S, NULL, &err);
    if (rc != VIGEN_OK) *out = vigen_strdup(err.message ? err.message : "");
    vigen_error_clear(&err);
    vigen_slots_clear(&S);
    return rc;
}

static void expect_text(const char *text, const char *want)
{
    char *out = NULL;
    int rc = render(text, &out);
    CHECK(rc == VIGEN_OK);
    if (rc != VIGEN_OK || strcmp(out, want) != 0) {
        fprintf(stderr, "  template:\n%s\n  got:\n%s\n  want:\n%s\n", text, out, want);
        testlib_failures++;
    }
    free(out);
}

/* An error naming every one of the words (file:line, the slot). */
static void expect_error(const char *text, const char *where, const char *slot, const char *what)
{
    char *out = NULL;
    int rc = render(text, &out);
    CHECK(rc == VIGEN_E_TEMPLATE);
    if (rc != VIGEN_E_TEMPLATE || strstr(out, where) == NULL || strstr(out, slot) == NULL || strstr(out, what) == NULL ||
        strchr(out, '\n') != NULL) {
        fprintf(stderr, "  template:\n%s\n  message: %s\n  want: %s, %s, %s\n", text, out, where, slot, what);
        testlib_failures++;
    }
    free(out);
}

static void test_rendering(void)
{
    /* the declaration is not copied; inline slots anywhere in a line */
    expect_text("/* vigen-template slots: NAME EMPTY */\nint @NAME@_x;@EMPTY@ /* @NAME@@NAME@ */\n",
                "int gauss2_x; /* gauss2gauss2 */\n");
    /* a declaration may span lines */
    expect_text("/* vigen-template slots: NAME\n *   EMPTY */\n@NAME@@EMPTY@\n", "gauss2\n");
    /* a block slot: every line preceded by what comes before the mark */
    expect_text("/* vigen-template slots: BODY NONE */\n{\n    @@BODY@@\n}\n * @@NONE@@\nend\n",
                "{\n    x = 1;\n    if (x) {\n        y = 2;\n    }\n}\nend\n");
    /* sections, negated and nested, with else */
    expect_text("/* vigen-template slots: ON OFF NAME */\n"
                "@if ON@\na\n  @if OFF@\nb\n  @else@\nc @NAME@\n  @end@\n@else@\nd\n@end@\n"
                "@if !OFF@\ne\n@end@\n@if OFF@\n@NAME@ f\n@end@\n",
                "a\nc gauss2\ne\n");
    /* no final newline: none added */
    expect_text("/* vigen-template slots: NAME */\n@NAME@", "gauss2");
}

static void test_contract(void)
{
    /* undeclared: used, not declared (the line of the use) */
    expect_error("/* vigen-template slots: NAME */\nok\nint @REAL@ x;\n", "t.in:3", "REAL", "not declared");
    /* unknown: declared, but the emitter supplies no such slot (line 1) */
    expect_error("/* vigen-template slots: NAME STAGES */\n@NAME@\n", "t.in:1", "STAGES", "unknown");
    /* missing: declared and used, but no value supplied (the line of the use) */
    expect_error("/* vigen-template slots: NAME ORDER */\n@NAME@\n\n@ORDER@\n", "t.in:4", "ORDER", "missing");
    /* declared, supplied, never used: the declaration must say what is used */
    expect_error("/* vigen-template slots: NAME ON */\n@NAME@\n", "t.in:1", "ON", "never used");
    /* a section that is off is checked all the same */
    expect_error("/* vigen-template slots: OFF */\n@if OFF@\n@REAL@\n@end@\n", "t.in:3", "REAL", "not declared");
    /* the wrong kind: a flag as text, text as a block, a block as a flag */
    expect_error("/* vigen-template slots: ON */\nx @ON@\n", "t.in:2", "ON", "inline");
    expect_error("/* vigen-template slots: NAME */\n  @@NAME@@\n", "t.in:2", "NAME", "block");
    expect_error("/* vigen-template slots: BODY */\n@if BODY@\n@end@\n", "t.in:2", "BODY", "@if");
}

static void test_malformed(void)
{
    expect_error("/* vigen-template slots: NAME */\nint @NAME x;\n", "t.in:2", "@NAME", "malformed");
    expect_error("/* vigen-template slots: NAME */\nmail a@b\n", "t.in:2", "@b", "malformed");
    expect_error("/* vigen-template slots: NAME */\n@@NAME@@ trailing\n", "t.in:2", "NAME", "end its line");
    expect_error("/* vigen-template slots: NAME */\nx @@NAME@\n", "t.in:2", "@@NAME", "malformed");
    expect_error("/* vigen-template slots: NAME */\n@if name@\n@end@\n", "t.in:2", "name", "malformed");
    expect_error("/* vigen-template slots: ON */\n@if ON@\nx\n", "t.in:3", "@if of line 2", "no @end@");
    expect_error("/* vigen-template slots: ON */\nx\n@end@\n", "t.in:3", "@end@", "malformed");
    expect_error("/* vigen-template slots: ON */\n@else@\n", "t.in:2", "@else@", "malformed");
    expect_error("/* vigen-template slots: NAME bad-name */\n@NAME@\n", "t.in:1", "bad", "malformed");
    expect_error("int x;\n", "t.in:1", "vigen-template slots", "declaration");
}

static char *slurp(const char *path)
{
    char *text = NULL;
    size_t len;
    vigen_error err;
    vigen_error_init(&err);
    if (vigen_read_file(&text, &len, path, (size_t)1 << 20, &err) != VIGEN_OK) fprintf(stderr, "%s\n", err.message);
    vigen_error_clear(&err);
    return text;
}

/* The names of the templates of the PRK variant (every .in file of templates/prk/), sorted;
 * returns how many (at most cap). */
static size_t prk_templates(char names[][64], size_t cap)
{
    size_t n = 0;
    DIR *d = opendir("templates/prk");
    CHECK(d != NULL);
    if (d == NULL) return 0;
    for (struct dirent *e; (e = readdir(d)) != NULL;) {
        size_t len = strlen(e->d_name);
        if (len < 4 || len >= 64 || strcmp(e->d_name + len - 3, ".in") != 0 || n == cap) continue;
        strcpy(names[n++], e->d_name);
    }
    closedir(d);
    qsort(names, n, sizeof names[0], (int (*)(const void *, const void *))strcmp);
    return n;
}

/* The shipped templates: the engine's own check covers used-but-undeclared;
 * here the other direction, every declared name occurs in a mark. */
static void test_shipped(void)
{
    char names[32][64];
    size_t nfiles = prk_templates(names, 32);
    CHECK(nfiles >= 4);   /* stepper.h.in, stepper.c.in, batch.h.in, batch.c.in at least */
    for (size_t f = 0; f < nfiles; f++) {
        char path[128];
        snprintf(path, sizeof path, "templates/prk/%s", names[f]);
        FILE *fp = fopen(path, "rb");
        CHECK(fp != NULL);
        if (fp == NULL) continue;
        static char text[1 << 16];
        size_t n = fread(text, 1, sizeof text - 1, fp);
        fclose(fp);
        text[n] = 0;
        char *end = strstr(text, "*/");
        CHECK(strncmp(text, "/* vigen-template slots:", 24) == 0 && end != NULL);
        if (end == NULL) continue;
        char decl[4096];
        size_t len = (size_t)(end - text);
        if (len >= sizeof decl) len = sizeof decl - 1;
        memcpy(decl, text + 24, len - 24);
        decl[len - 24] = 0;
        for (char *w = strtok(decl, " \n*"); w; w = strtok(NULL, " \n*")) {
            char inl[80], blk[80], flag[80], neg[80];
            snprintf(inl, sizeof inl, "@%s@", w);
            snprintf(blk, sizeof blk, "@@%s@@", w);
            snprintf(flag, sizeof flag, "@if %s@", w);
            snprintf(neg, sizeof neg, "@if !%s@", w);
            const char *body = end + 2;
            if (!strstr(body, inl) && !strstr(body, blk) && !strstr(body, flag) && !strstr(body, neg)) {
                fprintf(stderr, "%s: slot %s declared but never used\n", path, w);
                testlib_failures++;
            }
        }
    }
}

/* The templates directory: $VIGEN_TEMPLATE_DIR first, the variant's folder
 * below it. */
static void test_dir(void)
{
    setenv("VIGEN_TEMPLATE_DIR", "/somewhere/templates", 1);
    char *d = vigen_template_dir("prk");
    CHECK(strcmp(d, "/somewhere/templates/prk") == 0);
    free(d);
    unsetenv("VIGEN_TEMPLATE_DIR");
    d = vigen_template_dir("prk");
    size_t n = strlen(d);
    CHECK(n >= 14 && strcmp(d + n - 14, "/templates/prk") == 0);
    free(d);
}

/* The declarations of several templates collect in one array: a slot no
 * template declares stays 0. */
static void test_declared(void)
{
    vigen_slots S;
    standard_slots(&S);
    unsigned char *declared = calloc(S.n, 1);
    vigen_error err;
    vigen_error_init(&err);
    char *out = NULL;
    CHECK(vigen_template_render(&out, "/* vigen-template slots: NAME ON */\n@if ON@\n@NAME@\n@end@\n", "a.in", &S,
                                declared, &err) == VIGEN_OK);
    free(out);
    CHECK(vigen_template_render(&out, "/* vigen-template slots: BODY */\n@@BODY@@\n", "b.in", &S, declared, &err) ==
          VIGEN_OK);
    free(out);
    for (size_t k = 0; k < S.n; k++) {
        const char *name = S.v[k]->name;
        int want = strcmp(name, "NAME") == 0 || strcmp(name, "ON") == 0 || strcmp(name, "BODY") == 0;
        CHECK_MSG(declared[k] == want, "slot %s: declared flag %d", name, declared[k]);
    }
    free(declared);
    vigen_error_clear(&err);
    vigen_slots_clear(&S);
}

/* Writes text with the first occurrence of each `from` replaced by `to`. */
static void write_edited(const char *path, const char *text, const char *const *from, const char *const *to, int n)
{
    char *t = vigen_strdup(text);
    for (int k = 0; k < n; k++) {
        char *at = strstr(t, from[k]);
        CHECK_MSG(at != NULL, "%s: '%s' not in the template", path, from[k]);
        if (at == NULL) continue;
        char *u = vigen_strdup_printf("%.*s%s%s", (int)(at - t), t, to[k], at + strlen(from[k]));
        free(t);
        t = u;
    }
    FILE *f = fopen(path, "wb");
    CHECK(f != NULL);
    if (f) {
        fputs(t, f);
        fclose(f);
    }
    free(t);
}

typedef struct {
    int rc, loaded;
    char *h, *c, *message;
} emitted;

static emitted emit_gauss2(const char *file, const char *template_dir, const char *variant)
{
    vigen_emit_options opt = { "g2", VIGEN_REAL_DOUBLE, "gauss2.lua", 0, template_dir, variant, 0, 0 };
    emitted e = { 0, 0, NULL, NULL, NULL };
    vigen_tableau t;
    char *ident = NULL;
    vigen_error err;
    vigen_error_init(&err);
    e.rc = vigen_emit_load_render(&t, &e.loaded, file, &opt, &e.h, &e.c, &ident, &err);
    if (e.loaded) vigen_tableau_clear(&t);
    e.message = vigen_strdup(err.message ? err.message : "");
    vigen_error_clear(&err);
    free(ident);
    return e;
}

static void emitted_clear(emitted *e)
{
    free(e->h);
    free(e->c);
    free(e->message);
}

/* Both templates of the variant stop declaring and using ORDER while the
 * builder still supplies it: each template on its own keeps its contract,
 * only the variant as a whole can see the slot nobody declares. */
static void test_variant_contract(void)
{
    char dir[] = "/tmp/vigen-test-template-XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    char *prk = vigen_strdup_printf("%s/prk", dir);
    CHECK(mkdir(prk, 0777) == 0);
    /* the files stepper.c.in includes, as they are */
    char names[32][64];
    size_t nfiles = prk_templates(names, 32);
    for (size_t f = 0; f < nfiles; f++) {
        char *from = vigen_strdup_printf("templates/prk/%s", names[f]), *text = slurp(from);
        char *to = vigen_strdup_printf("%s/%s", prk, names[f]);
        CHECK(text != NULL);
        if (text) write_edited(to, text, NULL, NULL, 0);
        free(text);
        free(from);
        free(to);
    }
    char *h = slurp("templates/prk/stepper.h.in"), *c = slurp("templates/prk/stepper.c.in");
    CHECK(h != NULL && c != NULL);
    char *hp = vigen_strdup_printf("%s/stepper.h.in", prk), *cp = vigen_strdup_printf("%s/stepper.c.in", prk);
    if (h && c) {
        static const char *const hfrom[] = { " ORDER ", "_ORDER @ORDER@" }, *const hto[] = { " ", "_ORDER -1" };
        static const char *const cfrom[] = { " ORDER ", "@STAGES@, @ORDER@," }, *const cto[] = { " ", "@STAGES@, -1," };
        write_edited(hp, h, hfrom, hto, 2);
        write_edited(cp, c, cfrom, cto, 2);
        emitted e = emit_gauss2("tests/data/emit/gauss2.lua", dir, NULL);
        CHECK_MSG(e.rc == VIGEN_E_TEMPLATE && strstr(e.message, "slot ORDER") && strstr(e.message, "variant prk") &&
                      !strchr(e.message, '\n') && e.h == NULL && e.c == NULL && !e.loaded,
                  "rc %d: %s", e.rc, e.message);
        emitted_clear(&e);
        /* the unedited templates in the same place render */
        write_edited(hp, h, NULL, NULL, 0);
        write_edited(cp, c, NULL, NULL, 0);
        e = emit_gauss2("tests/data/emit/gauss2.lua", dir, NULL);
        CHECK_MSG(e.rc == VIGEN_OK && e.loaded, "rc %d: %s", e.rc, e.message);
        emitted_clear(&e);
        /* a template missing: a broken installation, said with the path and
         * what to do, and not blamed on the input file */
        remove(cp);
        e = emit_gauss2("tests/data/emit/gauss2.lua", dir, NULL);
        CHECK_MSG(e.rc == VIGEN_E_TEMPLATE && strncmp(e.message, "template ", 9) == 0 &&
                      strncmp(e.message + 9, cp, strlen(cp)) == 0 && strstr(e.message, "reinstall") &&
                      strstr(e.message, "VIGEN_TEMPLATE_DIR") && !strstr(e.message, "gauss2.lua") &&
                      !strchr(e.message, '\n') && !e.loaded,
                  "rc %d: %s", e.rc, e.message);
        emitted_clear(&e);
    }
    for (size_t f = 0; f < nfiles; f++) {
        char *to = vigen_strdup_printf("%s/%s", prk, names[f]);
        remove(to);
        free(to);
    }
    rmdir(prk);
    rmdir(dir);
    free(h);
    free(c);
    free(hp);
    free(cp);
    free(prk);
}

/* The variant by name: "prk" is the default; an unknown name is refused
 * before the file is read, listing the variants with their descriptions. */
static void test_variant_choice(void)
{
    emitted d = emit_gauss2("tests/data/emit/gauss2.lua", NULL, NULL);
    emitted p = emit_gauss2("tests/data/emit/gauss2.lua", NULL, "prk");
    CHECK(d.rc == VIGEN_OK && p.rc == VIGEN_OK);
    CHECK(d.rc == VIGEN_OK && p.rc == VIGEN_OK && strcmp(d.h, p.h) == 0 && strcmp(d.c, p.c) == 0);
    emitted_clear(&d);
    emitted_clear(&p);
    emitted u = emit_gauss2("/nonexistent/gauss2.lua", NULL, "rkn");
    CHECK_MSG(u.rc == VIGEN_E_USAGE && strstr(u.message, "unknown variant 'rkn'") &&
                  strstr(u.message, "prk (partitioned Runge-Kutta stepper") && !strchr(u.message, '\n') &&
                  !u.loaded && u.h == NULL,
              "rc %d: %s", u.rc, u.message);
    emitted_clear(&u);
    /* an error about the tableau names the file (16 digits as double) */
    emitted i = emit_gauss2("tests/data/published_printed/blanes_moan_s6_4.lua", NULL, NULL);
    CHECK_MSG(i.rc == VIGEN_E_INEXACT &&
                  strncmp(i.message, "tests/data/published_printed/blanes_moan_s6_4.lua: c[1]", 55) == 0 &&
                  !i.loaded,
              "rc %d: %s", i.rc, i.message);
    emitted_clear(&i);
}

/* The real types by name, as --real takes them. */
static void test_real_names(void)
{
    static const char *const names[] = { "double", "long-double", "float128" };
    static const int types[] = { VIGEN_REAL_DOUBLE, VIGEN_REAL_LONG_DOUBLE, VIGEN_REAL_FLOAT128 };
    for (int k = 0; k < 3; k++) {
        int r = -1;
        CHECK(vigen_emit_real_parse(&r, names[k]) == VIGEN_OK && r == types[k]);
        CHECK(strcmp(vigen_emit_real_name(types[k]), names[k]) == 0);
    }
    int r = 7;
    CHECK(vigen_emit_real_parse(&r, "long double") == VIGEN_E_USAGE && r == 7);
    CHECK(vigen_emit_real_parse(&r, "half") == VIGEN_E_USAGE && r == 7);
    CHECK(vigen_emit_real_name(3) == NULL && vigen_emit_real_name(-1) == NULL);
    CHECK(strcmp(vigen_emit_real_names(), "double, long-double or float128") == 0);
}

/* Writes text to dir/name. */
static void put(const char *dir, const char *name, const char *text)
{
    char *path = vigen_strdup_printf("%s/%s", dir, name);
    write_edited(path, text, NULL, NULL, 0);
    free(path);
}

/* Renders dir/name from its file; returns the status, *out the text or the
 * error message; declared (slots of standard_slots) may be NULL. */
static int render_in(const char *dir, const char *name, char **out, unsigned char *declared)
{
    vigen_slots S;
    standard_slots(&S);
    vigen_error err;
    vigen_error_init(&err);
    char *path = vigen_strdup_printf("%s/%s", dir, name);
    int rc = vigen_template_render_file(out, path, &S, declared, &err);
    if (rc != VIGEN_OK) *out = vigen_strdup(err.message ? err.message : "");
    free(path);
    vigen_error_clear(&err);
    vigen_slots_clear(&S);
    return rc;
}

static void expect_file_error(const char *dir, const char *name, const char *where, const char *what)
{
    char *out = NULL;
    int rc = render_in(dir, name, &out, NULL);
    CHECK_MSG(rc == VIGEN_E_TEMPLATE && strstr(out, where) && strstr(out, what) && !strchr(out, '\n'),
              "%s: rc %d: %s (want %s, %s)", name, rc, out, where, what);
    free(out);
}

/* @include FILE@: the file's rendering stands for the line, exactly what the
 * same lines pasted in place render to; the included file keeps its own
 * contract (checked in a section that is off too) and its declarations
 * count for the variant; a name can only reach the including file's folder;
 * a cycle, a missing file and an include in text rendered from memory are
 * errors. */
static void test_include(void)
{
    char dir[] = "/tmp/vigen-test-include-XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    static const char *const files[] = { "main.in", "part.in", "pasted.in", "off.in", "bad.in", "up.in",
                                         "abs.in", "hidden.in", "self.in", "gone.in" };
    put(dir, "part.in", "/* vigen-template slots: BODY NAME */\n{\n    @@BODY@@\n} /* @NAME@ */\n");
    put(dir, "main.in",
        "/* vigen-template slots: NAME OFF */\nint @NAME@;\n@include part.in@\n@if OFF@\n  @include part.in@\n@end@\nend\n");
    put(dir, "pasted.in",
        "/* vigen-template slots: NAME OFF BODY */\nint @NAME@;\n{\n    @@BODY@@\n} /* @NAME@ */\n@if OFF@\n"
        "{\n    @@BODY@@\n} /* @NAME@ */\n@end@\nend\n");
    vigen_slots S;
    standard_slots(&S);
    unsigned char *declared = calloc(S.n, 1);
    char *out = NULL, *pasted = NULL;
    CHECK(render_in(dir, "main.in", &out, declared) == VIGEN_OK);
    CHECK(render_in(dir, "pasted.in", &pasted, NULL) == VIGEN_OK);
    CHECK_MSG(strcmp(out, "int gauss2;\n{\n    x = 1;\n    if (x) {\n        y = 2;\n    }\n} /* gauss2 */\nend\n") == 0,
              "got:\n%s", out);
    CHECK_MSG(strcmp(out, pasted) == 0, "included:\n%s\npasted:\n%s", out, pasted);
    for (size_t k = 0; k < S.n; k++) {
        const char *name = S.v[k]->name;
        int want = strcmp(name, "NAME") == 0 || strcmp(name, "OFF") == 0 || strcmp(name, "BODY") == 0;
        CHECK_MSG(declared[k] == want, "slot %s: declared flag %d", name, declared[k]);
    }
    free(out);
    free(pasted);
    free(declared);
    vigen_slots_clear(&S);
    /* each file: its text, and what the error names */
    static const struct { const char *file, *text, *where, *what; } bad[] = {
        /* an included file breaking its contract, included in a section that is off */
        { "bad.in", "/* vigen-template slots: NAME */\n@NAME@\n@REAL@\n", "bad.in:3", "REAL" },
        { "off.in", "/* vigen-template slots: OFF */\n@if OFF@\n@include bad.in@\n@end@\n", "bad.in:3", "REAL" },
        /* names that would leave the folder, or hide in it */
        { "up.in", "/* vigen-template slots: NAME */\n@NAME@\n@include ../part.in@\n", "up.in:3", "malformed" },
        { "abs.in", "/* vigen-template slots: NAME */\n@NAME@\n  @include /etc/passwd@\n", "abs.in:3", "malformed" },
        { "hidden.in", "/* vigen-template slots: NAME */\n@NAME@\n@include .part.in@\n", "hidden.in:3", "malformed" },
        /* a file that includes itself: stopped, not recursing forever */
        { "self.in", "/* vigen-template slots: NAME */\n@NAME@\n@include self.in@\n", "self.in:3", "deeper than 8" },
        /* a missing included file: a broken installation, its path named */
        { "gone.in", "/* vigen-template slots: NAME */\n@NAME@\n@include nowhere.in@\n", "nowhere.in", "reinstall" },
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) put(dir, bad[k].file, bad[k].text);
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) expect_file_error(dir, bad[k].file, bad[k].where, bad[k].what);
    /* text rendered from memory has no folder to include from */
    expect_error("/* vigen-template slots: NAME */\n@NAME@\n@include part.in@\n", "t.in:3", "part.in", "template file");
    for (size_t f = 0; f < sizeof files / sizeof files[0]; f++) {
        char *path = vigen_strdup_printf("%s/%s", dir, files[f]);
        remove(path);
        free(path);
    }
    CHECK(rmdir(dir) == 0);
}

int main(void)
{
    test_include();
    test_declared();
    test_variant_contract();
    test_variant_choice();
    test_real_names();
    test_dir();
    test_rendering();
    test_contract();
    test_malformed();
    test_shipped();
    TEST_MAIN_END();
}
