/* families.c — the names of the node families (nodes.def) and basis
 * families (basis.def) of families.h, which the spec reader checks a spec
 * against before any node or basis is computed (nodes.c and basis.c compute
 * them). */
#include <string.h>
#include "method/families.h"

const char *const vigen_nodes_family_names[] = {
#define X(name, min_s, fn, description) #name,
#include "method/nodes.def"
#undef X
    NULL };

const char *const vigen_basis_family_names[] = {
#define X(name, fn, description) #name,
#include "method/basis.def"
#undef X
    NULL };

/* 1 when name is in the NULL-terminated list names. */
static int listed(const char *const *names, const char *name)
{
    for (size_t k = 0; name != NULL && names[k] != NULL; k++)
        if (strcmp(names[k], name) == 0) return 1;
    return 0;
}

int vigen_nodes_is_family(const char *name) { return listed(vigen_nodes_family_names, name); }

int vigen_basis_is_family(const char *name) { return listed(vigen_basis_family_names, name); }
