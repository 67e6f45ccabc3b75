/* nodes.h — certified quadrature-node families on [0, 1].
 *
 * The families, their smallest s and what their nodes are: the rows of
 * nodes.def (names for messages in families.h).
 * Every family returns s nodes in increasing order as arb balls, each certified
 * to contain the exact node, mapped from [-1, 1] by x -> (1 + x)/2 where the
 * family is classically defined on [-1, 1].  Nodes that are exactly 0, 1/2 or 1
 * mathematically are returned as exact balls (radius 0).
 */
#ifndef VIGEN_NODES_H
#define VIGEN_NODES_H

#include <arb.h>
#include "vigen/error.h"
#include "method/families.h"

/* Writes s nodes into nodes (an arb vector of length s, already initialised).
 * Errors: VIGEN_E_SPEC for an unknown family name (the message lists the known
 * ones) or an s outside the family's range; VIGEN_E_MATH when the family has no
 * s real nodes (chebyshev_quadrature(8)); VIGEN_E_PRECISION if roots cannot be
 * isolated at this precision (the caller retries higher). */
int vigen_nodes_family(arb_ptr nodes, const char *family, slong s, slong prec, vigen_error *err);

#endif
