/* spec.c — reading and validating method spec files, and calling their Lua
 * basis functions.
 *
 * The file runs in a sandbox with the spec vocabulary (vocabulary.c, once
 * per command: the method registry runs it and hands the table here); the table it returned is checked
 * by a C function that itself runs under vigen_sandbox_pcall, so that nothing
 * the table does (a memory error while reading it, say) can raise a Lua error
 * outside a protected call.  Every C allocation made during the check is
 * attached to the spec at once, so a Lua error at any point leaks nothing: the
 * caller frees the half-built spec.  Fields are read with raw accesses only;
 * no metamethod of the user's table runs.
 *
 * Validation failures are recorded in a C error record (not raised), so that
 * they keep their own code (VIGEN_E_SPEC, or VIGEN_E_SYNTAX from the
 * expression parser) and exact message.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <lauxlib.h>

#include "support/printable.h"
#include "lua/ball.h"
#include "lua/float_text.h"
#include "lua/quote.h"
#include "method/spec.h"
#include "method/families.h"
#include "method/vocabulary.h"
#include "vigen/limits.h"
#include "support/strbuf.h"
#include "support/nearest.h"
#include "support/nul.h"

static const char *const known_fields[] = { "name", "description", "source", "nodes", "basis", "order", NULL };

typedef struct {
    vigen_spec *spec;
    vigen_error err;        /* validation failure, if any */
    char **warnings;        /* unknown fields, sorted before they are reported */
    size_t n_warnings;
    vigen_strbuf text;      /* nodes_text / basis_text being built */
    char *entry, *src;      /* the list entry being checked: "nodes[2]", its text */
} load_ctx;

/* ------------------------------------------------------------------ helpers */

static void *xcalloc(size_t n, size_t size)
{
    void *p = calloc(n ? n : 1, size);
    if (p == NULL) abort();     /* as error.c: running out of C memory is fatal */
    return p;
}

static char *float_text(double x)
{
    size_t n = vigen_float_format(NULL, 0, x);
    char *s = xcalloc(n + 1, 1);
    vigen_float_format(s, n + 1, x);
    return s;
}

/* The exact string a user most likely meant by the Lua float x: the fraction
 * p/q with the smallest q <= 10^6 that Lua would round to x ("1/3" for
 * 0.3333333333333333), or NULL. */
static char *float_as_fraction(double x)
{
    if (!isfinite(x)) return NULL;
    for (long q = 1; q <= 1000000; q++) {
        double p = nearbyint(x * (double)q);
        if (fabs(p) > 9007199254740992.0) return NULL;
        if (p / (double)q == x) {
            if (q == 1) return vigen_strdup_printf("%.0f", p);
            return vigen_strdup_printf("%.0f/%ld", p, q);
        }
    }
    return NULL;
}

/* Records "PATH: ENTRY is the Lua float X; write the exact string "p/q"". */
static int refuse_float(load_ctx *cx, const char *entry, double x)
{
    char *f = float_text(x);
    char *frac = float_as_fraction(x);
    if (!isfinite(x))
        vigen_error_set(&cx->err, VIGEN_E_SPEC, "%s: %s is the Lua float %s, which is not a finite number; "
                        "write an exact value as a string, such as \"1/3\"", cx->spec->path, entry, f);
    else if (frac)
        vigen_error_set(&cx->err, VIGEN_E_SPEC, "%s: %s is the Lua float %s; write the exact string \"%s\"",
                        cx->spec->path, entry, f, frac);
    else
        vigen_error_set(&cx->err, VIGEN_E_SPEC,
                        "%s: %s is the Lua float %s, a rounded double; write the exact value as a string, "
                        "such as \"1/3\" or \"sqrt(2)/2\"", cx->spec->path, entry, f);
    free(f);
    free(frac);
    return cx->err.code;
}

static char *join_names(const char *const *names)
{
    vigen_strbuf b;
    vigen_strbuf_init(&b);
    vigen_strbuf_append(&b, "");
    for (int i = 0; names[i]; i++) {
        if (i) vigen_strbuf_append(&b, ", ");
        vigen_strbuf_append(&b, names[i]);
    }
    return b.data;
}

