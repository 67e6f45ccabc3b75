/* sandbox_caps.h — the sandbox struct and its caps (sandbox_caps.c): what
 * the sandbox's state (sandbox.c) and the capped library functions
 * (sandbox_libs.c) share.  Internal to src/lua. */
#ifndef VIGEN_LUA_SANDBOX_CAPS_H
#define VIGEN_LUA_SANDBOX_CAPS_H

#include <stddef.h>
#include <lua.h>

#include "lua/sandbox.h"

/* Work that the VM does in one instruction or that C library functions do
 * (copying a long string for `..`, string.rep, table.concat, growing a table)
 * allocates: every BYTES_PER_INSTRUCTION bytes allocated cost one instruction
 * of the budget, so that a loop of cheap-looking instructions over huge
 * strings ends under the instruction cap even though memory is freed as it
 * goes.  (Allocating, filling and collecting 32 bytes of fresh memory takes
 * about as long as one VM instruction.) */

#define BYTES_PER_INSTRUCTION 32

/* print escapes every byte (UTF-8 decoding, a table of escapes) and writes
 * it: about the cost of one VM instruction per byte, and so charged. */
#define PRINTED_BYTES_PER_INSTRUCTION 1

struct vigen_sandbox {
    lua_State *L;
    size_t memory_limit, memory_used;
    int memory_hit;                 /* the allocator refused a block in this call */
    int memory_capped;              /* ...and that refusal ended a protected call: the call is poisoned */
    size_t bytes_uncharged;         /* bytes allocated, not yet charged as instructions */
    long instruction_limit, instructions_left;
    int instruction_step;           /* the count the hook is armed with */
    int instructions_hit;           /* budget spent in this call */
    long total_left;                /* instructions left for the whole life of the state (all calls) */
    int total_hit;                  /* ...and that budget is spent */
    int hit_line;                   /* line running when the budget ran out */
    int depth;                      /* nesting of vigen_sandbox_pcall */
    char *display;                  /* file name for messages ("spec.lua") */
};

/* The allocator of a sandbox's state (lua_Alloc; ud is the sandbox): counts
 * the bytes, refuses to pass the memory cap, charges what it allocates as
 * instructions. */
void *vigen_sandbox_alloc(void *ud, void *ptr, size_t osize, size_t nsize);
/* Start of a top-level call: fresh instruction budget, cap flags cleared. */
void vigen_sandbox_reset_budget(vigen_sandbox *sb);

/* The sandbox a state belongs to (the allocator's user data). */
vigen_sandbox *vigen_sandbox_of(lua_State *L);

/* A cap was reached in this top-level call: from now on every instruction
 * raises again, the sandbox's pcall and xpcall rethrow instead of returning
 * false, and no message handler of the file runs. */
int vigen_sandbox_cap_reached(const vigen_sandbox *sb);
/* Makes the hook fire at every instruction (used once a cap is reached). */
void vigen_sandbox_poison(vigen_sandbox *sb);
/* Raises the error of the cap reached. */
int vigen_sandbox_raise_cap(lua_State *L, vigen_sandbox *sb);
/* Charges `units` instructions of work that C is about to do for the file,
 * raising the instruction cap instead if it does not fit in the budget. */
void vigen_sandbox_charge(lua_State *L, lua_Unsigned units);

/* Replaces, wraps or drops the library functions whose work grows with a
 * count the file chooses (sandbox_libs.c has the table). */
void vigen_sandbox_change_libraries(lua_State *L);

#endif
