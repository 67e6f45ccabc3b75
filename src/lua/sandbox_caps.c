/* sandbox_caps.c — the caps of a sandbox (sandbox_caps.h): the counting
 * allocator, the instruction hook and its budget, the charge of work done in
 * C, and the cap reached that poisons the call.  sandbox.c makes states with
 * them; the library functions (sandbox_libs.c) charge their work here. */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <lauxlib.h>

#include "lua/sandbox_caps.h"

static void count_hook(lua_State *L, lua_Debug *ar);

/* The allocator cannot raise an error: it takes the budget down and, once it
 * is spent, makes the hook fire at the next instruction (lua_sethook may be
 * called from anywhere, even asynchronously). */
static void charge_bytes(vigen_sandbox *sb, size_t bytes)
{
    sb->bytes_uncharged += bytes;
    if (sb->bytes_uncharged < BYTES_PER_INSTRUCTION) return;
    long units = (long)(sb->bytes_uncharged / BYTES_PER_INSTRUCTION);
    sb->bytes_uncharged %= BYTES_PER_INSTRUCTION;
    sb->instructions_left -= units;
    sb->total_left -= units;
    if ((sb->instructions_left <= 0 || sb->total_left <= 0) && sb->L && !sb->instructions_hit) {
        sb->instruction_step = 1;
        lua_sethook(sb->L, count_hook, LUA_MASKCOUNT, 1);
    }
}

void *vigen_sandbox_alloc(void *ud, void *ptr, size_t osize, size_t nsize)
{
    vigen_sandbox *sb = ud;
    size_t old = ptr ? osize : 0;
    if (nsize == 0) {
        free(ptr);
        sb->memory_used -= old;
        return NULL;
    }
    if (nsize > old && (sb->memory_used > sb->memory_limit ||
                        nsize - old > sb->memory_limit - sb->memory_used)) {
        sb->memory_hit = 1;
        return NULL;
    }
    void *q = realloc(ptr, nsize);
    if (q == NULL) return NULL;
    sb->memory_used = sb->memory_used - old + nsize;
    if (nsize > old) charge_bytes(sb, nsize - old);
    return q;
}

vigen_sandbox *vigen_sandbox_of(lua_State *L)
{
    void *ud = NULL;
    lua_getallocf(L, &ud);
    return ud;
}

static void arm_hook(vigen_sandbox *sb);

/* A cap was reached in this top-level call: from now on every instruction
 * raises again (the hook fires at every instruction), the pcall and xpcall of
 * the sandbox rethrow instead of returning false, and no message handler of
 * the file runs: nothing the file does can carry on after a cap. */
int vigen_sandbox_cap_reached(const vigen_sandbox *sb) { return sb->instructions_hit || sb->memory_capped; }

void vigen_sandbox_poison(vigen_sandbox *sb)
{
    sb->instruction_step = 1;
    lua_sethook(sb->L, count_hook, LUA_MASKCOUNT, 1);
}

/* Raises the error of the cap reached (the message is for Lua only:
 * translate_error words it from the flags). */
int vigen_sandbox_raise_cap(lua_State *L, vigen_sandbox *sb)
{
    if (sb->memory_capped) lua_pushliteral(L, "not enough memory");
    else lua_pushliteral(L, "instruction cap reached");
    return lua_error(L);
}

/* Line of the innermost Lua function running (the caller of a C function). */
static int current_line(lua_State *L)
{
    lua_Debug ar;
    for (int level = 0; lua_getstack(L, level, &ar); level++)
        if (lua_getinfo(L, "l", &ar) && ar.currentline > 0) return ar.currentline;
    return 0;
}

/* The instruction budget of this call (or of the whole state) is spent. */
static int instruction_cap(lua_State *L, vigen_sandbox *sb, int line)
{
    if (!vigen_sandbox_cap_reached(sb)) {
        sb->instructions_hit = 1;
        sb->total_hit = sb->total_left <= 0;
        sb->hit_line = line;
        vigen_sandbox_poison(sb);
    }
    return vigen_sandbox_raise_cap(L, sb);
}

static void count_hook(lua_State *L, lua_Debug *ar)
{
    vigen_sandbox *sb = vigen_sandbox_of(L);
    if (vigen_sandbox_cap_reached(sb)) {
        vigen_sandbox_raise_cap(L, sb);
        return;
    }
    sb->instructions_left -= sb->instruction_step;
    sb->total_left -= sb->instruction_step;
    if (sb->instructions_left > 0 && sb->total_left > 0) {
        arm_hook(sb);
        return;
    }
    instruction_cap(L, sb, lua_getinfo(L, "l", ar) ? ar->currentline : 0);
}

/* Charges `units` instructions of work that C is about to do for the file
 * (elements moved, compared, returned), and raises the instruction cap
 * instead if that work does not fit in what is left of the budget. */
void vigen_sandbox_charge(lua_State *L, lua_Unsigned units)
{
    vigen_sandbox *sb = vigen_sandbox_of(L);
    if (vigen_sandbox_cap_reached(sb)) vigen_sandbox_raise_cap(L, sb);
    long left = sb->instructions_left < sb->total_left ? sb->instructions_left : sb->total_left;
    if (left <= 0 || units >= (lua_Unsigned)left) {
        if (sb->total_left < sb->instructions_left) sb->total_left = 0;   /* which budget ran out */
        else sb->instructions_left = 0;
        instruction_cap(L, sb, current_line(L));
    }
    sb->instructions_left -= (long)units;
    sb->total_left -= (long)units;
}

/* The hook fires every `step` instructions (at most HOOK_STEP): fine enough
 * that the budget of the whole run (total_left) sees every long call, coarse
 * enough to cost nothing measurable. */
#define HOOK_STEP 4096

static void arm_hook(vigen_sandbox *sb)
{
    long step = sb->instructions_left < sb->total_left ? sb->instructions_left : sb->total_left;
    if (step > HOOK_STEP) step = HOOK_STEP;
    if (step < 1) step = 1;
    sb->instruction_step = (int)step;
    lua_sethook(sb->L, count_hook, LUA_MASKCOUNT, (int)step);
}

/* Start of a top-level call: fresh instruction budget, cap flags cleared. */
void vigen_sandbox_reset_budget(vigen_sandbox *sb)
{
    sb->memory_hit = 0;
    sb->memory_capped = 0;
    sb->instructions_hit = 0;
    sb->hit_line = 0;
    sb->instructions_left = sb->instruction_limit;
    arm_hook(sb);
}

