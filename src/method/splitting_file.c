/* splitting_file.c — reading splitting and composition files
 * (splitting_file.h).  As for tableau files, every read is raw, tables with
 * a metatable are refused, and reading happens after the file has run with
 * its memory cap lifted. */
#include <stdlib.h>
#include <string.h>
#include "support/printable.h"
#include "method/splitting_file.h"
#include "method/tableau_file.h"
#include "vigen/limits.h"
#include "support/strbuf.h"
#include "support/nul.h"

static int has_field(lua_State *L, int idx, const char *key)
{
    if (!lua_istable(L, idx)) return 0;
    idx = lua_absindex(L, idx);
    lua_pushstring(L, key);
    lua_rawget(L, idx);
    int found = !lua_isnil(L, -1);
    lua_pop(L, 1);
    return found;
}

int vigen_splitting_file_detect(lua_State *L, int idx) { return has_field(L, idx, "splitting"); }
int vigen_composition_file_detect(lua_State *L, int idx) { return has_field(L, idx, "composition"); }

static int plain_list(lua_State *L, int idx)
{
    if (!lua_istable(L, idx)) return 0;
    if (lua_getmetatable(L, idx)) {
        lua_pop(L, 1);
        return 0;
    }
    return 1;
}

/* Pushes field key of the table on top (raw). */
static void push_raw(lua_State *L, const char *key)
{
    lua_pushstring(L, key);
    lua_rawget(L, -2);
}

static int start(lua_State *L, vigen_sandbox *sb, const char *const *known, vigen_tableau *info, const char *path,
                 vigen_error *err)
{
    vigen_sandbox_lift_memory_cap(sb);
    if (!lua_checkstack(L, 8)) return vigen_error_set(err, VIGEN_E_MEMORY, "%s: out of memory", path);
    if (!plain_list(L, -1)) return vigen_error_set(err, VIGEN_E_SPEC, "%s: the file must return a plain table", path);
    int rc = vigen_table_check_fields(L, known, path, err);
    if (rc == VIGEN_OK) rc = vigen_table_read_info(info, L, path, err);
    return rc;
}

void vigen_splitting_clear(vigen_splitting *sp)
{
    for (slong k = 0; k < sp->n && sp->coef; k++) free(sp->coef[k]);
    free(sp->coef);
    free(sp->drift);
    memset(sp, 0, sizeof *sp);
}

