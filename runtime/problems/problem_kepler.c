/* problem_kepler.c — the Kepler problem in the plane, H = |p|^2/2 - 1/|q|,
 * eccentricity e: the orbit of semi-major axis 1 and period 2 pi started at
 * the pericentre; invariants angular momentum and the Runge-Lenz vector;
 * reference from Kepler's equation E - e sin E = t solved by Newton's
 * method to round-off.  Its Kepler splitting: the Kepler part is the whole
 * H (the flow: the universal-variable drift about mu = 1), the interaction
 * is zero; the coordinates are the problem's own. */
#include <math.h>
#include "problems_internal.h"

static double energy(double t, const double *q, const double *p, void *ctx)
{
    (void)t; (void)ctx;
    return (p[0] * p[0] + p[1] * p[1]) / 2 - 1 / hypot(q[0], q[1]);
}

static void dHdq(double t, const double *q, const double *p, double *out, void *ctx)
{
    (void)t; (void)p; (void)ctx;
    double r = hypot(q[0], q[1]), r3 = r * r * r;
    out[0] = q[0] / r3;
    out[1] = q[1] / r3;
}

static void d2Ldq2(double t, const double *q, const double *v, double *out, void *ctx)
{
    (void)t; (void)v; (void)ctx;
    double r = hypot(q[0], q[1]), r3 = r * r * r, r5 = r3 * r * r;
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++) out[2 * i + j] = 3 * q[i] * q[j] / r5 - (i == j) / r3;
}

static const char *const names[] = { "angular-momentum", "runge-lenz-x", "runge-lenz-y" };

/* L = q1 p2 - q2 p1; A = p x L e3 - q/|q| = (p2 L - q1/r, -p1 L - q2/r). */
static double invariant(const vigen_problem *pb, size_t k, double t, const double *q, const double *p)
{
    (void)pb; (void)t;
    double L = q[0] * p[1] - q[1] * p[0], r = hypot(q[0], q[1]);
    if (k == 0) return L;
    return k == 1 ? p[1] * L - q[0] / r : -p[0] * L - q[1] / r;
}

/* Eccentric anomaly E of mean anomaly M in [-pi, pi]: Newton's method from
 * E = M + e sin M, safeguarded by bisection of the bracket [lo, hi] (f(E) =
 * E - e sin E - M is increasing, f(-pi) <= 0 <= f(pi)), until the step is at
 * round-off. */
static double eccentric_anomaly(double M, double e)
{
    double lo = -PBI_PI, hi = PBI_PI, E = M + e * sin(M);
    for (int it = 0; it < 100; it++) {
        double f = E - e * sin(E) - M;
        if (f > 0) hi = E; else lo = E;
        double dE = f / (1 - e * cos(E));
        double next = E - dE;
        if (!(next > lo && next < hi)) next = (lo + hi) / 2;
        if (fabs(next - E) <= 2e-16 * (1 + fabs(E))) return next;
        E = next;
    }
    return E;
}

static int reference(const vigen_problem *pb, double t, double *q, double *p)
{
    double e = pb->param[0], s = sqrt(1 - e * e);
    /* mean anomaly t reduced to [-pi, pi]; remainder() is exact */
    double M = remainder(t - pb->t0, 2 * PBI_PI);
    double E = eccentric_anomaly(M, e), c = cos(E), sn = sin(E), d = 1 - e * c;
    q[0] = c - e;
    q[1] = s * sn;
    p[0] = -sn / d;
    p[1] = s * c / d;
    return 1;
}

/* The whole flow: the drift in the plane (z = 0, unchanged by the drift). */
static int kepler_flow(double t, double h, double *q, double *p, void *ctx)
{
    (void)t; (void)ctx;
    double x[3] = { q[0], q[1], 0 }, v[3] = { p[0], p[1], 0 };
    int st = vigen_kepler_drift(1, h, x, v);
    if (st != VIGEN_SUCCESS) return st;
    q[0] = x[0]; q[1] = x[1];
    p[0] = v[0]; p[1] = v[1];
    return VIGEN_SUCCESS;
}

static int zero_flow(double t, double h, double *q, double *p, void *ctx)
{
    (void)t; (void)q; (void)p; (void)ctx;
    return isfinite(h) ? VIGEN_SUCCESS : VIGEN_EINVAL;
}

static int vector_field(double t, const double *q, const double *p, double *dq, double *dp, void *ctx)
{
    double g[2];
    dHdq(t, q, p, g, ctx);
    dq[0] = p[0]; dq[1] = p[1];
    dp[0] = -g[0]; dp[1] = -g[1];
    return isfinite(dp[0]) && isfinite(dp[1]) ? VIGEN_SUCCESS : VIGEN_ENONFINITE;
}

/* kepler, interaction (zero) and interaction_gradient (of a zero
 * interaction: the identity) */
static const vigen_flow_fn flows[] = { kepler_flow, zero_flow, zero_flow };

static int split(vigen_problem *pb, int coords, vigen_split_problem *out)
{
    if (coords != VIGEN_NBODY_JACOBI) return VIGEN_EINVAL;
    *out = (vigen_split_problem){ .dim = 2, .nflows = 3, .flow = flows, .ctx = pb, .vector_field = vector_field,
                                  .H = energy };
    return VIGEN_SUCCESS;
}

static int same_state(const vigen_problem *pb, int to_split, const double *q, const double *p, double *qs,
                      double *ps)
{
    (void)pb; (void)to_split;
    for (int k = 0; k < 2; k++) {
        qs[k] = q[k];
        ps[k] = p[k];
    }
    return VIGEN_SUCCESS;
}

int vigen_pbi_kepler_setup(vigen_problem *pb)
{
    double e = pb->param[0];
    if (vigen_pbi_set_dim(pb, 2) != VIGEN_SUCCESS) return VIGEN_ENOMEM;
    vigen_pbi_unit_mass(pb, dHdq, energy, d2Ldq2);
    pb->q0[0] = 1 - e;
    pb->p0[1] = sqrt((1 + e) / (1 - e));
    pb->period = 2 * PBI_PI;
    pb->default_time = 100 * pb->period;
    pb->ninvariants = 3;
    pb->invariant_names = names;
    pb->invariant = invariant;
    pb->reference = reference;
    pb->split = split;
    pb->split_convert = same_state;
    return VIGEN_SUCCESS;
}
