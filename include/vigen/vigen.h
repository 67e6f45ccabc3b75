/* vigen.h — libvigen in one include: certified symplectic partitioned
 * Runge–Kutta methods, from a method file to a checked tableau to C source.
 *
 *   vigen_method_load / vigen_method_tableau   (method.h)  a spec or tableau file -> tableau
 *   vigen_check_tableau                        (check.h)   certified order, symplecticity, claims
 *   vigen_show_render                          (show.h)    text, LaTeX, JSON, Lua
 *   vigen_emit_render                          (emit.h)    the C stepper's header and source
 *   vigen_try_run, vigen_try_order             (try.h)     run steppers on standard problems
 *
 * Every function returns a status code (error.h, status.def) and fills a
 * vigen_error with a message naming the file and the entry. */
#ifndef VIGEN_VIGEN_H
#define VIGEN_VIGEN_H

#include "vigen/error.h"
#include "vigen/limits.h"
#include "vigen/tableau.h"
#include "vigen/method.h"
#include "vigen/trees.h"
#include "vigen/check.h"
#include "vigen/show.h"
#include "vigen/compare.h"
#include "vigen/emit.h"
#include "vigen/try.h"
#include "vigen/library.h"
#include "vigen/design.h"

/* The version of the library ("0.1.0"). */
const char *vigen_version(void);

#endif
