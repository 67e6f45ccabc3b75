/* tableau_file.h — reading a tableau file: the table it returns, checked
 * entry by entry, into a vigen_tableau (texts only; vigen_tableau_evaluate
 * makes the balls).  The format is described in vigen/tableau.h. */
#ifndef VIGEN_METHOD_TABLEAU_FILE_H
#define VIGEN_METHOD_TABLEAU_FILE_H

#include <lua.h>
#include "lua/sandbox.h"
#include "vigen/tableau.h"

/* 1 if the value at idx looks like a tableau (a table with s or A), else 0.
 * Raw reads; never raises a Lua error once two stack slots are free. */
int vigen_tableau_file_detect(lua_State *L, int idx);

/* Reads the tableau that the file at path returned, the value on top of sb's
 * stack (vigen_sandbox_run_file), into t (uninitialised on entry; initialised
 * on success).  Messages name the file and the entry ("gauss2.lua:
 * A[2][1]: ..."): missing fields, unknown fields, wrong sizes, Lua floats,
 * strings holding a NUL byte, unparsable expressions.  No Lua code of the file runs any more: the memory cap of sb
 * is lifted and sb stays with the caller. */
int vigen_tableau_from_table(vigen_tableau *t, vigen_sandbox *sb, const char *path, vigen_error *err);

/* Shared with the readers of other kinds of method file (splitting and
 * composition files, src/method/splitting_file.c): */

/* The entry on top of the Lua stack (a string: an exact expression or a
 * decimal; or a small Lua integer) into *out, a fresh string; messages name
 * the file and the label. */
int vigen_table_read_entry(lua_State *L, char **out, const char *path, const char *label, vigen_error *err);

/* Refuses a field of the table on top of the stack that is not in the
 * NULL-terminated list known (a typo), with a did-you-mean hint. */
int vigen_table_check_fields(lua_State *L, const char *const *known, const char *path, vigen_error *err);

/* name (required), source, description and the claims order, symplectic
 * (and digits) of the table on top of the stack into t. */
int vigen_table_read_info(vigen_tableau *t, lua_State *L, const char *path, vigen_error *err);

#endif
