/* test_emit_template.c — the template engine of `vigen emit` and its
 * contract: inline, block and flag slots render as template.h describes, and
 * every breach (a slot the template uses without declaring it, a declared
 * slot the emitter does not supply, a used slot without a value, a slot used
 * as the wrong kind, a malformed mark) is VIGEN_E_TEMPLATE with a message
 * naming the file, the line and the slot.  The shipped PRK templates declare
 * exactly the slots the PRK builder supplies (rendering them succeeds in
 * test_emit; here: every declared name is used). */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "testlib.h"
#include "emit/template.h"


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
    int rc = vigen_template_render(out, text, "t.in", &S, &err);
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

/* The shipped templates: the engine's own check covers used-but-undeclared;
 * here the other direction, every declared name occurs in a mark. */
static void test_shipped(void)
{
    static const char *const files[] = { "templates/prk/stepper.h.in", "templates/prk/stepper.c.in" };
    for (size_t f = 0; f < sizeof files / sizeof files[0]; f++) {
        FILE *fp = fopen(files[f], "rb");
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
                fprintf(stderr, "%s: slot %s declared but never used\n", files[f], w);
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

int main(void)
{
    test_dir();
    test_rendering();
    test_contract();
    test_malformed();
    test_shipped();
    TEST_MAIN_END();
}
