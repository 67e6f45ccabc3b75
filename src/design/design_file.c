/* design_file.c — reading a design file (vigen/design.h): run once in the
 * sandbox, every read raw, every field validated with a message naming the
 * file and the field. */
#include <stdlib.h>
#include <string.h>
#include <lua.h>
#include "vigen/design.h"
#include "vigen/limits.h"
#include "lua/sandbox.h"
#include "method/tableau_file.h"
#include "support/strbuf.h"
#include "support/nul.h"
#include "design/design_criterion.h"

#define DEFAULT_STARTS 2000L
/* minimize: each start is a descent with a checker run per trial point */
#define DEFAULT_MINIMIZE_STARTS 8L
#define MAX_STARTS 1000000L
/* Compositions of at most this many stages (the unknowns of a family). */
#define MAX_DESIGN_STAGES 64

static void push_raw(lua_State *L, const char *key)
{
    lua_pushstring(L, key);
    lua_rawget(L, -2);
}

/* A string field into *out (NULL when absent and not required). */
static int read_string(char **out, lua_State *L, const char *key, int required, const char *path, vigen_error *err)
{
    *out = NULL;
    push_raw(L, key);
    int rc = VIGEN_OK;
    if (lua_isnil(L, -1)) {
        if (required) rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: %s: missing (a string)", path, key);
    } else if (lua_type(L, -1) != LUA_TSTRING) {
        rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: %s: must be a string", path, key);
    } else {
        size_t len = 0;
        const char *s = lua_tolstring(L, -1, &len);
        if ((rc = vigen_refuse_nul(s, len, path, key, err)) == VIGEN_OK) {
            if (len == 0) rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: %s: must not be empty", path, key);
            else *out = vigen_strdup(s);
        }
    }
    lua_pop(L, 1);
    return rc;
}

/* A whole-number field in [lo, hi] (def when absent and not required). */
static int read_whole(long *out, lua_State *L, const char *key, int required, long def, long lo, long hi,
                      const char *path, vigen_error *err)
{
    *out = def;
    push_raw(L, key);
    int rc = VIGEN_OK;
    if (lua_isnil(L, -1)) {
        if (required) rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: %s: missing (a whole number from %ld to %ld)", path,
                                           key, lo, hi);
    } else if (!lua_isinteger(L, -1) || lua_tointeger(L, -1) < lo || lua_tointeger(L, -1) > hi) {
        rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: %s: must be a whole number from %ld to %ld", path, key, lo, hi);
    } else {
        *out = (long)lua_tointeger(L, -1);
    }
    lua_pop(L, 1);
    return rc;
}

void vigen_design_spec_clear(vigen_design_spec *d)
{
    free(d->path);
    free(d->name);
    free(d->family);
    free(d->base);
    free(d->minimize);
    free(d->stationary);
    for (slong i = 0; i < d->nnearest; i++) free(d->nearest[i]);
    free(d->nearest);
    memset(d, 0, sizeof *d);
}

