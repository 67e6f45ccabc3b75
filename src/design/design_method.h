/* design_method.h — the method file of a solution of a design: its text,
 * and the checker's verdict on it (design_method.c). */
#ifndef VIGEN_DESIGN_METHOD_H
#define VIGEN_DESIGN_METHOD_H

#include <arb.h>
#include "vigen/design.h"

/* The method file of solution index (1-based) of count: a composition of
 * base (as the file names it; NULL: a splitting, d->base NULL) with the
 * steps values[0 .. n-1] as certified decimals (the stages of a composition,
 * the substeps drift, kick, ..., drift of a splitting), the claims order,
 * order_separable, order_nystrom of claims[0..2] (each when >= 0) and
 * symplectic = true, how in its comment; a splitting of named flows
 * (d->flow_b) names them and claims generalized_order = gen[0..ngen-1].
 * Heap string. */
char *vigen_design_method_text(const vigen_design_spec *d, const char *base, const char *name, slong index,
                               slong count, char *const *values, const char *how, const int claims[3],
                               const int *gen, int ngen);

/* Checks text as the method file it is (shown_path in messages; order
 * the order claimed): sets sol->order, order_separable, error constants,
 * force, and sol->certified when the checker certifies every claim (else
 * sol->why).  An error only when the file cannot be loaded or checked. */
int vigen_design_method_check(vigen_design_solution *sol, const char *text, const char *shown_path, int order,
                              vigen_error *err);

/* The checker's principal error constant (family VIGEN_CHECK_EC_*) of the
 * composition file text, of order `order`: its midpoint into *ec, or -1
 * when the checker does not find that order (the objective of minimize);
 * the force evaluations of its step into *force. */
int vigen_design_method_error_constant(double *ec, long *force, const char *text, int order, int family,
                                       vigen_error *err);

#endif
