/* sandbox.c — a capped Lua 5.4 state for spec and tableau files.
 *
 * Layout of the state:
 *   - libraries: base, math, string, table only; dofile, loadfile, load,
 *     require, collectgarbage and string.dump removed; print writes to stderr
 *     (never to stdout, which may carry emitted code);
 *   - what would run outside the instruction cap is refused: setmetatable
 *     with a __gc field (Lua runs finalisers with hooks off) and the pattern
 *     functions string.find/match/gmatch/gsub (backtracking in C);
 *   - the allocator counts bytes and refuses to pass memory_limit (it and
 *     the instruction hook below are in sandbox_caps.c);
 *   - a count hook charges executed VM instructions against a budget that is
 *     reset at every top-level call; work done in C is charged too: what is
 *     allocated (BYTES_PER_INSTRUCTION) and what the library functions that
 *     loop over a count from the file are about to do (sandbox_libs.c says,
 *     function by function, what is offered);
 *   - a cap reached poisons the call: the hook fires on every instruction and
 *     raises again, pcall and xpcall rethrow the cap's error and do not run
 *     the file's message handler for it, so no script can carry on;
 *   - the ball library (ball.c), its functions also as globals;
 *   - the vocabulary of the kind of file, if the caller gives one (the method
 *     layer gives method files the node and basis family constructors); the
 *     text it returns is kept in the registry for the message below;
 *   - the globals table is strict: reading an unknown name is an error that
 *     lists the vocabulary and the functions.
 *
 * The sandbox struct is the allocator's user data, so the hook and the
 * allocator reach it through lua_getallocf.
 */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <lauxlib.h>
#include <lualib.h>

#include "support/file.h"
#include "lua/ball.h"
#include "core/expr.h"
#include "lua/sandbox.h"
#include "lua/sandbox_caps.h"
#include "support/strbuf.h"

#define MIB ((size_t)1 << 20)

/* registry field: what the vocabulary of the file says about itself */
#define VOCABULARY_KEY "vigen.vocabulary"



/* Process-wide defaults; the command line changes them with --max-memory and
 * --max-instructions (vigen_sandbox_limits_set_default). */
static vigen_sandbox_limits default_limits = {256 * MIB, 50000000L};

void vigen_sandbox_limits_default(vigen_sandbox_limits *limits) { *limits = default_limits; }

void vigen_sandbox_limits_set_default(const vigen_sandbox_limits *limits)
{
    if (limits->memory_limit > 0) default_limits.memory_limit = limits->memory_limit;
    if (limits->instruction_limit > 0) default_limits.instruction_limit = limits->instruction_limit;
}

lua_State *vigen_sandbox_state(vigen_sandbox *sb) { return sb->L; }

void vigen_sandbox_lift_memory_cap(vigen_sandbox *sb) { sb->memory_limit = (size_t)-1 / 2; }

/* ------------------------------------------------------------------ errors */

/* Lua's short_src truncates long names to "...tail"; put the whole name back
 * and make sure the message starts with "NAME:". */
static char *message_with_position(const char *display, const char *msg)
{
    size_t dn = strlen(display);
    if (msg == NULL) return vigen_strdup_printf("%s: (error object is not a string)", display);
    if (strncmp(msg, display, dn) == 0 && msg[dn] == ':') return vigen_strdup(msg);
    if (strncmp(msg, "...", 3) == 0) {
        const char *rest = msg + 3;
        for (size_t k = dn; k > 0; k--) {
            if (strncmp(rest, display + dn - k, k) == 0 && rest[k] == ':')
                return vigen_strdup_printf("%s%s", display, rest + k);
        }
    }
    return vigen_strdup_printf("%s: %s", display, msg);
}

static char *memory_text(size_t bytes)
{
    if (bytes % MIB == 0) return vigen_strdup_printf("%zu MiB", bytes / MIB);
    return vigen_strdup_printf("%zu bytes", bytes);
}

