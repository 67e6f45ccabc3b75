/* ball.c — complex arb balls as Lua userdata.
 *
 * A ball is a full userdata holding one acb_struct, with a __gc that clears
 * it.  No acb_t local is ever held across a call that may raise a Lua error:
 * every function first checks its arguments, then pushes its result ball
 * (which may raise "not enough memory", but owns nothing yet), and only then
 * computes, with temporaries that are cleared before returning.  C memory that
 * must survive a Lua call (an expression, an error record, a flint string)
 * lives in a "scratch" userdata whose __gc frees it.
 *
 * The precision and analytic flag live in a userdata anchored in the registry;
 * a pointer to it sits in the state's extra space so that every operation
 * reaches it without touching the Lua API.
 */
#include <stdio.h>
#include <string.h>

#include <lauxlib.h>

#include "lua/ball.h"
#include "core/expr.h"
#include "lua/float_text.h"

typedef struct {
    slong prec;
    int analytic;
} ball_context;

typedef struct {
    vigen_expr *expr;
    vigen_error err;
    char *str[2];       /* flint_malloc'ed */
} scratch;

static char ball_mt_key, scratch_mt_key, context_key;

static const char float_hint[] = "Lua's 1/3 is a rounded double: write exact(\"1/3\") or t/3";

static ball_context *context(lua_State *L) { return *(ball_context **)lua_getextraspace(L); }

/* ------------------------------------------------------------------ helpers */

static int is_ball(lua_State *L, int idx)
{
    if (lua_type(L, idx) != LUA_TUSERDATA || !lua_checkstack(L, 2) || !lua_getmetatable(L, idx)) return 0;
    lua_rawgetp(L, LUA_REGISTRYINDEX, &ball_mt_key);
    int same = lua_rawequal(L, -1, -2);
    lua_pop(L, 2);
    return same;
}

static acb_struct *push_ball(lua_State *L)
{
    acb_struct *z = lua_newuserdatauv(L, sizeof(acb_struct), 0);
    acb_init(z);                          /* allocates nothing */
    lua_rawgetp(L, LUA_REGISTRYINDEX, &ball_mt_key);
    lua_setmetatable(L, -2);
    return z;
}

static scratch *push_scratch(lua_State *L)
{
    scratch *s = lua_newuserdatauv(L, sizeof(scratch), 0);
    s->expr = NULL;
    vigen_error_init(&s->err);
    s->str[0] = s->str[1] = NULL;
    lua_rawgetp(L, LUA_REGISTRYINDEX, &scratch_mt_key);
    lua_setmetatable(L, -2);
    return s;
}

static void scratch_release(scratch *s)
{
    if (s->expr) vigen_expr_free(s->expr);
    s->expr = NULL;
    vigen_error_clear(&s->err);
    for (int i = 0; i < 2; i++) {
        if (s->str[i]) flint_free(s->str[i]);
        s->str[i] = NULL;
    }
}

static int scratch_gc(lua_State *L)
{
    scratch_release(lua_touserdata(L, 1));
    return 0;
}

static int ball_gc(lua_State *L)
{
    acb_struct *z = lua_touserdata(L, 1);
    acb_clear(z);
    acb_init(z);
    return 0;
}

/* Raises unless the value at idx is a ball or a Lua integer.  fname: the
 * function being called, or NULL for an arithmetic operator. */
