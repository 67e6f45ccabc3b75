/* sandbox_libs.c — the base, string and table library functions as the
 * sandbox offers them: each function whose work grows with a count the file
 * chooses is charged against the instruction cap, replaced or dropped (the
 * table below), and setmetatable refuses __gc. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <lauxlib.h>
#include <lualib.h>

#include "support/printable.h"
#include "lua/sandbox_caps.h"
#include "support/strbuf.h"

/* setmetatable without __gc: Lua runs finalisers with hooks off, so a
 * finaliser would escape the instruction cap (an endless __gc hangs lua_close). */
static int safe_setmetatable(lua_State *L)
{
    if (lua_type(L, 2) == LUA_TTABLE) {
        lua_pushliteral(L, "__gc");
        if (lua_rawget(L, 2) != LUA_TNIL)
            return luaL_error(L, "setmetatable: __gc finalisers are not allowed in spec and tableau files "
                                 "(they run outside the instruction cap)");
        lua_pop(L, 1);
    }
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_insert(L, 1);
    lua_call(L, lua_gettop(L) - 1, LUA_MULTRET);
    return lua_gettop(L);
}

/* ------------------------------------------------------------------ the libraries under the caps
 *
 * A C library function runs as one VM instruction, whatever it loops over,
 * and the count hook does not see inside it; the memory cap sees only what it
 * allocates.  So each function of the base, string and table libraries whose
 * work grows with a count the file chooses is offered in one of three ways
 * (docs/security.md has the same table):
 *
 *   function        offered   how
 *   pcall, xpcall   replaced  same results, but a cap's error is rethrown, never returned as false, and
 *                             the xpcall handler is not run for it (see cap_reached)
 *   table.move      wrapped   e - f + 1 elements charged (ELEMENT_COST each) before Lua's move runs
 *   table.concat    wrapped   j - i + 1 elements charged; #t read once here and passed on explicitly
 *   table.unpack    wrapped   likewise (Lua also refuses more than about 10^6 results)
 *   table.insert    replaced  #t read once; the elements shifted are charged before they move
 *   table.remove    replaced  likewise
 *   table.sort      wrapped   every comparison is charged (COMPARISON_COST), also with the file's
 *                             comparator (which runs under the hook too) and with __len/__index
 *                             proxies of any claimed length; Lua's sort stops comparators that lie
 *   table.pack      as is     its arguments are already on the stack; the table is charged as allocation
 *   string.rep      wrapped   refused before it is built if the result would pass the memory cap;
 *                             ('').rep(s, 2^50) is "" at once; the result is charged as allocation
 *   string.byte     wrapped   the number of results charged
 *   select          wrapped   the number of arguments charged (the VM copied them to call it)
 *   tonumber        wrapped   a string argument charged by its length (STRING_SCAN_BYTES a unit)
 *   print           replaced  writes to stderr; charged by the bytes written
 *   string.format   as is     width and precision have at most 2 digits (Lua refuses more); the
 *                             result is charged as allocation
 *   string.char, sub, upper, lower, reverse, tostring, concatenation (..)
 *                   as is     their work is proportional to what they allocate, which is charged
 *   string.find, match, gmatch, gsub
 *                   dropped   patterns backtrack in C, exponentially ('.-.-.-b')
 *   string.pack, unpack, packsize
 *                   dropped   they loop over a format string in C, and spec files have no binary data
 *   string.dump, load, loadfile, dofile, require, collectgarbage, io, os, debug, package, coroutine, utf8
 *                   dropped   (not a matter of caps: no file system, no bytecode, no other states)
 *   math.*, string.len, next, pairs, ipairs, rawget, rawset, rawlen, rawequal, type, getmetatable,
 *   assert, error   as is     constant work per call
 *   setmetatable    wrapped   __gc refused (finalisers run with hooks off)
 *
 * Not seen by these caps: single VM instructions whose work grows with their
 * operands without allocating, namely == and < between two long strings of the
 * same length (memcmp/strcoll), arithmetic on a long numeric string, and
 * passing `...` of up to ~10^6 values to a Lua function.  Each costs at most
 * tens of milliseconds (the memory cap bounds a string, Lua's stack limit the
 * values), so a wall-clock cap is what stops a loop of them.
 */

/* An element read or written by a table function (through __index or
 * __newindex functions written in C, ~30 ns), in VM instructions. */
#define ELEMENT_COST 4

/* Elements a C loop over positions i..j touches (0 if j < i), without overflow. */
static lua_Unsigned span(lua_Integer i, lua_Integer j)
{
    return j < i ? 0 : (lua_Unsigned)j - (lua_Unsigned)i + 1u;
}