static int compare_strings(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* Pushes t[name] (raw) and returns its type. */
static int raw_field(lua_State *L, int table, const char *name)
{
    lua_pushstring(L, name);
    return lua_rawget(L, table);
}

/* The string at idx, or NULL after recording an error when it holds a NUL
 * byte (as a C string it would silently end there). */
static const char *plain_string(lua_State *L, int idx, const char *entry, load_ctx *cx)
{
    size_t len;
    const char *s = lua_tolstring(L, idx, &len);
    return vigen_refuse_nul(s, len, cx->spec->path, entry, &cx->err) == VIGEN_OK ? s : NULL;
}

/* ------------------------------------------------------------------ checks */

static void warn_unknown_fields(lua_State *L, int table, load_ctx *cx)
{
    lua_pushnil(L);
    while (lua_next(L, table)) {
        char *w = NULL;
        if (lua_type(L, -2) == LUA_TSTRING) {
            size_t len;
            const char *raw = lua_tolstring(L, -2, &len);
            int known = 0;      /* compared with its length: "name\0x" is not "name" */
            for (int i = 0; known_fields[i]; i++)
                known |= strlen(known_fields[i]) == len && memcmp(raw, known_fields[i], len) == 0;
            if (!known) {
                vigen_strbuf shown;
                vigen_strbuf_init(&shown);
                vigen_printable_append(&shown, raw, len);
                char *key = shown.data;
                /* the closest known field within 2 edits ('node' is 1 from
                 * 'nodes' and 2 from 'name': nodes) */
                const char *near = vigen_nearest_name(key, known_fields, 2);
                char *all = join_names(known_fields);
                w = near ? vigen_strdup_printf("%s: unknown field '%s' is ignored; did you mean '%s'? (known fields: %s)",
                                               cx->spec->path, key, near, all)
                         : vigen_strdup_printf("%s: unknown field '%s' is ignored (known fields: %s)",
                                               cx->spec->path, key, all);
                free(all);
                free(key);
            }
        } else {
            char *k = lua_isinteger(L, -2) ? vigen_strdup_printf("%lld", (long long)lua_tointeger(L, -2))
                      : lua_type(L, -2) == LUA_TNUMBER ? float_text(lua_tonumber(L, -2))
                      : vigen_strdup_printf("a %s key", luaL_typename(L, -2));
            w = vigen_strdup_printf("%s: the spec table's entry [%s] is ignored: spec fields are named "
                                    "(name = ..., nodes = ..., basis = ...)", cx->spec->path, k);
            free(k);
        }
        if (w) {
            cx->warnings = realloc(cx->warnings, (cx->n_warnings + 1) * sizeof *cx->warnings);
            if (cx->warnings == NULL) abort();
            cx->warnings[cx->n_warnings++] = w;
        }
        lua_pop(L, 1);
    }
    /* table traversal order varies from run to run: sort for reproducible output */
    if (cx->n_warnings > 1) qsort(cx->warnings, cx->n_warnings, sizeof *cx->warnings, compare_strings);
    for (size_t i = 0; i < cx->n_warnings; i++) vigen_warn("%s", cx->warnings[i]);
}

static int check_string_field(lua_State *L, int table, const char *field, int required, char **out,
                              load_ctx *cx)
{
    const char *P = cx->spec->path;
    int t = raw_field(L, table, field);
    int code = VIGEN_OK;
    if (t == LUA_TNIL) {
        if (required)
            code = vigen_error_set(&cx->err, VIGEN_E_SPEC, "%s: %s is missing: add %s = \"...\" (a string)", P,
                                   field, field);
    } else if (t != LUA_TSTRING) {
        code = vigen_error_set(&cx->err, VIGEN_E_SPEC, "%s: %s must be a string, not a %s", P, field,
                               luaL_typename(L, -1));
    } else if (plain_string(L, -1, field, cx) == NULL) {
        code = cx->err.code;
    } else if (required && lua_rawlen(L, -1) == 0) {
        code = vigen_error_set(&cx->err, VIGEN_E_SPEC, "%s: %s is empty", P, field);
    } else {
        *out = vigen_strdup(lua_tostring(L, -1));
    }
    lua_pop(L, 1);
    return code;
}

/* The list at idx must be a non-empty sequence {a, b, c}; writes its length. */
static int check_list(lua_State *L, int idx, const char *field, const char *example, load_ctx *cx, slong *n_out)
{
    const char *P = cx->spec->path;
    lua_Integer n = (lua_Integer)lua_rawlen(L, idx);
    lua_pushnil(L);
    while (lua_next(L, idx)) {
        lua_pop(L, 1);
        if (!lua_isinteger(L, -1) || lua_tointeger(L, -1) < 1 || lua_tointeger(L, -1) > n) {
            const char *key;
            if (lua_type(L, -1) == LUA_TSTRING) {
                key = lua_pushfstring(L, "'%s'", lua_tostring(L, -1));
            } else if (lua_isinteger(L, -1)) {
                key = lua_pushfstring(L, "[%I]", lua_tointeger(L, -1));
            } else {
                key = lua_pushfstring(L, "of type %s", luaL_typename(L, -1));
            }
            int code = vigen_error_set(&cx->err, VIGEN_E_SPEC,
                                       "%s: %s has an entry with key %s; it must be a plain list such as %s",
                                       P, field, key, example);
            lua_pop(L, 2);
            return code;
        }
    }
    if (n == 0)
        return vigen_error_set(&cx->err, VIGEN_E_SPEC, "%s: %s is empty; give a list such as %s", P, field, example);
    if (n > VIGEN_MAX_STAGES)
        return vigen_error_set(&cx->err, VIGEN_E_SPEC, "%s: %s has %lld entries; vigen generates methods of at most "
                               "%d stages: give at most %d", P, field, (long long)n, VIGEN_MAX_STAGES,
                               VIGEN_MAX_STAGES);
    *n_out = (slong)n;
    return VIGEN_OK;
}

static const char nodes_example[] = "{\"0\", \"1/2\", \"1\"}";
static const char basis_example[] = "{\"1\", \"cos(pi*t)\"}";

/* The list entry being checked: cx->entry = "nodes[2]", and cx->src = its
 * expression text when it is a string or an integer (NULL otherwise, after an
 * error has been recorded for anything that is not a Lua function). */
static int read_entry(lua_State *L, int idx, const char *field, slong i, load_ctx *cx)
{
    const char *P = cx->spec->path;
    free(cx->entry);
    free(cx->src);
    cx->src = NULL;
    cx->entry = vigen_strdup_printf("%s[%ld]", field, (long)i + 1);
    int t = lua_type(L, idx);
    const char *family;
    long fs;
    if (t == LUA_TNUMBER && lua_isinteger(L, idx)) {
        lua_Integer v = lua_tointeger(L, idx);
        if (v > ((lua_Integer)1 << 53) || v < -((lua_Integer)1 << 53))
            return vigen_error_set(&cx->err, VIGEN_E_SPEC, "%s: %s is the Lua integer %lld, beyond 2^53 (Lua integer "
                                   "arithmetic wraps around silently): write it as a string", P, cx->entry,
                                   (long long)v);
        cx->src = vigen_strdup_printf("%lld", (long long)v);
    } else if (t == LUA_TNUMBER) {
        return refuse_float(cx, cx->entry, lua_tonumber(L, idx));
    } else if (t == LUA_TSTRING) {
        const char *str = plain_string(L, idx, cx->entry, cx);
        if (str == NULL) return cx->err.code;
        cx->src = vigen_strdup(str);
    } else if (vigen_vocabulary_get_family(L, idx, NULL, &family, &fs)) {
        return vigen_error_set(&cx->err, VIGEN_E_SPEC, "%s: %s is %s(%ld); a family is not a list entry: write %s = %s(%ld)",
                               P, cx->entry, family, fs, field, family, fs);
    } else if (t != LUA_TFUNCTION || strcmp(field, "basis") != 0) {
        if (strcmp(field, "basis") == 0)
            return vigen_error_set(&cx->err, VIGEN_E_SPEC, "%s: %s is a %s; basis functions are expression strings in t "
                                   "such as \"cos(pi*t)\" or Lua functions of t", P, cx->entry, luaL_typename(L, idx));
        return vigen_error_set(&cx->err, VIGEN_E_SPEC, "%s: %s is a %s; nodes are exact numbers written as strings, "
                               "such as \"1/2\" or \"1/2 - sqrt(3)/6\"", P, cx->entry, luaL_typename(L, idx));
    }
    return VIGEN_OK;
}

/* The temporaries of the list checks live in cx (freed by the loader) because
 * luaL_ref may raise "not enough memory" while they are held. */
static int check_nodes_list(lua_State *L, int idx, load_ctx *cx)
{
    vigen_spec *sp = cx->spec;
    slong n;
    int code = check_list(L, idx, "nodes", nodes_example, cx, &n);
    if (code) return code;
    sp->nodes_kind = VIGEN_SPEC_NODES_LIST;
    sp->node_exprs = xcalloc((size_t)n, sizeof *sp->node_exprs);
    sp->s = n;
    vigen_strbuf_clear(&cx->text);
    vigen_strbuf_append(&cx->text, "{");
    for (slong i = 0; i < n && code == VIGEN_OK; i++) {
        lua_rawgeti(L, idx, (lua_Integer)i + 1);
        code = read_entry(L, -1, "nodes", i, cx);
        lua_pop(L, 1);
        if (code) break;
        code = vigen_expr_parse(&sp->node_exprs[i], cx->src, 0, &cx->err);
        if (code) vigen_error_prefix(&cx->err, "%s: %s: ", sp->path, cx->entry);
        if (i) vigen_strbuf_append(&cx->text, ", ");
        vigen_lua_quote(&cx->text, cx->src);
    }
    vigen_strbuf_append(&cx->text, "}");
    sp->nodes_text = cx->text.data;
    vigen_strbuf_init(&cx->text);
    return code;
}

static int check_nodes(lua_State *L, int table, load_ctx *cx)
{
    vigen_spec *sp = cx->spec;
    const char *P = sp->path;
    int t = raw_field(L, table, "nodes");
    int idx = lua_gettop(L);
    int code = VIGEN_OK, kind;
    const char *family;
    long s;
    char *names = NULL;
    if (t == LUA_TTABLE) {
        code = check_nodes_list(L, idx, cx);
    } else if (vigen_vocabulary_get_family(L, idx, &kind, &family, &s)) {
        if (kind != VIGEN_FAMILY_NODES) {
            names = join_names(vigen_nodes_family_names);
            code = vigen_error_set(&cx->err, VIGEN_E_SPEC,
                                   "%s: nodes: %s(%ld) is a basis family, not a node family (node families: %s)",
                                   P, family, s, names);
        } else {
            sp->nodes_kind = VIGEN_SPEC_NODES_FAMILY;
            sp->node_family = vigen_strdup(family);
            sp->s = s;
            sp->nodes_text = vigen_strdup_printf("%s(%ld)", family, s);
        }
    } else if (t == LUA_TNIL) {
        names = join_names(vigen_nodes_family_names);
        code = vigen_error_set(&cx->err, VIGEN_E_SPEC,
                               "%s: nodes is missing: give a list of exact numbers such as %s or a node family "
                               "such as gauss_legendre(3) (node families: %s)", P, nodes_example, names);
    } else if (t == LUA_TSTRING && plain_string(L, idx, "nodes", cx) == NULL) {
        code = cx->err.code;
    } else if (t == LUA_TSTRING) {
        const char *str = lua_tostring(L, idx);
        vigen_expr *e = NULL;
        vigen_error perr;
        vigen_error_init(&perr);
        if (vigen_nodes_is_family(str)) {
            code = vigen_error_set(&cx->err, VIGEN_E_SPEC,
                                   "%s: nodes = \"%s\" needs the number of nodes: write nodes = %s(3), without quotes",
                                   P, str, str);
        } else if (vigen_expr_parse(&e, str, 0, &perr) == VIGEN_OK) {
            code = vigen_error_set(&cx->err, VIGEN_E_SPEC,
                                   "%s: nodes is a single string; write a list: nodes = {\"%s\"}", P, str);
        } else {
            names = join_names(vigen_nodes_family_names);
            code = vigen_error_set(&cx->err, VIGEN_E_SPEC,
                                   "%s: nodes: unknown node family '%s' (known: %s); write a family call such as "
                                   "gauss_legendre(3) or a list of exact numbers such as %s", P, str, names,
                                   nodes_example);
        }
        if (e) vigen_expr_free(e);
        vigen_error_clear(&perr);
    } else if (t == LUA_TFUNCTION) {
        code = vigen_error_set(&cx->err, VIGEN_E_SPEC,
                               "%s: nodes is a function; a node family is called with the number of nodes, "
                               "such as nodes = gauss_legendre(3)", P);
    } else if (t == LUA_TNUMBER) {
        code = vigen_error_set(&cx->err, VIGEN_E_SPEC,
                               "%s: nodes is a number; write a list such as %s or a family call such as "
                               "gauss_legendre(3)", P, nodes_example);
    } else {
        code = vigen_error_set(&cx->err, VIGEN_E_SPEC,
                               "%s: nodes must be a list of exact numbers or a node family, not a %s", P,
                               luaL_typename(L, idx));
    }
    free(names);
    lua_settop(L, idx - 1);
    return code;
}

static int check_basis_list(lua_State *L, int idx, load_ctx *cx)
{
    vigen_spec *sp = cx->spec;
    slong n;
    int code = check_list(L, idx, "basis", basis_example, cx, &n);
    if (code) return code;
    sp->basis_kind = VIGEN_SPEC_BASIS_LIST;
    sp->items = xcalloc((size_t)n, sizeof *sp->items);
    for (slong i = 0; i < n; i++) sp->items[i].lua_ref = LUA_NOREF;
    sp->basis_count = n;
    vigen_strbuf_clear(&cx->text);
    vigen_strbuf_append(&cx->text, "{");
    for (slong i = 0; i < n && code == VIGEN_OK; i++) {
        vigen_spec_basis_item *item = &sp->items[i];
        int t = lua_rawgeti(L, idx, (lua_Integer)i + 1);
        code = read_entry(L, -1, "basis", i, cx);
        if (code) {
            lua_pop(L, 1);
            break;
        }
        if (i) vigen_strbuf_append(&cx->text, ", ");
        if (t == LUA_TFUNCTION) {
            item->kind = VIGEN_SPEC_ITEM_LUA;
            item->label = vigen_strdup_printf("<Lua function, %s>", cx->entry);
            item->lua_ref = luaL_ref(L, LUA_REGISTRYINDEX);      /* pops the function */
            vigen_lua_quote(&cx->text, "<Lua function>");
        } else {
            lua_pop(L, 1);
            item->kind = VIGEN_SPEC_ITEM_EXPR;
            item->label = vigen_strdup(cx->src);
            code = vigen_expr_parse(&item->expr, cx->src, 1, &cx->err);
            if (code) vigen_error_prefix(&cx->err, "%s: %s: ", sp->path, cx->entry);
            vigen_lua_quote(&cx->text, cx->src);
        }
    }
    vigen_strbuf_append(&cx->text, "}");
    sp->basis_text = cx->text.data;
    vigen_strbuf_init(&cx->text);
    return code;
}

/* "monomials(s), trig(s), legendre(s), chebyshev_t(s)" (heap) */
static char *basis_calls(void)
{
    vigen_strbuf b;
    vigen_strbuf_init(&b);
    for (int i = 0; vigen_basis_family_names[i]; i++)
        vigen_strbuf_printf(&b, "%s%s(s)", i ? ", " : "", vigen_basis_family_names[i]);
    return b.data;
}

static int check_basis(lua_State *L, int table, load_ctx *cx)
{
    vigen_spec *sp = cx->spec;
    const char *P = sp->path;
    int t = raw_field(L, table, "basis");
    int idx = lua_gettop(L);
    int code = VIGEN_OK, kind;
    const char *family;
    long s;
    char *calls = NULL;
    if (t == LUA_TTABLE) {
        code = check_basis_list(L, idx, cx);
    } else if (vigen_vocabulary_get_family(L, idx, &kind, &family, &s)) {
        if (kind != VIGEN_FAMILY_BASIS) {
            calls = basis_calls();
            code = vigen_error_set(&cx->err, VIGEN_E_SPEC,
                                   "%s: basis: %s(%ld) is a node family, not a basis family (basis families: %s; "
                                   "or \"lagrange\")", P, family, s, calls);
        } else {
            sp->basis_kind = VIGEN_SPEC_BASIS_FAMILY;
            sp->basis_family = vigen_strdup(family);
            sp->basis_count = s;
            sp->basis_text = vigen_strdup_printf("%s(%ld)", family, s);
        }
    } else if (t == LUA_TSTRING && plain_string(L, idx, "basis", cx) == NULL) {
        code = cx->err.code;
    } else if (t == LUA_TSTRING) {
        const char *str = lua_tostring(L, idx);
        int is_family = vigen_basis_is_family(str);
        calls = basis_calls();
        if (strcmp(str, "lagrange") == 0) {
            sp->basis_kind = VIGEN_SPEC_BASIS_LAGRANGE;
            sp->basis_count = sp->s;
            sp->basis_text = vigen_strdup("\"lagrange\"");
        } else if (is_family) {
            code = vigen_error_set(&cx->err, VIGEN_E_SPEC,
                                   "%s: basis = \"%s\" needs the number of functions: write basis = %s(%ld), "
                                   "without quotes", P, str, str, (long)sp->s);
        } else if (vigen_nodes_is_family(str)) {
            code = vigen_error_set(&cx->err, VIGEN_E_SPEC,
                                   "%s: basis: '%s' is a node family, not a basis (write \"lagrange\", a family "
                                   "such as %s, or a list of functions of t)", P, str, calls);
        } else {
            code = vigen_error_set(&cx->err, VIGEN_E_SPEC,
                                   "%s: basis: unknown basis '%s'; write \"lagrange\", a family (%s) or a list of "
                                   "functions of t such as %s", P, str, calls, basis_example);
        }
    } else if (t == LUA_TNIL) {
        calls = basis_calls();
        code = vigen_error_set(&cx->err, VIGEN_E_SPEC,
                               "%s: basis is missing: write basis = \"lagrange\", a family (%s) or a list of "
                               "functions of t such as %s", P, calls, basis_example);
    } else if (t == LUA_TFUNCTION) {
        code = vigen_error_set(&cx->err, VIGEN_E_SPEC,
                               "%s: basis is a function; a basis family is called with the number of functions "
                               "(basis = trig(5)) and Lua functions go in a list "
                               "(basis = {\"1\", function(t) return cos(pi*t) end})", P);
    } else {
        calls = basis_calls();
        code = vigen_error_set(&cx->err, VIGEN_E_SPEC,
                               "%s: basis must be \"lagrange\", a basis family (%s) or a list, not a %s", P,
                               calls, luaL_typename(L, idx));
    }
    free(calls);
    lua_settop(L, idx - 1);
    return code;
}

/* Runs protected: 1 = the value the file returned, 2 = the load_ctx. */
static int validate(lua_State *L)
{
    load_ctx *cx = lua_touserdata(L, 2);
    vigen_spec *sp = cx->spec;
    const char *P = sp->path;
    if (lua_type(L, 1) != LUA_TTABLE) {
        vigen_error_set(&cx->err, VIGEN_E_SPEC,
                        "%s: the file must return a table { name = ..., nodes = ..., basis = ... }, not a %s", P,
                        luaL_typename(L, 1));
        return 0;
    }
    warn_unknown_fields(L, 1, cx);
    if (check_string_field(L, 1, "name", 1, &sp->name, cx)) return 0;
    if (check_string_field(L, 1, "description", 0, &sp->description, cx)) return 0;
    if (check_string_field(L, 1, "source", 0, &sp->source, cx)) return 0;
    /* order = p: a claim, checked against the certified order of the tableau */
    int ot = raw_field(L, 1, "order");
    if (ot != LUA_TNIL && !(lua_isinteger(L, -1) && lua_tointeger(L, -1) >= 1 && lua_tointeger(L, -1) <= 100)) {
        lua_pop(L, 1);
        vigen_error_set(&cx->err, VIGEN_E_SPEC, "%s: 'order' (a claim, checked when the tableau is generated) must "
                        "be an integer from 1 to 100", P);
        return 0;
    }
    if (ot != LUA_TNIL) sp->claim_order = (int)lua_tointeger(L, -1);
    lua_pop(L, 1);
    if (check_nodes(L, 1, cx)) return 0;
    if (check_basis(L, 1, cx)) return 0;
    if (sp->basis_count != sp->s) {
        vigen_error_set(&cx->err, VIGEN_E_SPEC,
                        "%s: basis has %ld function%s but nodes has %ld entr%s; Theorem 3 needs one node per "
                        "basis function", P, (long)sp->basis_count, sp->basis_count == 1 ? "" : "s", (long)sp->s,
                        sp->s == 1 ? "y" : "ies");
    }
    return 0;
}

/* ------------------------------------------------------------------ API */

int vigen_spec_detect(lua_State *L, int idx)
{
    if (!lua_istable(L, idx)) return 0;
    idx = lua_absindex(L, idx);
    int found = raw_field(L, idx, "nodes") != LUA_TNIL;
    lua_pop(L, 1);
    found |= raw_field(L, idx, "basis") != LUA_TNIL;
    lua_pop(L, 1);
    return found;
}

int vigen_spec_from_table(vigen_spec **out, vigen_sandbox *sb, const char *path, vigen_error *err)
{
    *out = NULL;
    vigen_spec *sp = xcalloc(1, sizeof *sp);
    sp->claim_order = -1;
    sp->path = vigen_strdup(path);
    sp->sandbox = sb;
    lua_State *L = vigen_sandbox_state(sb);
    load_ctx cx;
    memset(&cx, 0, sizeof cx);
    cx.spec = sp;
    vigen_error_init(&cx.err);
    vigen_strbuf_init(&cx.text);
    int code;
    if (!lua_checkstack(L, 3)) {
        code = vigen_error_set(err, VIGEN_E_MEMORY, "%s: out of memory", path);
    } else {
        lua_pushcfunction(L, validate);
        lua_insert(L, -2);
        lua_pushlightuserdata(L, &cx);
        code = vigen_sandbox_pcall(sb, 2, 0, err);
    }
    if (code == VIGEN_OK && cx.err.code != VIGEN_OK)
        code = vigen_error_set(err, cx.err.code, "%s", cx.err.message ? cx.err.message : "invalid spec");
    vigen_error_clear(&cx.err);
    for (size_t i = 0; i < cx.n_warnings; i++) free(cx.warnings[i]);
    free(cx.warnings);
    vigen_strbuf_clear(&cx.text);
    free(cx.entry);
    free(cx.src);
    if (code != VIGEN_OK) {
        vigen_spec_free(sp);    /* frees the sandbox too */
        return code;
    }
    *out = sp;
    return VIGEN_OK;
}

int vigen_spec_load(vigen_spec **out, const char *path, const vigen_sandbox_limits *limits, vigen_error *err)
{
    *out = NULL;
    vigen_sandbox *sb = NULL;
    int code = vigen_vocabulary_run_file(&sb, path, limits, err);
    if (code != VIGEN_OK) return code;
    return vigen_spec_from_table(out, sb, path, err);
}

void vigen_spec_free(vigen_spec *spec)
{
    if (spec == NULL) return;
    free(spec->path);
    free(spec->name);
    free(spec->description);
    free(spec->source);
    if (spec->node_exprs) {
        for (slong i = 0; i < spec->s; i++)
            if (spec->node_exprs[i]) vigen_expr_free(spec->node_exprs[i]);
        free(spec->node_exprs);
    }
    free(spec->node_family);
    free(spec->basis_family);
    if (spec->items) {
        for (slong i = 0; i < spec->basis_count; i++) {
            if (spec->items[i].expr) vigen_expr_free(spec->items[i].expr);
            free(spec->items[i].label);
        }
        free(spec->items);
    }
    free(spec->nodes_text);
    free(spec->basis_text);
    vigen_sandbox_free(spec->sandbox);   /* releases the Lua functions with the state */
    free(spec);
}

typedef struct {
    int ref;
    const acb_struct *t;
    acb_struct *res;
    int bad;                /* the function returned neither a ball nor an integer */
    int was_float;
    double float_value;
    const char *type_name;  /* Lua's static type name */
} call_ctx;

/* Runs protected: 1 = the call_ctx. */
static int call_basis_protected(lua_State *L)
{
    call_ctx *c = lua_touserdata(L, 1);
    lua_rawgeti(L, LUA_REGISTRYINDEX, c->ref);
    vigen_ball_push(L, c->t);
    lua_call(L, 1, 1);
    if (!vigen_ball_get(c->res, L, -1)) {
        c->bad = 1;
        c->was_float = lua_type(L, -1) == LUA_TNUMBER;
        c->float_value = c->was_float ? lua_tonumber(L, -1) : 0.0;
        c->type_name = luaL_typename(L, -1);
    }
    return 0;
}

int vigen_spec_call_basis(acb_t res, vigen_spec *spec, slong index, const acb_t t, int analytic, slong prec,
                          vigen_error *err)
{
    if (spec->basis_kind != VIGEN_SPEC_BASIS_LIST || index < 0 || index >= spec->basis_count) {
        acb_indeterminate(res);
        return vigen_error_set(err, VIGEN_E_USAGE, "%s: there is no basis list entry basis[%ld]", spec->path,
                               (long)index + 1);
    }
    const vigen_spec_basis_item *item = &spec->items[index];
    if (item->kind == VIGEN_SPEC_ITEM_EXPR) {
        int code = vigen_expr_eval_acb(res, item->expr, t, analytic, prec);
        if (code != VIGEN_OK)
            vigen_error_set(err, code, "%s: basis[%ld]: cannot evaluate \"%s\"", spec->path, (long)index + 1,
                            item->label);
        return code;
    }
    lua_State *L = vigen_sandbox_state(spec->sandbox);
    vigen_ball_set_context(L, prec, analytic);
    call_ctx c = { item->lua_ref, t, res, 0, 0, 0.0, NULL };
    acb_t out;
    acb_init(out);
    c.res = out;
    int code;
    if (!lua_checkstack(L, 2)) {
        code = vigen_error_set(err, VIGEN_E_MEMORY, "%s: out of memory", spec->path);
    } else {
        lua_pushcfunction(L, call_basis_protected);
        lua_pushlightuserdata(L, &c);
        code = vigen_sandbox_pcall(spec->sandbox, 1, 0, err);
    }
    if (code != VIGEN_OK) {
        if (err && err->message) {
            char *m = vigen_strdup_printf("%s (evaluating basis[%ld])", err->message, (long)index + 1);
            vigen_error_set(err, code, "%s", m);
            free(m);
        }
    } else if (c.bad && c.was_float) {
        char *f = float_text(c.float_value);
        code = vigen_error_set(err, VIGEN_E_SPEC,
                               "%s: basis[%ld] returned the Lua float %s; a basis function must return a ball "
                               "computed from t or a Lua integer (Lua's 1/3 is a rounded double: write "
                               "exact(\"1/3\") or t/3)", spec->path, (long)index + 1, f);
        free(f);
    } else if (c.bad) {
        code = vigen_error_set(err, VIGEN_E_SPEC,
                               "%s: basis[%ld] returned a %s; a basis function must return a ball computed "
                               "from t or a Lua integer", spec->path, (long)index + 1, c.type_name);
    }
    if (code == VIGEN_OK) acb_swap(res, out);
    else acb_indeterminate(res);
    acb_clear(out);
    return code;
}
