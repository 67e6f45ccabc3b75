/* tableau_file.h — reading a tableau file: the table it returns, checked
 * entry by entry, into a vigen_tableau (texts only; vigen_tableau_evaluate
 * makes the balls).  The format is described in vigen/tableau.h. */
#ifndef VIGEN_TABLEAU_FILE_H
#define VIGEN_TABLEAU_FILE_H

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

#endif
