/* tableau_file.c — reading tableau files (tableau_file.h).
 *
 * Tableau files are untrusted: every read below is raw (no __index, __len or
 * other metamethod can run outside a protected call), and tables carrying a
 * metatable are refused outright.  The reads happen after the file has run,
 * with the memory cap lifted, so that they cannot raise a Lua error.  Every
 * string is read with its length and refused when it holds a NUL byte, which
 * would silently end it as a C string ("1\0junk" read as "1").
 */
#include <stdlib.h>
#include <string.h>
#include <lauxlib.h>
#include "core/decimal.h"
#include "core/expr.h"
#include "support/printable.h"
#include "method/tableau_file.h"
#include "vigen/limits.h"
#include "support/strbuf.h"
#include "support/nearest.h"
#include "support/nul.h"

static void raw_getfield(lua_State *L, int idx, const char *key)
{
    idx = lua_absindex(L, idx);
    lua_pushstring(L, key);
    lua_rawget(L, idx);
}

static int has_metatable(lua_State *L, int idx)
{
    if (!lua_getmetatable(L, idx)) return 0;
    lua_pop(L, 1);
    return 1;
}

int vigen_tableau_file_detect(lua_State *L, int idx)
{
    if (!lua_istable(L, idx)) return 0;
    int found = 0;
    raw_getfield(L, idx, "A");
    found |= !lua_isnil(L, -1);
    lua_pop(L, 1);
    raw_getfield(L, idx, "s");
    found |= !lua_isnil(L, -1);
    lua_pop(L, 1);
    return found;
}

static char **texts_new(slong n)
{
    char **t = calloc((size_t)n, sizeof(char *));
    if (t == NULL) abort();
    return t;
}

int vigen_table_read_entry(lua_State *L, char **out, const char *path, const char *label, vigen_error *err)
{
    if (lua_type(L, -1) == LUA_TSTRING) {
        size_t len;
        const char *text = lua_tolstring(L, -1, &len);
        if (vigen_refuse_nul(text, len, path, label, err) != VIGEN_OK) return err->code;
        if (!vigen_decimal_is_rounded(text)) {
            vigen_expr *e = NULL;
            if (vigen_expr_parse(&e, text, 0, err) != VIGEN_OK)
                return vigen_error_prefix(err, "%s: %s: ", path, label);
            vigen_expr_free(e);
        }
        *out = vigen_strdup(text);
        return VIGEN_OK;
    }
    if (lua_isinteger(L, -1)) {
        /* Lua integers wrap around silently beyond 2^63; refuse anything a
         * double could not hold either, rather than trust it */
        lua_Integer v = lua_tointeger(L, -1);
        if (v > ((lua_Integer)1 << 53) || v < -((lua_Integer)1 << 53))
            return vigen_error_set(err, VIGEN_E_SPEC, "%s: %s is the Lua integer %lld, beyond 2^53 (Lua integer "
                                   "arithmetic wraps around): write it as a string", path, label, (long long)v);
        *out = vigen_strdup_printf("%lld", (long long)v);
        return VIGEN_OK;
    }
    if (lua_type(L, -1) == LUA_TNUMBER)
        return vigen_error_set(err, VIGEN_E_SPEC,
                               "%s: %s is the Lua float %.17g, a rounded binary value; write the entry as a "
                               "string with the exact value (e.g. \"1/3\") or with all its digits",
                               path, label, lua_tonumber(L, -1));
    return vigen_error_set(err, VIGEN_E_SPEC, "%s: %s must be a string (an exact expression or a decimal), not %s",
                           path, label, luaL_typename(L, -1));
}

/* Pushes field `key` of the table at the top and sets *present; when it is
 * absent pushes nothing, and fails if it is required. */
static int push_field(lua_State *L, const char *key, int required, int *present, const char *path,
                      vigen_error *err)
{
    raw_getfield(L, -1, key);
    *present = !lua_isnil(L, -1);
    if (*present) return VIGEN_OK;
    lua_pop(L, 1);
    if (required) return vigen_error_set(err, VIGEN_E_SPEC, "%s: the field '%s' is missing", path, key);
    return VIGEN_OK;
}

/* Reads field `key` (a list of s entries) of the table at the top into *out,
 * which stays NULL when the field is absent; on failure *out may be partly
 * filled (vigen_tableau_clear frees it). */
