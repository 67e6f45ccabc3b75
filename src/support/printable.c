/* printable.c — untrusted text escaped for terminals (support/printable.h). */
#include <stdlib.h>
#include <string.h>
#include "support/printable.h"
#include "support/strbuf.h"

int vigen_utf8_decode(const char *text, size_t left, unsigned long *cp)
{
    const unsigned char *p = (const unsigned char *)text;
    if (left == 0) return 0;
    unsigned char c = p[0];
    int n;
    unsigned char lo = 0x80, hi = 0xBF;   /* range of the second byte (Unicode table 3-7) */
    unsigned long v;
    if (c < 0x80) {
        *cp = c;
        return 1;
    }
    if (c >= 0xC2 && c <= 0xDF) n = 2, v = c & 0x1F;
    else if (c >= 0xE0 && c <= 0xEF) {
        n = 3, v = c & 0x0F;
        if (c == 0xE0) lo = 0xA0;          /* overlong */
        if (c == 0xED) hi = 0x9F;          /* surrogates */
    } else if (c >= 0xF0 && c <= 0xF4) {
        n = 4, v = c & 0x07;
        if (c == 0xF0) lo = 0x90;          /* overlong */
        if (c == 0xF4) hi = 0x8F;          /* above U+10FFFF */
    } else return 0;                       /* continuation byte, C0, C1, F5..FF */
    if ((size_t)n > left || p[1] < lo || p[1] > hi) return 0;
    for (int k = 1; k < n; k++) {
        if ((p[k] & 0xC0) != 0x80) return 0;
        v = (v << 6) | (p[k] & 0x3F);
    }
    *cp = v;
    return n;
}

/* Code points shown escaped although well-formed: C1 controls, the line and
 * paragraph separators, the bidirectional formatting characters. */
static int hidden(unsigned long cp)
{
    return (cp >= 0x80 && cp <= 0x9F) || cp == 0x061C || cp == 0x200E || cp == 0x200F ||
           (cp >= 0x2028 && cp <= 0x202E) || (cp >= 0x2066 && cp <= 0x2069);
}

/* Writes the escape of one byte (width 2) or code point (width 4), \xHH or
 * \uHHHH, into out; returns its length.  Written by hand: this runs for every
 * byte a file prints, and printf per byte made printing long strings slow. */
static size_t hex_escape(char *out, char kind, unsigned long value, int width)
{
    static const char digits[] = "0123456789abcdef";
    out[0] = '\\';
    out[1] = kind;
    for (int k = 0; k < width; k++) out[2 + k] = digits[(value >> (4 * (width - 1 - k))) & 0xF];
    return (size_t)width + 2;
}

void vigen_printable_append(vigen_strbuf *sb, const char *text, size_t len)
{
    vigen_strbuf_append(sb, "");
    size_t i = 0, run = 0;   /* text[run, i) is shown as it is */
    while (i < len) {
        unsigned long cp;
        int n = vigen_utf8_decode(text + i, len - i, &cp);
        unsigned char c = (unsigned char)text[i];
        char esc[8];
        size_t esc_len = 0;
        if (n == 0) esc_len = hex_escape(esc, 'x', c, 2), n = 1;
        else if (c == '\0') esc_len = 2, memcpy(esc, "\\0", 2);
        else if (c == '\n') esc_len = 2, memcpy(esc, "\\n", 2);
        else if (c == '\r') esc_len = 2, memcpy(esc, "\\r", 2);
        else if (c == '\t') esc_len = 2, memcpy(esc, "\\t", 2);
        else if (c < 0x20 || c == 0x7F) esc_len = hex_escape(esc, 'x', c, 2);
        else if (hidden(cp)) esc_len = hex_escape(esc, 'u', cp, 4);
        if (esc_len > 0) {
            vigen_strbuf_appendn(sb, text + run, i - run);
            vigen_strbuf_appendn(sb, esc, esc_len);
            run = i + (size_t)n;
        }
        i += (size_t)n;
    }
    vigen_strbuf_appendn(sb, text + run, len - run);
}

char *vigen_printable(const char *text)
{
    if (text == NULL) return NULL;
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    vigen_printable_append(&sb, text, strlen(text));
    return sb.data;
}
