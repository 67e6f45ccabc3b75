/* test_json.c — the JSON string writer (src/report/json.c) against RFC 8259
 * (section 7: '"', '\' and U+0000..U+001F must be escaped, with the short
 * forms \b \f \n \r \t where they exist) and RFC 3629 / Unicode table 3-7
 * (the well-formed UTF-8 byte sequences).  The expectations are written from
 * those rules, not from the writer's output; the random test checks its
 * output with a decoder that works by code points and their ranges, a
 * different formulation from the writer's lead-byte table. */
#include <stdlib.h>
#include <string.h>
#include "report/json.h"
#include "testlib.h"
#include "support/strbuf.h"

static char *render(const char *text)
{
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    vigen_json_string(&sb, text);
    return sb.data;   /* owned by the caller */
}

static void expect(const char *text, const char *want)
{
    char *got = render(text);
    CHECK_MSG(strcmp(got, want) == 0, "input \"%s\": got %s, want %s", text, got, want);
    free(got);
}

/* Decodes one code point of a UTF-8 string by its bit pattern; returns the
 * number of bytes, or 0 when the sequence is not well formed: truncated, a
 * longer form than the code point needs, a surrogate or above U+10FFFF. */
static int decode(const unsigned char *p, unsigned long *cp)
{
    int n;
    unsigned long v, min;
    if (p[0] < 0x80) { *cp = p[0]; return 1; }
    if ((p[0] & 0xE0) == 0xC0) { n = 2; v = p[0] & 0x1F; min = 0x80; }
    else if ((p[0] & 0xF0) == 0xE0) { n = 3; v = p[0] & 0x0F; min = 0x800; }
    else if ((p[0] & 0xF8) == 0xF0) { n = 4; v = p[0] & 0x07; min = 0x10000; }
    else return 0;
    for (int k = 1; k < n; k++) {
        if ((p[k] & 0xC0) != 0x80) return 0;
        v = (v << 6) | (p[k] & 0x3F);
    }
    if (v < min || v > 0x10FFFF || (v >= 0xD800 && v <= 0xDFFF)) return 0;
    *cp = v;
    return n;
}

/* The output is a JSON string in well-formed UTF-8: quoted, no raw control
 * character, every backslash starting one of the escapes of RFC 8259. */
static int valid_json_string(const char *s)
{
    size_t n = strlen(s);
    if (n < 2 || s[0] != '"' || s[n - 1] != '"') return 0;
    for (size_t i = 1; i + 1 < n;) {
        const unsigned char *p = (const unsigned char *)s + i;
        unsigned long cp;
        int len = decode(p, &cp);
        if (len == 0 || cp < 0x20 || cp == '"') return 0;
        if (cp == '\\') {
            char e = s[i + 1];
            if (strchr("\"\\/bfnrt", e) && e != '\0') { i += 2; continue; }
            if (e != 'u') return 0;
            for (int k = 2; k < 6; k++)
                if (!strchr("0123456789abcdefABCDEF", s[i + k]) || s[i + k] == '\0') return 0;
            i += 6;
            continue;
        }
        i += (size_t)len;
    }
    return 1;
}

int main(void)
{
    /* plain ASCII and the two characters that must be escaped */
    expect("gauss_3", "\"gauss_3\"");
    expect("", "\"\"");
    expect("a\"b\\c", "\"a\\\"b\\\\c\"");
    /* control characters: short escapes where RFC 8259 has them, \u00XX else */
    expect("\n", "\"\\n\"");
    expect("\t\r\b\f", "\"\\t\\r\\b\\f\"");
    expect("\x01\x1f", "\"\\u0001\\u001f\"");
    /* DEL and the C1 controls need no escape in JSON, but a raw C1 such as
     * U+009B (CSI) acts on some terminals: escaped too; U+00A0 is not one */
    expect("\x7f", "\"\\u007f\"");
    expect("\xc2\x80\xc2\x9b\xc2\x9f", "\"\\u0080\\u009b\\u009f\"");
    expect("\xc2\xa0", "\"\xc2\xa0\"");
    /* well-formed UTF-8 passes through: U+00E9, U+20AC, U+1F600, U+10FFFF */
    expect("\xc3\xa9", "\"\xc3\xa9\"");
    expect("\xe2\x82\xac", "\"\xe2\x82\xac\"");
    expect("\xf0\x9f\x98\x80", "\"\xf0\x9f\x98\x80\"");
    expect("\xf4\x8f\xbf\xbf", "\"\xf4\x8f\xbf\xbf\"");
    /* ill-formed: one U+FFFD per byte that cannot start a sequence */
    expect("\xff", "\"\\ufffd\"");
    expect("\x80", "\"\\ufffd\"");                          /* lone continuation byte */
    expect("\xc3", "\"\\ufffd\"");                          /* truncated at the end */
    expect("\xc3x", "\"\\ufffdx\"");                        /* truncated before ASCII */
    expect("\xc0\xaf", "\"\\ufffd\\ufffd\"");               /* overlong '/' */
    expect("\xe0\x80\xaf", "\"\\ufffd\\ufffd\\ufffd\"");    /* overlong, 3 bytes */
    expect("\xed\xa0\x80", "\"\\ufffd\\ufffd\\ufffd\"");    /* surrogate U+D800 */
    expect("\xf4\x90\x80\x80", "\"\\ufffd\\ufffd\\ufffd\\ufffd\"");   /* U+110000 */
    expect("\xf5\x80\x80\x80", "\"\\ufffd\\ufffd\\ufffd\\ufffd\"");
    expect("a\xffz\xc3\xa9", "\"a\\ufffdz\xc3\xa9\"");      /* recovery after a bad byte */

    /* random bytes: always a valid JSON string in well-formed UTF-8 */
    flint_rand_t state;
    flint_randinit(state);
    for (int trial = 0; trial < 20000; trial++) {
        char buf[24];
        int len = (int)n_randint(state, sizeof(buf));
        for (int k = 0; k < len; k++) {
            unsigned char b = (unsigned char)n_randint(state, 256);
            buf[k] = (char)(b ? b : 'x');
        }
        buf[len] = '\0';
        char *got = render(buf);
        CHECK_MSG(valid_json_string(got), "random input of %d bytes gave %s", len, got);
        free(got);
    }
    flint_randclear(state);

    /* the FILE writer writes what the buffer writer builds */
    FILE *f = tmpfile();
    CHECK(f != NULL);
    if (f) {
        const char *text = "q\"\n\xc3\xa9\xff";
        vigen_json_write_string(f, text);
        rewind(f);
        char back[64] = {0};
        size_t got = fread(back, 1, sizeof(back) - 1, f);
        char *want = render(text);
        CHECK(got == strlen(want) && strcmp(back, want) == 0);
        free(want);
        fclose(f);
    }
    TEST_MAIN_END();
}
