/* test_printable.c — escaping untrusted text for terminals (vigen_printable,
 * src/support/printable.c) and the refusal of NUL bytes.  The expectations are
 * written by hand from RFC 3629 (section 4: the well-formed UTF-8 byte
 * sequences, as ABNF) and from the escapes the header promises; the random
 * test checks the output with a validator built from that ABNF, row by row, a
 * different formulation from the decoder's lead-byte table. */
#include <stdlib.h>
#include <string.h>
#include "support/printable.h"
#include "testlib.h"
#include "support/strbuf.h"
#include "support/nul.h"

static void expect_n(const char *text, size_t len, const char *want)
{
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    vigen_printable_append(&sb, text, len);
    CHECK_MSG(strcmp(sb.data, want) == 0, "got \"%s\", want \"%s\"", sb.data, want);
    vigen_strbuf_clear(&sb);
}

static void expect(const char *text, const char *want)
{
    char *got = vigen_printable(text);
    CHECK_MSG(strcmp(got, want) == 0, "got \"%s\", want \"%s\"", got, want);
    free(got);
    expect_n(text, strlen(text), want);
}

/* RFC 3629, section 4:
 *   UTF8-1 = %x00-7F
 *   UTF8-2 = %xC2-DF UTF8-tail
 *   UTF8-3 = %xE0 %xA0-BF UTF8-tail / %xE1-EC 2( UTF8-tail ) /
 *            %xED %x80-9F UTF8-tail / %xEE-EF 2( UTF8-tail )
 *   UTF8-4 = %xF0 %x90-BF 2( UTF8-tail ) / %xF1-F3 3( UTF8-tail ) /
 *            %xF4 %x80-8F 2( UTF8-tail )
 * one row per alternative: first byte range, second byte range, length. */
static const struct { unsigned char lo1, hi1, lo2, hi2; int n; } abnf[] = {
    { 0xC2, 0xDF, 0x80, 0xBF, 2 }, { 0xE0, 0xE0, 0xA0, 0xBF, 3 }, { 0xE1, 0xEC, 0x80, 0xBF, 3 },
    { 0xED, 0xED, 0x80, 0x9F, 3 }, { 0xEE, 0xEF, 0x80, 0xBF, 3 }, { 0xF0, 0xF0, 0x90, 0xBF, 4 },
    { 0xF1, 0xF3, 0x80, 0xBF, 4 }, { 0xF4, 0xF4, 0x80, 0x8F, 4 },
};

/* Length of the UTF8-2/3/4 sequence at p by the ABNF, 0 if none. */
static int abnf_multibyte(const unsigned char *p)
{
    for (size_t r = 0; r < sizeof abnf / sizeof abnf[0]; r++) {
        if (p[0] < abnf[r].lo1 || p[0] > abnf[r].hi1 || p[1] < abnf[r].lo2 || p[1] > abnf[r].hi2) continue;
        for (int k = 2; k < abnf[r].n; k++)
            if (p[k] < 0x80 || p[k] > 0xBF) return 0;
        return abnf[r].n;
    }
    return 0;
}

/* The output promise: printable ASCII (0x20..0x7E) and well-formed multibyte
 * sequences only, none of them a C1 control (C2 80..C2 9F) nor one of the
 * separators and bidirectional controls (E2 80 A8..AE, E2 81 A6..A9, E2 80
 * 8E..8F, D8 9C). */
static int printable_output(const char *s)
{
    const unsigned char *p = (const unsigned char *)s;
    while (*p) {
        if (*p < 0x80) {
            if (*p < 0x20 || *p == 0x7F) return 0;
            p++;
            continue;
        }
        int n = abnf_multibyte(p);
        if (n == 0) return 0;
        if (p[0] == 0xC2 && p[1] <= 0x9F) return 0;
        if (p[0] == 0xD8 && p[1] == 0x9C) return 0;
        if (p[0] == 0xE2 && p[1] == 0x80 && ((p[2] >= 0xA8 && p[2] <= 0xAE) || p[2] == 0x8E || p[2] == 0x8F))
            return 0;
        if (p[0] == 0xE2 && p[1] == 0x81 && p[2] >= 0xA6 && p[2] <= 0xA9) return 0;
        p += n;
    }
    return 1;
}

