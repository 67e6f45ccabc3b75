/* problems.h — the Lagrangians of tests/unit/test_midpoint_vi.c, with their
 * gradients, inverse Legendre maps g and second derivatives written out by
 * hand (the derivations beside each one).  Included by that test only. */
#ifndef VIGEN_TEST_MIDPOINT_VI_PROBLEMS_H
#define VIGEN_TEST_MIDPOINT_VI_PROBLEMS_H

#include <math.h>
#include <vigen/lagrangian.h>

/* Anisotropic anharmonic potential in 2-D (Hénon–Heiles-like):
 * V = (q0^2 + 2 q1^2)/2 + 0.3 q0^2 q1 + 0.1 q0^4.  L = |v|^2/2 - V. */
static void aniso_gradV(const double *q, double *o)
{
    o[0] = q[0] + 0.6 * q[0] * q[1] + 0.4 * q[0] * q[0] * q[0];
    o[1] = 2.0 * q[1] + 0.3 * q[0] * q[0];
}
static void aniso_dLdq(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)v; (void)c;
    aniso_gradV(q, o);
    o[0] = -o[0];
    o[1] = -o[1];
}
static void unit_dLdv(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)q; (void)c;
    o[0] = v[0];
    o[1] = v[1];
}
static void unit_g(double t, const double *q, const double *p, double *o, void *c)
{
    (void)t; (void)q; (void)c;
    o[0] = p[0];
    o[1] = p[1];
}
static void aniso_d2q(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)v; (void)c;
    o[0] = -(1.0 + 0.6 * q[1] + 1.2 * q[0] * q[0]);
    o[1] = o[2] = -0.6 * q[0];
    o[3] = -2.0;
}
static void zero_2x2(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)q; (void)v; (void)c;
    o[0] = o[1] = o[2] = o[3] = 0.0;
}
static void unit_2x2(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)q; (void)v; (void)c;
    o[0] = o[3] = 1.0;
    o[1] = o[2] = 0.0;
}

/* Time-dependent: L = |v|^2/2 - V_aniso(q) + cos(1.3 t) q0 + sin(0.7 t) q1. */
static void forced2_dLdq(double t, const double *q, const double *v, double *o, void *c)
{
    aniso_dLdq(t, q, v, o, c);
    o[0] += cos(1.3 * t);
    o[1] += sin(0.7 * t);
}

/* 1-D forced oscillator L = v^2/2 - q^2/2 + F cos(2t) q, F = 0.6:
 * q'' = -q + F cos 2t, solved by q = cos t - (F/3) cos 2t
 * (q'' = -cos t + (4F/3) cos 2t = -q + F cos 2t). */
#define FORCE 0.6
static double forced_q(double t) { return cos(t) - FORCE / 3.0 * cos(2.0 * t); }
static double forced_p(double t) { return -sin(t) + 2.0 * FORCE / 3.0 * sin(2.0 * t); }
static void forced_dLdq(double t, const double *q, const double *v, double *o, void *c)
{
    (void)v; (void)c;
    o[0] = -q[0] + FORCE * cos(2.0 * t);
}
static void id1_dLdv(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)q; (void)c;
    o[0] = v[0];
}
static void id1_g(double t, const double *q, const double *p, double *o, void *c)
{
    (void)t; (void)q; (void)c;
    o[0] = p[0];
}

/* Relativistic particle, m = 1.3, c = 1, central potential
 * V = k |q|^2/2 + b |q|^4/4 (k = 1, b = 0.5) or, with aniso set, the
 * anisotropic V = (q0^2 + 2 q1^2)/2 (no rotation symmetry). */
