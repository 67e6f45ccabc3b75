/* problem_pendulum.c — the mathematical pendulum H = p^2/2 - cos q released
 * at rest from q = a (0 < a < pi).  With k = sin(a/2) and K = K(k) the
 * complete elliptic integral of the first kind, the exact solution is
 *   sin(q/2) = k sn(K - t | k^2),   p = -2 k cn(K - t | k^2),
 * with period 4K; evaluated with GSL's Jacobi elliptic functions. */
#include <math.h>
#include <stdlib.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_mode.h>
#include <gsl/gsl_sf_ellint.h>
#include <gsl/gsl_sf_elljac.h>
#include "problems_internal.h"

typedef struct {
    double k, K;    /* modulus sin(a/2), K(k) */
} pendulum;

static double energy(double t, const double *q, const double *p, void *ctx)
{
    (void)t; (void)ctx;
    return p[0] * p[0] / 2 - cos(q[0]);
}

static void dHdq(double t, const double *q, const double *p, double *out, void *ctx)
{
    (void)t; (void)p; (void)ctx;
    out[0] = sin(q[0]);
}

static void d2Ldq2(double t, const double *q, const double *v, double *out, void *ctx)
{
    (void)t; (void)v; (void)ctx;
    out[0] = -cos(q[0]);
}

static int reference(const vigen_problem *pb, double t, double *q, double *p)
{
    const pendulum *d = pb->data;
    /* u = K - t reduced to [-2K, 2K] (sn and cn have period 4K) */
    double u = remainder(d->K - (t - pb->t0), 4 * d->K);
    double sn, cn, dn;
    if (gsl_sf_elljac_e(u, d->k * d->k, &sn, &cn, &dn) != GSL_SUCCESS) return 0;
    double s = d->k * sn;
    q[0] = 2 * asin(s > 1 ? 1 : s < -1 ? -1 : s);
    p[0] = -2 * d->k * cn;
    return 1;
}

int vigen_pbi_pendulum_setup(vigen_problem *pb)
{
    double a = pb->param[0];
    pendulum *d = malloc(sizeof *d);
    if (d == NULL || vigen_pbi_set_dim(pb, 1) != VIGEN_SUCCESS) {
        free(d);
        return VIGEN_ENOMEM;
    }
    pb->data = d;
    d->k = sin(a / 2);
    /* k <= sin(1.55) < 1 by the parameter's range: inside the domain of
     * K(k) and of the Jacobi functions (m = k^2 < 1), where GSL reports no
     * error */
    gsl_sf_result K;
    if (gsl_sf_ellint_Kcomp_e(d->k, GSL_PREC_DOUBLE, &K) != GSL_SUCCESS) return VIGEN_EINVAL;
    d->K = K.val;
    vigen_pbi_unit_mass(pb, dHdq, energy, d2Ldq2);
    pb->q0[0] = a;
    pb->period = 4 * d->K;
    pb->default_time = 100 * pb->period;
    pb->reference = reference;
    return VIGEN_SUCCESS;
}
