/* initial_value.c — the storage of a problem's initial value, which each
 * setup (problem_<id>.c) allocates once it knows the dimension.  A file of
 * its own below the registry (problems.c, which frees the storage with the
 * problem) and the problem files, so that the registry calls the setups and
 * no setup calls the registry. */
#include <stdlib.h>
#include "problems_internal.h"

int vigen_pbi_set_dim(vigen_problem *pb, size_t dim)
{
    pb->dim = dim;
    pb->q0 = calloc(dim, sizeof *pb->q0);
    pb->p0 = calloc(dim, sizeof *pb->p0);
    return pb->q0 && pb->p0 ? VIGEN_SUCCESS : VIGEN_ENOMEM;
}