static void test_nul(void)
{
    vigen_error err;
    vigen_error_init(&err);
    CHECK(vigen_refuse_nul("1/3", 3, "f.lua", "b[1]", &err) == VIGEN_OK);
    CHECK(err.code == VIGEN_OK && err.message == NULL);
    CHECK(vigen_refuse_nul("", 0, "f.lua", "b[1]", &err) == VIGEN_OK);
    CHECK(vigen_refuse_nul("1\0junk", 6, "f.lua", "b[1]", &err) == VIGEN_E_SPEC);
    CHECK(err.code == VIGEN_E_SPEC && err.message &&
          strcmp(err.message, "f.lua: b[1] contains a NUL byte (\\0 at byte 2); remove it") == 0);
    CHECK(vigen_refuse_nul("\0", 1, "g.lua", "name", &err) == VIGEN_E_SPEC);
    CHECK(err.message && strcmp(err.message, "g.lua: name contains a NUL byte (\\0 at byte 1); remove it") == 0);
    /* the first NUL is named; the bytes after it are looked at too */
    CHECK(vigen_refuse_nul("abc\0\0", 5, "f.lua", "A[1][2]", &err) == VIGEN_E_SPEC);
    CHECK(err.message && strstr(err.message, "A[1][2] contains a NUL byte (\\0 at byte 4)") != NULL);
    vigen_error_clear(&err);
}

static void test_decode(void)
{
    unsigned long cp = 0;
    CHECK(vigen_utf8_decode("A", 1, &cp) == 1 && cp == 0x41);
    CHECK(vigen_utf8_decode("\xc3\xa9", 2, &cp) == 2 && cp == 0xE9);
    CHECK(vigen_utf8_decode("\xe2\x82\xac", 3, &cp) == 3 && cp == 0x20AC);
    CHECK(vigen_utf8_decode("\xf0\x9f\x98\x80", 4, &cp) == 4 && cp == 0x1F600);
    CHECK(vigen_utf8_decode("\xf4\x8f\xbf\xbf", 4, &cp) == 4 && cp == 0x10FFFF);
    /* a sequence longer than the bytes left is not read past them */
    CHECK(vigen_utf8_decode("\xe2\x82\xac", 2, &cp) == 0);
    CHECK(vigen_utf8_decode("x", 0, &cp) == 0);
}

