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
    for (slong k = 0; k < sp->nflows && sp->flow_names; k++) free(sp->flow_names[k]);
    for (slong k = 0; k < sp->ncorrector && sp->corrector_coef; k++) free(sp->corrector_coef[k]);
    free(sp->coef);
    free(sp->drift);
    free(sp->flow_names);
    free(sp->flow);
    free(sp->corrector_flow);
    free(sp->corrector_coef);
    for (slong k = 0; k < sp->nflows && sp->flow_bracket; k++) free(sp->flow_bracket[k]);
    free(sp->flow_bracket);
    free(sp->flow_degree);
    memset(sp, 0, sizeof *sp);
}

/* The flow index of the string on top of the stack, -1 when it names none. */
static int flow_index(lua_State *L, const vigen_splitting *sp)
{
    if (lua_type(L, -1) != LUA_TSTRING) return -1;
    size_t len = 0;
    const char *name = lua_tolstring(L, -1, &len);
    for (slong f = 0; f < sp->nflows; f++)
        if (strlen(sp->flow_names[f]) == len && memcmp(sp->flow_names[f], name, len) == 0) return (int)f;
    return -1;
}

static void flow_list(vigen_strbuf *sb, const vigen_splitting *sp)
{
    for (slong f = 0; f < sp->nflows; f++)
        vigen_strbuf_printf(sb, "%s\"%s\"", f ? ", " : "", sp->flow_names[f]);
}

/* `flows` (absent: the kick/drift file's two flows "drift" and "kick") */
static int read_flows(vigen_splitting *sp, lua_State *L, const char *path, vigen_error *err)
{
    static const char *const kick_drift[2] = {"drift", "kick"};
    push_raw(L, "flows");
    int rc = VIGEN_OK;
    if (lua_isnil(L, -1)) {
        sp->nflows = 2;
        sp->flow_names = calloc(2, sizeof *sp->flow_names);
        if (sp->flow_names == NULL) abort();
        for (int f = 0; f < 2; f++) sp->flow_names[f] = vigen_strdup(kick_drift[f]);
        sp->perturbation = 1;
        lua_pop(L, 1);
        push_raw(L, "perturbation");
        if (!lua_isnil(L, -1))
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: 'perturbation' names one of the 'flows'; a file of kicks and "
                                 "drifts has none", path);
        lua_pop(L, 1);
        return rc;
    }
    sp->named = 1;
    lua_Integer n = plain_list(L, -1) ? (lua_Integer)lua_rawlen(L, -1) : -1;
    if (n < 2 || n > VIGEN_MAX_STAGES) {
        lua_pop(L, 1);
        return vigen_error_set(err, VIGEN_E_SPEC, "%s: 'flows' must be a plain list of 2 to %d flow names, e.g. "
                               "flows = {\"kepler\", \"interaction\"}", path, VIGEN_MAX_STAGES);
    }
    sp->flow_names = calloc((size_t)n, sizeof *sp->flow_names);
    if (sp->flow_names == NULL) abort();
    for (slong k = 0; k < n && rc == VIGEN_OK; k++) {
        lua_rawgeti(L, -1, k + 1);
        size_t len = 0;
        const char *name = lua_type(L, -1) == LUA_TSTRING ? lua_tolstring(L, -1, &len) : NULL;
        char label[32];
        snprintf(label, sizeof label, "flows[%ld]", (long)(k + 1));
        int dup = flow_index(L, sp);
        if (name == NULL || len == 0)
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: %s must be a flow name (a non-empty string)", path, label);
        else if ((rc = vigen_refuse_nul(name, len, path, label, err)) != VIGEN_OK) {
        } else if (dup >= 0)
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: %s \"%s\" repeats flows[%d]; each flow is named once",
                                 path, label, name, dup + 1);
        else sp->flow_names[sp->nflows++] = vigen_strdup(name);
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    if (rc != VIGEN_OK) return rc;
    push_raw(L, "perturbation");
    sp->perturbation = 1;
    if (!lua_isnil(L, -1)) {
        int f = flow_index(L, sp);
        if (f < 0) {
            vigen_strbuf sb;
            vigen_strbuf_init(&sb);
            flow_list(&sb, sp);
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: 'perturbation' must name one of the flows (%s): the part "
                                 "eps B of H = A + eps B", path, sb.data);
            vigen_strbuf_clear(&sb);
        }
        sp->perturbation = f;
    }
    lua_pop(L, 1);
    return rc;
}

