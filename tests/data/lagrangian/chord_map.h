/* chord_map.h — a velocity map with a genuine parameter, for the tests and
 * docs/lagrangian.md (header-only; include it once).
 *
 *   phi_h(q0, q1; a) = (1 + h^2 a^2 / 2) (q1 - q0)/h - h^2 a c
 *
 * with one parameter a and a fixed vector c (the map's context).  Its
 * derivatives:
 *   D1phi = -(1 + h^2 a^2/2)/h I,   D2phi = (1 + h^2 a^2/2)/h I,
 *   Daphi = h (a (q1 - q0) - h c)                       (a column).
 * The parameter equation Daphi^T p_{n+1/2} = 0 reads
 *   a (q1 - q0).p_{n+1/2} = h c.p_{n+1/2},
 * which has the unique solution a = h c.p / ((q1 - q0).p) while the particle
 * moves ((q1 - q0).p_{n+1/2} is about 2 h T > 0 for a kinetic energy T), and
 * its derivative in a, h (q1 - q0).p, is not zero there: a is determined by
 * the momentum at every step, varies along the trajectory, and changes the
 * velocity by O(h^2) (so the scheme keeps order 2). */
#ifndef CHORD_MAP_H
#define CHORD_MAP_H

#include <stddef.h>
#include <vigen/lagrangian.h>

#define CHORD_DIM 2

/* c in ctx (CHORD_DIM doubles) */
static void chord_phi(double h, const double *q0, const double *q1, const double *a, double *out, void *ctx)
{
    const double *c = ctx, s = 1.0 + 0.5 * h * h * a[0] * a[0];
    for (size_t i = 0; i < CHORD_DIM; i++) out[i] = s * (q1[i] - q0[i]) / h - h * h * a[0] * c[i];
}
static void chord_D(double h, const double *a, double sign, double *out)
{
    const double s = sign * (1.0 + 0.5 * h * h * a[0] * a[0]) / h;
    for (size_t i = 0; i < CHORD_DIM; i++)
        for (size_t j = 0; j < CHORD_DIM; j++) out[i * CHORD_DIM + j] = i == j ? s : 0.0;
}
static void chord_D1(double h, const double *q0, const double *q1, const double *a, double *out, void *ctx)
{
    (void)q0; (void)q1; (void)ctx;
    chord_D(h, a, -1.0, out);
}
static void chord_D2(double h, const double *q0, const double *q1, const double *a, double *out, void *ctx)
{
    (void)q0; (void)q1; (void)ctx;
    chord_D(h, a, 1.0, out);
}
static void chord_Da(double h, const double *q0, const double *q1, const double *a, double *out, void *ctx)
{
    const double *c = ctx;
    for (size_t i = 0; i < CHORD_DIM; i++) out[i] = h * (a[0] * (q1[i] - q0[i]) - h * c[i]);
}

#endif
