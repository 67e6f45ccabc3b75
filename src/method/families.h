/* families.h — the names of the node families (nodes.def) and basis families
 * (basis.def): what the spec vocabulary offers as gauss_legendre(3), trig(5),
 * ... and what messages list.  The families themselves are computed by
 * nodes.c and basis.c. */
#ifndef VIGEN_FAMILIES_H
#define VIGEN_FAMILIES_H

#include "vigen/limits.h"

/* Largest s accepted by any family: the stage bound of every method. */
#define VIGEN_NODES_MAX_S VIGEN_MAX_STAGES

/* NULL-terminated lists of the family names, in table order. */
extern const char *const vigen_nodes_family_names[];
extern const char *const vigen_basis_family_names[];

/* 1 if name is a known node family / basis family. */
int vigen_nodes_is_family(const char *name);
int vigen_basis_is_family(const char *name);

#endif
