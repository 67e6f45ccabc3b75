/* strbuf.h — growable strings and heap formatting (no fixed-size buffers
 * anywhere in the generator), and the checked allocation behind them and the
 * error records. */
#ifndef VIGEN_SUPPORT_STRBUF_H
#define VIGEN_SUPPORT_STRBUF_H

#include <stdarg.h>
#include <stddef.h>

/* A growable string: data is NUL-terminated (or NULL while empty), len bytes
 * long, in a buffer of cap bytes.  The struct is named so that a public
 * header can take a pointer to it without showing it (vigen/trees.h). */
typedef struct vigen_strbuf { char *data; size_t len, cap; } vigen_strbuf;

/* An empty string (no allocation yet). */
void vigen_strbuf_init(vigen_strbuf *sb);
/* Frees the buffer and leaves sb empty. */
void vigen_strbuf_clear(vigen_strbuf *sb);
/* Appends the NUL-terminated text. */
void vigen_strbuf_append(vigen_strbuf *sb, const char *text);
/* Appends the n bytes at text. */
void vigen_strbuf_appendn(vigen_strbuf *sb, const char *text, size_t n);
/* Appends printf-style text. */
void vigen_strbuf_printf(vigen_strbuf *sb, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* A heap copy of s (free with free); NULL for NULL. */
char *vigen_strdup(const char *s);
/* printf-style formatting into a fresh heap string (free with free). */
char *vigen_strdup_printf(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;
/* vsnprintf into a fresh heap string (free with free). */
char *vigen_vstrdup_printf(const char *fmt, va_list ap);

/* realloc that never returns NULL: out of memory prints a line and aborts. */
void *vigen_xrealloc(void *p, size_t n);

#endif