/* The least string key of the table on top of the stack that names no
 * flow (NULL when every key does); a key that is not a string: "?". */
static const char *stray_key(lua_State *L, const vigen_splitting *sp)
{
    const char *least = NULL;
    lua_pushnil(L);
    while (lua_next(L, -2) != 0) {
        lua_pop(L, 1);
        if (lua_type(L, -1) != LUA_TSTRING) {
            lua_pop(L, 1);
            return "?";
        }
        const char *k = lua_tostring(L, -1);
        /* the key stays referenced by the table: its text outlives the pop */
        if (flow_index(L, sp) < 0 && (least == NULL || strcmp(k, least) < 0)) least = k;
    }
    return least;
}

/* The letters of bracket flow f: the list on top of the stack. */
static int read_letters(vigen_splitting *sp, int f, lua_State *L, const char *path, vigen_error *err)
{
    const char *name = sp->flow_names[f];
    lua_Integer n = plain_list(L, -1) ? (lua_Integer)lua_rawlen(L, -1) : -1;
    if (n < 2 || n > VIGEN_MAX_GENERALIZED)
        return vigen_error_set(err, VIGEN_E_SPEC, "%s: brackets.%s must be a plain list of 2 to %d letters (plain "
                               "flows), {L1, L2, L3} for the bracket {{L1, L2}, L3}", path, name,
                               VIGEN_MAX_GENERALIZED);
    sp->flow_bracket[f] = calloc((size_t)n, sizeof **sp->flow_bracket);
    if (sp->flow_bracket[f] == NULL) abort();
    sp->flow_degree[f] = (int)n;
    int rc = VIGEN_OK;
    for (lua_Integer k = 0; k < n && rc == VIGEN_OK; k++) {
        lua_rawgeti(L, -1, k + 1);
        int g = flow_index(L, sp);
        if (g < 0) {
            vigen_strbuf names, shown;
            vigen_strbuf_init(&names);
            vigen_strbuf_init(&shown);
            flow_list(&names, sp);
            size_t len = 0;
            const char *s = lua_type(L, -1) == LUA_TSTRING ? lua_tolstring(L, -1, &len) : "";
            vigen_printable_append(&shown, s, len);
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: brackets.%s[%ld] \"%s\" is not a flow of this file (%s)", path,
                                 name, (long)(k + 1), shown.data, names.data);
            vigen_strbuf_clear(&names);
            vigen_strbuf_clear(&shown);
        } else if (g == f)
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: brackets.%s[%ld] names the bracket itself; its letters are "
                                 "plain flows", path, name, (long)(k + 1));
        else if (g >= 2)
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: brackets.%s[%ld] \"%s\" is a bracket flow; the letters of a "
                                 "bracket are the plain flows (\"%s\", \"%s\")", path, name, (long)(k + 1),
                                 sp->flow_names[g], sp->flow_names[0], sp->flow_names[1]);
        else sp->flow_bracket[f][k] = g;
        lua_pop(L, 1);
    }
    return rc;
}

/* `brackets = { NAME = {LETTER, ...}, ... }`: flow_degree and flow_bracket
 * (all plain when absent) */
