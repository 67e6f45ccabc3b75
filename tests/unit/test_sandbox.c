/* test_sandbox.c — the Lua sandbox (caps, escapes, messages, the vocabulary
 * mechanism and the spec vocabulary method files run with), the ball library that Lua basis functions compute with, and the Lua string
 * literals vigen writes. */
#include <string.h>

#include <lauxlib.h>
#include <lualib.h>

#include "lua/ball.h"
#include "lua/float_text.h"
#include "lua/quote.h"
#include "lua/sandbox.h"
#include "method/vocabulary.h"
#include "testlib.h"
#include "support/strbuf.h"

static int contains(const char *haystack, const char *needle)
{
    return haystack != NULL && strstr(haystack, needle) != NULL;
}

static int starts_with(const char *s, const char *prefix)
{
    return s != NULL && strncmp(s, prefix, strlen(prefix)) == 0;
}

/* Runs text in a fresh sandbox with the spec vocabulary, as a method file
 * (limits may be NULL) and returns the status;
 * the message stays in err.  The stack must be balanced afterwards. */
static int run(const char *text, const vigen_sandbox_limits *limits, vigen_error *err)
{
    vigen_sandbox *sb = NULL;
    vigen_error_clear(err);
    int code = vigen_sandbox_new(&sb, limits, vigen_vocabulary_open, err);
    if (code != VIGEN_OK) return code;
    lua_State *L = vigen_sandbox_state(sb);
    int top = lua_gettop(L);
    code = vigen_sandbox_run_string(sb, text, "@spec.lua", err);
    CHECK(lua_gettop(L) == top + (code == VIGEN_OK ? 1 : 0));
    vigen_sandbox_free(sb);
    return code;
}

/* expect(text, code, phrase): the run fails with code and a message containing phrase. */
#define EXPECT(text, limits, want_code, phrase) do { \
    vigen_error e_; vigen_error_init(&e_); \
    int c_ = run((text), (limits), &e_); \
    CHECK_MSG(c_ == (want_code) && contains(e_.message, (phrase)), \
              "code %d (%s) message: %s", c_, vigen_status_name(c_), e_.message ? e_.message : "(none)"); \
    vigen_error_clear(&e_); } while (0)

static void test_limits_default(void)
{
    vigen_sandbox_limits lim;
    vigen_sandbox_limits_default(&lim);
    CHECK(lim.memory_limit == (size_t)256 << 20);
    CHECK(lim.instruction_limit == 50000000L);
}

static void test_run_and_errors(void)
{
    vigen_error err;
    vigen_error_init(&err);

    /* a chunk's value stays on the stack */
    vigen_sandbox *sb = NULL;
    CHECK(vigen_sandbox_new(&sb, NULL, NULL, &err) == VIGEN_OK);
    lua_State *L = vigen_sandbox_state(sb);
    CHECK(vigen_sandbox_run_string(sb, "return 6 * 7, 'ignored'", "@spec.lua", &err) == VIGEN_OK);
    CHECK(lua_gettop(L) == 1 && lua_isinteger(L, -1) && lua_tointeger(L, -1) == 42);
    lua_pop(L, 1);
    vigen_sandbox_free(sb);

    /* syntax and runtime errors carry file:line and their own codes */
    CHECK(run("local a = 1\nlocal b = 2\nreturn {a = }\n", NULL, &err) == VIGEN_E_SYNTAX);
    CHECK_MSG(starts_with(err.message, "spec.lua:3:"), "%s", err.message);
    CHECK(run("local x = 1\nerror('fails on purpose')\n", NULL, &err) == VIGEN_E_LUA);
    CHECK_MSG(starts_with(err.message, "spec.lua:2: fails on purpose"), "%s", err.message);
    CHECK(run("local t = nil\nreturn t.x\n", NULL, &err) == VIGEN_E_LUA);
    CHECK_MSG(starts_with(err.message, "spec.lua:2:") && contains(err.message, "index"), "%s", err.message);
    /* an error object that is not a string still names the file */
    CHECK(run("error({})", NULL, &err) == VIGEN_E_LUA);
    CHECK_MSG(starts_with(err.message, "spec.lua:") && contains(err.message, "table"), "%s", err.message);
    CHECK(run("error(setmetatable({}, {__tostring = function() return 'custom' end}))", NULL, &err) == VIGEN_E_LUA);
    CHECK_MSG(contains(err.message, "custom"), "%s", err.message);

    /* a chunk must return something */
    CHECK(run("local x = 1", NULL, &err) == VIGEN_E_SPEC);
    CHECK(contains(err.message, "spec.lua") && contains(err.message, "returned nothing"));
    CHECK(run("return nil", NULL, &err) == VIGEN_E_SPEC);

    /* a long path is shown whole, not as Lua's truncated "...tail" */
    const char *longname = "@some/very/long/directory/name/that/goes/on/and/on/and/on/and/on/spec.lua";
    CHECK(vigen_sandbox_new(&sb, NULL, NULL, &err) == VIGEN_OK);
    CHECK(vigen_sandbox_run_string(sb, "\nerror('x')", longname, &err) == VIGEN_E_LUA);
    CHECK_MSG(starts_with(err.message, longname + 1) && contains(err.message, "spec.lua:2: x"), "%s", err.message);
    vigen_sandbox_free(sb);

    /* missing file */
    CHECK(vigen_sandbox_new(&sb, NULL, NULL, &err) == VIGEN_OK);
    CHECK(vigen_sandbox_run_file(sb, "/nonexistent/dir/spec.lua", &err) == VIGEN_E_IO);
    CHECK(contains(err.message, "/nonexistent/dir/spec.lua"));
    vigen_sandbox_free(sb);
    vigen_error_clear(&err);
}

