/* flows.c — the flows of the N-body splittings in the form of
 * vigen_flow_fn (ctx = the vigen_nbody), the vector field and energy of the
 * whole H in each coordinate system, and the split problems they make
 * (vigen/nbody.h states the Hamiltonians).  Every flow writes its result
 * into the system's scratch memory first and copies it into (q, p) only
 * when every body succeeded and every value is finite, so that a failure
 * leaves the state unchanged.  The scratch is on the stack for systems of
 * up to STACK_BODIES bodies (the flows are then safe to call from several
 * threads on one system), the system's own memory above. */
#include <math.h>
#include <string.h>
#include "nbody_internal.h"

enum { STACK_BODIES = 32 };

/* The scratch of 9 n doubles: local (9 STACK_BODIES doubles) or the
 * system's. */
static double *scratch(vigen_nbody *sys, double *local)
{
    return sys->n <= STACK_BODIES ? local : sys->work;
}

static int all_finite(const double *a, size_t k)
{
    for (size_t i = 0; i < k; i++)
        if (!isfinite(a[i])) return 0;
    return 1;
}

/* The Kepler drift of bodies 1..n-1 with mu_i and velocity p_i / mass_i,
 * and the free drift q_0 += h p_0 / M of the centre of mass. */
static int kepler_all(vigen_nbody *sys, double h, double *q, double *p, const double *mu, double mu_all,
                      const double *mass)
{
    if (!isfinite(h)) return VIGEN_EINVAL;
    size_t n = sys->n, d = 3 * n;
    double local[9 * STACK_BODIES], *work = scratch(sys, local);
    double *qn = work, *pn = work + d;
    for (int c = 0; c < 3; c++) {
        qn[c] = q[c] + h * p[c] / sys->mtot;
        pn[c] = p[c];
    }
    for (size_t i = 1; i < n; i++) {
        double mi = mass ? mass[i] : sys->mred[i], v[3];
        for (int c = 0; c < 3; c++) {
            qn[3 * i + c] = q[3 * i + c];
            v[c] = p[3 * i + c] / mi;
        }
        int st = vigen_kepler_drift(mu ? mu[i] : mu_all, h, qn + 3 * i, v);
        if (st != VIGEN_SUCCESS) return st;
        for (int c = 0; c < 3; c++) pn[3 * i + c] = mi * v[c];
    }
    if (!all_finite(qn, 3)) return VIGEN_ENONFINITE;
    memcpy(q, qn, d * sizeof *q);
    memcpy(p, pn, d * sizeof *p);
    return VIGEN_SUCCESS;
}

int vigen_nbody_jacobi_kepler(double t, double h, double *q, double *p, void *ctx)
{
    (void)t;
    vigen_nbody *sys = ctx;
    if (sys == NULL || q == NULL || p == NULL) return VIGEN_EINVAL;
    return kepler_all(sys, h, q, p, sys->mu, 0, NULL);
}

int vigen_nbody_democratic_kepler(double t, double h, double *q, double *p, void *ctx)
{
    (void)t;
    vigen_nbody *sys = ctx;
    if (sys == NULL || q == NULL || p == NULL) return VIGEN_EINVAL;
    return kepler_all(sys, h, q, p, NULL, sys->G * sys->m[0], sys->m);
}

/* Adds h times the force to p (bodies 1..n-1) when every value is finite. */
static int kick(vigen_nbody *sys, double h, double *p, const double *force, double *work)
{
    size_t n = sys->n;
    double *pn = work + 6 * n, z = 0;
    for (int c = 0; c < 3; c++) pn[c] = p[c];
    for (size_t k = 0; k < 3 * n; k++) {
        if (k >= 3) pn[k] = p[k] + h * force[k];
        /* z stays 0 while every value is finite, NaN after any other */
        z += 0 * pn[k];
    }
    if (z != 0) return VIGEN_ENONFINITE;
    memcpy(p, pn, 3 * n * sizeof *p);
    return VIGEN_SUCCESS;
}

int vigen_nbody_jacobi_interaction(double t, double h, double *q, double *p, void *ctx)
{
    (void)t;
    vigen_nbody *sys = ctx;
    if (sys == NULL || q == NULL || p == NULL || !isfinite(h)) return VIGEN_EINVAL;
    double local[9 * STACK_BODIES], *work = scratch(sys, local);
    double *f = work + 3 * sys->n;
    vigen_nbody_jacobi_interaction_force(sys, q, work, f, NULL);
    return kick(sys, h, p, f, work);
}

int vigen_nbody_democratic_interaction(double t, double h, double *q, double *p, void *ctx)
{
    (void)t;
    vigen_nbody *sys = ctx;
    if (sys == NULL || q == NULL || p == NULL || !isfinite(h)) return VIGEN_EINVAL;
    double local[9 * STACK_BODIES], *work = scratch(sys, local);
    double *f = work + 3 * sys->n;
    vigen_nbody_pair_forces(sys, q, f, 1, 0);
    return kick(sys, h, p, f, work);
}