static int read_vector(lua_State *L, const char *key, slong s, char ***out, int required, const char *path,
                       vigen_error *err)
{
    int present;
    int rc = push_field(L, key, required, &present, path, err);
    if (rc != VIGEN_OK || !present) return rc;
    if (!lua_istable(L, -1) || has_metatable(L, -1)) {
        lua_pop(L, 1);
        return vigen_error_set(err, VIGEN_E_SPEC, "%s: '%s' must be a plain list of %ld entries", path, key, (long)s);
    }
    lua_Integer n = (lua_Integer)lua_rawlen(L, -1);
    if (n != s) {
        lua_pop(L, 1);
        return vigen_error_set(err, VIGEN_E_SPEC, "%s: '%s' has %lld entries but s = %ld", path, key, (long long)n,
                               (long)s);
    }
    *out = texts_new(s);
    for (slong i = 0; i < s && rc == VIGEN_OK; i++) {
        lua_rawgeti(L, -1, i + 1);
        char *label = vigen_strdup_printf("%s[%ld]", key, (long)(i + 1));
        rc = vigen_table_read_entry(L, &(*out)[i], path, label, err);
        free(label);
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    return rc;
}

/* As read_vector for an s x s matrix, row-major. */
static int read_matrix(lua_State *L, const char *key, slong s, char ***out, int required, const char *path,
                       vigen_error *err)
{
    int present;
    int rc = push_field(L, key, required, &present, path, err);
    if (rc != VIGEN_OK || !present) return rc;
    if (!lua_istable(L, -1) || has_metatable(L, -1) || (slong)lua_rawlen(L, -1) != s) {
        lua_pop(L, 1);
        return vigen_error_set(err, VIGEN_E_SPEC, "%s: '%s' must be a list of %ld rows of %ld entries", path, key,
                               (long)s, (long)s);
    }
    *out = texts_new(s * s);
    for (slong i = 0; i < s && rc == VIGEN_OK; i++) {
        lua_rawgeti(L, -1, i + 1);
        if (!lua_istable(L, -1) || has_metatable(L, -1) || (slong)lua_rawlen(L, -1) != s) {
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: %s[%ld] must be a row of %ld entries", path, key,
                                 (long)(i + 1), (long)s);
        }
        for (slong j = 0; j < s && rc == VIGEN_OK; j++) {
            lua_rawgeti(L, -1, j + 1);
            char *label = vigen_strdup_printf("%s[%ld][%ld]", key, (long)(i + 1), (long)(j + 1));
            rc = vigen_table_read_entry(L, &(*out)[i * s + j], path, label, err);
            free(label);
            lua_pop(L, 1);
        }
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    return rc;
}

static int read_string_field(lua_State *L, const char *key, char **out, const char *path, vigen_error *err)
{
    raw_getfield(L, -1, key);
    int rc = VIGEN_OK;
    size_t len;
    if (lua_type(L, -1) == LUA_TSTRING) {
        const char *text = lua_tolstring(L, -1, &len);
        rc = vigen_refuse_nul(text, len, path, key, err);
        if (rc == VIGEN_OK) *out = vigen_strdup(text);
    } else if (!lua_isnil(L, -1))
        rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: '%s' must be a string", path, key);
    lua_pop(L, 1);
    return rc;
}

static const char *const known_fields[] = {
    "name", "s", "c", "A", "b", "At", "ct", "bt", "digits", "source", "description",
    "basis", "nodes", "generator", "order", "symplectic", "order_separable", "order_nystrom", "spec", NULL};

int vigen_table_check_fields(lua_State *L, const char *const *known, const char *path, vigen_error *err)
{
    lua_pushnil(L);
    while (lua_next(L, -2) != 0) {
        lua_pop(L, 1);
        int is_known = 0;
        size_t len = 0;
        const char *key = lua_type(L, -1) == LUA_TSTRING ? lua_tolstring(L, -1, &len) : NULL;
        for (int k = 0; key && known[k]; k++)
            is_known |= strlen(known[k]) == len && memcmp(key, known[k], len) == 0;
        if (!is_known) {
            vigen_strbuf shown, list;
            vigen_strbuf_init(&shown);
            vigen_strbuf_init(&list);
            if (key) vigen_printable_append(&shown, key, len);
            else vigen_strbuf_append(&shown, "(a non-string key)");
            for (int k = 0; known[k]; k++) vigen_strbuf_printf(&list, "%s%s", k ? ", " : "", known[k]);
            const char *near = key && strlen(key) == len ? vigen_nearest_name(key, known, 2) : NULL;
            int rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: unknown field '%s'%s%s%s (known: %s)", path, shown.data,
                                     near ? "; did you mean '" : "", near ? near : "", near ? "'?" : "", list.data);
            vigen_strbuf_clear(&shown);
            vigen_strbuf_clear(&list);
            lua_pop(L, 1);
            return rc;
        }
    }
    return VIGEN_OK;
}