static void test_escapes(void)
{
    static const char *const names[] = { "io", "os", "require", "load", "dofile", "loadfile", "debug",
                                         "package", "utf8", "coroutine", "collectgarbage", "loadstring", NULL };
    for (int i = 0; names[i]; i++) {
        char *text = vigen_strdup_printf("local f = %s\nreturn 1", names[i]);
        char *phrase = vigen_strdup_printf("spec.lua:1: unknown name '%s'", names[i]);
        EXPECT(text, NULL, VIGEN_E_LUA, phrase);
        free(text);
        free(phrase);
    }
    vigen_error err;
    vigen_error_init(&err);
    /* not even through rawget, the string metatable or a library table */
    CHECK(run("assert(rawget(_G, 'io') == nil and rawget(_G, 'os') == nil and rawget(_G, 'debug') == nil)\n"
              "assert(string.dump == nil and getmetatable('').__index.dump == nil)\n"
              "assert(rawget(_G, 'load') == nil and rawget(_G, 'require') == nil)\n"
              "return true", NULL, &err) == VIGEN_OK);
    /* the safe libraries are there */
    CHECK(run("return math.floor(2.5) + #string.rep('a', 3) + #table.concat({'x', 'y'}) + select('#', 1, 2)",
              NULL, &err) == VIGEN_OK);

    /* precompiled chunks are refused: make one in an ordinary Lua state */
    lua_State *plain = luaL_newstate();
    luaL_openlibs(plain);
    CHECK(luaL_dostring(plain, "return string.dump(function() return 1 end)") == LUA_OK);
    size_t len;
    const char *bytecode = lua_tolstring(plain, -1, &len);
    CHECK(len > 4 && bytecode[0] == LUA_SIGNATURE[0]);
    vigen_sandbox *sb = NULL;
    CHECK(vigen_sandbox_new(&sb, NULL, NULL, &err) == VIGEN_OK);
    CHECK(vigen_sandbox_run_string(sb, bytecode, "@spec.luac", &err) == VIGEN_E_SYNTAX);
    CHECK_MSG(contains(err.message, "spec.luac") && contains(err.message, "precompiled"), "%s", err.message);
    vigen_sandbox_free(sb);
    lua_close(plain);
    vigen_error_clear(&err);
}

static void test_instruction_cap(void)
{
    vigen_error err;
    vigen_error_init(&err);
    /* the default cap, and its message */
    CHECK(run("local n = 0\nwhile true do n = n + 1 end", NULL, &err) == VIGEN_E_LIMIT);
    CHECK_MSG(starts_with(err.message, "spec.lua: the file ran for more than 50000000 Lua instructions") &&
              contains(err.message, "line 2"), "%s", err.message);

    vigen_sandbox_limits lim;
    vigen_sandbox_limits_default(&lim);
    lim.instruction_limit = 1000000;
    EXPECT("while true do end", &lim, VIGEN_E_LIMIT, "more than 1000000 Lua instructions");
    /* pcall cannot swallow the cap */
    EXPECT("while true do pcall(function() while true do end end) end", &lim, VIGEN_E_LIMIT, "instructions");
    EXPECT("while true do xpcall(function() while true do end end, function(m) return m end) end", &lim,
           VIGEN_E_LIMIT, "instructions");
    /* endless tail calls and deep recursion stop, without crashing */
    EXPECT("local function f() return f() end return f()", &lim, VIGEN_E_LIMIT, "instructions");
    CHECK(run("local function f(n) return 1 + f(n + 1) end return f(1)", NULL, &err) != VIGEN_OK);
    CHECK_MSG(starts_with(err.message, "spec.lua") && contains(err.message, "overflow"), "%s", err.message);
    CHECK(run("local t = setmetatable({}, {__index = function(t, k) return t[k] end}) return t.x", NULL, &err)
          != VIGEN_OK);
    CHECK_MSG(contains(err.message, "overflow"), "%s", err.message);
    CHECK(run("local function f(s) return (string.gsub(s, '.', f)) end return f('ab')", NULL, &err) != VIGEN_OK);

    /* what Lua runs with hooks off, or in C, is refused: __gc finalisers, patterns */
    EXPECT("local x = setmetatable({}, {__gc = function() while true do end end}) return 1", &lim, VIGEN_E_LUA,
           "__gc finalisers are not allowed");
    CHECK(run("local mt = {} local x = setmetatable({}, mt) mt.__gc = function() while true do end end\n"
              "x = nil return setmetatable({}, {__index = function() return 1 end}).y", &lim, &err) == VIGEN_OK);
    EXPECT("return string.rep('a', 3000):find('.-.-.-b')", &lim, VIGEN_E_LUA, "string.find is not available");
    EXPECT("return ('x'):gsub('x', 'y')", &lim, VIGEN_E_LUA, "string.gsub is not available");
    EXPECT("return string.match('x', 'x')", &lim, VIGEN_E_LUA, "string.match is not available");
    EXPECT("return string.gmatch('x', 'x')", &lim, VIGEN_E_LUA, "string.gmatch is not available");
    /* to-be-closed variables run under the cap */
    EXPECT("do local x <close> = setmetatable({}, {__close = function() while true do end end}) end", &lim,
           VIGEN_E_LIMIT, "instructions");
    EXPECT("local x <close> = setmetatable({}, {__close = function() while true do end end}) error('x')", &lim,
           VIGEN_E_LIMIT, "instructions");

    /* the budget is per top-level call: two calls of ~0.7 cap each both succeed */
    vigen_sandbox *sb = NULL;
    CHECK(vigen_sandbox_new(&sb, &lim, NULL, &err) == VIGEN_OK);
    lua_State *L = vigen_sandbox_state(sb);
    CHECK(vigen_sandbox_run_string(sb, "return function() local n = 0 for i = 1, 170000 do n = n + i end return n end",
                                   "@spec.lua", &err) == VIGEN_OK);
    for (int k = 0; k < 3; k++) {
        lua_pushvalue(L, -1);
        CHECK_MSG(vigen_sandbox_pcall(sb, 0, 1, &err) == VIGEN_OK, "%s", err.message);
        CHECK(lua_tointeger(L, -1) == (lua_Integer)170000 * 170001 / 2);
        lua_pop(L, 1);
    }
    /* after a cap the sandbox still works */
    CHECK(vigen_sandbox_run_string(sb, "while true do end", "@spec.lua", &err) == VIGEN_E_LIMIT);
    lua_pushvalue(L, -1);
    CHECK(vigen_sandbox_pcall(sb, 0, 1, &err) == VIGEN_OK);
    lua_pop(L, 2);
    CHECK(lua_gettop(L) == 0);
    vigen_sandbox_free(sb);

    /* an ordinary runtime error is not a cap */
    CHECK(run("error('x')", &lim, &err) == VIGEN_E_LUA);
    vigen_error_clear(&err);
}