int vigen_nbody_democratic_jump(double t, double h, double *q, double *p, void *ctx)
{
    (void)t;
    vigen_nbody *sys = ctx;
    if (sys == NULL || q == NULL || p == NULL || !isfinite(h)) return VIGEN_EINVAL;
    size_t n = sys->n;
    double local[9 * STACK_BODIES], S[3] = { 0, 0, 0 }, *qn = scratch(sys, local);
    for (size_t i = 1; i < n; i++)
        for (int c = 0; c < 3; c++) S[c] += p[3 * i + c];
    for (int c = 0; c < 3; c++) {
        qn[c] = q[c];
        S[c] *= h / sys->m[0];
    }
    for (size_t i = 1; i < n; i++)
        for (int c = 0; c < 3; c++) qn[3 * i + c] = q[3 * i + c] + S[c];
    if (!all_finite(qn, 3 * n)) return VIGEN_ENONFINITE;
    memcpy(q, qn, 3 * n * sizeof *q);
    return VIGEN_SUCCESS;
}

/* The vector field of the whole H in coordinates q' = A x, p' = A^-T p:
 * dq'/dt = A v, dp'/dt = A^-T f, from the inertial velocities and forces. */
static int vector_field(vigen_nbody *sys, int coords, const double *q, const double *p, double *dq, double *dp)
{
    if (sys == NULL || q == NULL || p == NULL || dq == NULL || dp == NULL) return VIGEN_EINVAL;
    size_t n = sys->n, d = 3 * n;
    double local[9 * STACK_BODIES], *work = scratch(sys, local);
    double *x = work, *v = work + d, *f = work + 2 * d;
    vigen_nbody_from_coordinates(sys, coords, q, p, x, v);
    for (size_t k = 0; k < d; k++) v[k] /= sys->m[k / 3];
    vigen_nbody_pair_forces(sys, x, f, 0, 0);
    if (coords == VIGEN_NBODY_JACOBI) {
        vigen_nbody_jacobi_positions(sys, v, dq);
        vigen_nbody_jacobi_momenta(sys, f, dp);
    } else {
        vigen_nbody_democratic_positions(sys, v, dq);
        vigen_nbody_democratic_momenta(sys, f, dp);
    }
    return all_finite(dq, d) && all_finite(dp, d) ? VIGEN_SUCCESS : VIGEN_ENONFINITE;
}

int vigen_nbody_jacobi_vector_field(double t, const double *q, const double *p, double *dq, double *dp, void *ctx)
{
    (void)t;
    return vector_field(ctx, VIGEN_NBODY_JACOBI, q, p, dq, dp);
}

int vigen_nbody_democratic_vector_field(double t, const double *q, const double *p, double *dq, double *dp,
                                        void *ctx)
{
    (void)t;
    return vector_field(ctx, VIGEN_NBODY_DEMOCRATIC, q, p, dq, dp);
}

static double energy(vigen_nbody *sys, int coords, const double *q, const double *p)
{
    size_t d = 3 * sys->n;
    double local[9 * STACK_BODIES], *work = scratch(sys, local);
    double *x = work, *pi = work + d;
    vigen_nbody_from_coordinates(sys, coords, q, p, x, pi);
    return vigen_nbody_energy(sys, x, pi);
}

double vigen_nbody_jacobi_energy(double t, const double *q, const double *p, void *ctx)
{
    (void)t;
    return energy(ctx, VIGEN_NBODY_JACOBI, q, p);
}

double vigen_nbody_democratic_energy(double t, const double *q, const double *p, void *ctx)
{
    (void)t;
    return energy(ctx, VIGEN_NBODY_DEMOCRATIC, q, p);
}

static const vigen_flow_fn jacobi_flows[] = { vigen_nbody_jacobi_kepler, vigen_nbody_jacobi_interaction,
                                              vigen_nbody_jacobi_interaction_gradient };
static const vigen_flow_fn democratic_flows[] = { vigen_nbody_democratic_kepler, vigen_nbody_democratic_interaction,
                                                  vigen_nbody_democratic_jump };
static const char *const jacobi_names[] = { "kepler", "interaction", "interaction_gradient" };
static const char *const democratic_names[] = { "kepler", "interaction", "jump" };

const char *vigen_nbody_flow_name(int coords, size_t k)
{
    if (k >= 3) return NULL;
    return coords == VIGEN_NBODY_JACOBI ? jacobi_names[k] : coords == VIGEN_NBODY_DEMOCRATIC ? democratic_names[k]
                                                                                            : NULL;
}

int vigen_nbody_split(vigen_nbody *sys, int coords, vigen_split_problem *out)
{
    if (sys == NULL || out == NULL) return VIGEN_EINVAL;
    if (coords == VIGEN_NBODY_JACOBI) {
        *out = (vigen_split_problem){ .dim = 3 * sys->n, .nflows = 3, .flow = jacobi_flows, .ctx = sys,
                                      .vector_field = vigen_nbody_jacobi_vector_field,
                                      .H = vigen_nbody_jacobi_energy };
        return VIGEN_SUCCESS;
    }
    if (coords == VIGEN_NBODY_DEMOCRATIC) {
        *out = (vigen_split_problem){ .dim = 3 * sys->n, .nflows = 3, .flow = democratic_flows, .ctx = sys,
                                      .vector_field = vigen_nbody_democratic_vector_field,
                                      .H = vigen_nbody_democratic_energy };
        return VIGEN_SUCCESS;
    }
    return VIGEN_EINVAL;
}
