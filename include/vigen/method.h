/* method.h — where tableaux come from: a spec file run through the
 * generator, or a tableau file read as it is.  Used by generate, show, check
 * and emit, which all accept either kind of file. */
#ifndef VIGEN_METHOD_H
#define VIGEN_METHOD_H

#include "vigen/error.h"
#include "vigen/tableau.h"

/* 1 if the file returns a table with an A field (a tableau), 0 if it looks
 * like a spec (nodes and basis), negative with err set when it cannot be run. */
int vigen_source_is_tableau(const char *path, vigen_error *err);

/* Loads path into t (uninitialised on entry; initialised on success).  A spec
 * is generated with `digits` certified digits; a tableau file is loaded and
 * evaluated at a precision adequate for `digits` digits. */
int vigen_source_load(vigen_tableau *t, const char *path, slong digits, vigen_error *err);

/* The generator: the tableau of the Galerkin variational integrator of the
 * spec file at path, every entry certified to `digits` significant digits
 * (out uninitialised on entry; initialised on success). */
int vigen_generate_file(vigen_tableau *out, const char *path, slong digits, vigen_error *err);

#endif
