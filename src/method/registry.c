/* registry.c — method files (vigen/method.h): the file run once in a
 * sandbox with the spec vocabulary, its table recognised by the rows of methods.def and handed to the
 * reader of its kind, which then makes the tableaux asked for. */
#include <stdlib.h>
#include <lauxlib.h>
#include "method/methods.h"
#include "method/vocabulary.h"
#include "vigen/method.h"
#include "support/strbuf.h"

enum {
#define X(id, name, detect, read, tableau, release, generated, fields, description) VIGEN_METHOD_##id,
#include "method/methods.def"
#undef X
    VIGEN_METHOD_KINDS
};

static const method_kind kinds[] = {
#define X(id, name, detect, read, tableau, release, generated, fields, description)                            \
    { name, detect, read, tableau, release, generated, fields, description },
#include "method/methods.def"
#undef X
};

/* Runs protected: 1 = the value the file returned; returns the index of the
 * first kind that accepts it, or -1. */
static int detect_protected(lua_State *L)
{
    int found = -1;
    for (int k = 0; k < VIGEN_METHOD_KINDS && found < 0; k++)
        if (kinds[k].detect(L, 1)) found = k;
    lua_pushinteger(L, found);
    return 1;
}

/* The file at path run once in a fresh sandbox, and its kind: on success
 * *sb holds the sandbox with the file's value on top and *kind its row (NULL
 * when no row accepts the value; err then says what a method file needs). */
static int run_and_detect(vigen_sandbox **sb, const method_kind **kind, const char *path,
                          const vigen_sandbox_limits *limits, vigen_error *err)
{
    *kind = NULL;
    int rc = vigen_vocabulary_run_file(sb, path, limits, err);
    lua_State *L = rc == VIGEN_OK ? vigen_sandbox_state(*sb) : NULL;
    if (rc == VIGEN_OK && !lua_checkstack(L, 4)) rc = vigen_error_set(err, VIGEN_E_MEMORY, "%s: out of memory", path);
    if (rc == VIGEN_OK) {
        lua_pushcfunction(L, detect_protected);
        lua_pushvalue(L, -2);
        rc = vigen_sandbox_pcall(*sb, 1, 1, err);
    }
    if (rc == VIGEN_OK) {
        lua_Integer k = lua_tointeger(L, -1);
        lua_pop(L, 1);
        if (k >= 0) {
            *kind = &kinds[k];
            return VIGEN_OK;
        }
        vigen_strbuf b;
        vigen_strbuf_init(&b);
        if (lua_istable(L, -1))
            vigen_strbuf_printf(&b, "%s: the table the file returns has none of the fields of a method file; give it ", path);
        else
            vigen_strbuf_printf(&b, "%s: the file returns a %s; it must return a table with ", path, luaL_typename(L, -1));
        for (int i = 0; i < VIGEN_METHOD_KINDS; i++)
            vigen_strbuf_printf(&b, "%s%s", i == 0 ? "" : i + 1 < VIGEN_METHOD_KINDS ? ", " : " or ", kinds[i].fields);
        rc = vigen_error_set(err, VIGEN_E_SPEC, "%s", b.data);
        vigen_strbuf_clear(&b);
    }
    vigen_sandbox_free(*sb);
    *sb = NULL;
    return rc;
}

static int load_default(vigen_method **out, const char *path, vigen_error *err)
{
    return vigen_method_load(out, path, NULL, err);
}

int vigen_method_load(vigen_method **out, const char *path, const vigen_sandbox_limits *limits, vigen_error *err)
{
    *out = NULL;
    vigen_sandbox *sb = NULL;
    const method_kind *kind;
    int rc = run_and_detect(&sb, &kind, path, limits, err);
    if (rc != VIGEN_OK) return rc;
    vigen_method *m = calloc(1, sizeof(*m));
    if (m == NULL) {
        vigen_sandbox_free(sb);
        return vigen_error_set(err, VIGEN_E_MEMORY, "out of memory");
    }
    m->kind = kind;
    rc = kind->read(&m->state, sb, path, load_default, err);
    if (rc != VIGEN_OK) {
        free(m);
        return rc;
    }
    *out = m;
    return VIGEN_OK;
}

int vigen_source_load(vigen_tableau *t, const char *path, slong digits, vigen_error *err)
{
    vigen_method *m = NULL;
    int rc = vigen_method_load(&m, path, NULL, err);
    if (rc != VIGEN_OK) return rc;
    rc = vigen_method_tableau(t, m, digits, err);
    vigen_method_free(m);
    return rc;
}