/* Translates a failed load or call; the error object is on top and is popped. */
static int translate_error(vigen_sandbox *sb, int status, vigen_error *err)
{
    lua_State *L = sb->L;
    const char *msg = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : NULL;
    if (sb->instructions_hit && sb->total_hit) {
        vigen_error_set(err, VIGEN_E_LIMIT,
                        "%s: its Lua code ran for more than %ld instructions in all (the basis functions are "
                        "called for every evaluation of the rigorous integrals; 20 times the per-call cap); "
                        "if it really needs more, raise the cap with the option --max-instructions N",
                        sb->display, 20 * sb->instruction_limit);
    } else if (sb->instructions_hit) {
        char *where = sb->hit_line > 0 ? vigen_strdup_printf("; it was stopped at line %d", sb->hit_line)
                                       : vigen_strdup("");
        vigen_error_set(err, VIGEN_E_LIMIT,
                        "%s: the file ran for more than %ld Lua instructions (an endless loop?)%s; "
                        "if it really needs more, raise the cap with the option --max-instructions N",
                        sb->display, sb->instruction_limit, where);
        free(where);
    } else if (sb->memory_capped ||
               (sb->memory_hit && (status == LUA_ERRMEM || (msg && strcmp(msg, "not enough memory") == 0)))) {
        char *cap = memory_text(sb->memory_limit);
        vigen_error_set(err, VIGEN_E_LIMIT,
                        "%s: the file used more than %s of memory (a runaway table or string?); "
                        "if it really needs more, raise the cap with the option --max-memory MIB",
                        sb->display, cap);
        free(cap);
    } else if (status == LUA_ERRMEM) {
        vigen_error_set(err, VIGEN_E_MEMORY, "%s: out of memory", sb->display);
    } else {
        char *m = message_with_position(sb->display, msg);
        vigen_error_set(err, status == LUA_ERRSYNTAX ? VIGEN_E_SYNTAX : VIGEN_E_LUA, "%s", m);
        free(m);
    }
    lua_pop(L, 1);
    return err ? err->code : (sb->instructions_hit || sb->memory_hit ? VIGEN_E_LIMIT : VIGEN_E_LUA);
}

/* Message handler: turns any error object into a string while still protected
 * (after a cap, without running the file's __tostring). */
static int message_handler(lua_State *L)
{
    if (vigen_sandbox_cap_reached(vigen_sandbox_of(L))) return 1;
    int t = lua_type(L, 1);
    if (t == LUA_TSTRING) return 1;
    if (t == LUA_TNUMBER) {
        lua_pushvalue(L, 1);
        lua_tostring(L, -1);
        return 1;
    }
    if (luaL_callmeta(L, 1, "__tostring") && lua_type(L, -1) == LUA_TSTRING) return 1;
    lua_pushfstring(L, "(error object is a %s value)", luaL_typename(L, 1));
    return 1;
}

int vigen_sandbox_pcall(vigen_sandbox *sb, int nargs, int nresults, vigen_error *err)
{
    lua_State *L = sb->L;
    int base = lua_gettop(L) - nargs;        /* index of the function */
    if (!lua_checkstack(L, 2)) {
        lua_settop(L, base - 1);
        return vigen_error_set(err, VIGEN_E_MEMORY, "%s: out of memory (Lua stack)", sb->display);
    }
    lua_pushcfunction(L, message_handler);   /* a light C function: no allocation */
    lua_insert(L, base);
    if (sb->depth == 0) vigen_sandbox_reset_budget(sb);
    sb->depth++;
    int status = lua_pcall(L, nargs, nresults, base);
    sb->depth--;
    int code = VIGEN_OK;
    if (status != LUA_OK) code = translate_error(sb, status, err);
    lua_remove(L, base);
    return code;
}

/* ------------------------------------------------------------------ running files */

static void set_display(vigen_sandbox *sb, const char *name)
{
    if (name[0] == '@' || name[0] == '=') name++;
    free(sb->display);
    sb->display = vigen_strdup(name);
}

