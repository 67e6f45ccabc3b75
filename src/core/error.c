/* error.c — error records, warnings and growable strings. */
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include "vigen/error.h"

static void *xrealloc(void *p, size_t n)
{
    void *q = realloc(p, n ? n : 1);
    if (q == NULL) {
        fputs("vigen: out of memory\n", stderr);
        abort();
    }
    return q;
}

static char *vformat(const char *fmt, va_list ap)
{
    va_list aq;
    va_copy(aq, ap);
    int n = vsnprintf(NULL, 0, fmt, aq);
    va_end(aq);
    if (n < 0) n = 0;
    char *s = xrealloc(NULL, (size_t)n + 1);
    vsnprintf(s, (size_t)n + 1, fmt, ap);
    return s;
}

void vigen_error_init(vigen_error *err) { err->code = VIGEN_OK; err->message = NULL; }

void vigen_error_clear(vigen_error *err)
{
    free(err->message);
    err->message = NULL;
    err->code = VIGEN_OK;
}

int vigen_error_setv(vigen_error *err, int code, const char *fmt, va_list ap)
{
    if (err == NULL) return code;
    char *msg = vformat(fmt, ap);
    free(err->message);
    err->message = msg;
    err->code = code;
    return code;
}

int vigen_error_set(vigen_error *err, int code, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vigen_error_setv(err, code, fmt, ap);
    va_end(ap);
    return code;
}

int vigen_error_prefix(vigen_error *err, const char *fmt, ...)
{
    if (err == NULL) return VIGEN_OK;
    va_list ap;
    va_start(ap, fmt);
    char *pre = vformat(fmt, ap);
    va_end(ap);
    const char *old = err->message ? err->message : "";
    char *msg = xrealloc(NULL, strlen(pre) + strlen(old) + 1);
    strcpy(msg, pre);
    strcat(msg, old);
    free(pre);
    free(err->message);
    err->message = msg;
    return err->code;
}

static const struct { const char *words; int exit_status; } status_table[] = {
#define X(name, exit_status, words) { words, exit_status },
#include "vigen/status.def"
#undef X
};

const char *vigen_status_name(int code)
{
    if (code < 0 || code >= VIGEN_STATUS_COUNT) return "unknown status";
    return status_table[code].words;
}

int vigen_status_exit_code(int code)
{
    if (code < 0 || code >= VIGEN_STATUS_COUNT) return 3;
    return status_table[code].exit_status;
}

static vigen_warning_fn warning_fn = NULL;
static void *warning_ctx = NULL;

void vigen_warning_set_handler(vigen_warning_fn fn, void *ctx)
{
    warning_fn = fn;
    warning_ctx = ctx;
}

void vigen_warn(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    char *msg = vformat(fmt, ap);
    va_end(ap);
    if (warning_fn) warning_fn(msg, warning_ctx);
    else fprintf(stderr, "vigen: warning: %s\n", msg);
    free(msg);
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
        sb->data = xrealloc(sb->data, cap);
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
    char *s = vformat(fmt, ap);
    va_end(ap);
    vigen_strbuf_append(sb, s);
    free(s);
}

char *vigen_strdup(const char *s)
{
    if (s == NULL) return NULL;
    size_t n = strlen(s) + 1;
    char *d = xrealloc(NULL, n);
    memcpy(d, s, n);
    return d;
}

char *vigen_strdup_printf(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    char *s = vformat(fmt, ap);
    va_end(ap);
    return s;
}

static size_t edit_distance(const char *a, const char *b)
{
    size_t na = strlen(a), nb = strlen(b);
    size_t *row = calloc(nb + 1, sizeof *row);
    if (row == NULL) return (size_t)-1;
    for (size_t j = 0; j <= nb; j++) row[j] = j;
    for (size_t i = 1; i <= na; i++) {
        size_t diag = row[0];
        row[0] = i;
        for (size_t j = 1; j <= nb; j++) {
            size_t up = row[j];
            size_t best = diag + (a[i - 1] != b[j - 1]);
            if (up + 1 < best) best = up + 1;
            if (row[j - 1] + 1 < best) best = row[j - 1] + 1;
            row[j] = best;
            diag = up;
        }
    }
    size_t d = row[nb];
    free(row);
    return d;
}

const char *vigen_nearest_name(const char *key, const char *const *names, size_t max_edits)
{
    const char *near = NULL;
    size_t nearest = max_edits + 1;
    /* a different case is the likeliest typo ("AT" for "At", not "A") */
    for (int i = 0; names[i]; i++)
        if (strcasecmp(key, names[i]) == 0) return names[i];
    for (int i = 0; names[i]; i++) {
        size_t d = edit_distance(key, names[i]);
        if (d < nearest && d < strlen(key)) {
            nearest = d;
            near = names[i];
        }
    }
    return near;
}
