/* splitting_file.h — reading splitting and composition files: methods
 * written as published, a sequence of kicks and drifts, or a base method
 * composed with steps gamma_i h.  The conversion to a PRK tableau is
 * method/splitting.c. */
#ifndef VIGEN_METHOD_SPLITTING_FILE_H
#define VIGEN_METHOD_SPLITTING_FILE_H

#include <lua.h>
#include "lua/sandbox.h"
#include "vigen/tableau.h"

/* 1 when the value at idx is a table with a `splitting` (resp.
 * `composition`) field.  Raw reads. */
int vigen_splitting_file_detect(lua_State *L, int idx);
int vigen_composition_file_detect(lua_State *L, int idx);

/* A splitting: substep k is a drift (q <- q + coef h dT/dp) when drift[k],
 * else a kick (p <- p - coef h dV/dq). */
typedef struct {
    slong n;
    int *drift;
    char **coef;
} vigen_splitting;

void vigen_splitting_clear(vigen_splitting *sp);

/* Reads the table on top of sb's stack (the file has run): info (name,
 * source, description, claims) into info (initialised by the caller with
 * vigen_tableau_init(info, 1)), the substeps into sp.  Messages name the
 * file and the entry (splitting[3][2]). */
int vigen_splitting_from_table(vigen_splitting *sp, vigen_tableau *info, vigen_sandbox *sb, const char *path,
                               vigen_error *err);

/* A composition: base (a file or a method name, as written) and the step
 * fractions gamma[0 .. m-1]. */
typedef struct {
    char *base;
    slong m;
    char **gamma;
} vigen_composition;

void vigen_composition_clear(vigen_composition *co);
int vigen_composition_from_table(vigen_composition *co, vigen_tableau *info, vigen_sandbox *sb, const char *path,
                                 vigen_error *err);

#endif
