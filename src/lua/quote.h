/* quote.h — Lua string literals for text that vigen writes as Lua: the
 * entries and metadata of tableau files, and the nodes/basis descriptions a
 * spec leaves in them. */
#ifndef VIGEN_QUOTE_H
#define VIGEN_QUOTE_H

#include "vigen/error.h"
#include "support/strbuf.h"

/* Appends text as a Lua string literal that reads back as exactly text:
 * "..." when that needs no escape, otherwise a long bracket [==[...]==] whose
 * level the text does not contain (or, for text with a carriage return,
 * "..." with escapes). */
void vigen_lua_quote(vigen_strbuf *out, const char *text);

#endif