static int read_brackets(vigen_splitting *sp, lua_State *L, const char *path, vigen_error *err)
{
    sp->flow_degree = calloc((size_t)sp->nflows, sizeof *sp->flow_degree);
    sp->flow_bracket = calloc((size_t)sp->nflows, sizeof *sp->flow_bracket);
    if (sp->flow_degree == NULL || sp->flow_bracket == NULL) abort();
    for (slong f = 0; f < sp->nflows; f++) sp->flow_degree[f] = 1;
    push_raw(L, "brackets");
    int rc = VIGEN_OK;
    if (lua_isnil(L, -1)) {
        lua_pop(L, 1);
        return rc;
    }
    const char *stray = NULL;
    if (!sp->named)
        rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: 'brackets' defines bracket flows of the named 'flows'; a file of "
                             "kicks and drifts has none", path);
    else if (!plain_list(L, -1))
        rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: 'brackets' must be a plain table { FLOW = {LETTER, LETTER, ...} "
                             "}, FLOW one of the 'flows'", path);
    else if ((stray = stray_key(L, sp)) != NULL) {
        vigen_strbuf names;
        vigen_strbuf_init(&names);
        flow_list(&names, sp);
        char *shown = vigen_printable(stray);
        rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: brackets.%s is not a flow of this file (%s); a bracket flow is "
                             "named in 'flows' too", path, shown, names.data);
        free(shown);
        vigen_strbuf_clear(&names);
    }
    /* which flows are brackets: they must follow the two plain ones */
    slong nbrackets = 0;
    for (slong f = 0; f < sp->nflows && rc == VIGEN_OK; f++) {
        push_raw(L, sp->flow_names[f]);
        if (!lua_isnil(L, -1)) {
            if (f < 2)
                rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: flows[%ld] \"%s\" is a bracket; the two plain flows "
                                     "(the letters) come first in 'flows'", path, (long)(f + 1), sp->flow_names[f]);
            nbrackets++;
        }
        lua_pop(L, 1);
    }
    if (rc == VIGEN_OK && sp->nflows - nbrackets != 2)
        rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: a file with 'brackets' has exactly two plain flows (the letters); "
                             "flows[3] \"%s\" is neither a bracket nor one of them", path, sp->flow_names[2]);
    /* every flow after the two plain ones is a bracket */
    for (slong f = 2; f < sp->nflows && rc == VIGEN_OK; f++) {
        push_raw(L, sp->flow_names[f]);
        rc = read_letters(sp, (int)f, L, path, err);
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    if (rc == VIGEN_OK && sp->flow_degree[sp->perturbation] > 1)
        rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: 'perturbation' must name a plain flow (\"%s\" or \"%s\"), not the "
                             "bracket \"%s\"", path, sp->flow_names[0], sp->flow_names[1],
                             sp->flow_names[sp->perturbation]);
    return rc;
}

/* The list `key` of substeps {FLOW, coef} (the table on top of the stack),
 * from 1 (min) to max entries, into flow[] and coef[]. */
static int read_substeps(slong *out_n, int **out_flow, char ***out_coef, const vigen_splitting *sp, lua_State *L,
                         const char *key, lua_Integer min, const char *path, vigen_error *err)
{
    vigen_strbuf names, shape;
    vigen_strbuf_init(&names);
    vigen_strbuf_init(&shape);
    if (sp->named) {
        flow_list(&names, sp);
        vigen_strbuf_printf(&shape, "{FLOW, coef} with FLOW one of %s", names.data);
    } else vigen_strbuf_append(&shape, "{\"kick\", coef} or {\"drift\", coef}");
    const char *why = sp->named ? "" : " (kick: p <- p - coef h dV/dq; drift: q <- q + coef h dT/dp)";
    int rc = VIGEN_OK;
    push_raw(L, key);
    lua_Integer n = plain_list(L, -1) ? (lua_Integer)lua_rawlen(L, -1) : -1;
    if (n < min || n > 4 * VIGEN_MAX_STAGES)
        rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: '%s' must be a plain list of %d to %d substeps, each %s",
                             path, key, (int)min, 4 * VIGEN_MAX_STAGES, shape.data);
    else {
        *out_n = (slong)n;
        *out_flow = calloc((size_t)n, sizeof **out_flow);
        *out_coef = calloc((size_t)n, sizeof **out_coef);
        if (*out_flow == NULL || *out_coef == NULL) abort();
    }
    for (slong k = 0; k < n && rc == VIGEN_OK; k++) {
        lua_rawgeti(L, -1, k + 1);
        int f = -1;
        if (plain_list(L, -1) && lua_rawlen(L, -1) == 2) {
            lua_rawgeti(L, -1, 1);
            f = flow_index(L, sp);
            if (f < 0 && sp->named && lua_type(L, -1) == LUA_TSTRING) {
                vigen_strbuf shown;
                vigen_strbuf_init(&shown);
                size_t len = 0;
                const char *name = lua_tolstring(L, -1, &len);
                vigen_printable_append(&shown, name, len);
                rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: %s[%ld][1] \"%s\" is not a flow of this file (%s)", path,
                                     key, (long)(k + 1), shown.data, names.data);
                vigen_strbuf_clear(&shown);
            }
            lua_pop(L, 1);
        }
        if (f < 0 && rc == VIGEN_OK)
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: %s[%ld] must be %s%s", path, key, (long)(k + 1), shape.data,
                                 why);
        if (rc == VIGEN_OK) {
            (*out_flow)[k] = f;
            lua_rawgeti(L, -1, 2);
            char label[48];
            snprintf(label, sizeof label, "%s[%ld][2]", key, (long)(k + 1));
            rc = vigen_table_read_entry(L, &(*out_coef)[k], path, label, err);
            lua_pop(L, 1);
        }
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    vigen_strbuf_clear(&names);
    vigen_strbuf_clear(&shape);
    return rc;
}