/* A cap cannot be caught: pcall and xpcall rethrow it, no message handler of
 * the file runs for it, and the rest of the call raises at once. */
static void test_caps_unwind(void)
{
    vigen_error err;
    vigen_error_init(&err);
    vigen_sandbox_limits lim;
    vigen_sandbox_limits_default(&lim);
    lim.instruction_limit = 1000000;
    /* a handler that never returns (Lua runs it with hooks off after a cap) */
    EXPECT("xpcall(function() while true do end end, function(m) while true do end end)", &lim, VIGEN_E_LIMIT,
           "more than 1000000 Lua instructions");
    /* the same handler for an ordinary error: it runs, under the cap */
    EXPECT("xpcall(function() error('x') end, function(m) while true do end end)", &lim, VIGEN_E_LIMIT,
           "more than 1000000 Lua instructions");
    /* a handler that raises again, a handler that answers, nested pcalls */
    EXPECT("for i = 1, 1e9 do xpcall(function() while true do end end, function(m) error(m) end) end", &lim,
           VIGEN_E_LIMIT, "instructions");
    EXPECT("local ok, e = xpcall(function() while true do end end, function() return 'handled' end)\n"
           "return e", &lim, VIGEN_E_LIMIT, "instructions");
    EXPECT("local ok = pcall(pcall, pcall, function() while true do end end) return ok", &lim, VIGEN_E_LIMIT,
           "instructions");
    /* the error object stays the cap's: a table with __tostring does not replace it */
    EXPECT("local hang = setmetatable({}, {__tostring = function() while true do end end})\n"
           "local ok, e = xpcall(function() while true do end end, function() return hang end) error(e)", &lim,
           VIGEN_E_LIMIT, "instructions");
    /* without a cap, pcall and xpcall behave as Lua's own */
    CHECK(run("local ok, e = pcall(error, 'x', 0) assert(not ok and e == 'x')\n"
              "local a, b, c = pcall(function(...) return ... end, 1, 2) assert(a == true and b == 1 and c == 2)\n"
              "local ok2, e2 = xpcall(function() error({code = 7}) end, function(o) return o.code * 6 end)\n"
              "assert(not ok2 and e2 == 42)\n"
              "local ok3, e3 = xpcall(function(a, b) return a + b end, print, 40, 2) assert(ok3 and e3 == 42)\n"
              "local ok4, e4 = xpcall(error, function(m) error(m) end, 'y')\n"
              "assert(not ok4)\n"
              "local ok5 = pcall(error, setmetatable({}, {__tostring = function() return 'obj' end}))\n"
              "assert(not ok5) return 1", &lim, &err) == VIGEN_OK);
    CHECK_MSG(err.message == NULL || err.message[0] == 0, "%s", err.message);
    EXPECT("return xpcall(print)", &lim, VIGEN_E_LUA, "bad argument #2");
    EXPECT("return pcall()", &lim, VIGEN_E_LUA, "bad argument #1");
    vigen_error_clear(&err);
}

/* Library functions whose loops in C take a count from the file: the work is
 * charged to the instruction budget before it is done. */
