/* sandbox.h — a Lua 5.4 state for untrusted spec and tableau files.
 *
 * Spec and tableau files are code written by someone else.  The sandbox opens
 * only the base, math, string and table libraries, removes dofile, loadfile,
 * load, require, collectgarbage and the io/os/package/debug libraries, loads
 * source text only (never precompiled chunks), caps memory with a custom
 * allocator and caps executed instructions with a count hook.  Exceeding a cap
 * raises a Lua error whose message says which cap and how to raise it.
 *
 * The sandbox also provides the vocabulary of spec files (node and basis family
 * constructors such as gauss_legendre(3) and trig(5)) and the ball library
 * (see ball.h) that Lua basis functions compute with.
 */
#ifndef VIGEN_SANDBOX_H
#define VIGEN_SANDBOX_H

#include <stddef.h>
#include <lua.h>
#include "error.h"

typedef struct vigen_sandbox vigen_sandbox;

typedef struct {
    size_t memory_limit;      /* bytes; default 256 MiB */
    long instruction_limit;   /* VM instructions per top-level call; default 50 million */
} vigen_sandbox_limits;

void vigen_sandbox_limits_default(vigen_sandbox_limits *limits);

int vigen_sandbox_new(vigen_sandbox **out, const vigen_sandbox_limits *limits /* NULL: defaults */,
                      vigen_error *err);
void vigen_sandbox_free(vigen_sandbox *sb);
lua_State *vigen_sandbox_state(vigen_sandbox *sb);

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
