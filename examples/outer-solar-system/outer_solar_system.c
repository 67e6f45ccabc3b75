/* outer_solar_system.c — the Sun and Jupiter, Saturn, Uranus, Neptune and
 * Pluto (the "outer-solar-system" problem of vigen's collection: data of
 * Hairer, Lubich and Wanner, masses relative to the Sun, AU, days),
 * integrated with the 2-stage Gauss method that vigen generates from
 * gauss2_spec.lua at build time.
 *
 * Prints the largest relative errors of the energy, the total linear
 * momentum and the total angular momentum over the run, and Jupiter's mean
 * orbital period measured from the simulation (its angle about the Sun,
 * unwrapped): about 4332.6 days, or 11.86 years; then the final positions
 * (AU).
 * First the problem is checked (vigen/diagnostics.h: its gradients against
 * differences of H, its separability, its Hessian): the program prints the
 * check's sentence (problem-check) or stops with it.
 *
 *   outer_solar_system [DAYS [H]]        defaults 200000 and 10
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <vigen/diagnostics.h>
#include <vigen/problems.h>
#include "gauss2.h"   /* generated and emitted from gauss2_spec.lua by vigen_add_stepper */

static double norm3(const double v[3]) { return sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

/* invariants 0..2: linear momentum; 3..5: angular momentum (the collection's names) */
static void invariants(const vigen_problem *pb, double t, const double *q, const double *p, double P[3], double L[3])
{
    for (int k = 0; k < 3; k++) {
        P[k] = vigen_problem_invariant(pb, (size_t)k, t, q, p);
        L[k] = vigen_problem_invariant(pb, (size_t)k + 3, t, q, p);
    }
}

int main(int argc, char **argv)
{
    double days = argc > 1 ? atof(argv[1]) : 200000, h = argc > 2 ? atof(argv[2]) : 10;
    if (!(days > 0 && h > 0 && days / h < 1e9)) {
        fprintf(stderr, "usage: outer_solar_system [DAYS [H]]  (positive, DAYS/H < 1e9)\n");
        return 2;
    }
    vigen_problem *pb;
    char why[200];
    if (vigen_problem_create(&pb, "outer-solar-system", NULL, why, sizeof why) != VIGEN_SUCCESS) {
        fprintf(stderr, "%s\n", why);
        return 1;
    }
    double t, q[18], p[18], P0[3], L0[3], P[3], L[3];
    vigen_problem_initial(pb, &t, q, p);
    vigen_problem_report rep;   /* the problem checked before integrating: gradients, separability */
    if (vigen_problem_check(vigen_problem_hamiltonian(pb), t, q, p, &rep) != VIGEN_SUCCESS) {
        fprintf(stderr, "outer_solar_system: the problem fails its check: %s\n", rep.message);
        return 1;
    }
    printf("problem-check %s\n", rep.message);
    double E0 = vigen_problem_energy(pb, t, q, p);
    invariants(pb, t, q, p, P0, L0);
    double pscale = 0;   /* the size of the momenta, for a relative momentum error */
    for (int i = 0; i < 18; i++) pscale += fabs(p[i]);

    gauss2_workspace *w = gauss2_alloc(vigen_problem_hamiltonian(pb), NULL);
    if (w == NULL) return 1;
    double dE = 0, dP = 0, dL = 0, angle = 0;
    double prev = atan2(q[4] - q[1], q[3] - q[0]);   /* Jupiter (body 1) about the Sun (body 0) */
    unsigned long n = (unsigned long)(days / h + 0.5);
    for (unsigned long k = 0; k < n; k++) {
        int st = gauss2_step(w, &t, q, p, h);
        if (st != VIGEN_SUCCESS) {
            fprintf(stderr, "step %lu: %s\n", k, vigen_strerror(st));
            return 1;
        }
        invariants(pb, t, q, p, P, L);
        double d[3] = { P[0] - P0[0], P[1] - P0[1], P[2] - P0[2] }, e[3] = { L[0] - L0[0], L[1] - L0[1], L[2] - L0[2] };
        dE = fmax(dE, fabs(vigen_problem_energy(pb, t, q, p) / E0 - 1));
        dP = fmax(dP, norm3(d) / pscale);
        dL = fmax(dL, norm3(e) / norm3(L0));
        double a = atan2(q[4] - q[1], q[3] - q[0]);
        angle += remainder(a - prev, 2 * 3.14159265358979323846);   /* unwrapped */
        prev = a;
    }
    const vigen_stats *s = gauss2_stats(w);
    printf("outer solar system: 2-stage Gauss from gauss2_spec.lua, h = %g days, %lu steps, %.1f gradient evaluations per step\n",
           h, n, (double)(s->dHdq_evals + s->dHdp_evals) / (double)s->steps);
    printf("energy-error %.3e\n", dE);
    printf("momentum-error %.3e\n", dP);
    printf("angular-momentum-error %.3e\n", dL);
    printf("jupiter-period-days %.1f\n", t * 2 * 3.14159265358979323846 / fabs(angle));
    static const char *const body[6] = { "sun", "jupiter", "saturn", "uranus", "neptune", "pluto" };
    for (int i = 0; i < 6; i++)
        printf("position-%s %.10f %.10f %.10f\n", body[i], q[3 * i], q[3 * i + 1], q[3 * i + 2]);
    gauss2_free(w);
    vigen_problem_free(pb);
    return 0;
}
