/* vocabulary.h — what a method file (spec or tableau file) may name beyond
 * the generic sandbox: the node and basis family constructors, one per row of
 * nodes.def and basis.def (gauss_legendre(3), trig(5), ...), and the values
 * they make, family descriptors.  Every method file runs in a sandbox with
 * this vocabulary (vigen_vocabulary_run_file), so spec and tableau files see
 * the same globals.
 */
#ifndef VIGEN_VOCABULARY_H
#define VIGEN_VOCABULARY_H

#include <lua.h>
#include "vigen/error.h"
#include "vigen/limits.h"
#include "lua/sandbox.h"

/* The vocabulary argument of vigen_sandbox_new: sets the family
 * constructors as globals and returns the text the unknown-name message
 * lists ("node families: gauss_legendre, ...; basis families: monomials, ..."). */
int vigen_vocabulary_open(lua_State *L);

/* A fresh sandbox with this vocabulary and these limits (NULL: defaults),
 * the file at path run once in it (vigen_sandbox_run_file): on success *sb
 * holds the sandbox with the file's value on top; on failure *sb is NULL. */
int vigen_vocabulary_run_file(vigen_sandbox **sb, const char *path, const vigen_sandbox_limits *limits,
                              vigen_error *err);

/* Family descriptors, the values of gauss_legendre(3), trig(5), ...  If the
 * value at idx is one, sets *kind, *family (a static name) and *s (each may be
 * NULL) and returns 1; otherwise returns 0.  Never raises a Lua error. */
enum { VIGEN_FAMILY_NODES = 1, VIGEN_FAMILY_BASIS = 2 };
int vigen_vocabulary_get_family(lua_State *L, int idx, int *kind, const char **family, long *s);

#endif
