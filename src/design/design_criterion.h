/* design_criterion.h — the fields of a design file that state an optimality
 * criterion solved as equations (design_criterion.c): stationary =
 * "error_norm", nearest = { decimals }, and first = "kick" (a splitting
 * whose first drift is 0). */
#ifndef VIGEN_DESIGN_CRITERION_H
#define VIGEN_DESIGN_CRITERION_H

#include <lua.h>
#include "vigen/design.h"

/* Reads those fields of the design table on top of L's stack into d,
 * validated; a mistake is VIGEN_E_SPEC naming path and the field. */
int design_file_read_criterion(vigen_design_spec *d, lua_State *L, int splitting, const char *path, vigen_error *err);

#endif
