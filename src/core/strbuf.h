/* strbuf.h — the allocation helpers behind vigen_strbuf and the error
 * records (strbuf.c), shared by src/core only; the public string functions
 * are declared in vigen/error.h. */
#ifndef VIGEN_CORE_STRBUF_H
#define VIGEN_CORE_STRBUF_H

#include <stdarg.h>
#include <stddef.h>

/* realloc that never returns NULL: out of memory prints a line and aborts. */
void *vigen_xrealloc(void *p, size_t n);
/* vsnprintf into a fresh heap string (free with free). */
char *vigen_vstrdup_printf(const char *fmt, va_list ap);

#endif
