/* design_criterion_file.c — the criterion fields of a design file
 * (design_criterion.h), each read raw and validated. */
#include <stdlib.h>
#include <string.h>
#include "design/design_criterion.h"
#include "support/strbuf.h"

#define MAX_NEAREST 64

static int field_type(lua_State *L, const char *key)
{
    lua_pushstring(L, key);
    lua_rawget(L, -2);
    return lua_type(L, -1);
}

int design_file_read_criterion(vigen_design_spec *d, lua_State *L, int splitting, const char *path, vigen_error *err)
{
    int rc = VIGEN_OK, t = field_type(L, "stationary");
    if (t != LUA_TNIL) {
        if (t != LUA_TSTRING || strcmp(lua_tostring(L, -1), "error_norm") != 0)
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: stationary: must be \"error_norm\" (the stationary points "
                                 "of the Lyndon norm of the principal error)", path);
        else d->stationary = vigen_strdup("error_norm");
    }
    lua_pop(L, 1);
    t = field_type(L, "first");
    if (rc == VIGEN_OK && t != LUA_TNIL) {
        const char *s = t == LUA_TSTRING ? lua_tostring(L, -1) : "";
        if (!splitting) rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: first: only a splitting has a first substep", path);
        else if (strcmp(s, "kick") == 0) d->first_kick = 1;
        else if (strcmp(s, "drift") != 0)
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: first: must be \"kick\" or \"drift\"", path);
    }
    lua_pop(L, 1);
    t = field_type(L, "nearest");
    if (rc == VIGEN_OK && t != LUA_TNIL) {
        lua_Integer n = t == LUA_TTABLE ? (lua_Integer)lua_rawlen(L, -1) : 0;
        if (n < 1 || n > MAX_NEAREST) {
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: nearest: must be a list of decimals (strings), one per "
                                 "unknown", path);
        } else {
            d->nearest = calloc((size_t)n, sizeof(char *));
            for (lua_Integer i = 1; i <= n && rc == VIGEN_OK; i++) {
                lua_rawgeti(L, -1, i);
                if (lua_type(L, -1) != LUA_TSTRING)
                    rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: nearest: entry %lld must be a string", path,
                                         (long long)i);
                else d->nearest[d->nnearest++] = vigen_strdup(lua_tostring(L, -1));
                lua_pop(L, 1);
            }
        }
    }
    lua_pop(L, 1);
    if (rc == VIGEN_OK && d->nnearest > 0 && d->starts == 0) d->starts = 1;   /* one Newton run, from the point given */
    return rc;
}