static void check_operand(lua_State *L, int idx, const char *fname, const char *op)
{
    int t = lua_type(L, idx);
    if (t == LUA_TNUMBER && lua_isinteger(L, idx)) {
        /* Lua integers wrap around silently past 2^63: one that large is
         * more likely a wrapped result than a number the user meant */
        lua_Integer v = lua_tointeger(L, idx);
        if (v > ((lua_Integer)1 << 53) || v < -((lua_Integer)1 << 53))
            luaL_error(L, "basis function: the Lua integer %I is beyond 2^53 (Lua integer arithmetic wraps around "
                          "silently); compute with balls, e.g. exact(\"2\")^62", v);
        return;
    }
    if (t == LUA_TNUMBER) {
        const char *f = vigen_push_float_text(L, lua_tonumber(L, idx));
        /* a short literal (0.5, 2.25) was most likely meant exactly: suggest
         * that very value; a long one (0.3333333333333333) has no exact text */
        char hint[96];
        if (strlen(f) <= 12)
            snprintf(hint, sizeof hint, "a Lua float is a rounded double: write exact(\"%s\") if that value is meant exactly", f);
        else
            snprintf(hint, sizeof hint, "%s", float_hint);
        if (fname) luaL_error(L, "basis function: %s got a Lua float (%s); %s", fname, f, hint);
        luaL_error(L, "basis function: a Lua float (%s) met a ball; %s", f, hint);
    }
    if (is_ball(L, idx)) return;
    if (fname) {
        if (t == LUA_TNONE)
            luaL_error(L, "basis function: %s(x) needs an argument, a ball or a Lua integer", fname);
        luaL_error(L, "basis function: %s expects a ball or a Lua integer, not a %s", fname, luaL_typename(L, idx));
    }
    luaL_error(L, "basis function: a ball cannot be combined with a %s (%s); use balls, Lua integers and exact(\"...\")",
               luaL_typename(L, idx), op);
}

/* The value of a checked operand; tmp holds it when it is a Lua integer. */
static acb_srcptr operand(acb_t tmp, lua_State *L, int idx)
{
    if (lua_type(L, idx) == LUA_TNUMBER) {
        acb_set_si(tmp, (slong)lua_tointeger(L, idx));
        return tmp;
    }
    return lua_touserdata(L, idx);
}

/* ------------------------------------------------------------------ metamethods */

enum { OP_ADD, OP_SUB, OP_MUL, OP_DIV, OP_POW };

static int arith(lua_State *L, int op)
{
    static const char *const names[] = { "+", "-", "*", "/", "^" };
    check_operand(L, 1, NULL, names[op]);
    check_operand(L, 2, NULL, names[op]);
    const ball_context *c = context(L);
    acb_struct *r = push_ball(L);
    acb_t ta, tb;
    acb_init(ta);
    acb_init(tb);
    acb_srcptr a = operand(ta, L, 1);
    if (op == OP_POW && lua_type(L, 2) == LUA_TNUMBER) {
        acb_pow_si(r, a, (slong)lua_tointeger(L, 2), c->prec);   /* exact integer power */
    } else {
        acb_srcptr b = operand(tb, L, 2);
        switch (op) {
        case OP_ADD: acb_add(r, a, b, c->prec); break;
        case OP_SUB: acb_sub(r, a, b, c->prec); break;
        case OP_MUL: acb_mul(r, a, b, c->prec); break;
        case OP_DIV: acb_div(r, a, b, c->prec); break;
        default: acb_pow_analytic(r, a, b, c->analytic, c->prec); break;
        }
    }
    acb_clear(ta);
    acb_clear(tb);
    return 1;
}

static int ball_add(lua_State *L) { return arith(L, OP_ADD); }
static int ball_sub(lua_State *L) { return arith(L, OP_SUB); }
static int ball_mul(lua_State *L) { return arith(L, OP_MUL); }
static int ball_div(lua_State *L) { return arith(L, OP_DIV); }
static int ball_pow(lua_State *L) { return arith(L, OP_POW); }

static int ball_unm(lua_State *L)
{
    check_operand(L, 1, NULL, "-");
    const ball_context *c = context(L);
    acb_struct *r = push_ball(L);
    acb_t ta;
    acb_init(ta);
    acb_neg(r, operand(ta, L, 1));
    acb_set_round(r, r, c->prec);
    acb_clear(ta);
    return 1;
}