/* n units of cost each, saturating (a span of 2^62 must not wrap to 0). */
static lua_Unsigned times(lua_Unsigned n, lua_Unsigned cost)
{
    return n > (lua_Unsigned)-1 / cost ? (lua_Unsigned)-1 : n * cost;
}

/* Calls the library's own function (upvalue 1) with the arguments on the
 * stack and returns what it returns. */
static int call_original(lua_State *L, int nresults)
{
    int n = lua_gettop(L);
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_insert(L, 1);
    lua_call(L, n, nresults);
    return lua_gettop(L);
}

/* The end of pcall and xpcall: a cap's error goes on up (also a memory error,
 * which then poisons the call like the others); any other error is returned
 * as false, message, as Lua's own pcall does. */
static int finish_pcall(lua_State *L, int status, int extra)
{
    vigen_sandbox *sb = vigen_sandbox_of(L);
    if (status == LUA_ERRMEM && sb->memory_hit && !vigen_sandbox_cap_reached(sb)) {
        sb->memory_capped = 1;
        vigen_sandbox_poison(sb);
    }
    if (status != LUA_OK && (vigen_sandbox_cap_reached(sb) || status == LUA_ERRMEM)) return lua_error(L);
    if (status != LUA_OK) {
        lua_pushboolean(L, 0);
        lua_pushvalue(L, -2);
        return 2;
    }
    return lua_gettop(L) - extra;
}

static int capped_pcall(lua_State *L)
{
    luaL_checkany(L, 1);
    lua_pushboolean(L, 1);
    lua_insert(L, 1);
    return finish_pcall(L, lua_pcall(L, lua_gettop(L) - 2, LUA_MULTRET, 0), 0);
}

/* The file's message handler (upvalue 1), run only for errors that are not a
 * cap: once a cap is reached Lua calls the handler with hooks off, and a
 * handler that loops would never be stopped. */
static int capped_handler(lua_State *L)
{
    if (vigen_sandbox_cap_reached(vigen_sandbox_of(L))) return 1;
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_insert(L, 1);
    lua_call(L, lua_gettop(L) - 1, 1);
    return 1;
}

static int capped_xpcall(lua_State *L)
{
    int n = lua_gettop(L);
    luaL_checktype(L, 2, LUA_TFUNCTION);
    lua_pushvalue(L, 2);
    lua_pushcclosure(L, capped_handler, 1);
    lua_replace(L, 2);
    lua_pushboolean(L, 1);
    lua_pushvalue(L, 1);
    lua_rotate(L, 3, 2);      /* f, handler, true, f, args... */
    return finish_pcall(L, lua_pcall(L, n - 2, LUA_MULTRET, 2), 2);
}

static int capped_move(lua_State *L)
{
    lua_Integer f = luaL_checkinteger(L, 2), e = luaL_checkinteger(L, 3);
    if (f > 0 || e < LUA_MAXINTEGER + f)     /* else Lua's move refuses: too many elements */
        vigen_sandbox_charge(L, times(span(f, e), ELEMENT_COST));
    return call_original(L, LUA_MULTRET);
}

/* table.concat(t, sep, i, j) and table.unpack(t, i, j): positions i..j in
 * arguments arg and arg + 1.  The last is #t by default, read once here and
 * passed on: a __len that answers differently the second time cannot slip
 * past the charge. */
static int capped_range(lua_State *L, int arg, int nresults)
{
    lua_Integer i = luaL_optinteger(L, arg, 1);
    lua_Integer j = lua_isnoneornil(L, arg + 1) ? luaL_len(L, 1) : luaL_checkinteger(L, arg + 1);
    vigen_sandbox_charge(L, times(span(i, j), ELEMENT_COST));
    lua_settop(L, arg - 1);
    lua_pushinteger(L, i);
    lua_pushinteger(L, j);
    return call_original(L, nresults);
}

static int capped_concat(lua_State *L) { return capped_range(L, 3, 1); }
static int capped_unpack(lua_State *L) { return capped_range(L, 2, LUA_MULTRET); }

