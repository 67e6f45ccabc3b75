/* galerkin.h — Theorem 3 of Leok & Zhang: the symplectic PRK tableau of a
 * Galerkin Hamiltonian variational integrator (docs/math.md, "Theorem 3 of Leok & Zhang").
 *
 *   M_ij = psi_i(c_j), B_i = int_0^1 psi_i, Apsi_ij = int_0^c_i psi_j,
 *   b = M^-1 B, A = Apsi M^-T, at_ij = (b_i b_j - b_j a_ji)/b_i, ct_i = sum_j at_ij.
 *
 * Everything is computed in arb balls.  Structural facts are used exactly:
 * a node that is exactly 0 gives a zero row of A, a node exactly 1 gives the
 * row a_i. = b (int_0^1 phi_j = b_j), hence exact zeros in At.
 */
#ifndef VIGEN_GALERKIN_H
#define VIGEN_GALERKIN_H

#include "vigen/error.h"
#include "method/spec.h"
#include "vigen/tableau.h"

/* One computation at precision prec; out must be uninitialised (it is
 * initialised here, also on failure, so the caller always clears it).
 * VIGEN_E_PRECISION means "retry at a higher precision". */
int vigen_galerkin_compute(vigen_tableau *out, vigen_spec *spec, slong prec, vigen_error *err);

/* The generator: raises the precision until every entry is certified to
 * `digits` significant digits (or, for entries that are zero, to absolute
 * accuracy 10^-digits/2), fills the entry texts and the metadata, and warns
 * (vigen_warn) when sum b != 1 or a node lies outside [0, 1].  out must be
 * uninitialised; on success the caller clears it. */
int vigen_galerkin_generate(vigen_tableau *out, vigen_spec *spec, slong digits, vigen_error *err);

/* The first working precision tried for `digits` digits, and the cap. */
slong vigen_galerkin_initial_prec(slong digits, slong s);
slong vigen_galerkin_max_prec(slong digits, slong s);

#endif
