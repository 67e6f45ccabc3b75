/* lagrangian.c — the Lagrangian integrators `vigen try` knows by name
 * (vigen/lagrangian.h, docs/lagrangian.md).  They have no tableau: the
 * driver makes the runtime's integrator on the problem's Lagrangian with
 * vigen_lagrangian_integrator_alloc (the slot KIND of
 * templates/try/driver.c.in is its number) and drives it through its
 * stepper type, as it drives an emitted stepper.  Their order is the one
 * the literature proves (2 for each), not one the checker certifies.  The
 * table alone, below the files that use it: locate.c offers its names,
 * problem_check.c checks the problem against its methods. */
#include <string.h>
#include "vigen/lagrangian.h"
#include "try/try_internal.h"

static const try_lagrangian_method methods[] = {
    { "hp-trapezoidal", VIGEN_LAGRANGIAN_HP_TRAPEZOIDAL, 2,
      "Hamilton-Pontryagin integrator, trapezoidal discrete Lagrangian (Stormer-Verlet for L = T - V)" },
    { "hp-midpoint", VIGEN_LAGRANGIAN_HP_MIDPOINT, 2, "Hamilton-Pontryagin integrator, midpoint discrete Lagrangian (implicit midpoint for L = T - V)" },
    { "midpoint-vi", VIGEN_LAGRANGIAN_MIDPOINT_VI, 2, "mid-point variational integrator of Cresson-Safi, with the inverse Legendre map" },
    { "trapezoidal-vi", VIGEN_LAGRANGIAN_TRAPEZOIDAL_VI, 2, "trapezoidal variational integrator, one-step form (the leapfrog for L = T - V)" },
};

const char *try_lagrangian_name(size_t k)
{
    return k < sizeof methods / sizeof methods[0] ? methods[k].name : NULL;
}

const try_lagrangian_method *try_lagrangian_find(const char *name)
{
    for (size_t k = 0; name && k < sizeof methods / sizeof methods[0]; k++)
        if (strcmp(methods[k].name, name) == 0) return &methods[k];
    return NULL;
}

void try_lagrangian_print(FILE *out)
{
    for (size_t k = 0; k < sizeof methods / sizeof methods[0]; k++)
        fprintf(out, "%-16s %s\n", methods[k].name, methods[k].description);
}
