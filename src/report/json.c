/* json.c — the JSON string writer (see json.h). */
#include "report/json.h"

/* Length of the well-formed UTF-8 sequence at p (RFC 3629, table 3-7 of
 * Unicode), or 0 when the byte at p does not start one. */
static int utf8_length(const unsigned char *p)
{
    unsigned char c = p[0];
    int n;
    unsigned char lo = 0x80, hi = 0xBF;   /* range of the second byte */
    if (c < 0x80) return 1;
    if (c >= 0xC2 && c <= 0xDF) n = 2;
    else if (c >= 0xE0 && c <= 0xEF) {
        n = 3;
        if (c == 0xE0) lo = 0xA0;          /* overlong */
        if (c == 0xED) hi = 0x9F;          /* surrogates */
    } else if (c >= 0xF0 && c <= 0xF4) {
        n = 4;
        if (c == 0xF0) lo = 0x90;          /* overlong */
        if (c == 0xF4) hi = 0x8F;          /* above U+10FFFF */
    } else return 0;                       /* continuation byte, C0, C1, F5..FF */
    if (p[1] < lo || p[1] > hi) return 0;
    for (int k = 2; k < n; k++)
        if ((p[k] & 0xC0) != 0x80) return 0;
    return n;
}

void vigen_json_string(vigen_strbuf *sb, const char *text)
{
    vigen_strbuf_append(sb, "\"");
    for (const unsigned char *p = (const unsigned char *)text; *p;) {
        int n = utf8_length(p);
        if (n == 0) {
            vigen_strbuf_append(sb, "\\ufffd");
            p++;
            continue;
        }
        switch (*p) {
        case '"': vigen_strbuf_append(sb, "\\\""); break;
        case '\\': vigen_strbuf_append(sb, "\\\\"); break;
        case '\b': vigen_strbuf_append(sb, "\\b"); break;
        case '\f': vigen_strbuf_append(sb, "\\f"); break;
        case '\n': vigen_strbuf_append(sb, "\\n"); break;
        case '\r': vigen_strbuf_append(sb, "\\r"); break;
        case '\t': vigen_strbuf_append(sb, "\\t"); break;
        default:
            if (*p < 0x20) vigen_strbuf_printf(sb, "\\u%04x", (unsigned)*p);
            else vigen_strbuf_appendn(sb, (const char *)p, (size_t)n);
        }
        p += n;
    }
    vigen_strbuf_append(sb, "\"");
}

void vigen_json_write_string(FILE *out, const char *text)
{
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    vigen_json_string(&sb, text);
    if (sb.data) fwrite(sb.data, 1, sb.len, out);
    vigen_strbuf_clear(&sb);
}
