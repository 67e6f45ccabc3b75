/* methods.h — the kinds of method file (methods.def): the functions each
 * row names, declared from the table itself. */
#ifndef VIGEN_METHODS_H
#define VIGEN_METHODS_H

#include <lua.h>
#include "lua/sandbox.h"
#include "method/spec.h"
#include "method/tableau_file.h"
#include "method/splitting_file.h"
#include "vigen/method.h"
#include "vigen/tableau.h"

/* The registry's loader (vigen_method_load with the default caps), handed
 * to every kind's reader: a kind made of other methods (a composition and
 * its base) loads them with it.  The kinds are plug-ins of the registry
 * (registry.c, methods.def), below it; this is their way back to it. */
typedef int (*vigen_method_loader)(vigen_method **out, const char *path, vigen_error *err);

/* A kind of method file: the row of methods.def as a struct. */
typedef struct {
    const char *name;
    int (*detect)(lua_State *L, int idx);
    int (*read)(void **state, vigen_sandbox *sb, const char *path, vigen_method_loader load, vigen_error *err);
    int (*tableau)(vigen_tableau *t, void *state, slong digits, vigen_error *err);
    void (*release)(void *state);
    int generated;
    const char *fields;
    const char *description;
} method_kind;

/* A loaded method: its kind and the state its reader made. */
struct vigen_method {
    const method_kind *kind;
    void *state;
};

#define X(id, name, detect, read, tableau, release, generated, fields, description)                            \
    int read(void **state, vigen_sandbox *sb, const char *path, vigen_method_loader load, vigen_error *err);  \
    int tableau(vigen_tableau *t, void *state, slong digits, vigen_error *err);                               \
    void release(void *state);
#include "method/methods.def"
#undef X

#endif
