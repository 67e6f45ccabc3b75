/* strbuf.c — growable strings and heap-allocated formatting: vigen_strbuf,
 * vigen_strdup, vigen_strdup_printf, and the checked allocation they share
 * with error.c. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "vigen/error.h"
#include "support/strbuf.h"

void *vigen_xrealloc(void *p, size_t n)
{
    void *q = realloc(p, n ? n : 1);
    if (q == NULL) {
        fputs("vigen: out of memory\n", stderr);
        abort();
    }
    return q;
}

char *vigen_vstrdup_printf(const char *fmt, va_list ap)
{
    va_list aq;
    va_copy(aq, ap);
    int n = vsnprintf(NULL, 0, fmt, aq);
    va_end(aq);
    if (n < 0) n = 0;
    char *s = vigen_xrealloc(NULL, (size_t)n + 1);
    vsnprintf(s, (size_t)n + 1, fmt, ap);
    return s;
}

void vigen_strbuf_init(vigen_strbuf *sb) { sb->data = NULL; sb->len = sb->cap = 0; }

void vigen_strbuf_clear(vigen_strbuf *sb)
{
    free(sb->data);
    vigen_strbuf_init(sb);
}

void vigen_strbuf_appendn(vigen_strbuf *sb, const char *text, size_t n)
{
    if (sb->len + n + 1 > sb->cap) {
        size_t cap = sb->cap ? sb->cap : 64;
        while (cap < sb->len + n + 1) cap *= 2;
        sb->data = vigen_xrealloc(sb->data, cap);
        sb->cap = cap;
    }
    memcpy(sb->data + sb->len, text, n);
    sb->len += n;
    sb->data[sb->len] = '\0';
}

void vigen_strbuf_append(vigen_strbuf *sb, const char *text) { vigen_strbuf_appendn(sb, text, strlen(text)); }

void vigen_strbuf_printf(vigen_strbuf *sb, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    char *s = vigen_vstrdup_printf(fmt, ap);
    va_end(ap);
    vigen_strbuf_append(sb, s);
    free(s);
}

char *vigen_strdup(const char *s)
{
    if (s == NULL) return NULL;
    size_t n = strlen(s) + 1;
    char *d = vigen_xrealloc(NULL, n);
    memcpy(d, s, n);
    return d;
}

char *vigen_strdup_printf(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    char *s = vigen_vstrdup_printf(fmt, ap);
    va_end(ap);
    return s;
}

