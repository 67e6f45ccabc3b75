/* vmap_internal.h — evaluating a velocity map phi_h(q0, q1; a) and the transposed
 * products of its derivatives that the Hamilton–Pontryagin equations need
 * (internal to the runtime).  A NULL map is the trivial one,
 * phi = (q1 - q0)/h, whose derivatives -I/h and I/h are applied exactly. */
#ifndef VIGEN_VMAP_H
#define VIGEN_VMAP_H

#include <stddef.h>
#include <vigen/lagrangian.h>

/* v = phi_h(q0, q1; a); dq = q1 - q0 as the caller computed it (the trivial
 * map uses dq / h, which keeps the bits q1 = q0 + dq may lose). */
void vigen_vmap_value(const vigen_velocity_map *phi, size_t n, double h, const double *q0,
                      const double *q1, const double *dq, const double *a, double *v);

enum { VIGEN_VMAP_D1 = 1, VIGEN_VMAP_D2 = 2, VIGEN_VMAP_DA = 3, VIGEN_VMAP_D1_PLUS_D2 = 4 };

/* out = scale * D^T y for D = D1 phi, D2 phi (out: n entries), Da phi (out:
 * nparams entries) or D1 phi + D2 phi (n entries).  D is scratch of
 * n * max(n, nparams) doubles.  For the trivial map D1 + D2 = 0. */
void vigen_vmap_apply_transpose(const vigen_velocity_map *phi, int which, size_t n, double h,
                                const double *q0, const double *q1, const double *a,
                                const double *y, double scale, double *D, double *out);

#endif