static void test_library_loops(void)
{
    vigen_error err;
    vigen_error_init(&err);
    vigen_sandbox_limits lim;
    vigen_sandbox_limits_default(&lim);
    lim.instruction_limit = 1000000;
    const char *huge_len = "local t = setmetatable({}, {__len = function() return 1 << 40 end})\n";
    static const char *const hostile[] = {
        "table.move({}, 1, 1 << 40, 2)",
        "table.move({}, math.mininteger + 1, -1, 1)",
        "table.sort(setmetatable({}, {__len = function() return (1 << 31) - 2 end, __index = rawlen,"
        " __newindex = rawequal}))",
        "table.sort({3, 2, 1}, function(a, b) while true do end end)",
        "table.concat(setmetatable({}, {__index = rawlen}), '', 1, 1 << 40)",
        "table.concat(setmetatable({}, {__index = rawlen, __len = function() return 1 << 40 end}))",
        "local t = setmetatable({}, {__index = rawlen})\n"
        "for i = 1, 1e9 do local n = select('#', table.unpack(t, 1, 999000)) end",
        "local s = string.rep('x', 999000) for i = 1, 1e9 do local n = select('#', s:byte(1, -1)) end",
        "local function f(...) for i = 1, 1e9 do local n = select('#', ...) end end\n"
        "f(string.byte(string.rep('x', 400000), 1, -1))",
        "local s = string.rep('0', 1 << 24) for i = 1, 1e9 do local x = tonumber(s) end",
        "local s = string.rep('x', 1 << 24) for i = 1, 1e9 do local t = s .. 'y' end",
        "local s = string.rep('x', 1 << 24) for i = 1, 1e9 do local t = string.rep(s, 2) end",
        NULL,
    };
    for (int i = 0; hostile[i]; i++) EXPECT(hostile[i], &lim, VIGEN_E_LIMIT, "more than 1000000 Lua instructions");
    /* #t is read once for the charge and passed on: a length that grows on its second reading is not used */
    char *text = vigen_strdup_printf("%s%s", huge_len, "table.insert(t, 1, 'x')");
    EXPECT(text, &lim, VIGEN_E_LIMIT, "instructions");
    free(text);
    text = vigen_strdup_printf("%s%s", huge_len, "table.remove(t, 1)");
    EXPECT(text, &lim, VIGEN_E_LIMIT, "instructions");
    free(text);
    CHECK_MSG(run("local n = 0 local t = setmetatable({}, {__len = function() n = n + 1\n"
                  "  return n == 1 and 2 or 1 << 40 end, __index = rawlen})\n"
                  "assert(table.concat(t) == '00') return 1", &lim, &err) == VIGEN_OK, "%s", err.message);
    /* the wrapped functions still do what Lua's do */
    CHECK_MSG(run("local t = {5, 3, 4, 1, 2} table.sort(t) assert(table.concat(t, ',') == '1,2,3,4,5')\n"
                  "table.sort(t, function(a, b) return a > b end) assert(table.concat(t) == '54321')\n"
                  "assert(table.concat({1, 2, 3}, '-', 2) == '2-3' and table.concat({}, 'x') == '')\n"
                  "local m = table.move({1, 2, 3}, 1, 3, 2) assert(table.concat(m) == '1123')\n"
                  "local a, b, c = table.unpack({7, 8, 9}, 2) assert(a == 8 and b == 9 and c == nil)\n"
                  "local u = {1, 2, 3} table.insert(u, 1, 0) table.insert(u, 4) assert(table.concat(u) == '01234')\n"
                  "assert(table.remove(u, 1) == 0 and table.remove(u) == 4 and table.concat(u) == '123')\n"
                  "assert(table.remove({}) == nil and select('#', string.byte('abc', 1, -1)) == 3)\n"
                  "assert(select(2, 'a', 'b', 'c') == 'b' and select('#') == 0 and select(-1, 1, 2) == 2)\n"
                  "assert(tonumber('0x10') == 16 and tonumber('z', 36) == 35 and tonumber('x') == nil)\n"
                  "assert(string.byte('A') == 65 and ('abc'):byte(-1) == 99 and ('abc'):byte(10) == nil)\n"
                  "return 1", &lim, &err) == VIGEN_OK, "%s", err.message);
    EXPECT("table.insert({1}, 5, 'x')", &lim, VIGEN_E_LUA, "position out of bounds");
    EXPECT("table.move({}, math.mininteger, -1, 1)", &lim, VIGEN_E_LUA, "too many elements to move");
    EXPECT("table.insert({1}, 1, 2, 3)", &lim, VIGEN_E_LUA, "wrong number of arguments to 'insert'");
    EXPECT("table.sort({1, 'x'})", &lim, VIGEN_E_LUA, "attempt to compare");
    EXPECT("table.sort({3, 2, 1}, function(a, b) error('comparator fails') end)", &lim, VIGEN_E_LUA,
           "comparator fails");
    /* string.format refuses widths and precisions over two digits */
    EXPECT("return string.format('%099999999d', 1)", &lim, VIGEN_E_LUA, "invalid conversion");
    EXPECT("return string.format('%.99999999f', 1)", &lim, VIGEN_E_LUA, "invalid conversion");
    /* binary packing is not offered */
    EXPECT("return string.pack('i4', 1)", &lim, VIGEN_E_LUA, "string.pack is not available");
    EXPECT("return string.packsize(string.rep('b', 1000))", &lim, VIGEN_E_LUA, "string.packsize is not available");
    EXPECT("return string.unpack('b', 'x')", &lim, VIGEN_E_LUA, "string.unpack is not available");
    vigen_error_clear(&err);
}

static void test_memory_cap(void)
{
    vigen_error err;
    vigen_error_init(&err);
    /* string.rep bomb at the default cap */
    CHECK(run("return string.rep('x', 1 << 30)", NULL, &err) == VIGEN_E_LIMIT);
    CHECK_MSG(starts_with(err.message, "spec.lua: the file used more than 256 MiB of memory"), "%s", err.message);

    /* refused before it is built, as the memory cap */
    CHECK(run("return string.rep('x', 1 << 40)", NULL, &err) == VIGEN_E_LIMIT);
    /* an empty string repeated 2^50 times is "" at once (Lua's own loop would spin for days) */
    CHECK(run("assert(string.rep('', 1 << 50) == '' and ('').rep('', 1 << 50, '') == '') return 1", NULL, &err) == VIGEN_OK);

    vigen_sandbox_limits lim;
    vigen_sandbox_limits_default(&lim);
    lim.memory_limit = (size_t)16 << 20;
    EXPECT("local s = 'x' while true do s = s .. s end", &lim, VIGEN_E_LIMIT, "more than 16 MiB of memory");
    /* table-growth bombs */
    EXPECT("local t = {} for i = 1, 1e9 do t[i] = i end", &lim, VIGEN_E_LIMIT, "16 MiB");
    EXPECT("local t = {} for i = 1, 1e9 do t[i] = string.rep('x', 1000) .. i end", &lim, VIGEN_E_LIMIT, "memory");
    EXPECT("local t = {} for i = 1, 1e9 do t[i] = {i} end", &lim, VIGEN_E_LIMIT, "memory");
    /* a caught memory error is not swallowed: pcall rethrows it, as the memory cap */
    lim.instruction_limit = 5000000;
    EXPECT("while true do pcall(string.rep, 'x', 1 << 30) end", &lim, VIGEN_E_LIMIT, "16 MiB of memory");
    EXPECT("local ok = pcall(function() local t = {} for i = 1, 1e9 do t[i] = {i} end end)\n"
           "if not ok then while true do end end", &lim, VIGEN_E_LIMIT, "16 MiB of memory");
    EXPECT("xpcall(function() local t = {} for i = 1, 1e9 do t[i] = {i} end end, function(m) return 1 end)\n"
           "return 1", &lim, VIGEN_E_LIMIT, "16 MiB of memory");
    /* a sandbox that hit the cap works afterwards */
    vigen_sandbox *sb = NULL;
    lim.instruction_limit = 50000000;
    CHECK(vigen_sandbox_new(&sb, &lim, NULL, &err) == VIGEN_OK);
    CHECK(vigen_sandbox_run_string(sb, "local t = {} for i = 1, 1e9 do t[i] = i end", "@spec.lua", &err)
          == VIGEN_E_LIMIT);
    CHECK(vigen_sandbox_run_string(sb, "return #string.rep('y', 1000)", "@spec.lua", &err) == VIGEN_OK);
    lua_pop(vigen_sandbox_state(sb), 1);
    vigen_sandbox_free(sb);
    /* the cap is distinguished from other errors */
    CHECK(run("error('not enough memory')", &lim, &err) == VIGEN_E_LUA);
    vigen_error_clear(&err);
}

