/* json.c — the JSON string writer (see json.h). */
#include <string.h>

#include "support/printable.h"
#include "report/json.h"
#include "support/strbuf.h"

void vigen_json_string(vigen_strbuf *sb, const char *text)
{
    vigen_strbuf_append(sb, "\"");
    size_t left = strlen(text);
    for (const unsigned char *p = (const unsigned char *)text; *p;) {
        unsigned long cp = 0;
        int n = vigen_utf8_decode((const char *)p, left, &cp);
        if (n <= 0) {
            vigen_strbuf_append(sb, "\\ufffd");
            p++;
            left--;
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
            /* C0, DEL and C1 escaped: valid JSON either way, but a raw C1 (U+009B,
             * CSI) acts on some terminals */
            if (cp < 0x20 || (cp >= 0x7f && cp <= 0x9f)) vigen_strbuf_printf(sb, "\\u%04lx", cp);
            else vigen_strbuf_appendn(sb, (const char *)p, (size_t)n);
        }
        p += n;
        left -= (size_t)n;
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