static int read_fields(vigen_design_spec *d, lua_State *L, const char *path, vigen_error *err)
{
    static const char *const known[] = {"name", "design", "base", "stages", "order", "symmetric", "solutions",
                                        "minimize", "starts", "seed", "description", "stationary", "nearest",
                                        "first", NULL};
    int rc = vigen_table_check_fields(L, known, path, err);
    if (rc == VIGEN_OK) rc = read_string(&d->name, L, "name", 1, path, err);
    if (rc == VIGEN_OK) {
        for (const char *c = d->name; *c; c++)
            if (!(*c == '_' || (*c >= 'a' && *c <= 'z') || (*c >= 'A' && *c <= 'Z') || (*c >= '0' && *c <= '9')))
                return vigen_error_set(err, VIGEN_E_SPEC, "%s: name: must be letters, digits and '_' (it names the "
                                       "files written, NAME_k.lua)", path);
    }
    if (rc == VIGEN_OK) rc = read_string(&d->family, L, "design", 1, path, err);
    if (rc == VIGEN_OK && strcmp(d->family, "composition") != 0 && strcmp(d->family, "splitting") != 0)
        return vigen_error_set(err, VIGEN_E_SPEC, "%s: design: unknown family '%s' (families: composition, "
                               "splitting)", path, d->family);
    int splitting = rc == VIGEN_OK && strcmp(d->family, "splitting") == 0;
    if (rc == VIGEN_OK) rc = read_string(&d->base, L, "base", !splitting, path, err);
    if (rc == VIGEN_OK && splitting && d->base)
        return vigen_error_set(err, VIGEN_E_SPEC, "%s: base: a splitting has no base (its kicks and drifts are the "
                               "unknowns; stages is the number of kicks)", path);
    long v = 0;
    if (rc == VIGEN_OK && (rc = read_whole(&v, L, "stages", 1, 0, 1, MAX_DESIGN_STAGES, path, err)) == VIGEN_OK)
        d->stages = (int)v;
    if (rc == VIGEN_OK && (rc = read_whole(&v, L, "order", 1, 0, 1, 1000, path, err)) == VIGEN_OK) d->order = (int)v;
    if (rc == VIGEN_OK && (rc = read_whole(&v, L, "starts", 0, 0, 1, MAX_STARTS, path, err)) == VIGEN_OK)
        d->starts = v;
    if (rc == VIGEN_OK && (rc = read_whole(&v, L, "seed", 0, 1, 0, 2147483647L, path, err)) == VIGEN_OK)
        d->seed = (unsigned long)v;
    if (rc == VIGEN_OK) {
        push_raw(L, "symmetric");
        if (lua_isnil(L, -1)) d->symmetric = 0;
        else if (lua_isboolean(L, -1)) d->symmetric = lua_toboolean(L, -1);
        else rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: symmetric: must be true or false", path);
        lua_pop(L, 1);
    }
    char *solutions = NULL;
    if (rc == VIGEN_OK) rc = read_string(&solutions, L, "solutions", 0, path, err);
    if (rc == VIGEN_OK) rc = read_string(&d->minimize, L, "minimize", 0, path, err);
    if (rc == VIGEN_OK) rc = design_file_read_criterion(d, L, splitting, path, err);
    if (rc == VIGEN_OK) {
        int asked = (solutions != NULL) + (d->minimize != NULL) + (d->stationary != NULL) + (d->nnearest > 0);
        if (asked > 1)
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: solutions, minimize, stationary and nearest: give one of "
                                 "them", path);
        else if (asked == 0)
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: what is wanted? give solutions = \"all\" or minimize = "
                                 "\"error_constant\"", path);
        else if (solutions && strcmp(solutions, "all") != 0)
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: solutions: must be \"all\"", path);
        else if (d->minimize && strcmp(d->minimize, "error_constant") != 0 &&
                 strcmp(d->minimize, "error_constant_separable") != 0 && strcmp(d->minimize, "error_constant_nystrom") != 0)
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: minimize: must be \"error_constant\" (general H), "
                                 "\"error_constant_separable\" or \"error_constant_nystrom\"", path);
        d->goal = d->minimize ? VIGEN_DESIGN_MINIMIZE : VIGEN_DESIGN_ALL;
        if (d->starts == 0) d->starts = d->goal == VIGEN_DESIGN_MINIMIZE ? DEFAULT_MINIMIZE_STARTS : DEFAULT_STARTS;
    }
    free(solutions);
    return rc;
}

int vigen_design_read(vigen_design_spec *d, const char *path, vigen_error *err)
{
    memset(d, 0, sizeof *d);
    vigen_sandbox *sb = NULL;
    int rc = vigen_sandbox_new(&sb, NULL, NULL, err);
    if (rc == VIGEN_OK) rc = vigen_sandbox_run_file(sb, path, err);
    if (rc == VIGEN_OK) {
        lua_State *L = vigen_sandbox_state(sb);
        vigen_sandbox_lift_memory_cap(sb);
        if (!lua_istable(L, -1) || lua_getmetatable(L, -1))
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: the file must return a plain table { name = ..., design = "
                                 "\"composition\", ... }", path);
        else rc = read_fields(d, L, path, err);
    }
    vigen_sandbox_free(sb);
    if (rc == VIGEN_OK) d->path = vigen_strdup(path);
    else vigen_design_spec_clear(d);
    return rc;
}
