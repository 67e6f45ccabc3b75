/* printable.h — text from untrusted files made safe to show on a terminal.
 *
 * Names, descriptions, entries and Lua error messages come from spec and
 * tableau files, which may hold any bytes.  Before such text reaches a
 * terminal (messages on stderr, the text reports on stdout) it goes through
 * vigen_printable: well-formed printable UTF-8 (RFC 3629) is kept as it is;
 * control characters become C-style escapes (\n, \r, \t, and \xNN for the
 * other C0 controls and DEL: ESC is \x1b); the C1 controls U+0080..U+009F,
 * the line and paragraph separators U+2028, U+2029 and the bidirectional
 * formatting characters (U+061C, U+200E, U+200F, U+202A..U+202E,
 * U+2066..U+2069, which reorder what a terminal shows) become \uNNNN; every
 * byte that does not start a well-formed UTF-8 sequence becomes \xNN.  A
 * backslash is kept, so that escaping is idempotent (a message escaped twice
 * reads the same); the result is for display, not meant to be read back.
 */
#ifndef VIGEN_SUPPORT_PRINTABLE_H
#define VIGEN_SUPPORT_PRINTABLE_H

#include <stddef.h>
#include "support/strbuf.h"

/* The escaped copy of text (heap, free with free); NULL for NULL. */
char *vigen_printable(const char *text);

/* Appends the escaped form of the len bytes at text to sb; a NUL byte among
 * them is written \0. */
void vigen_printable_append(vigen_strbuf *sb, const char *text, size_t len);

/* Length (1 to 4) of the well-formed UTF-8 sequence (RFC 3629: no overlong
 * form, no surrogate, nothing above U+10FFFF) starting at p, of which at most
 * left bytes may be read; 0 when the byte at p starts none.  Sets *cp to its
 * code point when it returns > 0. */
int vigen_utf8_decode(const char *p, size_t left, unsigned long *cp);

#endif
