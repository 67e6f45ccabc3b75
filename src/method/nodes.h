/* nodes.h — certified quadrature-node families on [0, 1].
 *
 * The families are the rows of nodes.def; their names are in families.h.
 * Every family returns s nodes in increasing order as arb balls, each certified
 * to contain the exact node, mapped from [-1, 1] by x -> (1 + x)/2 where the
 * family is classically defined on [-1, 1].  Nodes that are exactly 0, 1/2 or 1
 * mathematically are returned as exact balls (radius 0).
 *
 *   gauss_legendre(s)        roots of P_s                        s >= 1
 *   gauss_lobatto(s)         -1, 1 and roots of P'_{s-1}          s >= 2
 *   radau_left(s)            roots of P_s + P_{s-1} (contains -1) s >= 1
 *   radau_right(s)           roots of P_s - P_{s-1} (contains +1) s >= 1
 *   chebyshev_quadrature(s)  roots of Chebyshev's G_s (equal-weight quadrature);
 *                            s = 8 and s >= 10 have complex roots: refused
 *   chebyshev_gauss(s)       roots of T_s: cos((2k-1) pi / (2s))  s >= 1
 *   chebyshev_lobatto(s)     cos(k pi / (s-1)), k = 0..s-1        s >= 2
 *   equispaced(s)            k/(s-1), k = 0..s-1                  s >= 2
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