/* A vocabulary of one word, to see what the sandbox does with any. */
static int toy_word(lua_State *L)
{
    lua_pushinteger(L, 42);
    return 1;
}

static int toy_vocabulary(lua_State *L)
{
    lua_pushcfunction(L, toy_word);
    lua_setglobal(L, "answer");
    lua_pushliteral(L, "toy words: answer");
    return 1;
}

static int failing_vocabulary(lua_State *L) { return luaL_error(L, "no words today"); }

/* Runs text in a fresh sandbox with this vocabulary; the message stays in err. */
static int run_with(lua_CFunction vocabulary, const char *text, vigen_error *err)
{
    vigen_sandbox *sb = NULL;
    vigen_error_clear(err);
    int code = vigen_sandbox_new(&sb, NULL, vocabulary, err);
    if (code == VIGEN_OK) code = vigen_sandbox_run_string(sb, text, "@file.lua", err);
    vigen_sandbox_free(sb);
    return code;
}

static void test_vocabulary_mechanism(void)
{
    vigen_error err;
    vigen_error_init(&err);
    /* no vocabulary: the families are unknown, the message lists the functions only */
    CHECK(run_with(NULL, "return gauss_legendre(3)", &err) == VIGEN_E_LUA);
    CHECK_MSG(err.message && strcmp(err.message, "file.lua:1: unknown name 'gauss_legendre' (functions: sqrt, exp, "
                                                 "log, sin, cos, tan, pi, exact)") == 0, "%s", err.message);
    /* a vocabulary's globals are there, and its text comes first in the message */
    CHECK(run_with(toy_vocabulary, "return answer() == 42 and sin ~= nil", &err) == VIGEN_OK);
    CHECK(run_with(toy_vocabulary, "return answr", &err) == VIGEN_E_LUA);
    CHECK_MSG(err.message && strcmp(err.message, "file.lua:1: unknown name 'answr' (toy words: answer; functions: "
                                                 "sqrt, exp, log, sin, cos, tan, pi, exact)") == 0, "%s", err.message);
    /* a vocabulary that fails leaves no sandbox */
    vigen_sandbox *sb = NULL;
    CHECK(vigen_sandbox_new(&sb, NULL, failing_vocabulary, &err) == VIGEN_E_LUA && sb == NULL);
    CHECK_MSG(starts_with(err.message, "cannot set up the Lua sandbox: ") && contains(err.message, "no words today"),
              "%s", err.message);
    vigen_error_clear(&err);
}

static void test_vocabulary(void)
{
    vigen_error err;
    vigen_error_init(&err);
    /* strict globals, with the vocabulary in the message */
    CHECK(run("local x = 1\nreturn { nodes = gauss(3) }", NULL, &err) == VIGEN_E_LUA);
    CHECK_MSG(starts_with(err.message, "spec.lua:2: unknown name 'gauss' (node families: gauss_legendre, ") &&
              contains(err.message, "basis families: monomials, trig, legendre, chebyshev_t") &&
              contains(err.message, "functions: sqrt, exp, log, sin, cos, tan, pi, exact)"), "%s", err.message);

    /* every family constructor makes a descriptor that says what it is */
    static const char *const node_names[] = { "gauss_legendre", "gauss_lobatto", "radau_left", "radau_right",
                                              "chebyshev_quadrature", "chebyshev_gauss", "chebyshev_lobatto",
                                              "equispaced", NULL };
    static const char *const basis_names[] = { "monomials", "trig", "legendre", "chebyshev_t", NULL };
    vigen_sandbox *sb = NULL;
    CHECK(vigen_sandbox_new(&sb, NULL, vigen_vocabulary_open, &err) == VIGEN_OK);
    lua_State *L = vigen_sandbox_state(sb);
    for (int pass = 0; pass < 2; pass++) {
        const char *const *names = pass ? basis_names : node_names;
        for (int i = 0; names[i]; i++) {
            char *text = vigen_strdup_printf("return %s(%d)", names[i], i + 2);
            CHECK_MSG(vigen_sandbox_run_string(sb, text, "@spec.lua", &err) == VIGEN_OK, "%s", err.message);
            int kind = 0;
            const char *family = NULL;
            long s = 0;
            CHECK(vigen_vocabulary_get_family(L, -1, &kind, &family, &s) == 1);
            CHECK(kind == (pass ? VIGEN_FAMILY_BASIS : VIGEN_FAMILY_NODES));
            CHECK(family && strcmp(family, names[i]) == 0);
            CHECK(s == i + 2);
            lua_pop(L, 1);
            free(text);
        }
    }
    CHECK(vigen_sandbox_run_string(sb, "return tostring(gauss_legendre(3)) .. ' ' .. tostring(trig(5))",
                                   "@spec.lua", &err) == VIGEN_OK);
    CHECK(strcmp(lua_tostring(L, -1), "gauss_legendre(3) trig(5)") == 0);
    lua_pop(L, 1);
    /* plain values are not families */
    CHECK(vigen_sandbox_run_string(sb, "return {kind = 'nodes', family = 'gauss_legendre', s = 3}", "@spec.lua",
                                   &err) == VIGEN_OK);
    CHECK(vigen_vocabulary_get_family(L, -1, NULL, NULL, NULL) == 0);
    lua_pop(L, 1);
    CHECK(vigen_sandbox_run_string(sb, "return exact('1/2')", "@spec.lua", &err) == VIGEN_OK);
    CHECK(vigen_vocabulary_get_family(L, -1, NULL, NULL, NULL) == 0);
    lua_pop(L, 1);
    vigen_sandbox_free(sb);

    /* s must be a Lua integer >= 1 */
    EXPECT("return gauss_legendre(2.5)", NULL, VIGEN_E_LUA, "not the float 2.5");
    EXPECT("return gauss_legendre(3.0)", NULL, VIGEN_E_LUA, "not the float 3.0");
    EXPECT("return trig(1/3)", NULL, VIGEN_E_LUA, "0.3333333333333333");
    EXPECT("return gauss_legendre(0)", NULL, VIGEN_E_LUA, "must be >= 1");
    EXPECT("return legendre(-2)", NULL, VIGEN_E_LUA, "must be >= 1");
    EXPECT("return gauss_legendre()", NULL, VIGEN_E_LUA, "needs the number of nodes");
    EXPECT("return trig()", NULL, VIGEN_E_LUA, "needs the number of basis functions");
    EXPECT("return gauss_legendre('3')", NULL, VIGEN_E_LUA, "not a string");
    EXPECT("return trig(3, 4)", NULL, VIGEN_E_LUA, "takes one argument");
    EXPECT("return equispaced(100000)", NULL, VIGEN_E_LUA, "at most");
    EXPECT("\nreturn gauss_legendre(2.5)", NULL, VIGEN_E_LUA, "spec.lua:2:");

    /* print exists (it writes to stderr, never to stdout) */
    CHECK(run("return type(print) == 'function'", NULL, &err) == VIGEN_OK);
    vigen_error_clear(&err);
}

