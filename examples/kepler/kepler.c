/* kepler.c — the Kepler problem with eccentricity 0.6, integrated over many
 * periods with two steppers emitted by `vigen emit`: the 2-stage Gauss
 * method (gauss2.lua, order 4) and Stormer-Verlet (verlet.lua, order 2).
 *
 *   H(q, p) = |p|^2 / 2 - 1 / |q|,   q, p in R^2,
 *   q(0) = (1 - e, 0),  p(0) = (0, sqrt((1 + e) / (1 - e))):
 *
 * an ellipse with semi-major axis 1 and period 2 pi, starting at the
 * pericentre; H = -1/2 and the angular momentum L = q1 p2 - q2 p1 =
 * sqrt(1 - e^2) are conserved.  Both methods are symplectic, so the energy
 * error stays bounded (no drift), and both conserve L (a quadratic invariant)
 * up to round-off.  For each tenth of the run the program prints the largest
 * relative errors |H/H0 - 1| and |L/L0 - 1| seen at any step.  Before
 * integrating it checks the problem (vigen/diagnostics.h: the gradients
 * against differences of H, the separability promise) and stops with the
 * check's sentence if the problem is wrong.
 *
 *   kepler [PERIODS [STEPS_PER_PERIOD]]      defaults 10000 and 200
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <vigen/diagnostics.h>
#include <vigen/runtime.h>
#include "gauss2.h"   /* emitted from gauss2.lua by vigen_add_stepper */
#include "verlet.h"   /* emitted from verlet.lua */

static const double e = 0.6;
static const double pi = 3.14159265358979323846;

/* ---- the problem, through the callback API of vigen/runtime.h ---------- */
static void dHdq(double t, const double *q, const double *p, double *out, void *ctx)
{
    (void)t; (void)p; (void)ctx;
    double r2 = q[0] * q[0] + q[1] * q[1], r3 = r2 * sqrt(r2);
    out[0] = q[0] / r3;
    out[1] = q[1] / r3;
}

static void dHdp(double t, const double *q, const double *p, double *out, void *ctx)
{
    (void)t; (void)q; (void)ctx;
    out[0] = p[0];
    out[1] = p[1];
}

static double energy(double t, const double *q, const double *p, void *ctx)
{
    (void)t; (void)ctx;
    return (p[0] * p[0] + p[1] * p[1]) / 2 - 1 / sqrt(q[0] * q[0] + q[1] * q[1]);
}

static double angular_momentum(const double *q, const double *p) { return q[0] * p[1] - q[1] * p[0]; }

static const vigen_hamiltonian kepler = { .dim = 2, .dHdq = dHdq, .dHdp = dHdp, .H = energy, .separable = 1 };

/* The start of the orbit: the pericentre. */
static void initial(double *t, double q[2], double p[2])
{
    *t = 0;
    q[0] = 1 - e;
    q[1] = 0;
    p[0] = 0;
    p[1] = sqrt((1 + e) / (1 - e));
}

/* ---- the observer: called by vigen_integrate after every step ---------- */
typedef struct {
    const char *name;
    double H0, L0;
    double max_dH, max_dL;        /* over the current tenth of the run */
    unsigned long tenth;          /* steps per tenth */
    unsigned long steps_per_period;
} monitor;

static int observe(unsigned long step, double t, const double *q, const double *p, void *ctx)
{
    monitor *m = ctx;
    double dH = fabs(energy(t, q, p, NULL) / m->H0 - 1);
    double dL = fabs(angular_momentum(q, p) / m->L0 - 1);
    if (dH > m->max_dH) m->max_dH = dH;
    if (dL > m->max_dL) m->max_dL = dL;
    if (step > 0 && step % m->tenth == 0) {
        printf("%-8s %7lu..%-7lu %12.3e %12.3e\n", m->name, (step - m->tenth) / m->steps_per_period + 1,
               step / m->steps_per_period, m->max_dH, m->max_dL);
        m->max_dH = m->max_dL = 0;
    }
    return 0;   /* nonzero would stop the integration */
}

/* Integrates from the pericentre with the emitted stepper of type T. */
static int run(const vigen_stepper_type *T, const char *label, unsigned long periods, unsigned long per_period)
{
    double t, q[2], p[2];
    initial(&t, q, p);
    double h = 2 * pi / per_period;
    unsigned long nsteps = periods * per_period;
    monitor m = { label, energy(0, q, p, NULL), angular_momentum(q, p), 0, 0, nsteps / 10, per_period };

    void *w = T->alloc(&kepler, NULL);   /* NULL options: fixed-point iteration, Kahan sums */
    if (w == NULL) { fprintf(stderr, "%s: cannot allocate\n", label); return 1; }
    int st = vigen_integrate(T, w, &t, q, p, h, nsteps, 1, observe, &m, NULL);
    if (st != VIGEN_SUCCESS) {
        fprintf(stderr, "%s: %s\n", label, vigen_strerror(st));
        T->free(w);
        return 1;
    }
    const vigen_stats *s = T->stats(w);
    printf("%-8s %lu steps, %.2f gradient evaluations per step (tableau %s, %d stages, order %d)\n\n", label,
           s->steps, (double)(s->dHdq_evals + s->dHdp_evals) / s->steps, T->name, T->stages, T->order);
    T->free(w);
    return 0;
}

int main(int argc, char **argv)
{
    unsigned long periods = argc > 1 ? strtoul(argv[1], NULL, 10) : 10000;
    unsigned long per_period = argc > 2 ? strtoul(argv[2], NULL, 10) : 200;
    if (periods < 10 || per_period < 1) {
        fprintf(stderr, "usage: kepler [PERIODS >= 10 [STEPS_PER_PERIOD]]\n");
        return 2;
    }
    /* a sign or a factor wrong in dHdq or dHdp, or a coupling in a problem
     * marked separable, would give wrong orbits without a warning: check */
    double t, q[2], p[2];
    vigen_problem_report rep;
    initial(&t, q, p);
    if (vigen_problem_check(&kepler, t, q, p, &rep) != VIGEN_SUCCESS) {
        fprintf(stderr, "kepler: the problem fails its check: %s\n", rep.message);
        return 1;
    }
    printf("Kepler problem, e = %.1f, %lu periods of 2 pi, h = 2 pi / %lu\n", e, periods, per_period);
    printf("problem check: %s\n", rep.message);
    printf("largest relative errors in each tenth of the run:\n\n");
    printf("%-8s %15s %12s %12s\n", "stepper", "periods", "|H/H0 - 1|", "|L/L0 - 1|");
    if (run(&gauss2_type, "gauss2", periods, per_period)) return 1;
    if (run(&verlet_type, "verlet", periods, per_period)) return 1;
    return 0;
}
