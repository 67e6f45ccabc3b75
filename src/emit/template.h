/* template.h — the small template mechanism `vigen emit` renders C with.
 *
 * A template is ordinary, readable C (templates/NAME.in) with two kinds of
 * marks:
 *
 *   //$ <Lua statement>     a whole line (leading blanks allowed) of Lua code:
 *                           loops and conditionals over the data, e.g.
 *                               //$ for i = 1, s do
 *                               ...C lines repeated per stage...
 *                               //$ end
 *                           The line itself produces no output.
 *   ${<Lua expression>}     a slot inside a C line, replaced by the value of
 *                           the expression: a string, or a Lua integer.  Lua
 *                           floats, booleans and nil are refused (a float's
 *                           text is not a reproducible literal: coefficients
 *                           arrive as strings).  The expression may contain
 *                           braces only when they balance.
 *
 * Every other line is copied with its newline.  The names visible in a
 * template are the fields of the data table, then the standard Lua functions
 * of the base, string, table and math libraries (no io, os, load, require);
 * reading any other global is an error, which catches typos.  Error messages
 * carry the template's file name and line.
 *
 * The data table comes as Lua source text ("return { s = 2, NAME = 'x', ... }")
 * that the emitter writes with vigen_template_quote for every string, so the
 * data can never be read as code.  Rendering is deterministic: the template
 * sees only the data, and iteration order is the template's own business
 * (templates use numeric loops or ipairs, never pairs).
 */
#ifndef VIGEN_TEMPLATE_H
#define VIGEN_TEMPLATE_H

#include <stddef.h>
#include "vigen/error.h"

/* Renders template text (named `chunkname` in messages, e.g. "stepper.c.in")
 * with the data table returned by the Lua chunk `data_lua`.  On success *out
 * is a heap string (free with free()).  Errors: VIGEN_E_SYNTAX (template or
 * data is not valid Lua), VIGEN_E_LUA (a slot or statement failed at run
 * time), VIGEN_E_MEMORY. */
int vigen_template_render(char **out, const char *template_text, const char *chunkname,
                          const char *data_lua, vigen_error *err);

/* Like vigen_template_render but reads the template from path. */
int vigen_template_render_file(char **out, const char *path, const char *data_lua, vigen_error *err);

/* Appends text to sb as a Lua string literal that reads back as exactly text
 * (every byte outside printable ASCII, and quote and backslash, escaped). */
void vigen_template_quote(vigen_strbuf *sb, const char *text);

/* The directory holding the stepper templates: $VIGEN_TEMPLATE_DIR when set,
 * else VIGEN_TEMPLATE_DIR if defined at build time, else
 * VIGEN_SOURCE_DIR "/templates".  Returns a static string. */
const char *vigen_template_dir(void);

#endif
