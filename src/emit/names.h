/* names.h — what the emitter writes of the user's and the file's words: the
 * symbol prefix (vigen_emit_identifier, in <vigen/emit.h>), texts made safe
 * for comments and string literals, the tableau digest, and the lines of the
 * header that describe the method. */
#ifndef VIGEN_EMIT_NAMES_H
#define VIGEN_EMIT_NAMES_H

#include <stddef.h>
#include "vigen/tableau.h"
#include "emit/template.h"

/* Printable ASCII safe inside a C comment and a C string literal: no comment
 * opener or closer, no trigraph, no backslash, no double quote; at most
 * maxlen characters (then " ..."). */
char *vigen_emit_safe_text(const char *s, size_t maxlen);

/* A tableau name for a string literal: [A-Za-z0-9_.+-] only, at most 100. */
char *vigen_emit_safe_name(const char *s);

/* FNV-1a 64 of the canonical tableau text (see emit.h). */
unsigned long long vigen_emit_digest(const vigen_tableau *t);

/* The last lines of an emitted file's header: the method's description and
 * source (made safe) and "Do not edit". */
void vigen_emit_header_about(vigen_slot *H, const vigen_tableau *t);

#endif