/* the claim generalized_order = {r1, ..., rk} */
static int read_generalized(vigen_splitting *sp, lua_State *L, const char *path, vigen_error *err)
{
    push_raw(L, "generalized_order");
    int rc = VIGEN_OK;
    if (!lua_isnil(L, -1)) {
        lua_Integer n = plain_list(L, -1) ? (lua_Integer)lua_rawlen(L, -1) : -1;
        if (n < 1 || n > VIGEN_MAX_GENERALIZED || !sp->named)
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: 'generalized_order' (a claim) must be a plain list of 1 to %d "
                                 "positive integers {r1, r2, ...}, in a file with named 'flows'", path,
                                 VIGEN_MAX_GENERALIZED);
        for (lua_Integer k = 0; k < n && rc == VIGEN_OK; k++) {
            lua_rawgeti(L, -1, k + 1);
            if (lua_isinteger(L, -1) && lua_tointeger(L, -1) >= 1 && lua_tointeger(L, -1) < 1000)
                sp->generalized[sp->ngeneralized++] = (int)lua_tointeger(L, -1);
            else
                rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: generalized_order[%ld] must be a positive integer", path,
                                     (long)(k + 1));
            lua_pop(L, 1);
        }
    }
    lua_pop(L, 1);
    return rc;
}

int vigen_splitting_from_table(vigen_splitting *sp, vigen_tableau *info, vigen_sandbox *sb, const char *path,
                               vigen_error *err)
{
    static const char *const known[] = {"name", "splitting", "source", "description", "order", "symplectic",
                                        "order_separable", "order_nystrom", "digits", "flows", "perturbation",
                                        "corrector", "generalized_order", "brackets", NULL};
    memset(sp, 0, sizeof *sp);
    lua_State *L = vigen_sandbox_state(sb);
    int rc = start(L, sb, known, info, path, err);
    if (rc == VIGEN_OK) rc = read_flows(sp, L, path, err);
    if (rc == VIGEN_OK) rc = read_brackets(sp, L, path, err);
    if (rc == VIGEN_OK) rc = read_substeps(&sp->n, &sp->flow, &sp->coef, sp, L, "splitting", 2, path, err);
    if (rc == VIGEN_OK) {
        push_raw(L, "corrector");
        int present = !lua_isnil(L, -1);
        lua_pop(L, 1);
        if (present)
            rc = read_substeps(&sp->ncorrector, &sp->corrector_flow, &sp->corrector_coef, sp, L, "corrector", 1,
                               path, err);
    }
    if (rc == VIGEN_OK) rc = read_generalized(sp, L, path, err);
    if (rc == VIGEN_OK) {
        sp->drift = calloc((size_t)sp->n, sizeof *sp->drift);
        if (sp->drift == NULL) abort();
        /* kick/drift files: flow 0 is "drift"; two named flows: the first is the letter A */
        for (slong k = 0; k < sp->n; k++) sp->drift[k] = sp->nflows == 2 && sp->flow[k] == 0;
    }
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
