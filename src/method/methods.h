/* methods.h — the kinds of method file (methods.def): the functions each
 * row names, declared from the table itself. */
#ifndef VIGEN_METHODS_H
#define VIGEN_METHODS_H

#include <lua.h>
#include "lua/sandbox.h"
#include "method/spec.h"
#include "lua/tableau_file.h"
#include "lua/splitting_file.h"
#include "vigen/tableau.h"

#define X(id, name, detect, read, tableau, release, generated, fields, description)                            \
    int read(void **state, vigen_sandbox *sb, const char *path, vigen_error *err);                            \
    int tableau(vigen_tableau *t, void *state, slong digits, vigen_error *err);                               \
    void release(void *state);
#include "method/methods.def"
#undef X

#endif