static void test_float_format(void)
{
    static const struct { double x; const char *text; } cases[] = {
        { 1.0 / 3.0, "0.3333333333333333" }, { 0.5, "0.5" }, { 3.0, "3.0" }, { -2.0, "-2.0" },
        { 0.1, "0.1" }, { 1e300, "1e+300" }, { 2.0 / 3.0, "0.6666666666666666" }, { 0.0, "0.0" },
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        size_t n = vigen_float_format(NULL, 0, cases[i].x);
        char *buf = malloc(n + 1);
        CHECK(vigen_float_format(buf, n + 1, cases[i].x) == n);
        CHECK_MSG(strcmp(buf, cases[i].text) == 0, "%s vs %s", buf, cases[i].text);
        free(buf);
    }
    char small[4];
    CHECK(vigen_float_format(small, sizeof small, 1.0 / 3.0) == 18 && strcmp(small, "0.3") == 0);
}

/* A literal from vigen_lua_quote, read back by Lua, is the text itself. */
static void test_quote(void)
{
    static const char *const texts[] = {
        "1/2 - sqrt(3)/6", "", "say \"hi\"", "back\\slash", "\nleading newline", "a]]b", "a]]b]=]c]==]",
        "line\r\nbreak", "{\"0\", \"1/2\"}", "\x1b[31mred\x1b[0m", "bell\a", "del\x7f", "new\nline]", "new\nline]=", "]\n]]",
    };
    vigen_error err;
    vigen_error_init(&err);
    for (size_t i = 0; i < sizeof texts / sizeof texts[0]; i++) {
        vigen_strbuf chunk;
        vigen_strbuf_init(&chunk);
        vigen_strbuf_append(&chunk, "return ");
        vigen_lua_quote(&chunk, texts[i]);
        vigen_sandbox *sb = NULL;
        CHECK(vigen_sandbox_new(&sb, NULL, NULL, &err) == VIGEN_OK);
        int code = sb ? vigen_sandbox_run_string(sb, chunk.data, "@quote.lua", &err) : VIGEN_E_MEMORY;
        CHECK_MSG(code == VIGEN_OK, "%s: %s", chunk.data, err.message);
        if (code == VIGEN_OK) {
            lua_State *L = vigen_sandbox_state(sb);
            size_t len;
            const char *back = lua_tolstring(L, -1, &len);
            CHECK_MSG(back && len == strlen(texts[i]) && memcmp(back, texts[i], len) == 0, "%s", chunk.data);
        }
        vigen_error_clear(&err);
        vigen_sandbox_free(sb);
        vigen_strbuf_clear(&chunk);
    }
    /* control characters never stand raw in a literal (the file may be shown
     * on a terminal) */
    for (size_t i = 0; i < sizeof texts / sizeof texts[0]; i++) {
        vigen_strbuf q;
        vigen_strbuf_init(&q);
        vigen_lua_quote(&q, texts[i]);
        int raw = 0;
        for (size_t k = 0; k < q.len; k++) {
            unsigned char ch = (unsigned char)q.data[k];
            if ((ch < 32 && ch != '\n') || ch == 127) raw = 1;
        }
        CHECK_MSG(!raw, "a raw control character in %s", q.data);
        vigen_strbuf_clear(&q);
    }
    /* text that needs no escape stays a plain "..." literal */
    vigen_strbuf b;
    vigen_strbuf_init(&b);
    vigen_lua_quote(&b, "1/3");
    CHECK(strcmp(b.data, "\"1/3\"") == 0);
    vigen_strbuf_clear(&b);
}

/* ------------------------------------------------------------------ balls */