typedef struct { double m, c; int aniso; } rel_ctx;
static void rel_gradV(const rel_ctx *r, const double *q, double *o)
{
    if (r->aniso) {
        o[0] = q[0];
        o[1] = 2.0 * q[1];
        return;
    }
    const double s = 1.0 + 0.5 * (q[0] * q[0] + q[1] * q[1]);
    o[0] = s * q[0];
    o[1] = s * q[1];
}
static double rel_V(const rel_ctx *r, const double *q)
{
    if (r->aniso) return 0.5 * (q[0] * q[0] + 2.0 * q[1] * q[1]);
    const double r2 = q[0] * q[0] + q[1] * q[1];
    return 0.5 * r2 + 0.125 * r2 * r2;
}
static void rel_dLdq(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)v;
    rel_gradV(c, q, o);
    o[0] = -o[0];
    o[1] = -o[1];
}
static double rel_gamma(const rel_ctx *r, const double *v)
{
    return 1.0 / sqrt(1.0 - (v[0] * v[0] + v[1] * v[1]) / (r->c * r->c));
}
static void rel_dLdv(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)q;
    const rel_ctx *r = c;
    const double mg = r->m * rel_gamma(r, v);
    o[0] = mg * v[0];
    o[1] = mg * v[1];
}
/* v = p c / sqrt(m^2 c^2 + |p|^2), the inverse of p = m gamma v. */
static void rel_g(double t, const double *q, const double *p, double *o, void *c)
{
    (void)t; (void)q;
    const rel_ctx *r = c;
    const double s = r->c / sqrt(r->m * r->m * r->c * r->c + p[0] * p[0] + p[1] * p[1]);
    o[0] = p[0] * s;
    o[1] = p[1] * s;
}
static void rel_d2q(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)v;
    const rel_ctx *r = c;
    if (r->aniso) {
        o[0] = -1.0; o[1] = o[2] = 0.0; o[3] = -2.0;
        return;
    }
    const double s = 1.0 + 0.5 * (q[0] * q[0] + q[1] * q[1]);
    o[0] = -(s + q[0] * q[0]);
    o[1] = o[2] = -q[0] * q[1];
    o[3] = -(s + q[1] * q[1]);
}
/* d2L/dv2 = m gamma I + m gamma^3 v v^T / c^2 */
static void rel_d2v(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)q;
    const rel_ctx *r = c;
    const double gm = rel_gamma(r, v), a = r->m * gm, b = r->m * gm * gm * gm / (r->c * r->c);
    o[0] = a + b * v[0] * v[0];
    o[1] = o[2] = b * v[0] * v[1];
    o[3] = a + b * v[1] * v[1];
}
static double rel_energy(const rel_ctx *r, const double *q, const double *p)
{
    return r->c * sqrt(r->m * r->m * r->c * r->c + p[0] * p[0] + p[1] * p[1]) + rel_V(r, q);
}


/* Charged particle in the plane, axially symmetric magnetic field:
 * L = |v|^2/2 + A(q).v - |q|^2/2 with A = a(r) (-y, x), a = a0 + b r^2
 * (field B = 2 a0 + 4 b r^2 along z): dL/dv = v + A depends on q, dL/dq on
 * v (non-separable), g(q, p) = p - A(q).  With l = x vy - y vx:
 *   dL/dq = (2b x l + a vy - x, 2b y l - a vx - y). */
#define MAG_A0 0.8
#define MAG_B 0.3
static double mag_a(const double *q) { return MAG_A0 + MAG_B * (q[0] * q[0] + q[1] * q[1]); }
static void mag_dLdq(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)c;
    const double a = mag_a(q), l = q[0] * v[1] - q[1] * v[0];
    o[0] = 2.0 * MAG_B * q[0] * l + a * v[1] - q[0];
    o[1] = 2.0 * MAG_B * q[1] * l - a * v[0] - q[1];
}
static void mag_dLdv(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)c;
    const double a = mag_a(q);
    o[0] = v[0] - a * q[1];
    o[1] = v[1] + a * q[0];
}
static void mag_g(double t, const double *q, const double *p, double *o, void *c)
{
    (void)t; (void)c;
    const double a = mag_a(q);
    o[0] = p[0] + a * q[1];
    o[1] = p[1] - a * q[0];
}
static void mag_d2q(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)c;
    const double b = MAG_B, x = q[0], y = q[1], l = x * v[1] - y * v[0];
    o[0] = 2.0 * b * l + 4.0 * b * x * v[1] - 1.0;
    o[1] = o[2] = 2.0 * b * (y * v[1] - x * v[0]);
    o[3] = 2.0 * b * l - 4.0 * b * y * v[0] - 1.0;
}
static void mag_d2qv(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)v; (void)c;
    const double b = MAG_B, x = q[0], y = q[1], a = mag_a(q);
    o[0] = -2.0 * b * x * y;
    o[1] = 2.0 * b * x * x + a;
    o[2] = -2.0 * b * y * y - a;
    o[3] = 2.0 * b * x * y;
}

#endif