static int run_buffer(vigen_sandbox *sb, const char *text, size_t len, vigen_error *err)
{
    lua_State *L = sb->L;
    if (len >= 3 && memcmp(text, "\xEF\xBB\xBF", 3) == 0) { text += 3; len -= 3; }   /* UTF-8 BOM */
    if (len > 0 && text[0] == LUA_SIGNATURE[0])
        return vigen_error_set(err, VIGEN_E_SYNTAX,
                               "%s: is a precompiled Lua chunk; vigen reads source text only",
                               sb->display);
    if (!lua_checkstack(L, 3)) return vigen_error_set(err, VIGEN_E_MEMORY, "%s: out of memory", sb->display);
    int base = lua_gettop(L);
    char *chunkname = vigen_strdup_printf("@%s", sb->display);
    sb->memory_hit = 0;
    sb->memory_capped = 0;
    sb->instructions_hit = 0;
    int status = luaL_loadbufferx(L, text, len, chunkname, "t");   /* lua_load is protected */
    free(chunkname);
    if (status != LUA_OK) return translate_error(sb, status, err);
    int code = vigen_sandbox_pcall(sb, 0, LUA_MULTRET, err);
    if (code != VIGEN_OK) return code;
    int n = lua_gettop(L) - base;
    if (n == 0 || lua_isnil(L, base + 1)) {
        lua_settop(L, base);
        return vigen_error_set(err, VIGEN_E_SPEC,
                               "%s: the file returned nothing; it must end with `return { ... }`",
                               sb->display);
    }
    lua_settop(L, base + 1);
    return VIGEN_OK;
}

int vigen_sandbox_run_string(vigen_sandbox *sb, const char *text, const char *chunkname, vigen_error *err)
{
    set_display(sb, chunkname ? chunkname : "=(string)");
    return run_buffer(sb, text, strlen(text), err);
}

int vigen_sandbox_run_file(vigen_sandbox *sb, const char *path, vigen_error *err)
{
    set_display(sb, path);
    char *data = NULL;
    size_t len = 0;
    int code = vigen_read_file(&data, &len, path, sb->memory_limit, err);
    if (code == VIGEN_E_LIMIT) {
        char *lim = memory_text(sb->memory_limit);
        vigen_error_set(err, VIGEN_E_LIMIT,
                        "%s: the file is larger than the sandbox's memory cap (%s); "
                        "if it really needs more, raise the cap with the option --max-memory MIB", path, lim);
        free(lim);
    }
    if (code == VIGEN_OK) code = run_buffer(sb, data, len, err);
    free(data);
    return code;
}

/* __index of the globals table: pi (a fresh ball at the current precision) or an error. */
static int strict_index(lua_State *L)
{
    if (lua_type(L, 2) == LUA_TSTRING && strcmp(lua_tostring(L, 2), "pi") == 0) {
        lua_getfield(L, LUA_REGISTRYINDEX, "vigen.ball.lib");
        lua_getfield(L, -1, "pi");
        return 1;
    }
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    if (lua_type(L, 2) == LUA_TSTRING) {
        luaL_addstring(&b, "unknown name '");
        lua_pushvalue(L, 2);
        luaL_addvalue(&b);
        luaL_addstring(&b, "'");
    } else {
        luaL_addstring(&b, "unknown global (a ");
        luaL_addstring(&b, luaL_typename(L, 2));
        luaL_addstring(&b, " key)");
    }
    luaL_addstring(&b, " (");
    if (lua_getfield(L, LUA_REGISTRYINDEX, VOCABULARY_KEY) == LUA_TSTRING) {
        luaL_addvalue(&b);
        luaL_addstring(&b, "; ");
    } else {
        lua_pop(L, 1);
    }
    luaL_addstring(&b, "functions: ");
    lua_pushfstring(L, "%s, %s, exact", vigen_expr_function_names(), vigen_expr_constant_names());
    luaL_addvalue(&b);
    luaL_addstring(&b, ")");
    luaL_pushresult(&b);
    return luaL_error(L, "%s", lua_tostring(L, -1));
}

