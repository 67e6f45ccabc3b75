/* quote.c — Lua string literals (quote.h).  Long brackets rather than
 * backslash escapes keep expressions and nested literals readable in the
 * file; a carriage return, which a long bracket does not keep, and any other
 * control character, which would reach a terminal that shows the file, are
 * escaped instead. */
#include <string.h>

#include "lua/quote.h"
#include "support/strbuf.h"

void vigen_lua_quote(vigen_strbuf *out, const char *text)
{
    int control = 0;
    for (const unsigned char *p = (const unsigned char *)text; *p; p++)
        if ((*p < 32 && *p != '\n') || *p == 127) control = 1;
    if (!control && strpbrk(text, "\"\\\n") == NULL) {
        vigen_strbuf_printf(out, "\"%s\"", text);
        return;
    }
    if (control) {
        /* a long bracket would read \r\n back as \n, and would carry ESC and
         * the like to the terminal as they are: escape instead */
        vigen_strbuf_append(out, "\"");
        for (const char *p = text; *p; p++) {
            unsigned char ch = (unsigned char)*p;
            if (ch == '"' || ch == '\\') vigen_strbuf_printf(out, "\\%c", ch);
            else if (ch < 32 || ch == 127) vigen_strbuf_printf(out, "\\%03d", ch);
            else vigen_strbuf_appendn(out, p, 1);
        }
        vigen_strbuf_append(out, "\"");
        return;
    }
    int level = 0;
    vigen_strbuf close;
    vigen_strbuf_init(&close);
    /* the level whose closing bracket first occurs where it is appended: a
     * text ending in ']' would otherwise close "]]" one character early */
    for (;;) {
        vigen_strbuf_clear(&close);
        vigen_strbuf_append(&close, text);
        size_t at = close.len;
        vigen_strbuf_append(&close, "]");
        for (int i = 0; i < level; i++) vigen_strbuf_append(&close, "=");
        vigen_strbuf_append(&close, "]");
        const char *first = strstr(close.data, close.data + at);
        if (first == close.data + at) break;
        level++;
    }
    vigen_strbuf_clear(&close);
    vigen_strbuf_append(out, "[");
    for (int i = 0; i < level; i++) vigen_strbuf_append(out, "=");
    /* Lua drops a newline right after the opening bracket: double it */
    vigen_strbuf_append(out, text[0] == '\n' ? "[\n" : "[");
    vigen_strbuf_append(out, text);
    vigen_strbuf_append(out, "]");
    for (int i = 0; i < level; i++) vigen_strbuf_append(out, "=");
    vigen_strbuf_append(out, "]");
}
