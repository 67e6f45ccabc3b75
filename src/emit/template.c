/* template.c — renders the stepper templates (C text with //$ Lua lines and ${expr}
 * slots, compiled line by line into one Lua function so that Lua's error
 * messages point at template lines. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <lua.h>
#include <lauxlib.h>
#include <lualib.h>
#include "emit/template.h"

void vigen_template_quote(vigen_strbuf *sb, const char *text)
{
    vigen_strbuf_append(sb, "\"");
    for (const unsigned char *c = (const unsigned char *)text; *c; c++) {
        if (*c == '"' || *c == '\\') {
            char e[3] = { '\\', (char)*c, 0 };
            vigen_strbuf_append(sb, e);
        } else if (*c < 0x20 || *c > 0x7e) {
            vigen_strbuf_printf(sb, "\\%03u", (unsigned)*c);
        } else {
            vigen_strbuf_appendn(sb, (const char *)c, 1);
        }
    }
    vigen_strbuf_append(sb, "\"");
}

/* Lua prelude, on the template's first line (no newline) so that line
 * numbers match.  D is the data table; _o appends output; _s converts a
 * slot value, refusing floats, booleans and nil. */
static const char prelude[] =
    "local D = ...; local _b, _n = {}, 0; "
    "local function _o(x) _n = _n + 1; _b[_n] = x end; "
    "local function _s(v, e) local ty = math.type(v); "
    "if type(v) == 'string' then return v elseif ty == 'integer' then return tostring(v) end; "
    "error('slot ${' .. e .. '} has a ' .. (ty or type(v)) .. ' value, not a string or integer', 2) end; "
    "local _G0 = _G; "
    "local _ENV = setmetatable({}, { __index = function(_, k) local v = D[k]; "
    "if v == nil then v = _G0[k] end; if v == nil then error('unknown name ' .. tostring(k), 2) end; "
    "return v end }); ";

/* Appends the Lua statement that outputs text[0..n) literally. */
static void emit_text(vigen_strbuf *lua, const char *text, size_t n)
{
    if (n == 0) return;
    char *tmp = malloc(n + 1);
    if (tmp == NULL) abort();
    memcpy(tmp, text, n);
    tmp[n] = 0;
    vigen_strbuf_append(lua, "_o(");
    vigen_template_quote(lua, tmp);
    vigen_strbuf_append(lua, ") ");
    free(tmp);
}

/* Compiles one non-code template line (without its newline) into Lua. */
static int compile_line(vigen_strbuf *lua, const char *line, size_t len, int newline,
                        const char *chunkname, long lineno, vigen_error *err)
{
    size_t i = 0, start = 0;
    while (i < len) {
        if (line[i] == '$' && i + 1 < len && line[i + 1] == '{') {
            emit_text(lua, line + start, i - start);
            size_t j = i + 2;
            int depth = 1;
            while (j < len) {
                if (line[j] == '{') depth++;
                else if (line[j] == '}' && --depth == 0) break;
                j++;
            }
            if (j >= len)
                return vigen_error_set(err, VIGEN_E_SYNTAX, "%s:%ld: unterminated ${ slot", chunkname, lineno);
            char *expr = malloc(j - i - 1);
            if (expr == NULL) abort();
            memcpy(expr, line + i + 2, j - i - 2);
            expr[j - i - 2] = 0;
            vigen_strbuf_printf(lua, "_o(_s((%s), ", expr);
            vigen_template_quote(lua, expr);
            vigen_strbuf_append(lua, ")) ");
            free(expr);
            i = start = j + 1;
        } else {
            i++;
        }
    }
    emit_text(lua, line + start, len - start);
    if (newline) vigen_strbuf_append(lua, "_o(\"\\n\") ");
    return VIGEN_OK;
}

/* Compiles a whole template into a Lua chunk, one Lua line per template line. */
static int compile_template(vigen_strbuf *lua, const char *text, const char *chunkname, vigen_error *err)
{
    vigen_strbuf_append(lua, prelude);
    long lineno = 1;
    const char *p = text;
    while (*p) {
        const char *nl = strchr(p, '\n');
        size_t len = nl ? (size_t)(nl - p) : strlen(p);
        const char *q = p;
        while (q < p + len && (*q == ' ' || *q == '\t')) q++;
        if ((size_t)(p + len - q) >= 3 && q[0] == '/' && q[1] == '/' && q[2] == '$') {
            vigen_strbuf_appendn(lua, q + 3, (size_t)(p + len - q - 3));
            vigen_strbuf_append(lua, " ");
        } else {
            int rc = compile_line(lua, p, len, nl != NULL, chunkname, lineno, err);
            if (rc != VIGEN_OK) return rc;
        }
        if (nl == NULL) break;
        vigen_strbuf_append(lua, "\n");
        lineno++;
        p = nl + 1;
    }
    vigen_strbuf_append(lua, "\nreturn table.concat(_b)\n");
    return VIGEN_OK;
}