/* table.insert(t, [pos,] v), as Lua's, with the shift charged first. */
static int capped_insert(lua_State *L)
{
    luaL_checktype(L, 1, LUA_TTABLE);
    lua_Integer e = (lua_Integer)((lua_Unsigned)luaL_len(L, 1) + 1u);   /* first empty position */
    lua_Integer pos = e;
    switch (lua_gettop(L)) {
    case 2:
        break;
    case 3:
        pos = luaL_checkinteger(L, 2);
        luaL_argcheck(L, (lua_Unsigned)pos - 1u < (lua_Unsigned)e, 2, "position out of bounds");
        vigen_sandbox_charge(L, times(e > pos ? (lua_Unsigned)e - (lua_Unsigned)pos : 0, ELEMENT_COST));
        for (lua_Integer i = e; i > pos; i--) {
            lua_geti(L, 1, i - 1);
            lua_seti(L, 1, i);
        }
        break;
    default:
        return luaL_error(L, "wrong number of arguments to 'insert'");
    }
    lua_seti(L, 1, pos);
    return 0;
}

/* table.remove(t [, pos]), as Lua's, with the shift charged first. */
static int capped_remove(lua_State *L)
{
    luaL_checktype(L, 1, LUA_TTABLE);
    lua_Integer size = luaL_len(L, 1);
    lua_Integer pos = luaL_optinteger(L, 2, size);
    if (pos != size)
        luaL_argcheck(L, (lua_Unsigned)pos - 1u <= (lua_Unsigned)size, 2, "position out of bounds");
    vigen_sandbox_charge(L, times(size > pos ? (lua_Unsigned)size - (lua_Unsigned)pos : 0, ELEMENT_COST));
    lua_geti(L, 1, pos);
    for (; pos < size; pos++) {
        lua_geti(L, 1, pos + 1);
        lua_seti(L, 1, pos);
    }
    lua_pushnil(L);
    lua_seti(L, 1, pos);
    return 1;
}

/* A comparison of table.sort: two element reads, a call and a compare, about
 * as much work as this many VM instructions. */
#define COMPARISON_COST 16

/* The comparator table.sort is given: charges the comparison, then compares
 * as Lua's sort would (the file's function in upvalue 1, or a < b). */
static int counted_less(lua_State *L)
{
    vigen_sandbox_charge(L, COMPARISON_COST);
    if (lua_isnil(L, lua_upvalueindex(1))) {
        lua_pushboolean(L, lua_compare(L, 1, 2, LUA_OPLT));
        return 1;
    }
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_insert(L, 1);
    lua_call(L, 2, 1);
    return 1;
}

/* table.sort does O(n log n) comparisons on a length the file may invent
 * (__len) over elements it may make up in C (__index = rawlen): the work is
 * bounded by charging each comparison. */
static int capped_sort(lua_State *L)
{
    if (!lua_isnoneornil(L, 2)) luaL_checktype(L, 2, LUA_TFUNCTION);
    lua_settop(L, 2);
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_insert(L, 1);                               /* sort, t, comparator */
    lua_pushcclosure(L, counted_less, 1);
    lua_call(L, 2, 0);
    return 0;
}

/* Lua's own reading of string.byte's positions (posrelatI, getendpos). */
static int capped_byte(lua_State *L)
{
    size_t len;
    luaL_checklstring(L, 1, &len);
    lua_Integer n = (lua_Integer)len;
    lua_Integer i = luaL_optinteger(L, 2, 1);
    lua_Integer j = luaL_optinteger(L, 3, i);
    if (i == 0) i = 1;
    else if (i < 0) i = i < -n ? 1 : n + i + 1;
    if (j > n) j = n;
    else if (j < 0) j = j < -n ? 0 : n + j + 1;
    vigen_sandbox_charge(L, span(i, j));
    return call_original(L, LUA_MULTRET);
}

static int capped_select(lua_State *L)
{
    vigen_sandbox_charge(L, (lua_Unsigned)lua_gettop(L));
    return call_original(L, LUA_MULTRET);
}

/* Reading a number scans the whole string (strtod): one unit of work per
 * this many bytes. */
#define STRING_SCAN_BYTES 8

static int capped_tonumber(lua_State *L)
{
    if (lua_type(L, 1) == LUA_TSTRING) vigen_sandbox_charge(L, (lua_Unsigned)(lua_rawlen(L, 1) / STRING_SCAN_BYTES));
    return call_original(L, LUA_MULTRET);
}

/* A dropped function: upvalue 1 is its name, upvalue 2 why it is not offered. */
static int not_offered(lua_State *L)
{
    return luaL_error(L, "string.%s is not available in spec and tableau files: %s",
                      lua_tostring(L, lua_upvalueindex(1)), lua_tostring(L, lua_upvalueindex(2)));
}

/* string.rep loops in C: ("").rep(2^50) would spin forever outside the
 * instruction cap, and a huge result is better refused before it is built. */
