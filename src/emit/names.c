/* names.c — the emitted symbol prefix (C keywords from c_keywords.def), the
 * file's texts made safe for comments and string literals, and the digest
 * of the canonical tableau text that the header records. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "vigen/emit.h"
#include "emit/names.h"
#include "support/strbuf.h"

static const char *const c_keywords[] = {
#define X(word) #word,
#include "emit/c_keywords.def"
#undef X
    NULL
};

static int is_c_keyword(const char *s)
{
    for (int k = 0; c_keywords[k]; k++)
        if (strcmp(s, c_keywords[k]) == 0) return 1;
    return 0;
}

char *vigen_emit_identifier(const char *name)
{
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    if (name[0] == '\0' || !((name[0] >= 'A' && name[0] <= 'Z') || (name[0] >= 'a' && name[0] <= 'z')))
        vigen_strbuf_append(&sb, "m_");
    for (const char *c = name; *c; c++) {
        char ch = *c;
        int ok = (ch >= 'A' && ch <= 'Z') || (ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9') || ch == '_';
        vigen_strbuf_appendn(&sb, ok ? &ch : "_", 1);
    }
    if (is_c_keyword(sb.data)) vigen_strbuf_append(&sb, "_");
    return sb.data;
}

char *vigen_emit_safe_text(const char *s, size_t maxlen)
{
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    vigen_strbuf_append(&sb, "");
    char prev = 0;
    size_t n = 0;
    for (const unsigned char *c = (const unsigned char *)s; *c && n < maxlen; c++, n++) {
        char ch = (*c >= 0x20 && *c <= 0x7e) ? (char)*c : '_';
        if (ch == '\\') ch = '/';
        if (ch == '"') ch = '\'';
        if ((prev == '*' && ch == '/') || (prev == '/' && ch == '*') || (prev == '?' && ch == '?'))
            vigen_strbuf_append(&sb, " ");
        vigen_strbuf_appendn(&sb, &ch, 1);
        prev = ch;
    }
    if (*s && n >= maxlen && strlen(s) > maxlen) vigen_strbuf_append(&sb, " ...");
    return sb.data;
}

char *vigen_emit_safe_name(const char *s)
{
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    vigen_strbuf_append(&sb, "");
    for (const char *c = s; *c && sb.len < 100; c++) {
        char ch = *c;
        int ok = (ch >= 'A' && ch <= 'Z') || (ch >= 'a' && ch <= 'z') || (ch >= '0' && ch <= '9') || ch == '_' ||
                 ch == '.' || ch == '+' || ch == '-';
        vigen_strbuf_appendn(&sb, ok ? &ch : "_", 1);
    }
    return sb.data;
}

static void digest_add(unsigned long long *h, const char *text)
{
    for (const unsigned char *c = (const unsigned char *)text; *c; c++) {
        *h ^= *c;
        *h *= 1099511628211ULL;
    }
    *h ^= (unsigned char)'\n';
    *h *= 1099511628211ULL;
}

static void digest_texts(unsigned long long *h, char **texts, slong n)
{
    if (texts == NULL) { digest_add(h, "-"); return; }
    for (slong k = 0; k < n; k++) digest_add(h, texts[k]);
}

unsigned long long vigen_emit_digest(const vigen_tableau *t)
{
    unsigned long long h = 14695981039346656037ULL;
    char num[32];
    digest_add(&h, "vigen-tableau-v1");
    digest_add(&h, t->name ? t->name : "");
    snprintf(num, sizeof num, "%ld", (long)t->s);
    digest_add(&h, num);
    digest_texts(&h, t->c_text, t->s);
    digest_texts(&h, t->A_text, t->s * t->s);
    digest_texts(&h, t->b_text, t->s);
    digest_texts(&h, t->At_text, t->s * t->s);
    digest_texts(&h, t->ct_text, t->s);
    digest_texts(&h, t->bt_text, t->s);
    return h;
}

void vigen_emit_header_about(vigen_slot *H, const vigen_tableau *t)
{
    if (t->description) {
        char *d = vigen_emit_safe_text(t->description, 300);
        vigen_slot_line(H, "Description: %s", d);
        free(d);
    }
    if (t->source) {
        char *d = vigen_emit_safe_text(t->source, 300);
        vigen_slot_line(H, "Source: %s", d);
        free(d);
    }
    vigen_slot_line(H, "Do not edit: regenerate with vigen emit.");
}
