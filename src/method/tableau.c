/* tableau.c — tableau records, the tableau file format (read and write),
 * atomic file output and the symplecticity residual. */
#define _DEFAULT_SOURCE /* mkstemp, realpath, fchmod, lstat */
#include <errno.h>
#include <limits.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <lauxlib.h>
#include "core/decimal.h"
#include "core/expr.h"
#include "vigen/tableau.h"
#include "lua/sandbox.h"

static char **texts_new(slong n)
{
    char **t = calloc((size_t)n, sizeof(char *));
    if (t == NULL) abort();
    return t;
}

static void texts_free(char **t, slong n)
{
    if (t == NULL) return;
    for (slong i = 0; i < n; i++) free(t[i]);
    free(t);
}

void vigen_tableau_init(vigen_tableau *t, slong s)
{
    memset(t, 0, sizeof(*t));
    t->s = s;
    t->c = _arb_vec_init(s);
    t->b = _arb_vec_init(s);
    t->ct = _arb_vec_init(s);
    t->bt = _arb_vec_init(s);
    arb_mat_init(t->A, s, s);
    arb_mat_init(t->At, s, s);
    t->claim_order = -1;
    t->claim_symplectic = -1;
}

void vigen_tableau_clear(vigen_tableau *t)
{
    slong s = t->s;
    free(t->name);
    texts_free(t->c_text, s);
    texts_free(t->b_text, s);
    texts_free(t->ct_text, s);
    texts_free(t->bt_text, s);
    texts_free(t->A_text, s * s);
    texts_free(t->At_text, s * s);
    _arb_vec_clear(t->c, s);
    _arb_vec_clear(t->b, s);
    _arb_vec_clear(t->ct, s);
    _arb_vec_clear(t->bt, s);
    arb_mat_clear(t->A);
    arb_mat_clear(t->At);
    free(t->description);
    free(t->source);
    free(t->basis);
    free(t->nodes);
    free(t->generator);
    memset(t, 0, sizeof(*t));
}

int vigen_tableau_entry_eval(arb_t res, const char *text, slong prec, vigen_error *err)
{
    if (vigen_decimal_parse_rounded(res, text, prec)) return VIGEN_OK;
    return vigen_expr_eval_string(res, text, prec, err);
}

/* ---------------------------------------------------------------- reading */

/* Tableau files are untrusted: every read below is raw (no __index, __len or
 * other metamethod can run outside a protected call), and tables carrying a
 * metatable are refused outright. */
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

