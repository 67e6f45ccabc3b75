/* basis.h — the basis functions psi_1..psi_s of a spec, resolved at a working
 * precision: their values psi_i(x) and their integrals int_0^x psi_i.
 *
 * How each kind is integrated (always rigorously):
 *   lagrange, the polynomial families of basis.def, and expression strings
 *             that are polynomials in t: exact antiderivative of an arb_poly;
 *   trig      closed forms: int_0^x cos(k pi t) dt = sin(k pi x)/(k pi), ...;
 *   expressions built from polynomials and sin/cos/exp of linear arguments
 *             (sums, constant factors): their exact antiderivatives;
 *   other expressions and Lua functions: acb_calc_integrate (certified
 *             Gauss–Legendre with error bounds from complex-ball evaluation).
 */
#ifndef VIGEN_BASIS_H
#define VIGEN_BASIS_H

#include <arb.h>
#include "vigen/error.h"
#include "method/spec.h"

typedef struct vigen_basis vigen_basis;

/* Resolves the basis of spec at precision prec.  nodes (length spec->s) are
 * needed for the Lagrange basis.  Errors: VIGEN_E_SPEC (unknown family). */
int vigen_basis_new(vigen_basis **out, vigen_spec *spec, arb_srcptr nodes, slong prec, vigen_error *err);
void vigen_basis_free(vigen_basis *basis);

slong vigen_basis_count(const vigen_basis *basis);
/* 1 when psi_i(c_j) = delta_ij by construction (the Lagrange basis), so M = I. */
int vigen_basis_is_interpolating(const vigen_basis *basis);

/* res = psi_i(x) (i 0-based).  VIGEN_E_DOMAIN when psi_i is undefined, complex
 * or infinite at x; VIGEN_E_PRECISION when realness cannot be decided yet. */
int vigen_basis_value(arb_t res, vigen_basis *basis, slong i, const arb_t x, slong prec, vigen_error *err);

/* res = int_0^x psi_i(t) dt.  VIGEN_E_INTEGRAL when the rigorous integration
 * does not reach the target accuracy (worth one retry at a higher precision;
 * failing again means a singularity or branch cut on or near the interval),
 * VIGEN_E_DOMAIN when the integrand is complex there. */
int vigen_basis_integral(arb_t res, vigen_basis *basis, slong i, const arb_t x, slong prec, vigen_error *err);

/* Human-readable name of psi_i for messages: "cos(pi*t)", "t^2", "l_3 (Lagrange)". */
const char *vigen_basis_label(const vigen_basis *basis, slong i);

#endif