int vigen_splitting_from_table(vigen_splitting *sp, vigen_tableau *info, vigen_sandbox *sb, const char *path,
                               vigen_error *err)
{
    static const char *const known[] = {"name", "splitting", "source", "description", "order", "symplectic",
                                        "order_separable", "order_nystrom", "digits", NULL};
    memset(sp, 0, sizeof *sp);
    lua_State *L = vigen_sandbox_state(sb);
    int rc = start(L, sb, known, info, path, err);
    if (rc != VIGEN_OK) return rc;
    push_raw(L, "splitting");
    lua_Integer n = plain_list(L, -1) ? (lua_Integer)lua_rawlen(L, -1) : -1;
    if (n < 2 || n > 4 * VIGEN_MAX_STAGES) {
        lua_pop(L, 1);
        return vigen_error_set(err, VIGEN_E_SPEC, "%s: 'splitting' must be a plain list of 2 to %d substeps, each "
                               "{\"kick\", coef} or {\"drift\", coef}", path, 4 * VIGEN_MAX_STAGES);
    }
    sp->n = (slong)n;
    sp->drift = calloc((size_t)n, sizeof *sp->drift);
    sp->coef = calloc((size_t)n, sizeof *sp->coef);
    if (sp->drift == NULL || sp->coef == NULL) rc = vigen_error_set(err, VIGEN_E_MEMORY, "out of memory");
    for (slong k = 0; k < sp->n && rc == VIGEN_OK; k++) {
        lua_rawgeti(L, -1, k + 1);
        size_t len = 0;
        const char *kind = NULL;
        if (plain_list(L, -1) && lua_rawlen(L, -1) == 2) {
            lua_rawgeti(L, -1, 1);
            if (lua_type(L, -1) == LUA_TSTRING) kind = lua_tolstring(L, -1, &len);
            int is_drift = kind && len == 5 && memcmp(kind, "drift", 5) == 0;
            int is_kick = kind && len == 4 && memcmp(kind, "kick", 4) == 0;
            lua_pop(L, 1);
            if (!is_drift && !is_kick) kind = NULL;
            sp->drift[k] = is_drift;
        }
        if (kind == NULL)
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: splitting[%ld] must be {\"kick\", coef} or {\"drift\", coef} "
                                 "(kick: p <- p - coef h dV/dq; drift: q <- q + coef h dT/dp)", path, (long)(k + 1));
        if (rc == VIGEN_OK) {
            lua_rawgeti(L, -1, 2);
            char label[48];
            snprintf(label, sizeof label, "splitting[%ld][2]", (long)(k + 1));
            rc = vigen_table_read_entry(L, &sp->coef[k], path, label, err);
            lua_pop(L, 1);
        }
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    if (rc != VIGEN_OK) vigen_splitting_clear(sp);
    return rc;
}

void vigen_composition_clear(vigen_composition *co)
{
    for (slong k = 0; k < co->m && co->gamma; k++) free(co->gamma[k]);
    free(co->gamma);
    free(co->base);
    memset(co, 0, sizeof *co);
}

int vigen_composition_from_table(vigen_composition *co, vigen_tableau *info, vigen_sandbox *sb, const char *path,
                                 vigen_error *err)
{
    static const char *const known[] = {"name", "composition", "source", "description", "order", "symplectic",
                                        "order_separable", "order_nystrom", "digits", NULL};
    static const char *const known_inner[] = {"base", "gamma", NULL};
    memset(co, 0, sizeof *co);
    lua_State *L = vigen_sandbox_state(sb);
    int rc = start(L, sb, known, info, path, err);
    if (rc != VIGEN_OK) return rc;
    push_raw(L, "composition");
    if (!plain_list(L, -1)) rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: 'composition' must be a plain table "
                                                 "{ base = NAME_OR_FILE, gamma = {...} }", path);
    if (rc == VIGEN_OK) rc = vigen_table_check_fields(L, known_inner, path, err);
    if (rc == VIGEN_OK) {
        push_raw(L, "base");
        size_t len = 0;
        const char *base = lua_type(L, -1) == LUA_TSTRING ? lua_tolstring(L, -1, &len) : NULL;
        if (base == NULL || len == 0)
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: composition.base must be a method name or a file (a string)",
                                 path);
        else if ((rc = vigen_refuse_nul(base, len, path, "composition.base", err)) == VIGEN_OK)
            co->base = vigen_strdup(base);
        lua_pop(L, 1);
    }
    if (rc == VIGEN_OK) {
        push_raw(L, "gamma");
        lua_Integer m = plain_list(L, -1) ? (lua_Integer)lua_rawlen(L, -1) : -1;
        if (m < 1 || m > VIGEN_MAX_STAGES)
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: composition.gamma must be a plain list of 1 to %d step "
                                 "fractions", path, VIGEN_MAX_STAGES);
        else {
            co->m = (slong)m;
            co->gamma = calloc((size_t)m, sizeof *co->gamma);
            if (co->gamma == NULL) rc = vigen_error_set(err, VIGEN_E_MEMORY, "out of memory");
        }
        for (slong k = 0; k < co->m && rc == VIGEN_OK; k++) {
            lua_rawgeti(L, -1, k + 1);
            char label[48];
            snprintf(label, sizeof label, "composition.gamma[%ld]", (long)(k + 1));
            rc = vigen_table_read_entry(L, &co->gamma[k], path, label, err);
            lua_pop(L, 1);
        }
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    if (rc != VIGEN_OK) vigen_composition_clear(co);
    return rc;
}
