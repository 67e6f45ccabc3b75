/* point_vortices.c — n point vortices of unit strength on a regular polygon
 * (the "point-vortices" problem of vigen's collection, canonical coordinates
 * q_i = x_i, p_i = y_i), integrated with the method of Leok and Zhang's
 * Example 4 (basis {1, cos(pi t), sin(pi t)}, order 2), generated from
 * leok_zhang_ex4.lua at build time.  The Hamiltonian is not separable: the
 * stepper solves its stage equations by fixed-point iteration.
 *
 * The polygon rotates rigidly (the exact solution); the program prints the
 * largest distance to it, the largest relative energy error and the largest
 * changes of the linear and angular impulse.
 * First the problem is checked (vigen/diagnostics.h: its gradients against
 * differences of H, its separability, its Hessian): the program prints the
 * check's sentence (problem-check) or stops with it.
 *
 *   point_vortices [N [PERIODS [STEPS_PER_PERIOD]]]      defaults 3, 10, 200
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <vigen/diagnostics.h>
#include <vigen/problems.h>
#include "lz4.h"   /* generated and emitted from leok_zhang_ex4.lua by vigen_add_stepper */

int main(int argc, char **argv)
{
    long n = argc > 1 ? atol(argv[1]) : 3, periods = argc > 2 ? atol(argv[2]) : 10;
    long per_period = argc > 3 ? atol(argv[3]) : 200;
    char params[64], why[200];
    snprintf(params, sizeof params, "n=%ld", n);
    vigen_problem *pb;
    if (periods < 1 || per_period < 1 ||
        vigen_problem_create(&pb, "point-vortices", params, why, sizeof why) != VIGEN_SUCCESS) {
        fprintf(stderr, "%s\nusage: point_vortices [N [PERIODS [STEPS_PER_PERIOD]]]\n",
                periods < 1 || per_period < 1 ? "" : why);
        return 2;
    }
    size_t dim = vigen_problem_dim(pb), ninv = vigen_problem_invariant_count(pb);
    double t, *q = malloc(4 * dim * sizeof *q);
    if (q == NULL) return 1;
    double *p = q + dim, *qr = p + dim, *pr = qr + dim, I0[3], dI[3] = { 0, 0, 0 };
    vigen_problem_initial(pb, &t, q, p);
    vigen_problem_report rep;   /* the problem checked before integrating: gradients, separability */
    if (vigen_problem_check(vigen_problem_hamiltonian(pb), t, q, p, &rep) != VIGEN_SUCCESS) {
        fprintf(stderr, "point_vortices: the problem fails its check: %s\n", rep.message);
        return 1;
    }
    printf("problem-check %s\n", rep.message);
    double E0 = vigen_problem_energy(pb, t, q, p), h = vigen_problem_period(pb) / (double)per_period;
    for (size_t k = 0; k < ninv && k < 3; k++) I0[k] = vigen_problem_invariant(pb, k, t, q, p);

    lz4_workspace *w = lz4_alloc(vigen_problem_hamiltonian(pb), NULL);
    if (w == NULL) return 1;
    double dE = 0, dx = 0;
    for (long step = 0; step < periods * per_period; step++) {
        int st = lz4_step(w, &t, q, p, h);
        if (st != VIGEN_SUCCESS) {
            fprintf(stderr, "step %ld: %s\n", step, vigen_strerror(st));
            return 1;
        }
        dE = fmax(dE, fabs(vigen_problem_energy(pb, t, q, p) / E0 - 1));
        for (size_t k = 0; k < ninv && k < 3; k++)
            dI[k] = fmax(dI[k], fabs(vigen_problem_invariant(pb, k, t, q, p) - I0[k]));
        vigen_problem_reference(pb, t, qr, pr);
        for (size_t i = 0; i < dim; i++) dx = fmax(dx, hypot(q[i] - qr[i], p[i] - pr[i]));
    }
    const vigen_stats *s = lz4_stats(w);
    printf("%ld point vortices: Leok-Zhang Example 4, %ld periods, h = T/%ld, %.1f stage iterations per step\n", n,
           periods, per_period, (double)s->iterations / (double)s->steps);
    printf("reference-error %.3e\n", dx);
    printf("energy-error %.3e\n", dE);
    for (size_t k = 0; k < ninv && k < 3; k++) printf("%s-error %.3e\n", vigen_problem_invariant_name(pb, k), dI[k]);
    lz4_free(w);
    vigen_problem_free(pb);
    free(q);
    return 0;
}
