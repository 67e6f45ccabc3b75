/* vocabulary.c — the globals method files see beyond the generic sandbox
 * (vocabulary.h): one constructor closure per node and basis family, the
 * names taken from families.h (that is from nodes.def and basis.def), the
 * metatable of the family descriptors they make, and the sandbox every method
 * file runs in.
 */
#include <lauxlib.h>

#include "lua/float_text.h"
#include "method/families.h"
#include "method/vocabulary.h"

static char family_mt_key;          /* registry key of the family descriptor metatable */

typedef struct {
    int kind;
    const char *family;
    lua_Integer s;
} family_desc;

int vigen_vocabulary_get_family(lua_State *L, int idx, int *kind, const char **family, long *s)
{
    idx = lua_absindex(L, idx);
    if (lua_type(L, idx) != LUA_TUSERDATA || !lua_checkstack(L, 2) || !lua_getmetatable(L, idx)) return 0;
    lua_rawgetp(L, LUA_REGISTRYINDEX, &family_mt_key);
    int same = lua_rawequal(L, -1, -2);
    lua_pop(L, 2);
    if (!same) return 0;
    const family_desc *d = lua_touserdata(L, idx);
    if (kind) *kind = d->kind;
    if (family) *family = d->family;
    if (s) *s = (long)d->s;
    return 1;
}

static int family_tostring(lua_State *L)
{
    const family_desc *d = lua_touserdata(L, 1);
    lua_pushfstring(L, "%s(%I)", d->family, d->s);
    return 1;
}

/* gauss_legendre(3), trig(5), ...: upvalues are the kind and the family name. */
static int family_new(lua_State *L)
{
    int kind = (int)lua_tointeger(L, lua_upvalueindex(1));
    const char *name = lua_touserdata(L, lua_upvalueindex(2));
    const char *what = kind == VIGEN_FAMILY_NODES ? "the number of nodes" : "the number of basis functions";
    int n = lua_gettop(L);
    if (n == 0)
        return luaL_error(L, "%s(s) needs %s s, a Lua integer >= 1, e.g. %s(3)", name, what, name);
    if (n > 1)
        return luaL_error(L, "%s(s) takes one argument, %s s, not %d", name, what, n);
    if (lua_type(L, 1) != LUA_TNUMBER)
        return luaL_error(L, "%s(s): s must be a Lua integer >= 1 (%s), not a %s", name, what, luaL_typename(L, 1));
    if (!lua_isinteger(L, 1)) {
        const char *f = vigen_push_float_text(L, lua_tonumber(L, 1));
        return luaL_error(L, "%s(s): s must be a Lua integer >= 1 (%s), not the float %s", name, what, f);
    }
    lua_Integer s = lua_tointeger(L, 1);
    if (s < 1) return luaL_error(L, "%s(s): s must be >= 1, not %I", name, s);
    if (s > VIGEN_NODES_MAX_S)
        return luaL_error(L, "%s(%I): s may be at most %d", name, s, (int)VIGEN_NODES_MAX_S);
    family_desc *d = lua_newuserdatauv(L, sizeof *d, 0);
    d->kind = kind;
    d->family = name;
    d->s = s;
    lua_rawgetp(L, LUA_REGISTRYINDEX, &family_mt_key);
    lua_setmetatable(L, -2);
    return 1;
}

/* Sets one constructor global per name and adds "LABEL: a, b, c" to b. */
static void register_families(lua_State *L, luaL_Buffer *b, int kind, const char *label, const char *const *names)
{
    luaL_addstring(b, label);
    for (int i = 0; names[i]; i++) {
        luaL_addstring(b, i ? ", " : ": ");
        luaL_addstring(b, names[i]);
        lua_pushinteger(L, kind);
        lua_pushlightuserdata(L, (void *)names[i]);
        lua_pushcclosure(L, family_new, 2);
        lua_setglobal(L, names[i]);
    }
}

int vigen_vocabulary_open(lua_State *L)
{
    lua_newtable(L);
    lua_pushliteral(L, "family");
    lua_setfield(L, -2, "__name");
    lua_pushcfunction(L, family_tostring);
    lua_setfield(L, -2, "__tostring");
    lua_pushboolean(L, 0);
    lua_setfield(L, -2, "__metatable");
    lua_rawsetp(L, LUA_REGISTRYINDEX, &family_mt_key);

    luaL_Buffer b;
    luaL_buffinit(L, &b);
    register_families(L, &b, VIGEN_FAMILY_NODES, "node families", vigen_nodes_family_names);
    luaL_addstring(&b, "; ");
    register_families(L, &b, VIGEN_FAMILY_BASIS, "basis families", vigen_basis_family_names);
    luaL_pushresult(&b);
    return 1;
}

int vigen_vocabulary_run_file(vigen_sandbox **sb, const char *path, const vigen_sandbox_limits *limits,
                              vigen_error *err)
{
    int rc = vigen_sandbox_new(sb, limits, vigen_vocabulary_open, err);
    if (rc == VIGEN_OK) rc = vigen_sandbox_run_file(*sb, path, err);
    if (rc != VIGEN_OK) {
        vigen_sandbox_free(*sb);
        *sb = NULL;
    }
    return rc;
}
