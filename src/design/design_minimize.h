/* design_minimize.h — the member of a family with free parameters whose
 * error constant is smallest among those found (design_minimize.c). */
#ifndef VIGEN_DESIGN_MINIMIZE_H
#define VIGEN_DESIGN_MINIMIZE_H

#include "design/design_internal.h"

/* The conditions rows[0..m-1] of sys (m < k) with the free unknowns pinned:
 * rows[m..k-1] become the pins' rows (rows has room for k), set at the best
 * point found on return.  From d->starts random starts in [-box, box]^k,
 * every real branch (at most 4 per start) descended by Nelder-Mead on the
 * checker's error constant named by d->minimize; with d->screen > 0 the
 * descents start instead from the best minima of the principal error's
 * Lyndon norm found from d->screen random points (q: the order of the
 * composition's base, for those conditions).  xbest (k values) and
 * *ecbest: the best point and its error constant; *nminima: the distinct
 * local minima found; *evals: checker runs.  Returns 1 when some start gave
 * a point whose order the checker confirmed. */
int design_minimize(double *xbest, double *ecbest, slong *nminima, long *evals, design_system *sys, slong *rows,
                    slong m, const vigen_design_spec *d, const char *base, int q, double box);

#endif