static int setup_state(lua_State *L)
{
    luaL_requiref(L, LUA_GNAME, luaopen_base, 1);
    luaL_requiref(L, LUA_MATHLIBNAME, luaopen_math, 1);
    luaL_requiref(L, LUA_STRLIBNAME, luaopen_string, 1);
    luaL_requiref(L, LUA_TABLIBNAME, luaopen_table, 1);
    lua_pop(L, 4);

    static const char *const removed[] = { "dofile", "loadfile", "load", "require", "collectgarbage", NULL };
    for (int i = 0; removed[i]; i++) {
        lua_pushnil(L);
        lua_setglobal(L, removed[i]);
    }
    lua_getglobal(L, LUA_STRLIBNAME);
    lua_pushnil(L);
    lua_setfield(L, -2, "dump");
    lua_pop(L, 1);
    vigen_sandbox_change_libraries(L);

    /* reproducible math.random */
    lua_getglobal(L, LUA_MATHLIBNAME);
    lua_getfield(L, -1, "randomseed");
    lua_pushinteger(L, 0);
    lua_call(L, 1, 0);
    lua_pop(L, 1);

    /* balls, and their functions as globals */
    vigen_ball_open(L);
    lua_getfield(L, LUA_REGISTRYINDEX, "vigen.ball.lib");
    for (int i = 0; i < vigen_expr_function_count(); i++) {
        const vigen_expr_function *f = vigen_expr_function_at(i);
        if (!f->in_ball_library) continue;
        lua_getfield(L, -1, f->name);
        lua_setglobal(L, f->name);
    }
    lua_getfield(L, -1, "exact");
    lua_setglobal(L, "exact");
    lua_pop(L, 1);

    /* the vocabulary of the kind of file, and what it says about itself */
    lua_CFunction vocabulary = lua_tocfunction(L, 1);
    if (vocabulary) {
        lua_pushcfunction(L, vocabulary);
        lua_call(L, 0, 1);
        lua_setfield(L, LUA_REGISTRYINDEX, VOCABULARY_KEY);
    }

    /* strict globals */
    lua_pushglobaltable(L);
    lua_newtable(L);
    lua_pushcfunction(L, strict_index);
    lua_setfield(L, -2, "__index");
    lua_setmetatable(L, -2);
    lua_pop(L, 1);
    return 0;
}

static int panic_handler(lua_State *L)
{
    const char *msg = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : "(not a string)";
    fprintf(stderr, "vigen: internal error: unprotected Lua error: %s\n", msg);
    return 0;   /* Lua aborts */
}

int vigen_sandbox_new(vigen_sandbox **out, const vigen_sandbox_limits *limits, lua_CFunction vocabulary,
                     vigen_error *err)
{
    *out = NULL;
    vigen_sandbox_limits def;
    vigen_sandbox_limits_default(&def);
    vigen_sandbox *sb = calloc(1, sizeof *sb);
    if (sb == NULL) return vigen_error_set(err, VIGEN_E_MEMORY, "out of memory");
    sb->memory_limit = limits && limits->memory_limit > 0 ? limits->memory_limit : def.memory_limit;
    sb->instruction_limit = limits && limits->instruction_limit > 0 ? limits->instruction_limit
                                                                    : def.instruction_limit;
    /* every call has instruction_limit; all calls together 20 times that, so
     * that a basis function called thousands of times by the integrator
     * cannot run for hours one capped call at a time */
    sb->total_left = sb->instruction_limit > LONG_MAX / 20 ? LONG_MAX : 20 * sb->instruction_limit;
    sb->display = vigen_strdup("sandbox");
    sb->L = lua_newstate(vigen_sandbox_alloc, sb);
    if (sb->L == NULL) {
        int code = sb->memory_hit ? VIGEN_E_LIMIT : VIGEN_E_MEMORY;
        vigen_sandbox_free(sb);
        return vigen_error_set(err, code, "cannot create a Lua state (memory cap too small or out of memory)");
    }
    lua_atpanic(sb->L, panic_handler);
    lua_pushcfunction(sb->L, setup_state);
    if (vocabulary) lua_pushcfunction(sb->L, vocabulary);
    else lua_pushnil(sb->L);
    int code = vigen_sandbox_pcall(sb, 1, 0, err);
    if (code != VIGEN_OK) {
        vigen_error_prefix(err, "cannot set up the Lua sandbox: ");
        vigen_sandbox_free(sb);
        return code;
    }
    *out = sb;
    return VIGEN_OK;
}

void vigen_sandbox_free(vigen_sandbox *sb)
{
    if (sb == NULL) return;
    if (sb->L) {
        /* finalisers written in Lua run at close: give them a fresh budget */
        if (sb->total_left < sb->instruction_limit) sb->total_left = sb->instruction_limit;
        vigen_sandbox_reset_budget(sb);
        lua_close(sb->L);
    }
    free(sb->display);
    free(sb);
}