/* Reads the entry at the top of the Lua stack into *out (a fresh string). */
static int read_entry(lua_State *L, char **out, const char *path, const char *label, vigen_error *err)
{
    if (lua_type(L, -1) == LUA_TSTRING) {
        const char *text = lua_tostring(L, -1);
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

/* Reads field `key` (a list of s entries) of the table at the top. */
static int read_vector(lua_State *L, const char *key, slong s, char ***out, int required, const char *path,
                       vigen_error *err)
{
    int rc = VIGEN_OK;
    raw_getfield(L, -1, key);
    if (lua_isnil(L, -1)) {
        lua_pop(L, 1);
        if (required) return vigen_error_set(err, VIGEN_E_SPEC, "%s: the field '%s' is missing", path, key);
        return VIGEN_OK;
    }
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
    char **texts = texts_new(s);
    for (slong i = 0; i < s && rc == VIGEN_OK; i++) {
        lua_rawgeti(L, -1, i + 1);
        char *label = vigen_strdup_printf("%s[%ld]", key, (long)(i + 1));
        rc = read_entry(L, &texts[i], path, label, err);
        free(label);
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    if (rc != VIGEN_OK) { texts_free(texts, s); return rc; }
    *out = texts;
    return VIGEN_OK;
}

static int read_matrix(lua_State *L, const char *key, slong s, char ***out, int required, const char *path,
                       vigen_error *err)
{
    int rc = VIGEN_OK;
    raw_getfield(L, -1, key);
    if (lua_isnil(L, -1)) {
        lua_pop(L, 1);
        if (required) return vigen_error_set(err, VIGEN_E_SPEC, "%s: the field '%s' is missing", path, key);
        return VIGEN_OK;
    }
    if (!lua_istable(L, -1) || has_metatable(L, -1) || (slong)lua_rawlen(L, -1) != s) {
        lua_pop(L, 1);
        return vigen_error_set(err, VIGEN_E_SPEC, "%s: '%s' must be a list of %ld rows of %ld entries", path, key,
                               (long)s, (long)s);
    }
    char **texts = texts_new(s * s);
    for (slong i = 0; i < s && rc == VIGEN_OK; i++) {
        lua_rawgeti(L, -1, i + 1);
        if (!lua_istable(L, -1) || has_metatable(L, -1) || (slong)lua_rawlen(L, -1) != s) {
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: %s[%ld] must be a row of %ld entries", path, key,
                                 (long)(i + 1), (long)s);
        }
        for (slong j = 0; j < s && rc == VIGEN_OK; j++) {
            lua_rawgeti(L, -1, j + 1);
            char *label = vigen_strdup_printf("%s[%ld][%ld]", key, (long)(i + 1), (long)(j + 1));
            rc = read_entry(L, &texts[i * s + j], path, label, err);
            free(label);
            lua_pop(L, 1);
        }
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    if (rc != VIGEN_OK) { texts_free(texts, s * s); return rc; }
    *out = texts;
    return VIGEN_OK;
}

static int read_string_field(lua_State *L, const char *key, char **out, const char *path, vigen_error *err)
{
    raw_getfield(L, -1, key);
    int rc = VIGEN_OK;
    if (lua_type(L, -1) == LUA_TSTRING) *out = vigen_strdup(lua_tostring(L, -1));
    else if (!lua_isnil(L, -1))
        rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: '%s' must be a string", path, key);
    lua_pop(L, 1);
    return rc;
}

static const char *const known_fields[] = {
    "name", "s", "c", "A", "b", "At", "ct", "bt", "digits", "source", "description",
    "basis", "nodes", "generator", "order", "symplectic", "spec", NULL};

int vigen_tableau_load(vigen_tableau *t, const char *path, const vigen_sandbox_limits *limits, vigen_error *err)
{
    vigen_sandbox *sb = NULL;
    int rc = vigen_sandbox_new(&sb, limits, err);
    if (rc != VIGEN_OK) return rc;
    rc = vigen_sandbox_run_file(sb, path, err);
    if (rc != VIGEN_OK) { vigen_sandbox_free(sb); return rc; }
    lua_State *L = vigen_sandbox_state(sb);
    /* reading below allocates outside any protected call: lift the memory cap
     * so that it cannot raise (the file has finished running) */
    vigen_sandbox_lift_memory_cap(sb);
    if (!lua_istable(L, -1) || has_metatable(L, -1)) {
        vigen_sandbox_free(sb);
        return vigen_error_set(err, VIGEN_E_SPEC, "%s: a tableau file must return a plain table (return { name = ..., s = ..., "
                               "c = {...}, A = {{...}}, b = {...} })", path);
    }

    /* unknown fields are most likely typos ("At" spelled "AT"): refuse them */
    lua_pushnil(L);
    while (lua_next(L, -2) != 0) {
        lua_pop(L, 1);
        int known = 0;
        if (lua_type(L, -1) == LUA_TSTRING)
            for (int k = 0; known_fields[k]; k++) known |= strcmp(lua_tostring(L, -1), known_fields[k]) == 0;
        if (!known) {
            const char *key = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : "(a non-string key)";
            const char *near = lua_type(L, -1) == LUA_TSTRING ? vigen_nearest_name(key, known_fields, 2) : NULL;
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: unknown field '%s'%s%s%s (known: name, s, c, A, b, At, ct, bt, "
                                 "digits, source, description, basis, nodes, generator, order, symplectic)", path, key,
                                 near ? "; did you mean '" : "", near ? near : "", near ? "'?" : "");
            lua_pop(L, 1);
            vigen_sandbox_free(sb);
            return rc;
        }
    }

    raw_getfield(L, -1, "s");
    if (!lua_isinteger(L, -1) || lua_tointeger(L, -1) < 1 || lua_tointeger(L, -1) > 4096) {
        lua_pop(L, 1);
        vigen_sandbox_free(sb);
        return vigen_error_set(err, VIGEN_E_SPEC, "%s: 's' (the number of stages) must be an integer from 1 to 4096",
                               path);
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
    if (rc == VIGEN_OK) {
        raw_getfield(L, -1, "digits");
        if (lua_isinteger(L, -1) && lua_tointeger(L, -1) >= 0) t->digits = (slong)lua_tointeger(L, -1);
        else if (!lua_isnil(L, -1))
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: 'digits' must be a non-negative integer", path);
        lua_pop(L, 1);
    }
    if (rc == VIGEN_OK) {
        raw_getfield(L, -1, "order");
        if (lua_isinteger(L, -1) && lua_tointeger(L, -1) >= 0 && lua_tointeger(L, -1) < 1000)
            t->claim_order = (int)lua_tointeger(L, -1);
        else if (!lua_isnil(L, -1))
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: 'order' (a claim) must be a non-negative integer", path);
        lua_pop(L, 1);
    }
    if (rc == VIGEN_OK) {
        raw_getfield(L, -1, "symplectic");
        if (lua_isboolean(L, -1)) t->claim_symplectic = lua_toboolean(L, -1);
        else if (!lua_isnil(L, -1))
            rc = vigen_error_set(err, VIGEN_E_SPEC, "%s: 'symplectic' (a claim) must be true or false", path);
        lua_pop(L, 1);
    }
    vigen_sandbox_free(sb);
    if (rc != VIGEN_OK) { vigen_tableau_clear(t); return rc; }
    t->has_At = t->At_text != NULL;
    t->has_ct = t->ct_text != NULL;
    t->has_bt = t->bt_text != NULL;
    if ((t->has_ct || t->has_bt) && !t->has_At) {
        int code = vigen_error_set(err, VIGEN_E_SPEC, "%s: 'ct'/'bt' are given without 'At'", path);
        vigen_tableau_clear(t);
        return code;
    }
    return VIGEN_OK;
}

static int eval_texts(arb_ptr out, char **texts, slong n, slong prec, const char *key, vigen_error *err)
{
    for (slong k = 0; k < n; k++) {
        int rc = vigen_tableau_entry_eval(out + k, texts[k], prec, err);
        if (rc != VIGEN_OK) return vigen_error_prefix(err, "%s[%ld]: ", key, (long)(k + 1));
        if (!arb_is_finite(out + k))
            return vigen_error_set(err, VIGEN_E_DOMAIN, "%s[%ld] is not finite", key, (long)(k + 1));
    }
    return VIGEN_OK;
}

static int eval_matrix(arb_mat_t out, char **texts, slong prec, const char *key, slong s, vigen_error *err)
{
    for (slong i = 0; i < s; i++)
        for (slong j = 0; j < s; j++) {
            arb_ptr x = arb_mat_entry(out, i, j);
            int rc = vigen_tableau_entry_eval(x, texts[i * s + j], prec, err);
            if (rc != VIGEN_OK) return vigen_error_prefix(err, "%s[%ld][%ld]: ", key, (long)(i + 1), (long)(j + 1));
            if (!arb_is_finite(x))
                return vigen_error_set(err, VIGEN_E_DOMAIN, "%s[%ld][%ld] is not finite", key, (long)(i + 1), (long)(j + 1));
        }
    return VIGEN_OK;
}

int vigen_tableau_evaluate(vigen_tableau *t, slong prec, vigen_error *err)
{
    slong s = t->s;
    int rc = eval_texts(t->c, t->c_text, s, prec, "c", err);
    if (rc == VIGEN_OK) rc = eval_texts(t->b, t->b_text, s, prec, "b", err);
    if (rc == VIGEN_OK) rc = eval_matrix(t->A, t->A_text, prec, "A", s, err);
    if (rc == VIGEN_OK && t->has_At) rc = eval_matrix(t->At, t->At_text, prec, "At", s, err);
    if (rc == VIGEN_OK && t->has_ct) rc = eval_texts(t->ct, t->ct_text, s, prec, "ct", err);
    if (rc == VIGEN_OK && t->has_bt) rc = eval_texts(t->bt, t->bt_text, s, prec, "bt", err);
    if (rc != VIGEN_OK) return rc;
    if (!t->has_bt) _arb_vec_set(t->bt, t->b, s);
    if (t->has_At && !t->has_ct)
        /* ct not given: the natural one, ct_i = sum_j at_ij (has_ct stays 0) */
        for (slong i = 0; i < s; i++) {
            arb_zero(t->ct + i);
            for (slong j = 0; j < s; j++) arb_add(t->ct + i, t->ct + i, arb_mat_entry(t->At, i, j), prec);
        }
    t->prec = prec;
    return VIGEN_OK;
}

/* ---------------------------------------------------------------- writing */

/* True when the ball is far narrower than `digits` digits need: if those
 * digits still cannot be certified, the value sits (within the radius) on a
 * rounding tie, which no precision can decide. */
static int tight_for(const arb_t x, slong digits)
{
    if (arb_contains_zero(x) || arb_is_exact(x)) return 0;
    arb_t q;
    arb_init(q);
    arb_get_rad_arb(q, x);
    arb_div_arf(q, q, arb_midref(x), 64);
    arb_abs(q, q);
    arb_t lim;
    arb_init(lim);
    arb_set_si(lim, 10);
    arb_pow_ui(lim, lim, (ulong)(digits + 8), 64);
    arb_mul(q, q, lim, 64);
    int tight = arf_cmpabs_2exp_si(arb_midref(q), 0) < 0;
    arb_clear(q);
    arb_clear(lim);
    return tight;
}

static int format_entry(char **out, const arb_t x, slong digits)
{
    /* an exact integer (the node 1 of Lobatto or equispaced nodes, an exact 0)
     * is written as one, an exact literal, not as the rounded "1.000..." */
    char *text = vigen_decimal_format_integer(x);
    if (text == NULL) text = vigen_decimal_format(x, digits);
    /* A value on a tie (9/40 = 0.225 at 2 digits) has two correct roundings
     * and a ball around it never picks one: write it with the fewest extra
     * digits that are certified (0.225), which is still a correct rounding. */
    for (slong extra = 1; text == NULL && extra <= 20 && tight_for(x, digits); extra++)
        text = vigen_decimal_format(x, digits + extra);
    if (text == NULL && arb_contains_zero(x)) {
        /* a ball around zero: certify |x| <= 10^-digits / 2, written "0e-digits" */
        char *z = vigen_decimal_format_zero(x);
        if (z != NULL) {
            long K = 0;
            if (strcmp(z, "0") == 0) text = z;
            else if (sscanf(z, "0e%ld", &K) == 1 && K <= -digits) {
                free(z);
                text = vigen_strdup_printf("0e-%ld", (long)digits);
            } else free(z);
        }
    }
    if (text == NULL) return VIGEN_E_PRECISION;
    free(*out);
    *out = text;
    return VIGEN_OK;
}

/* Formats one named entry; on failure says which entry and why. */
static int format_named(char **out, const arb_t x, slong digits, slong prec, const char *label, vigen_error *err)
{
    if (format_entry(out, x, digits) == VIGEN_OK) return VIGEN_OK;
    char *v = arb_get_str(x, digits + 20, 0);
    int code = vigen_error_set(err, VIGEN_E_PRECISION,
                               "%s = %s cannot be rounded to %ld certified digits at %ld bits (if the exact value "
                               "lies halfway between two %ld-digit decimals, no precision decides it: ask for "
                               "--digits %ld)", label, v, (long)digits, (long)prec, (long)digits, (long)(digits + 1));
    flint_free(v);
    return code;
}

static int format_vector(char ***texts, arb_srcptr v, slong n, slong digits, slong prec, const char *key,
                         vigen_error *err)
{
    if (*texts == NULL) *texts = texts_new(n);
    for (slong k = 0; k < n; k++) {
        char label[64];
        snprintf(label, sizeof label, "%s[%ld]", key, (long)(k + 1));
        if (format_named(&(*texts)[k], v + k, digits, prec, label, err) != VIGEN_OK) return VIGEN_E_PRECISION;
    }
    return VIGEN_OK;
}

static int format_matrix(char ***texts, const arb_mat_t m, slong s, slong digits, slong prec, const char *key,
                         vigen_error *err)
{
    if (*texts == NULL) *texts = texts_new(s * s);
    for (slong i = 0; i < s; i++)
        for (slong j = 0; j < s; j++) {
            char label[64];
            snprintf(label, sizeof label, "%s[%ld][%ld]", key, (long)(i + 1), (long)(j + 1));
            if (format_named(&(*texts)[i * s + j], arb_mat_entry(m, i, j), digits, prec, label, err) != VIGEN_OK)
                return VIGEN_E_PRECISION;
        }
    return VIGEN_OK;
}

int vigen_tableau_texts_from_balls(vigen_tableau *t, slong digits, vigen_error *err)
{
    slong s = t->s, p = t->prec;
    int rc = format_vector(&t->c_text, t->c, s, digits, p, "c", err);
    if (rc == VIGEN_OK) rc = format_vector(&t->b_text, t->b, s, digits, p, "b", err);
    if (rc == VIGEN_OK) rc = format_matrix(&t->A_text, t->A, s, digits, p, "A", err);
    if (rc == VIGEN_OK && t->has_At) rc = format_matrix(&t->At_text, t->At, s, digits, p, "At", err);
    if (rc == VIGEN_OK && t->has_ct) rc = format_vector(&t->ct_text, t->ct, s, digits, p, "ct", err);
    if (rc == VIGEN_OK && t->has_bt) rc = format_vector(&t->bt_text, t->bt, s, digits, p, "bt", err);
    if (rc != VIGEN_OK) return rc;
    t->digits = digits;
    return VIGEN_OK;
}

/* Appends a Lua string literal: "..." when that needs no escapes, else a long
 * bracket string [==[...]==] with a level the text does not contain. */
static void append_lua_string(vigen_strbuf *sb, const char *text)
{
    if (strpbrk(text, "\"\\\n\r") == NULL) {
        vigen_strbuf_printf(sb, "\"%s\"", text);
        return;
    }
    int level = 0;
    for (;;) {
        char close[64];
        close[0] = ']';
        memset(close + 1, '=', (size_t)level);
        close[level + 1] = ']';
        close[level + 2] = '\0';
        if (strstr(text, close) == NULL) break;
        level++;
    }
    vigen_strbuf_append(sb, "[");
    for (int i = 0; i < level; i++) vigen_strbuf_append(sb, "=");
    vigen_strbuf_append(sb, text[0] == '\n' ? "[\n" : "[");
    vigen_strbuf_append(sb, text);
    vigen_strbuf_append(sb, "]");
    for (int i = 0; i < level; i++) vigen_strbuf_append(sb, "=");
    vigen_strbuf_append(sb, "]");
}

static void append_vector(vigen_strbuf *sb, const char *key, char **texts, slong s)
{
    vigen_strbuf_printf(sb, "  %s = {", key);
    for (slong i = 0; i < s; i++) {
        vigen_strbuf_append(sb, i ? ", " : " ");
        append_lua_string(sb, texts[i]);
    }
    vigen_strbuf_append(sb, " },\n");
}

static void append_matrix(vigen_strbuf *sb, const char *key, char **texts, slong s)
{
    vigen_strbuf_printf(sb, "  %s = {\n", key);
    for (slong i = 0; i < s; i++) {
        vigen_strbuf_append(sb, "    {");
        for (slong j = 0; j < s; j++) {
            vigen_strbuf_append(sb, j ? ", " : " ");
            append_lua_string(sb, texts[i * s + j]);
        }
        vigen_strbuf_append(sb, " },\n");
    }
    vigen_strbuf_append(sb, "  },\n");
}

static void append_string_field(vigen_strbuf *sb, const char *key, const char *value)
{
    if (value == NULL) return;
    vigen_strbuf_printf(sb, "  %s = ", key);
    append_lua_string(sb, value);
    vigen_strbuf_append(sb, ",\n");
}

char *vigen_tableau_to_lua(const vigen_tableau *t)
{
    vigen_strbuf sb;
    vigen_strbuf_init(&sb);
    if (t->generator != NULL) {
        vigen_strbuf_printf(&sb, "-- Generated by %s; do not edit: regenerate with `vigen generate`.\n", t->generator);
        vigen_strbuf_printf(&sb, "-- Every decimal entry is the correct rounding of the exact coefficient to %ld\n"
                                 "-- significant digits (more for a value on a rounding tie); an integer (\"0\",\n"
                                 "-- \"1\") is exact and \"0e-%ld\" a certified |x| <= 0.5e-%ld.\n",
                            (long)t->digits, (long)t->digits, (long)t->digits);
    }
    vigen_strbuf_append(&sb, "return {\n");
    append_string_field(&sb, "name", t->name);
    append_string_field(&sb, "description", t->description);
    append_string_field(&sb, "source", t->source);
    append_string_field(&sb, "basis", t->basis);
    append_string_field(&sb, "nodes", t->nodes);
    append_string_field(&sb, "generator", t->generator);
    if (t->digits > 0) vigen_strbuf_printf(&sb, "  digits = %ld,\n", (long)t->digits);
    if (t->claim_order >= 0) vigen_strbuf_printf(&sb, "  order = %d,\n", t->claim_order);
    if (t->claim_symplectic >= 0)
        vigen_strbuf_printf(&sb, "  symplectic = %s,\n", t->claim_symplectic ? "true" : "false");
    vigen_strbuf_printf(&sb, "  s = %ld,\n", (long)t->s);
    append_vector(&sb, "c", t->c_text, t->s);
    append_matrix(&sb, "A", t->A_text, t->s);
    append_vector(&sb, "b", t->b_text, t->s);
    if (t->has_At) append_matrix(&sb, "At", t->At_text, t->s);
    if (t->has_ct) append_vector(&sb, "ct", t->ct_text, t->s);
    if (t->has_bt) append_vector(&sb, "bt", t->bt_text, t->s);
    vigen_strbuf_append(&sb, "}\n");
    return sb.data;
}

/* Writes everything or fails (no partial output left behind). */
static int write_all(int fd, const char *text, size_t n)
{
    while (n > 0) {
        ssize_t k = write(fd, text, n);
        if (k < 0) {
            if (errno == EINTR) continue;
            return 0;
        }
        text += k;
        n -= (size_t)k;
    }
    return 1;
}

int vigen_write_file_atomic(const char *path, const char *text, vigen_error *err)
{
    size_t n = strlen(text);
    if (strcmp(path, "-") == 0) {
        if (fwrite(text, 1, n, stdout) != n || fflush(stdout) != 0)
            return vigen_error_set(err, VIGEN_E_IO, "cannot write to standard output: %s", strerror(errno));
        return VIGEN_OK;
    }
    /* A symbolic link is followed: the file it points to is replaced, the
     * link stays.  A device or FIFO (/dev/null, a pipe) is written directly:
     * renaming over it would replace the device with a regular file. */
    char *target = NULL;
    struct stat st;
    int exists = 0;
    if (lstat(path, &st) == 0 && S_ISLNK(st.st_mode)) {
        target = realpath(path, NULL);
        if (target == NULL) {
            /* /dev/stdout -> /proc/self/fd/1 -> "pipe:[...]": no path, but a
             * device or pipe that can be written in place */
            if (stat(path, &st) == 0 && !S_ISREG(st.st_mode)) target = vigen_strdup(path);
            else return vigen_error_set(err, VIGEN_E_IO, "cannot write %s: it is a symbolic link to a missing file",
                                        path);
        }
    } else target = vigen_strdup(path);
    if (stat(target, &st) == 0) {
        exists = 1;
        if (!S_ISREG(st.st_mode)) {
            int code = VIGEN_OK;
            FILE *f = fopen(target, "wb");
            if (f == NULL || fwrite(text, 1, n, f) != n || fclose(f) != 0)
                code = vigen_error_set(err, VIGEN_E_IO, "cannot write %s: %s", path, strerror(errno));
            free(target);
            return code;
        }
    }
    /* A fresh, unpredictable temporary in the same directory (mkstemp creates
     * it exclusively, so nobody can plant a link there), then rename. */
    char *tmp = vigen_strdup_printf("%s.tmp.XXXXXX", target);
    int fd = mkstemp(tmp);
    if (fd < 0) {
        int code = vigen_error_set(err, VIGEN_E_IO, "cannot create a temporary file next to %s: %s", path,
                                   strerror(errno));
        free(tmp);
        free(target);
        return code;
    }
    /* the new file gets the old one's permissions, or the usual 0666 & ~umask */
    mode_t mode;
    if (exists) mode = st.st_mode & 07777;
    else {
        mode_t mask = umask(0);
        umask(mask);
        mode = 0666 & ~mask;
    }
    int ok = fchmod(fd, mode) == 0 && write_all(fd, text, n);
    ok = (close(fd) == 0) && ok;
    if (!ok || rename(tmp, target) != 0) {
        int code = vigen_error_set(err, VIGEN_E_IO, "cannot write %s: %s", path, strerror(errno));
        remove(tmp);
        free(tmp);
        free(target);
        return code;
    }
    free(tmp);
    free(target);
    return VIGEN_OK;
}

void vigen_tableau_symplectic_residual(arb_t res, const vigen_tableau *t, slong prec)
{
    slong s = t->s;
    arb_t r, u;
    arb_init(r);
    arb_init(u);
    arb_zero(res);
    for (slong i = 0; i < s; i++)
        for (slong j = 0; j < s; j++) {
            arb_mul(r, t->b + i, arb_mat_entry(t->At, i, j), prec);
            arb_addmul(r, t->b + j, arb_mat_entry(t->A, j, i), prec);
            arb_mul(u, t->b + i, t->b + j, prec);
            arb_sub(r, r, u, prec);
            arb_abs(r, r);
            arb_max(res, res, r, prec);
        }
    /* bt must equal b as well */
    for (slong i = 0; i < s; i++) {
        arb_sub(r, t->bt + i, t->b + i, prec);
        arb_abs(r, r);
        arb_max(res, res, r, prec);
    }
    arb_clear(r);
    arb_clear(u);
}
