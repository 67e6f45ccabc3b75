/* vmap.c — velocity maps: the built-in trivial map (q1 - q0)/h with its
 * exact derivatives, the transposed products D^T p of a user's map that
 * the Hamilton–Pontryagin equations are written with. */
#include <math.h>
#include <stdlib.h>
#include "vmap_internal.h"

void vigen_vmap_value(const vigen_velocity_map *phi, size_t n, double h, const double *q0,
                      const double *q1, const double *dq, const double *a, double *v)
{
    if (phi == NULL) {
        for (size_t i = 0; i < n; i++) v[i] = dq[i] / h;
        return;
    }
    phi->phi(h, q0, q1, a, v, phi->ctx);
}

void vigen_vmap_apply_transpose(const vigen_velocity_map *phi, int which, size_t n, double h,
                                const double *q0, const double *q1, const double *a,
                                const double *y, double scale, double *D, double *out)
{
    if (phi == NULL) {
        /* D1 = -I/h, D2 = I/h, no parameters, D1 + D2 = 0 */
        for (size_t i = 0; i < n; i++)
            out[i] = which == VIGEN_VMAP_D1 ? -scale * y[i] / h : which == VIGEN_VMAP_D2 ? scale * y[i] / h : 0.0;
        return;
    }
    size_t cols = which == VIGEN_VMAP_DA ? phi->nparams : n;
    vigen_vmap_fn f = which == VIGEN_VMAP_DA ? phi->Daphi : which == VIGEN_VMAP_D2 ? phi->D2phi : phi->D1phi;
    f(h, q0, q1, a, D, phi->ctx);
    for (size_t j = 0; j < cols; j++) {
        double s = 0.0;
        for (size_t i = 0; i < n; i++) s += D[i * cols + j] * y[i];
        out[j] = scale * s;
    }
    if (which == VIGEN_VMAP_D1_PLUS_D2) {
        phi->D2phi(h, q0, q1, a, D, phi->ctx);
        for (size_t j = 0; j < n; j++) {
            double s = 0.0;
            for (size_t i = 0; i < n; i++) s += D[i * n + j] * y[i];
            out[j] += scale * s;
        }
    }
}