static int safe_rep(lua_State *L)
{
    size_t len, seplen = 0;
    luaL_checklstring(L, 1, &len);
    lua_Integer n = luaL_checkinteger(L, 2);
    luaL_optlstring(L, 3, "", &seplen);
    if (n <= 0 || len + seplen == 0) {
        lua_pushliteral(L, "");
        return 1;
    }
    vigen_sandbox *sb = vigen_sandbox_of(L);
    if ((lua_Unsigned)n > (lua_Unsigned)(sb->memory_limit / (len + seplen))) {
        /* reported exactly like the allocator's refusal: the memory cap */
        sb->memory_hit = 1;
        if (!vigen_sandbox_cap_reached(sb)) {
            sb->memory_capped = 1;
            vigen_sandbox_poison(sb);
        }
        return vigen_sandbox_raise_cap(L, sb);
    }
    return call_original(L, 1);
}

/* print writes to stderr, since stdout may be carrying emitted code, and
 * escaped (vigen_printable), since the file's bytes must not reach the
 * terminal as control sequences. */
static int stderr_print(lua_State *L)
{
    int n = lua_gettop(L);
    for (int i = 1; i <= n; i++) {
        size_t len;
        const char *s = luaL_tolstring(L, i, &len);
        vigen_sandbox_charge(L, len / PRINTED_BYTES_PER_INSTRUCTION);
        /* no Lua call between the allocation and the free: nothing can
         * raise past the buffer */
        vigen_strbuf sb;
        vigen_strbuf_init(&sb);
        vigen_printable_append(&sb, s, len);
        if (i > 1) fputc('\t', stderr);
        if (sb.data) fwrite(sb.data, 1, sb.len, stderr);
        vigen_strbuf_clear(&sb);
        lua_pop(L, 1);
    }
    fputc('\n', stderr);
    return 0;
}

/* The functions of the table above that are wrapped, replaced or dropped
 * (wrapper NULL: dropped, with the reason given).  Wrappers get the library's
 * own function as upvalue 1. */
static const struct {
    const char *library, *name;
    lua_CFunction wrapper;
    const char *reason;
} library_changes[] = {
    { LUA_GNAME, "pcall", capped_pcall, NULL },
    { LUA_GNAME, "xpcall", capped_xpcall, NULL },
    { LUA_GNAME, "select", capped_select, NULL },
    { LUA_GNAME, "tonumber", capped_tonumber, NULL },
    { LUA_GNAME, "setmetatable", safe_setmetatable, NULL },
    { LUA_GNAME, "print", stderr_print, NULL },
    { LUA_TABLIBNAME, "move", capped_move, NULL },
    { LUA_TABLIBNAME, "concat", capped_concat, NULL },
    { LUA_TABLIBNAME, "unpack", capped_unpack, NULL },
    { LUA_TABLIBNAME, "insert", capped_insert, NULL },
    { LUA_TABLIBNAME, "remove", capped_remove, NULL },
    { LUA_TABLIBNAME, "sort", capped_sort, NULL },
    { LUA_STRLIBNAME, "rep", safe_rep, NULL },
    { LUA_STRLIBNAME, "byte", capped_byte, NULL },
    { LUA_STRLIBNAME, "find", NULL, "Lua patterns run outside the instruction cap" },
    { LUA_STRLIBNAME, "match", NULL, "Lua patterns run outside the instruction cap" },
    { LUA_STRLIBNAME, "gmatch", NULL, "Lua patterns run outside the instruction cap" },
    { LUA_STRLIBNAME, "gsub", NULL, "Lua patterns run outside the instruction cap" },
    { LUA_STRLIBNAME, "pack", NULL, "binary packing loops over its format outside the instruction cap" },
    { LUA_STRLIBNAME, "unpack", NULL, "binary packing loops over its format outside the instruction cap" },
    { LUA_STRLIBNAME, "packsize", NULL, "binary packing loops over its format outside the instruction cap" },
};

/* Installs library_changes in the libraries (or _G) of L. */
void vigen_sandbox_change_libraries(lua_State *L)
{
    for (size_t k = 0; k < sizeof library_changes / sizeof library_changes[0]; k++) {
        if (strcmp(library_changes[k].library, LUA_GNAME) == 0) lua_pushglobaltable(L);
        else lua_getglobal(L, library_changes[k].library);
        if (library_changes[k].wrapper) {
            lua_getfield(L, -1, library_changes[k].name);
            lua_pushcclosure(L, library_changes[k].wrapper, 1);
        } else {
            lua_pushstring(L, library_changes[k].name);
            lua_pushstring(L, library_changes[k].reason);
            lua_pushcclosure(L, not_offered, 2);
        }
        lua_setfield(L, -2, library_changes[k].name);
        lua_pop(L, 1);
    }
}