/* Evaluates the Lua function returned by chunk at t; res gets the value. */
static int call_fn(const char *chunk, const acb_t t, int analytic, slong prec, acb_t res, vigen_error *err)
{
    vigen_sandbox *sb = NULL;
    vigen_error_clear(err);
    int code = vigen_sandbox_new(&sb, NULL, NULL, err);
    if (code != VIGEN_OK) return code;
    lua_State *L = vigen_sandbox_state(sb);
    code = vigen_sandbox_run_string(sb, chunk, "@spec.lua", err);
    if (code == VIGEN_OK) {
        vigen_ball_set_context(L, prec, analytic);
        vigen_ball_push(L, t);
        code = vigen_sandbox_pcall(sb, 1, 1, err);
        if (code == VIGEN_OK) {
            if (!vigen_ball_get(res, L, -1)) code = vigen_error_set(err, VIGEN_E_SPEC, "not a ball");
            lua_pop(L, 1);
        }
    }
    CHECK(lua_gettop(L) == 0);
    vigen_sandbox_free(sb);
    return code;
}

static void acb_set_q(acb_t z, slong p, slong q, slong prec)
{
    fmpq_t r;
    fmpq_init(r);
    fmpq_set_si(r, p, (ulong)q);
    acb_zero(z);
    arb_set_fmpq(acb_realref(z), r, prec);
    fmpq_clear(r);
}

static int real_contains_q(const acb_t z, slong p, slong q)
{
    fmpq_t r;
    fmpq_init(r);
    fmpq_set_si(r, p, (ulong)q);
    int ok = arb_contains_fmpq(acb_realref(z), r) && arb_contains_zero(acb_imagref(z));
    fmpq_clear(r);
    return ok;
}

static int radius_below(const acb_t z, slong e)
{
    return mag_cmp_2exp_si(arb_radref(acb_realref(z)), e) <= 0 && mag_cmp_2exp_si(arb_radref(acb_imagref(z)), e) <= 0;
}