static int lua_status_code(int st) { return st == LUA_ERRSYNTAX ? VIGEN_E_SYNTAX : st == LUA_ERRMEM ? VIGEN_E_MEMORY : VIGEN_E_LUA; }

static lua_State *new_state(void)
{
    lua_State *L = luaL_newstate();
    if (L == NULL) return NULL;
    luaL_requiref(L, LUA_GNAME, luaopen_base, 1);
    luaL_requiref(L, LUA_STRLIBNAME, luaopen_string, 1);
    luaL_requiref(L, LUA_TABLIBNAME, luaopen_table, 1);
    luaL_requiref(L, LUA_MATHLIBNAME, luaopen_math, 1);
    lua_pop(L, 4);
    static const char *const removed[] = { "dofile", "loadfile", "load", "require", "collectgarbage" };
    for (size_t k = 0; k < sizeof removed / sizeof removed[0]; k++) {
        lua_pushnil(L);
        lua_setglobal(L, removed[k]);
    }
    /* math.random is the only nondeterministic function left: remove it. */
    lua_getglobal(L, "math");
    lua_pushnil(L);
    lua_setfield(L, -2, "random");
    lua_pushnil(L);
    lua_setfield(L, -2, "randomseed");
    lua_pop(L, 1);
    return L;
}

int vigen_template_render(char **out, const char *template_text, const char *chunkname,
                          const char *data_lua, vigen_error *err)
{
    *out = NULL;
    vigen_strbuf lua;
    vigen_strbuf_init(&lua);
    int rc = compile_template(&lua, template_text, chunkname, err);
    if (rc != VIGEN_OK) { vigen_strbuf_clear(&lua); return rc; }

    lua_State *L = new_state();
    if (L == NULL) { vigen_strbuf_clear(&lua); return vigen_error_set(err, VIGEN_E_MEMORY, "cannot create a Lua state"); }
    char *name = vigen_strdup_printf("=%s", chunkname);
    int st = luaL_loadbufferx(L, lua.data, lua.len, name, "t");
    free(name);
    vigen_strbuf_clear(&lua);
    if (st != LUA_OK) {
        rc = vigen_error_set(err, lua_status_code(st), "template %s", lua_tostring(L, -1));
        lua_close(L);
        return rc;
    }
    st = luaL_loadbufferx(L, data_lua, strlen(data_lua), "=template data", "t");
    if (st == LUA_OK) st = lua_pcall(L, 0, 1, 0);
    if (st != LUA_OK || !lua_istable(L, -1)) {
        rc = vigen_error_set(err, st == LUA_OK ? VIGEN_E_SPEC : lua_status_code(st), "%s: %s",
                             "template data", st == LUA_OK ? "did not return a table" : lua_tostring(L, -1));
        lua_close(L);
        return rc;
    }
    st = lua_pcall(L, 1, 1, 0);
    if (st != LUA_OK || !lua_isstring(L, -1)) {
        rc = vigen_error_set(err, st == LUA_OK ? VIGEN_E_LUA : lua_status_code(st), "template %s",
                             st == LUA_OK ? "returned no text" : lua_tostring(L, -1));
        lua_close(L);
        return rc;
    }
    *out = vigen_strdup(lua_tostring(L, -1));
    lua_close(L);
    return VIGEN_OK;
}

static char *read_whole_file(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (f == NULL) return NULL;
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    char buf[4096];
    size_t n;
    while ((n = fread(buf, 1, sizeof buf, f)) > 0) vigen_strbuf_appendn(&sb, buf, n);
    int bad = ferror(f);
    fclose(f);
    if (bad) { vigen_strbuf_clear(&sb); return NULL; }
    if (sb.data == NULL) return vigen_strdup("");
    return sb.data;
}

int vigen_template_render_file(char **out, const char *path, const char *data_lua, vigen_error *err)
{
    *out = NULL;
    char *text = read_whole_file(path);
    if (text == NULL) return vigen_error_set(err, VIGEN_E_IO, "cannot read template %s (set VIGEN_TEMPLATE_DIR to the templates/ directory)", path);
    const char *base = strrchr(path, '/');
    int rc = vigen_template_render(out, text, base ? base + 1 : path, data_lua, err);
    free(text);
    return rc;
}

const char *vigen_template_dir(void)
{
    const char *env = getenv("VIGEN_TEMPLATE_DIR");
    if (env && *env) return env;
#if defined(VIGEN_TEMPLATE_DIR)
    return VIGEN_TEMPLATE_DIR;
#elif defined(VIGEN_SOURCE_DIR)
    return VIGEN_SOURCE_DIR "/templates";
#else
    return "templates";
#endif
}
