/* method.h — where tableaux come from: a method file, run once in the Lua
 * sandbox and recognised by its fields (the kinds are the rows of
 * src/method/methods.def): a spec run through the generator, or a tableau
 * file read as it is.  Used by generate, show, check and emit, which all
 * accept either kind of file. */
#ifndef VIGEN_METHOD_H
#define VIGEN_METHOD_H

#include "vigen/error.h"
#include "vigen/tableau.h"

/* vigen_method_load, vigen_method_tableau and vigen_method_free in one call:
 * the tableau of the file at path (t uninitialised on entry; initialised on
 * success), the file run once. */
int vigen_source_load(vigen_tableau *t, const char *path, slong digits, vigen_error *err);

/* A method file, run once: a spec (its tableau is generated at the digits
 * asked for) or a tableau file (read as it is).  A file of neither kind is
 * refused with one message naming the file and the fields of each kind.  Every command that takes a
 * FILE loads it with vigen_method_load and asks for tableaux with
 * vigen_method_tableau, as often as it needs, without running the file again. */
typedef struct vigen_method vigen_method;

/* Runs the file at path once in a sandbox with these caps and reads it as
 * the kind of method it is; *out is NULL after a failure, whose message
 * names the file. */
int vigen_method_load(vigen_method **out, const char *path, const vigen_sandbox_limits *limits /* NULL: defaults */,
                      vigen_error *err);
/* Frees a loaded method (NULL: nothing). */
void vigen_method_free(vigen_method *m);
/* 1 when the tableau is computed from the file at the digits asked for (a
 * spec), 0 when the file states it (a tableau file). */
int vigen_method_is_generated(const vigen_method *m);
/* The tableau (t uninitialised on entry, initialised on success): generated
 * with `digits` certified digits, or read from the tableau file and evaluated
 * at a precision adequate for `digits` digits.  digits <= 0 asks for a
 * tableau file's tableau as stated (entry texts, balls not evaluated, prec 0;
 * an emitter evaluating the texts itself wants this); a spec refuses it
 * with VIGEN_E_USAGE. */
int vigen_method_tableau(vigen_tableau *t, vigen_method *m, slong digits, vigen_error *err);

/* Where a composition file's base named by a bare name (not a file beside
 * it) is looked up: the command line sets vigen_library_resolve
 * (vigen/library.h).  NULL (the default): files only. */
typedef int (*vigen_name_resolver_fn)(char **path, const char *name, vigen_error *err);
void vigen_method_set_name_resolver(vigen_name_resolver_fn fn);

/* What method files may contain, from the tables of the code: the kinds of
 * method file, the node and basis families, the functions and constants of
 * exact expressions, each with one line of description (`vigen help spec`).
 * A heap string; free with free(). */
char *vigen_method_vocabulary_text(void);

#endif
