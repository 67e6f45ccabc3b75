/* show.h — render a tableau as text, LaTeX, JSON or a tableau file. */
#ifndef VIGEN_SHOW_H
#define VIGEN_SHOW_H

#include "vigen/error.h"
#include "vigen/tableau.h"

typedef enum { VIGEN_SHOW_TEXT, VIGEN_SHOW_LATEX, VIGEN_SHOW_JSON, VIGEN_SHOW_LUA } vigen_show_format;

/* *fmt from a format's name ("text", "latex", "json", "lua"): 1, or 0 (*fmt
 * untouched) for any other name. */
int vigen_show_parse_format(vigen_show_format *fmt, const char *name);
/* The format names for a message: "text, latex, json or lua". */
const char *vigen_show_format_names(void);

/* Renders t (evaluated) into a heap string.  Entries written in the file as
 * decimals are printed as they are; exact expressions are printed as certified
 * decimals with `digits` significant digits (raising t's precision as needed). */
int vigen_show_render(char **out, vigen_tableau *t, vigen_show_format fmt, slong digits, vigen_error *err);

/* Display string of every entry: the file's decimal text, or a certified
 * decimal of the exact value.  Re-evaluates t at higher precision when needed. */
int vigen_show_entry_strings(vigen_tableau *t, slong digits, char ***c, char ***A, char ***b, char ***ct,
                             char ***At, char ***bt, vigen_error *err);

#endif
