/* registry.c — load a tableau from a tableau file or a spec file. */
#include <lauxlib.h>
#include "method/galerkin.h"
#include "lua/sandbox.h"
#include "vigen/method.h"
#include "lua/spec.h"
#include <stdlib.h>

struct vigen_method {
    char *path;
    int generated;
    vigen_spec *spec;   /* generated: the loaded spec */
};

int vigen_source_is_tableau(const char *path, vigen_error *err)
{
    vigen_sandbox *sb = NULL;
    if (vigen_sandbox_new(&sb, NULL, err) != VIGEN_OK) return -1;
    if (vigen_sandbox_run_file(sb, path, err) != VIGEN_OK) { vigen_sandbox_free(sb); return -1; }
    vigen_sandbox_lift_memory_cap(sb);
    lua_State *L = vigen_sandbox_state(sb);
    /* a tableau has s or A; anything else is read as a spec, whose loader
     * explains what is missing.  Raw reads: the file is untrusted. */
    int is_tableau = 1;
    if (lua_istable(L, -1)) {
        lua_pushliteral(L, "A");
        lua_rawget(L, -2);
        int has_A = !lua_isnil(L, -1);
        lua_pop(L, 1);
        lua_pushliteral(L, "s");
        lua_rawget(L, -2);
        int has_s = !lua_isnil(L, -1);
        lua_pop(L, 1);
        is_tableau = has_A || has_s;
    }
    vigen_sandbox_free(sb);
    return is_tableau;
}

int vigen_source_load(vigen_tableau *t, const char *path, slong digits, vigen_error *err)
{
    int kind = vigen_source_is_tableau(path, err);
    if (kind < 0) return err->code;
    if (kind == 0) {
        vigen_spec *spec = NULL;
        int rc = vigen_spec_load(&spec, path, NULL, err);
        if (rc != VIGEN_OK) return rc;
        rc = vigen_galerkin_generate(t, spec, digits, err);
        vigen_spec_free(spec);
        return rc;
    }
    int rc = vigen_tableau_load(t, path, NULL, err);
    if (rc != VIGEN_OK) return rc;
    slong prec = vigen_galerkin_initial_prec(digits, t->s);
    rc = vigen_tableau_evaluate(t, prec, err);
    if (rc != VIGEN_OK) {
        vigen_error_prefix(err, "%s: ", path);
        vigen_tableau_clear(t);
    }
    return rc;
}

int vigen_generate_file(vigen_tableau *out, const char *path, slong digits, vigen_error *err)
{
    vigen_spec *spec = NULL;
    int rc = vigen_spec_load(&spec, path, NULL, err);
    if (rc != VIGEN_OK) return rc;
    rc = vigen_galerkin_generate(out, spec, digits, err);
    vigen_spec_free(spec);
    return rc;
}

int vigen_method_load(vigen_method **out, const char *path, const vigen_sandbox_limits *limits, vigen_error *err)
{
    *out = NULL;
    int kind = vigen_source_is_tableau(path, err);
    if (kind < 0) return err->code;
    vigen_method *m = calloc(1, sizeof(*m));
    if (m == NULL) return vigen_error_set(err, VIGEN_E_MEMORY, "out of memory");
    m->path = vigen_strdup(path);
    m->generated = kind == 0;
    if (m->generated) {
        int rc = vigen_spec_load(&m->spec, path, limits, err);
        if (rc != VIGEN_OK) { vigen_method_free(m); return rc; }
    }
    *out = m;
    return VIGEN_OK;
}

void vigen_method_free(vigen_method *m)
{
    if (m == NULL) return;
    if (m->spec) vigen_spec_free(m->spec);
    free(m->path);
    free(m);
}

int vigen_method_is_generated(const vigen_method *m) { return m->generated; }

int vigen_method_tableau(vigen_tableau *t, vigen_method *m, slong digits, vigen_error *err)
{
    if (m->generated) return vigen_galerkin_generate(t, m->spec, digits, err);
    int rc = vigen_tableau_load(t, m->path, NULL, err);
    if (rc != VIGEN_OK) return rc;
    slong prec = vigen_galerkin_initial_prec(digits, t->s);
    rc = vigen_tableau_evaluate(t, prec, err);
    if (rc != VIGEN_OK) {
        vigen_error_prefix(err, "%s: ", m->path);
        vigen_tableau_clear(t);
    }
    return rc;
}
