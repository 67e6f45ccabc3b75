/* ball.h — complex arb balls as Lua values, for basis functions written in Lua.
 *
 * A Lua basis function receives t as a ball userdata and must return a ball or
 * an exact Lua integer.  Balls support + - * / ^ (integer or ball exponents),
 * unary minus, comparison is refused (a ball comparison is not a boolean), and
 * tostring.  The library table `ball` offers ball.pi, ball.sqrt, ball.exp,
 * ball.log, ball.sin, ball.cos, ball.tan and ball.exact("1/3") (an exact
 * expression string, parsed by expr.h).  The same functions are also global
 * (sqrt, exp, log, sin, cos, tan, pi, exact) inside spec files.
 *
 * Mixing a ball with a Lua float (1/3 in Lua is the double 0.333...) raises a
 * Lua error telling the user to write exact("1/3") or t/3: a rounded binary
 * value never silently enters ball arithmetic.  Lua integers are exact.
 *
 * Every ball operation uses the precision and analyticity flag of the current
 * evaluation (vigen_ball_set_context); with analytic set, sqrt and log use the
 * analytic variants so that acb_calc_integrate sees branch cuts.
 */
#ifndef VIGEN_BALL_H
#define VIGEN_BALL_H

#include <lua.h>
#include <acb.h>

/* Registers the ball metatable and library in L (called by the sandbox).  It
 * keeps a pointer in lua_getextraspace(L). */
void vigen_ball_open(lua_State *L);

/* Sets the precision and analytic flag used by ball operations in L (after
 * vigen_ball_open; touches no Lua API, so it may be called unprotected). */
void vigen_ball_set_context(lua_State *L, slong prec, int analytic);

/* Pushes a copy of z as a ball userdata.  Allocates Lua memory, so it may raise
 * "not enough memory": call it inside a protected call. */
void vigen_ball_push(lua_State *L, const acb_t z);

/* If the value at idx is a ball, or a Lua integer, writes it to res and
 * returns 1; otherwise (float, string, table, nil...) returns 0. */
int vigen_ball_get(acb_t res, lua_State *L, int idx);

#endif
