/* printable.h — the library side of vigen/printable.h: the UTF-8 decoder
 * behind it, and the one refusal of strings holding NUL bytes. */
#ifndef VIGEN_CORE_PRINTABLE_H
#define VIGEN_CORE_PRINTABLE_H

#include <stddef.h>
#include "vigen/printable.h"

/* Length (1 to 4) of the well-formed UTF-8 sequence (RFC 3629: no overlong
 * form, no surrogate, nothing above U+10FFFF) starting at p, of which at most
 * left bytes may be read; 0 when the byte at p starts none.  Sets *cp to its
 * code point when it returns > 0. */
int vigen_utf8_decode(const char *p, size_t left, unsigned long *cp);

/* VIGEN_OK when the len bytes at text hold no NUL byte; otherwise records
 * VIGEN_E_SPEC with "PATH: ENTRY contains a NUL byte (\0 at byte K); remove
 * it" (K counted from 1) and returns it.  Strings read from files go through
 * this before they are used as C strings, which would end at the NUL. */
int vigen_refuse_nul(const char *text, size_t len, const char *path, const char *entry, vigen_error *err);

#endif
