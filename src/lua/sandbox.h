/* sandbox.h — a Lua 5.4 state for untrusted spec and tableau files.
 *
 * vigen_sandbox_new is where every Lua state of vigen is made, so that every
 * file runs with the same libraries and caps.
 *
 * Spec and tableau files are code written by someone else.  The sandbox opens
 * only the base, math, string and table libraries, removes dofile, loadfile,
 * load, require, collectgarbage, string.dump and the io/os/package/debug
 * libraries, loads source text only (never precompiled chunks), caps memory
 * with a custom allocator and caps executed instructions with a count hook.
 * Exceeding a cap raises a Lua error whose message says which cap and how to
 * raise it; the error cannot be caught (pcall and xpcall rethrow it, and the
 * rest of the call raises at once).  Work done in C is charged to the
 * instruction budget: bytes allocated, and the counts that library loops
 * (table.move/sort/concat/unpack/insert/remove, string.byte, select,
 * tonumber) are about to go through.  What would run outside the instruction
 * cap is refused: __gc finalisers (setmetatable with a __gc field), the
 * pattern functions string.find/match/gmatch/gsub and
 * string.pack/unpack/packsize.  print writes to stderr.  Reading an unknown
 * global is an error listing the vocabulary and the functions.
 *
 * The sandbox provides the ball library (see ball.h) that Lua basis functions
 * compute with.  What a kind of file may name beyond that is its vocabulary,
 * given by the layer that reads such files (the method layer's is the node and
 * basis family constructors such as gauss_legendre(3) and trig(5)).
 */
#ifndef VIGEN_SANDBOX_H
#define VIGEN_SANDBOX_H

#include <stddef.h>
#include <lua.h>
#include "vigen/error.h"
#include "vigen/limits.h"

typedef struct vigen_sandbox vigen_sandbox;

/* A fresh state with these limits (NULL: defaults).  vocabulary (may be
 * NULL) runs once while the state is set up, before its globals become
 * strict: it sets the globals of the vocabulary and returns one string, what
 * the unknown-name message lists before the functions, e.g.
 *   spec.lua:4: unknown name 'gauss' (node families: gauss_legendre, ...; functions: sqrt, ...) */
int vigen_sandbox_new(vigen_sandbox **out, const vigen_sandbox_limits *limits, lua_CFunction vocabulary,
                      vigen_error *err);
void vigen_sandbox_free(vigen_sandbox *sb);
lua_State *vigen_sandbox_state(vigen_sandbox *sb);

/* After the file has run: no memory cap any more, so that C code reading its
 * result (raw accesses, outside protected calls) cannot hit a Lua error. */
void vigen_sandbox_lift_memory_cap(vigen_sandbox *sb);

/* Reads path, runs it as a text chunk named "@path" and leaves its single
 * return value on the stack.  Errors carry file:line: VIGEN_E_IO (unreadable),
 * VIGEN_E_SYNTAX (Lua syntax error), VIGEN_E_LUA (runtime error), VIGEN_E_LIMIT
 * (memory or instruction cap), VIGEN_E_SPEC (the chunk returned nothing). */
int vigen_sandbox_run_file(vigen_sandbox *sb, const char *path, vigen_error *err);

/* Like vigen_sandbox_run_file but for a string (tests); chunkname as given. */
int vigen_sandbox_run_string(vigen_sandbox *sb, const char *text, const char *chunkname, vigen_error *err);

/* lua_pcall with the instruction budget reset and errors translated as above.
 * The function and its nargs arguments are on the stack. */
int vigen_sandbox_pcall(vigen_sandbox *sb, int nargs, int nresults, vigen_error *err);

#endif