/* The optional integer and boolean fields: digits and the claims. */
static int read_numbers(vigen_tableau *t, lua_State *L, const char *path, vigen_error *err)
{
    int rc = VIGEN_OK;
    raw_getfield(L, -1, "digits");
    if (lua_isinteger(L, -1) && lua_tointeger(L, -1) >= 0) t->digits = (slong)lua_tointeger(L, -1);
    else if (!lua_isnil(L, -1))
        rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: 'digits' must be a non-negative integer", path);
    lua_pop(L, 1);
    if (rc != VIGEN_OK) return rc;
    raw_getfield(L, -1, "order");
    if (lua_isinteger(L, -1) && lua_tointeger(L, -1) >= 0 && lua_tointeger(L, -1) < 1000)
        t->claim_order = (int)lua_tointeger(L, -1);
    else if (!lua_isnil(L, -1))
        rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: 'order' (a claim) must be a non-negative integer", path);
    lua_pop(L, 1);
    if (rc != VIGEN_OK) return rc;
    static const char *const family_claims[2] = {"order_separable", "order_nystrom"};
    for (int f = 0; f < 2 && rc == VIGEN_OK; f++) {
        raw_getfield(L, -1, family_claims[f]);
        if (lua_isinteger(L, -1) && lua_tointeger(L, -1) >= 0 && lua_tointeger(L, -1) < 1000)
            *(f ? &t->claim_order_nys : &t->claim_order_sep) = (int)lua_tointeger(L, -1);
        else if (!lua_isnil(L, -1))
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: '%s' (a claim) must be a non-negative integer", path,
                                 family_claims[f]);
        lua_pop(L, 1);
    }
    if (rc != VIGEN_OK) return rc;
    raw_getfield(L, -1, "symplectic");
    if (lua_isboolean(L, -1)) t->claim_symplectic = lua_toboolean(L, -1);
    else if (!lua_isnil(L, -1))
        rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: 'symplectic' (a claim) must be true or false", path);
    lua_pop(L, 1);
    return rc;
}

int vigen_table_read_info(vigen_tableau *t, lua_State *L, const char *path, vigen_error *err)
{
    int rc = read_string_field(L, "name", &t->name, path, err);
    if (rc == VIGEN_OK && t->name == NULL)
        rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: the field 'name' (a string) is missing", path);
    if (rc == VIGEN_OK) rc = read_string_field(L, "source", &t->source, path, err);
    if (rc == VIGEN_OK) rc = read_string_field(L, "description", &t->description, path, err);
    if (rc == VIGEN_OK) rc = read_numbers(t, L, path, err);
    return rc;
}

int vigen_tableau_from_table(vigen_tableau *t, vigen_sandbox *sb, const char *path, vigen_error *err)
{
    lua_State *L = vigen_sandbox_state(sb);
    /* reading below allocates outside any protected call: lift the memory cap
     * so that it cannot raise (the file has finished running) */
    vigen_sandbox_lift_memory_cap(sb);
    if (!lua_checkstack(L, 8)) return vigen_error_set(err, VIGEN_E_MEMORY, "%s: out of memory", path);
    if (!lua_istable(L, -1) || has_metatable(L, -1))
        return vigen_error_set(err, VIGEN_E_SPEC, "%s: a tableau file must return a plain table (return { name = ..., "
                               "s = ..., c = {...}, A = {{...}}, b = {...} })", path);
    int rc = vigen_table_check_fields(L, known_fields, path, err);
    if (rc != VIGEN_OK) return rc;

    raw_getfield(L, -1, "s");
    if (!lua_isinteger(L, -1) || lua_tointeger(L, -1) < 1 || lua_tointeger(L, -1) > VIGEN_MAX_STAGES) {
        lua_pop(L, 1);
        return vigen_error_set(err, VIGEN_E_SPEC, "%s: 's' (the number of stages) must be an integer from 1 to %d",
                               path, VIGEN_MAX_STAGES);
    }
    slong s = (slong)lua_tointeger(L, -1);
    lua_pop(L, 1);

    vigen_tableau_init(t, s);
    rc = read_string_field(L, "name", &t->name, path, err);
    if (rc == VIGEN_OK && t->name == NULL)
        rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: the field 'name' (a string) is missing", path);
    if (rc == VIGEN_OK) rc = read_vector(L, "c", s, &t->c_text, 1, path, err);
    if (rc == VIGEN_OK) rc = read_matrix(L, "A", s, &t->A_text, 1, path, err);
    if (rc == VIGEN_OK) rc = read_vector(L, "b", s, &t->b_text, 1, path, err);
    if (rc == VIGEN_OK) rc = read_matrix(L, "At", s, &t->At_text, 0, path, err);
    if (rc == VIGEN_OK) rc = read_vector(L, "ct", s, &t->ct_text, 0, path, err);
    if (rc == VIGEN_OK) rc = read_vector(L, "bt", s, &t->bt_text, 0, path, err);
    if (rc == VIGEN_OK) rc = read_string_field(L, "source", &t->source, path, err);
    if (rc == VIGEN_OK) rc = read_string_field(L, "description", &t->description, path, err);
    if (rc == VIGEN_OK) rc = read_string_field(L, "basis", &t->basis, path, err);
    if (rc == VIGEN_OK) rc = read_string_field(L, "nodes", &t->nodes, path, err);
    if (rc == VIGEN_OK) rc = read_string_field(L, "generator", &t->generator, path, err);
    if (rc == VIGEN_OK) rc = read_numbers(t, L, path, err);

    t->has_At = t->At_text != NULL;
    t->has_ct = t->ct_text != NULL;
    t->has_bt = t->bt_text != NULL;
    if (rc == VIGEN_OK && (t->has_ct || t->has_bt) && !t->has_At)
        rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: 'ct'/'bt' are given without 'At'", path);
    if (rc != VIGEN_OK) vigen_tableau_clear(t);
    return rc;
}