int main(void)
{
    /* printable ASCII, backslash included, is kept */
    expect("gauss_3 (s = 3): 1/2 - sqrt(3)/6", "gauss_3 (s = 3): 1/2 - sqrt(3)/6");
    expect("", "");
    expect("a\\b \"q\" 'x' ~", "a\\b \"q\" 'x' ~");
    CHECK(vigen_printable(NULL) == NULL);
    /* C0 controls and DEL: \n \r \t, else \xNN */
    expect("1\n2", "1\\n2");
    expect("\t\r", "\\t\\r");
    expect("\x1b[31mred\x1b[0m", "\\x1b[31mred\\x1b[0m");
    expect("\x01\x07\x08\x0b\x0c\x1f\x7f", "\\x01\\x07\\x08\\x0b\\x0c\\x1f\\x7f");
    /* a NUL byte inside counted text */
    expect_n("1\0junk", 6, "1\\0junk");
    expect_n("\0", 1, "\\0");
    /* well-formed UTF-8 at the edges of each RFC 3629 row is kept:
     * U+00A0, U+07FF, U+0800, U+D7FF, U+E000, U+FFFD, U+10000, U+10FFFF */
    expect("\xc2\xa0", "\xc2\xa0");
    expect("\xdf\xbf", "\xdf\xbf");
    expect("\xe0\xa0\x80", "\xe0\xa0\x80");
    expect("\xed\x9f\xbf", "\xed\x9f\xbf");
    expect("\xee\x80\x80", "\xee\x80\x80");
    expect("\xef\xbf\xbd", "\xef\xbf\xbd");
    expect("\xf0\x90\x80\x80", "\xf0\x90\x80\x80");
    expect("\xf4\x8f\xbf\xbf", "\xf4\x8f\xbf\xbf");
    expect("St\xc3\xb6rmer\xe2\x80\x93Verlet", "St\xc3\xb6rmer\xe2\x80\x93Verlet");
    /* well-formed but hidden: C1 controls U+0080..U+009F (U+009B is CSI) */
    expect("\xc2\x80", "\\u0080");
    expect("\xc2\x9b" "2J", "\\u009b2J");
    expect("\xc2\x9f", "\\u009f");
    /* separators and bidirectional controls; their neighbours are kept */
    expect("\xe2\x80\xae" "exe.txt", "\\u202eexe.txt");
    expect("\xe2\x80\xa8\xe2\x80\xa9", "\\u2028\\u2029");
    expect("\xe2\x80\x8e\xe2\x80\x8f", "\\u200e\\u200f");
    expect("\xe2\x81\xa6\xe2\x81\xa9", "\\u2066\\u2069");
    expect("\xd8\x9c", "\\u061c");
    expect("\xe2\x80\xa7\xe2\x80\xaf\xe2\x81\xaa", "\xe2\x80\xa7\xe2\x80\xaf\xe2\x81\xaa");
    /* ill-formed (RFC 3629 section 3 and 10): every byte that starts no
     * well-formed sequence is \xNN, and reading resumes at the next byte */
    expect("\xff", "\\xff");
    expect("\xfe\xff", "\\xfe\\xff");
    expect("\x80", "\\x80");                                /* lone continuation byte */
    expect("\xc3", "\\xc3");                                /* truncated at the end */
    expect("\xc3x", "\\xc3x");                              /* truncated before ASCII */
    expect("\xe2\x82", "\\xe2\\x82");                       /* truncated euro sign */
    expect("\xc0\xaf", "\\xc0\\xaf");                       /* overlong '/' */
    expect("\xc1\xbf", "\\xc1\\xbf");                       /* overlong */
    expect("\xe0\x80\xaf", "\\xe0\\x80\\xaf");              /* overlong, 3 bytes */
    expect("\xf0\x80\x80\xaf", "\\xf0\\x80\\x80\\xaf");     /* overlong, 4 bytes */
    expect("\xed\xa0\x80", "\\xed\\xa0\\x80");              /* surrogate U+D800 */
    expect("\xed\xbf\xbf", "\\xed\\xbf\\xbf");              /* surrogate U+DFFF */
    expect("\xf4\x90\x80\x80", "\\xf4\\x90\\x80\\x80");     /* U+110000 */
    expect("\xf5\x80\x80\x80", "\\xf5\\x80\\x80\\x80");
    expect("a\xffz\xc3\xa9", "a\\xffz\xc3\xa9");
    expect("\xe2\x82\xe2\x82\xac", "\\xe2\\x82\xe2\x82\xac");   /* a bad start, then a good one */

    test_nul();
    test_decode();

    /* random bytes (NUL included): the output keeps its promise, escaping is
     * idempotent, and text that is already printable is left alone */
    flint_rand_t state;
    flint_randinit(state);
    for (int trial = 0; trial < 20000; trial++) {
        char buf[24];
        size_t len = (size_t)n_randint(state, sizeof buf);
        for (size_t k = 0; k < len; k++) {
            /* half the time from the bytes that matter most: controls, C2, E2, continuations */
            static const unsigned char hot[] = { 0x00, 0x0a, 0x1b, 0x7f, 0x80, 0x9b, 0xa8, 0xae, 0xbf,
                                                 0xc2, 0xc3, 0xe2, 0xed, 0xf0, 0xf4, 0xff };
            buf[k] = (char)(n_randint(state, 2) ? hot[n_randint(state, sizeof hot)] : n_randint(state, 256));
        }
        vigen_strbuf sb;
        vigen_strbuf_init(&sb);
        vigen_printable_append(&sb, buf, len);
        CHECK_MSG(printable_output(sb.data), "random input of %zu bytes gave \"%s\"", len, sb.data);
        char *again = vigen_printable(sb.data);
        CHECK_MSG(strcmp(again, sb.data) == 0, "not idempotent: \"%s\" then \"%s\"", sb.data, again);
        free(again);
        vigen_strbuf_clear(&sb);
    }
    flint_randclear(state);
    TEST_MAIN_END();
}
