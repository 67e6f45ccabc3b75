/* problem_jupiter_saturn.c — the Sun (with the inner planets' masses),
 * Jupiter and Saturn as three point masses in R^3: a near-integrable
 * system near a mean-motion resonance (the periods, 11.86 and 29.46 years,
 * are near 2:5, the "great inequality" of Laplace, with a period of about
 * 900 years).  Data of Hairer, Lubich and Wanner, Geometric Numerical
 * Integration, sec. I.2.3 (the rows of the Sun, Jupiter and Saturn of the
 * outer solar system: masses relative to the Sun, AU, days,
 * G = 2.95912208286e-4); the planets' masses are multiplied by the
 * parameter mass-scale (the eps of H = H_kepler + eps H_interaction, for
 * studying methods of generalized order):
 *   H = sum_i |p_i|^2/(2 m_i) - G sum_{i<j} m_i m_j / |q_i - q_j|,
 * q = (q_Sun, q_Jupiter, q_Saturn), p_i = m_i v_i.  No Hessian (Newton's
 * method uses finite differences), no Lagrangian, no invariants beyond the
 * energy, no reference solution; its Kepler splittings are the runtime's
 * N-body ones. */
#include <math.h>
#include <stdlib.h>
#include "problems_internal.h"

enum { NBODY = 3 };

static const double G = 2.95912208286e-4;
static const double mass[NBODY] = { 1.00000597682, 0.000954786104043, 0.000285583733151 };
static const double position[NBODY][3] = {
    { 0, 0, 0 }, { -3.5023653, -3.8169847, -1.5507963 }, { 9.0755314, -3.0458353, -1.6483708 } };
static const double velocity[NBODY][3] = {
    { 0, 0, 0 }, { 0.00565429, -0.00412490, -0.00190589 }, { 0.00168318, 0.00483525, 0.00192462 } };

static double energy(double t, const double *q, const double *p, void *ctx)
{
    (void)t;
    const vigen_problem *pb = ctx;
    return vigen_nbody_energy(pb->nbody, q, p);
}

static void dHdq(double t, const double *q, const double *p, double *out, void *ctx)
{
    (void)t; (void)p;
    const vigen_problem *pb = ctx;
    vigen_nbody_forces(pb->nbody, q, out);
    for (int k = 0; k < 3 * NBODY; k++) out[k] = -out[k];
}

static void dHdp(double t, const double *q, const double *p, double *out, void *ctx)
{
    (void)t; (void)q;
    const vigen_problem *pb = ctx;
    const double *m = pb->data;
    for (int k = 0; k < 3 * NBODY; k++) out[k] = p[k] / m[k / 3];
}

int vigen_pbi_jupiter_saturn_setup(vigen_problem *pb)
{
    double scale = pb->param[0], *m = malloc(NBODY * sizeof *m);
    if (m == NULL || vigen_pbi_set_dim(pb, 3 * NBODY) != VIGEN_SUCCESS) {
        free(m);
        return VIGEN_ENOMEM;
    }
    pb->data = m;
    for (int i = 0; i < NBODY; i++) m[i] = i == 0 ? mass[0] : scale * mass[i];
    pb->ham = (vigen_hamiltonian){ .dHdq = dHdq, .dHdp = dHdp, .H = energy, .separable = 1 };
    for (int i = 0; i < NBODY; i++)
        for (int c = 0; c < 3; c++) {
            pb->q0[3 * i + c] = position[i][c];
            pb->p0[3 * i + c] = m[i] * velocity[i][c];
        }
    /* Jupiter's period from its osculating orbit, as for the outer solar
     * system: a = 1/(2/r - v^2/mu), T = 2 pi sqrt(a^3/mu) */
    double mu = G * (m[0] + m[1]), r = 0, v2 = 0;
    for (int c = 0; c < 3; c++) {
        r += position[1][c] * position[1][c];
        v2 += velocity[1][c] * velocity[1][c];
    }
    double a = 1 / (2 / sqrt(r) - v2 / mu);
    pb->period = 2 * PBI_PI * sqrt(a * a * a / mu);
    pb->default_time = 400000;
    return vigen_pbi_nbody_split_setup(pb, NBODY, G, m);
}