static int ball_compare(lua_State *L)
{
    return luaL_error(L, "basis function: balls cannot be compared: a ball is an interval, so a test "
                         "such as t < 1/2 has no yes-or-no answer; write the function without comparisons");
}

/* "0.500000" -> "0.5", "7.000" -> "7" (exact values print without padding). */
static void trim_zeros(char *s)
{
    if (strchr(s, '.') == NULL || strpbrk(s, "[eE") != NULL) return;
    size_t n = strlen(s);
    while (n > 0 && s[n - 1] == '0') s[--n] = '\0';
    if (n > 0 && s[n - 1] == '.') s[--n] = '\0';
}

static int ball_tostring(lua_State *L)
{
    if (!is_ball(L, 1)) return luaL_error(L, "ball tostring: not a ball");
    const acb_struct *z = lua_touserdata(L, 1);
    slong digits = (slong)(context(L)->prec * 0.30103) + 1;
    scratch *s = push_scratch(L);
    s->str[0] = arb_get_str(acb_realref(z), digits, 0);
    trim_zeros(s->str[0]);
    if (arb_is_zero(acb_imagref(z))) {
        lua_pushstring(L, s->str[0]);
    } else {
        s->str[1] = arb_get_str(acb_imagref(z), digits, 0);
        trim_zeros(s->str[1]);
        lua_pushfstring(L, "%s + %s*i", s->str[0], s->str[1]);
    }
    scratch_release(s);
    return 1;
}

/* ------------------------------------------------------------------ library */

/* ball.NAME for a row of the expression function table (the upvalue). */
static int l_function(lua_State *L)
{
    const vigen_expr_function *f = lua_touserdata(L, lua_upvalueindex(1));
    check_operand(L, 1, f->name, NULL);
    const ball_context *c = context(L);
    acb_struct *r = push_ball(L);
    acb_t tz;
    acb_init(tz);
    f->eval_acb(r, operand(tz, L, 1), c->analytic, c->prec);
    acb_clear(tz);
    return 1;
}

/* exact("1/3"): an exact expression string, evaluated as a real ball. */
static int l_exact(lua_State *L)
{
    int t = lua_type(L, 1);
    if (t == LUA_TNUMBER && lua_isinteger(L, 1)) {
        acb_struct *r = push_ball(L);
        acb_set_si(r, (slong)lua_tointeger(L, 1));
        return 1;
    }
    if (t == LUA_TNUMBER) {
        const char *f = vigen_push_float_text(L, lua_tonumber(L, 1));
        return luaL_error(L, "exact() takes a string such as exact(\"1/3\"), not the Lua float %s", f);
    }
    if (t != LUA_TSTRING)
        return luaL_error(L, "exact() takes a string such as exact(\"1/3\"), not a %s", luaL_typename(L, 1));
    size_t len;
    const char *text = lua_tolstring(L, 1, &len);
    if (strlen(text) != len) return luaL_error(L, "exact(): the string contains a zero byte");
    const ball_context *c = context(L);
    scratch *s = push_scratch(L);
    acb_struct *r = push_ball(L);
    int code = vigen_expr_parse(&s->expr, text, 0, &s->err);
    slong prec = c->prec;
    /* A domain question undecided at this precision (1/(x - y) with x, y close)
     * may be decided higher up; a genuine domain error fails every time. */
    for (int attempt = 0; code == VIGEN_OK && attempt < 3; attempt++, prec *= 4) {
        vigen_error_clear(&s->err);
        code = vigen_expr_eval_arb(acb_realref(r), s->expr, NULL, prec, &s->err);
        if (code != VIGEN_E_DOMAIN) break;
    }
    if (code != VIGEN_OK)
        return luaL_error(L, "exact(\"%s\"): %s", text, s->err.message ? s->err.message : vigen_status_name(code));
    arb_zero(acb_imagref(r));
    acb_set_round(r, r, c->prec);
    scratch_release(s);
    return 1;
}

