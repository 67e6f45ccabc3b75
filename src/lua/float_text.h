/* float_text.h — how a Lua float is shown in messages: the shortest decimal
 * that reads back as the same double, written the way Lua writes it.  Used by
 * the sandbox, the ball library and the spec reader when they refuse a float. */
#ifndef VIGEN_FLOAT_TEXT_H
#define VIGEN_FLOAT_TEXT_H

#include <stddef.h>
#include <lua.h>

/* Writes the shortest decimal text that reads back as x, the way Lua shows a
 * float ("0.3333333333333333", "0.5", "3.0", "1e+300"), snprintf-style: returns
 * the length needed, writes at most size bytes (NUL included). */
size_t vigen_float_format(char *buf, size_t size, double x);
/* Pushes that text as a Lua string (Lua memory: nothing leaks if a later call
 * raises) and returns it. */
const char *vigen_push_float_text(lua_State *L, double x);

#endif
