/* float_text.c — the text of a Lua float in messages (float_text.h). */
#include <stdlib.h>
#include <string.h>

#include <lauxlib.h>

#include "vigen/error.h"
#include "lua/float_text.h"
#include "support/strbuf.h"

size_t vigen_float_format(char *buf, size_t size, double x)
{
    char *text = NULL;
    for (int digits = 1; digits <= 17; digits++) {
        free(text);
        text = vigen_strdup_printf("%.*g", digits, x);
        if (x != x || strtod(text, NULL) == x) break;
    }
    size_t n = strlen(text);
    if (strspn(text, "-0123456789") == n) {     /* Lua shows integral floats with ".0" */
        char *t = vigen_strdup_printf("%s.0", text);
        free(text);
        text = t;
        n += 2;
    }
    if (size > 0) {
        size_t k = n < size - 1 ? n : size - 1;
        memcpy(buf, text, k);
        buf[k] = '\0';
    }
    free(text);
    return n;
}

const char *vigen_push_float_text(lua_State *L, double x)
{
    luaL_Buffer b;
    size_t n = vigen_float_format(NULL, 0, x);
    char *p = luaL_buffinitsize(L, &b, n + 1);
    vigen_float_format(p, n + 1, x);
    luaL_pushresultsize(&b, n);
    return lua_tostring(L, -1);
}
