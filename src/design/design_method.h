/* design_method.h — the method file of a solution of a design: its text,
 * and the checker's verdict on it (design_method.c). */
#ifndef VIGEN_DESIGN_METHOD_H
#define VIGEN_DESIGN_METHOD_H

#include <arb.h>
#include "vigen/design.h"

/* The composition file of solution index (1-based) of count: base as the
 * file names it, the steps gamma[0 .. stages-1] as certified decimals, claims
 * order = d->order, order_separable and order_nystrom (when >= 0) and
 * symplectic = true, how in its comment.  Heap string. */
char *vigen_design_method_text(const vigen_design_spec *d, const char *base, const char *name, slong index,
                               slong count, char *const *gamma, const char *how, int order_sep, int order_nys);

/* Checks text as the composition file it is (shown_path in messages; order
 * the order claimed): sets sol->order, order_separable, error constants,
 * force, and sol->certified when the checker certifies every claim (else
 * sol->why).  An error only when the file cannot be loaded or checked. */
int vigen_design_method_check(vigen_design_solution *sol, const char *text, const char *shown_path, int order,
                              vigen_error *err);

/* The checker's principal error constant (family VIGEN_CHECK_EC_*) of the
 * composition file text, of order `order`: its midpoint into *ec, or -1
 * when the checker does not find that order (the objective of minimize). */
int vigen_design_method_error_constant(double *ec, const char *text, int order, int family, vigen_error *err);

#endif