static void test_balls(void)
{
    slong prec = 128;
    vigen_error err;
    vigen_error_init(&err);
    acb_t t, r;
    acb_init(t);
    acb_init(r);

    /* cos(pi t) at t = 1/3 is 1/2 */
    acb_set_q(t, 1, 3, prec);
    CHECK(call_fn("return function(t) return cos(pi*t) end", t, 0, prec, r, &err) == VIGEN_OK);
    CHECK(real_contains_q(r, 1, 2) && radius_below(r, -100));
    CHECK(call_fn("return function(t) return ball.cos(ball.pi*t) end", t, 1, prec, r, &err) == VIGEN_OK);
    CHECK(real_contains_q(r, 1, 2) && radius_below(r, -100));

    /* t^2/3 at 1/2 is 1/12: integer arithmetic on balls is exact up to rounding */
    acb_set_q(t, 1, 2, prec);
    CHECK(call_fn("return function(t) return t^2/3 end", t, 0, prec, r, &err) == VIGEN_OK);
    CHECK(real_contains_q(r, 1, 12) && radius_below(r, -120) && arb_is_zero(acb_imagref(r)));
    CHECK(call_fn("return function(t) return t/3 end", t, 0, prec, r, &err) == VIGEN_OK);
    CHECK(real_contains_q(r, 1, 6) && radius_below(r, -120));
    CHECK(call_fn("return function(t) return 2 - t + 1 * t * 4 - -t end", t, 0, prec, r, &err) == VIGEN_OK);
    CHECK(real_contains_q(r, 4, 1) && radius_below(r, -120));
    CHECK(call_fn("return function(t) return t^-2 + 2^t * 0 end", t, 0, prec, r, &err) == VIGEN_OK);
    CHECK(real_contains_q(r, 4, 1));
    CHECK(call_fn("return function(t) return exact('1/3') * 3 - t end", t, 0, prec, r, &err) == VIGEN_OK);
    CHECK(real_contains_q(r, 1, 2) && radius_below(r, -120));
    CHECK(call_fn("return function(t) return exact(1) + exp(0) + log(1) + sin(0) + tan(0) + sqrt(4) end", t, 0,
                  prec, r, &err) == VIGEN_OK);
    CHECK(real_contains_q(r, 4, 1));
    CHECK(call_fn("return function(t) return t^exact('1/2') * sqrt(t) end", t, 0, prec, r, &err) == VIGEN_OK);
    CHECK(real_contains_q(r, 1, 2) && radius_below(r, -100));

    /* a Lua float never enters ball arithmetic */
    CHECK(call_fn("return function(t)\n  return (1/3)*t\nend", t, 0, prec, r, &err) == VIGEN_E_LUA);
    CHECK_MSG(starts_with(err.message, "spec.lua:2: basis function: a Lua float (0.3333333333333333) met a ball; "
                                       "Lua's 1/3 is a rounded double: write exact(\"1/3\") or t/3"),
              "%s", err.message);
    CHECK(call_fn("return function(t) return t + 0.5 end", t, 0, prec, r, &err) == VIGEN_E_LUA);
    CHECK(contains(err.message, "Lua float (0.5)"));
    CHECK(call_fn("return function(t) return t * math.pi end", t, 0, prec, r, &err) == VIGEN_E_LUA);
    CHECK(contains(err.message, "exact(\"1/3\")"));
    CHECK(call_fn("return function(t) return t ^ 0.5 end", t, 0, prec, r, &err) == VIGEN_E_LUA);
    CHECK(call_fn("return function(t) return sqrt(0.5) end", t, 0, prec, r, &err) == VIGEN_E_LUA);
    CHECK(contains(err.message, "sqrt") && contains(err.message, "0.5"));
    CHECK(call_fn("return function(t) return exact(0.5) end", t, 0, prec, r, &err) == VIGEN_E_LUA);
    CHECK(contains(err.message, "exact(") && contains(err.message, "0.5"));
    CHECK(call_fn("return function(t) return exact('1/') end", t, 0, prec, r, &err) == VIGEN_E_LUA);
    CHECK(contains(err.message, "exact(\"1/\")"));
    CHECK(call_fn("return function(t) return exact('t') end", t, 0, prec, r, &err) == VIGEN_E_LUA);
    CHECK(call_fn("return function(t) return t + 'x' end", t, 0, prec, r, &err) == VIGEN_E_LUA);
    CHECK(contains(err.message, "string"));
    CHECK(call_fn("return function(t) return t + {} end", t, 0, prec, r, &err) == VIGEN_E_LUA);
    CHECK(call_fn("return function(t) return sqrt() end", t, 0, prec, r, &err) == VIGEN_E_LUA);
    CHECK(call_fn("return function(t) return ball.nope end", t, 0, prec, r, &err) == VIGEN_E_LUA);
    CHECK(contains(err.message, "ball.nope"));

    /* balls cannot be compared */
    CHECK(call_fn("return function(t) if t < 1 then return t end return 0 end", t, 0, prec, r, &err)
          == VIGEN_E_LUA);
    CHECK(contains(err.message, "cannot be compared"));
    CHECK(call_fn("return function(t) if t <= t * 1 then return t end return 0 end", t, 0, prec, r, &err)
          == VIGEN_E_LUA);
    CHECK(call_fn("return function(t) if t == t * 1 then return t end return 0 end", t, 0, prec, r, &err)
          == VIGEN_E_LUA);
    CHECK(contains(err.message, "cannot be compared"));
    CHECK(call_fn("return function(t) return getmetatable(t) == 'ball' and t or 0 end", t, 0, prec, r, &err)
          == VIGEN_OK && real_contains_q(r, 1, 2));

    /* tostring */
    CHECK(call_fn("return function(t) assert(tostring(t) == '0.5') "
                  "assert(tostring(t + 6) == '6.5') assert(tostring(sqrt(-t)):sub(-2) == '*i') return t end", t, 0, prec, r, &err) == VIGEN_OK);

    /* analytic mode: holomorphic on a real ball, indeterminate across the branch cut */
    acb_set_q(t, 1, 4, prec);
    mag_set_ui_2exp_si(arb_radref(acb_realref(t)), 1, -20);
    CHECK(call_fn("return function(t) return sqrt(t) end", t, 1, prec, r, &err) == VIGEN_OK);
    CHECK(real_contains_q(r, 1, 2) && acb_is_finite(r));
    CHECK(call_fn("return function(t) return log(t) + t^exact('1/3') end", t, 1, prec, r, &err) == VIGEN_OK);
    CHECK(acb_is_finite(r));
    acb_set_q(t, -1, 1, prec);
    mag_set_ui_2exp_si(arb_radref(acb_imagref(t)), 1, -20);
    CHECK(call_fn("return function(t) return sqrt(t) end", t, 1, prec, r, &err) == VIGEN_OK);
    CHECK(!acb_is_finite(r));
    CHECK(call_fn("return function(t) return log(t) end", t, 1, prec, r, &err) == VIGEN_OK);
    CHECK(!acb_is_finite(r));
    CHECK(call_fn("return function(t) return t^exact('1/2') end", t, 1, prec, r, &err) == VIGEN_OK);
    CHECK(!acb_is_finite(r));
    CHECK(call_fn("return function(t) return t^2 end", t, 1, prec, r, &err) == VIGEN_OK);
    CHECK(acb_is_finite(r));   /* integer powers are entire */
    CHECK(call_fn("return function(t) return sqrt(t) end", t, 0, prec, r, &err) == VIGEN_OK);
    CHECK(acb_is_finite(r));   /* without the flag: the principal branch */

    /* the precision comes from the context: pi at 300 bits */
    CHECK(call_fn("return function(t) return pi end", t, 0, 300, r, &err) == VIGEN_OK);
    acb_t p;
    acb_init(p);
    acb_const_pi(p, 400);
    CHECK(acb_overlaps(r, p) && radius_below(r, -290) && !radius_below(r, -350));
    acb_clear(p);

    /* balls and failed exact() calls piling up until a cap: nothing leaks (run under valgrind) */
    vigen_sandbox_limits lim;
    vigen_sandbox_limits_default(&lim);
    lim.memory_limit = (size_t)8 << 20;
    lim.instruction_limit = 2000000;
    EXPECT("local t = exact('1/3') local a = {} while true do a[#a + 1] = t * t + sqrt(t) end", &lim, VIGEN_E_LIMIT,
           "memory");
    EXPECT("local a = {} while true do a[#a + 1] = tostring(exact('1/3')) .. #a end", &lim, VIGEN_E_LIMIT, "memory");
    EXPECT("while true do pcall(exact, '1/') pcall(exact, 'sqrt(-1)') end", &lim, VIGEN_E_LIMIT, "instructions");

    /* vigen_ball_get: balls and integers only */
    vigen_sandbox *sb = NULL;
    CHECK(vigen_sandbox_new(&sb, NULL, NULL, &err) == VIGEN_OK);
    lua_State *L = vigen_sandbox_state(sb);
    lua_pushinteger(L, -7);
    CHECK(vigen_ball_get(r, L, -1) == 1 && real_contains_q(r, -7, 1) && radius_below(r, -1000));
    lua_pushnumber(L, 0.5);
    CHECK(vigen_ball_get(r, L, -1) == 0);
    lua_pushstring(L, "1/2");
    CHECK(vigen_ball_get(r, L, -1) == 0);
    lua_newtable(L);
    CHECK(vigen_ball_get(r, L, -1) == 0);
    lua_pop(L, 4);
    vigen_sandbox_free(sb);

    acb_clear(t);
    acb_clear(r);
    vigen_error_clear(&err);
}

int main(void)
{
    test_limits_default();
    test_run_and_errors();
    test_escapes();
    test_instruction_cap();
    test_caps_unwind();
    test_library_loops();
    test_memory_cap();
    test_vocabulary_mechanism();
    test_vocabulary();
    test_float_format();
    test_quote();
    test_balls();
    TEST_MAIN_END();
}
