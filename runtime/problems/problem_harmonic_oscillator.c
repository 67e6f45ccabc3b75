/* problem_harmonic_oscillator.c — H = p^2/2 + omega^2 q^2/2 from q = 1,
 * p = 0; the exact solution q = cos(omega t), p = -omega sin(omega t). */
#include <math.h>
#include "problems_internal.h"

static double omega_of(void *ctx) { return ((const vigen_problem *)ctx)->param[0]; }

static double energy(double t, const double *q, const double *p, void *ctx)
{
    (void)t;
    double w = omega_of(ctx);
    return (p[0] * p[0] + w * w * q[0] * q[0]) / 2;
}

static void dHdq(double t, const double *q, const double *p, double *out, void *ctx)
{
    (void)t; (void)p;
    double w = omega_of(ctx);
    out[0] = w * w * q[0];
}

static void d2Ldq2(double t, const double *q, const double *v, double *out, void *ctx)
{
    (void)t; (void)q; (void)v;
    double w = omega_of(ctx);
    out[0] = -w * w;
}

static int reference(const vigen_problem *pb, double t, double *q, double *p)
{
    double w = pb->param[0];
    /* the phase reduced exactly to [-pi, pi] keeps long times accurate */
    double phase = remainder(w * (t - pb->t0), 2 * PBI_PI);
    q[0] = cos(phase);
    p[0] = -w * sin(phase);
    return 1;
}

int vigen_pbi_harmonic_oscillator_setup(vigen_problem *pb)
{
    if (vigen_pbi_set_dim(pb, 1) != VIGEN_SUCCESS) return VIGEN_ENOMEM;
    vigen_pbi_unit_mass(pb, dHdq, energy, d2Ldq2);
    pb->q0[0] = 1;
    pb->period = 2 * PBI_PI / pb->param[0];
    pb->default_time = 100 * pb->period;
    pb->reference = reference;
    return VIGEN_SUCCESS;
}