/* ball.pi, and ball.<unknown> */
static int lib_index(lua_State *L)
{
    for (int i = 0; lua_type(L, 2) == LUA_TSTRING && i < vigen_expr_constant_count(); i++) {
        const vigen_expr_constant *k = vigen_expr_constant_at(i);
        if (strcmp(lua_tostring(L, 2), k->name) != 0) continue;
        acb_struct *r = push_ball(L);
        k->eval_acb(r, context(L)->prec);
        return 1;
    }
    return luaL_error(L, "ball.%s does not exist (the ball library has %s, %s, exact)",
                      lua_type(L, 2) == LUA_TSTRING ? lua_tostring(L, 2) : luaL_typename(L, 2),
                      vigen_expr_constant_names(), vigen_expr_function_names());
}

/* ------------------------------------------------------------------ API */

void vigen_ball_open(lua_State *L)
{
    ball_context *c = lua_newuserdatauv(L, sizeof *c, 0);
    c->prec = 128;
    c->analytic = 0;
    lua_rawsetp(L, LUA_REGISTRYINDEX, &context_key);
    *(ball_context **)lua_getextraspace(L) = c;

    static const luaL_Reg meta[] = {
        { "__gc", ball_gc }, { "__add", ball_add }, { "__sub", ball_sub }, { "__mul", ball_mul },
        { "__div", ball_div }, { "__pow", ball_pow }, { "__unm", ball_unm }, { "__lt", ball_compare },
        { "__le", ball_compare }, { "__eq", ball_compare }, { "__tostring", ball_tostring }, { NULL, NULL }
    };
    lua_newtable(L);
    luaL_setfuncs(L, meta, 0);
    lua_pushliteral(L, "ball");
    lua_setfield(L, -2, "__name");
    lua_pushliteral(L, "ball");
    lua_setfield(L, -2, "__metatable");      /* getmetatable(t) cannot reach the metamethods */
    lua_rawsetp(L, LUA_REGISTRYINDEX, &ball_mt_key);

    lua_newtable(L);
    lua_pushcfunction(L, scratch_gc);
    lua_setfield(L, -2, "__gc");
    lua_pushboolean(L, 0);
    lua_setfield(L, -2, "__metatable");
    lua_rawsetp(L, LUA_REGISTRYINDEX, &scratch_mt_key);

    static const luaL_Reg lib[] = { { "exact", l_exact }, { NULL, NULL } };
    luaL_newlib(L, lib);
    for (int i = 0; i < vigen_expr_function_count(); i++) {
        const vigen_expr_function *f = vigen_expr_function_at(i);
        if (!f->in_ball_library) continue;
        lua_pushlightuserdata(L, (void *)f);
        lua_pushcclosure(L, l_function, 1);
        lua_setfield(L, -2, f->name);
    }
    lua_newtable(L);
    lua_pushcfunction(L, lib_index);
    lua_setfield(L, -2, "__index");
    lua_setmetatable(L, -2);
    lua_pushvalue(L, -1);
    lua_setfield(L, LUA_REGISTRYINDEX, "vigen.ball.lib");
    lua_setglobal(L, "ball");
}

void vigen_ball_set_context(lua_State *L, slong prec, int analytic)
{
    ball_context *c = context(L);
    c->prec = prec > 2 ? prec : 2;
    c->analytic = analytic != 0;
}

void vigen_ball_push(lua_State *L, const acb_t z)
{
    acb_struct *r = push_ball(L);
    acb_set(r, z);
}

int vigen_ball_get(acb_t res, lua_State *L, int idx)
{
    if (lua_type(L, idx) == LUA_TNUMBER && lua_isinteger(L, idx)) {
        acb_set_si(res, (slong)lua_tointeger(L, idx));
        return 1;
    }
    if (!is_ball(L, idx)) return 0;
    acb_set(res, (const acb_struct *)lua_touserdata(L, idx));
    return 1;
}
