/* fuzz_template.c — libFuzzer harness for the template engine
 * (src/emit/template.h).  The first byte chooses what is fuzzed:
 *   even: the rest is a template, rendered with a fixed slot set;
 *   odd:  the rest gives the values of the slots (NUL-separated: two texts,
 *         the lines of a block, flag bits) of a fixed template that uses
 *         every kind of mark; it must render, and the text values must
 *         appear in the output as they are. */
#include "emit/template.h"
#include "fuzz_common.h"

static void fixed_slots(vigen_slots *S)
{
    vigen_slots_init(S);
    vigen_slots_text(S, "NAME", "gauss2");
    vigen_slots_text(S, "EMPTY", "");
    vigen_slots_text(S, "REAL", "double");
    vigen_slots_flag(S, "ON", 1);
    vigen_slots_flag(S, "OFF", 0);
    vigen_slot *b = vigen_slots_lines(S, "BODY");
    vigen_slot_line(b, "x = 1;");
    vigen_slot_line(b, "if (x) {");
    vigen_slot_line(b, "    y = 2;");
    vigen_slot_line(b, "}");
    vigen_slots_lines(S, "NONE");
}

static const char fixed_template[] =
    "/* vigen-template slots: NAME VALUE BODY A B */\n"
    "/* @NAME@.c\n"
    " * @@BODY@@\n"
    " */\n"
    "@if A@\n"
    "static const char *v = \"@VALUE@\"; /* @NAME@ */\n"
    "@if !B@\n"
    "    @@BODY@@\n"
    "@else@\n"
    "int @NAME@_x;\n"
    "@end@\n"
    "@else@\n"
    "@VALUE@@NAME@\n"
    "@end@\n";

/* The next NUL-terminated piece of [*p, end), or all that is left. */
static char *piece(const char **p, const char *end)
{
    const char *z = memchr(*p, '\0', (size_t)(end - *p));
    if (z == NULL) z = end;
    char *s = fuzz_cstring((const uint8_t *)*p, (size_t)(z - *p));
    *p = z < end ? z + 1 : end;
    return s;
}

static void fuzz_values(const char *p, const char *end)
{
    char *name = piece(&p, end), *value = piece(&p, end), *body = piece(&p, end), *flags = piece(&p, end);
    vigen_slots S;
    vigen_slots_init(&S);
    vigen_slots_text(&S, "NAME", name);
    vigen_slots_text(&S, "VALUE", value);
    vigen_slot *b = vigen_slots_lines(&S, "BODY");
    for (char *line = body, *nl; line != NULL; line = nl) {
        nl = strchr(line, '\n');
        if (nl) *nl++ = '\0';
        vigen_slot_line(b, "%s", line);
    }
    vigen_slots_flag(&S, "A", flags[0] & 1);
    vigen_slots_flag(&S, "B", flags[0] & 2);
    vigen_error err;
    vigen_error_init(&err);
    unsigned char declared[8] = {0};
    char *out = NULL;
    int rc = vigen_template_render(&out, fixed_template, "fixed.in", &S, declared, &err);
    FUZZ_ASSERT(rc == VIGEN_OK);   /* the values never change the contract */
    FUZZ_ASSERT(strstr(out, name) != NULL);
    if (flags[0] & 1) FUZZ_ASSERT(strstr(out, value) != NULL);
    for (size_t k = 0; k < S.n; k++) FUZZ_ASSERT(declared[k]);
    free(out);
    vigen_error_clear(&err);
    vigen_slots_clear(&S);
    free(name);
    free(value);
    free(body);
    free(flags);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size == 0) return 0;
    if (data[0] & 1) {
        fuzz_values((const char *)data + 1, (const char *)data + size);
        return 0;
    }
    char *text = fuzz_cstring(data + 1, size - 1);
    vigen_slots S;
    fixed_slots(&S);
    vigen_error err;
    vigen_error_init(&err);
    char *out = NULL;
    int rc = vigen_template_render(&out, text, "fuzz.in", &S, NULL, &err);
    FUZZ_ASSERT(rc == VIGEN_OK ? out != NULL : err.message != NULL);
    free(out);
    vigen_error_clear(&err);
    vigen_slots_clear(&S);
    free(text);
    return 0;
}
