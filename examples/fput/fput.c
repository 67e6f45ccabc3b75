/* fput.c — the FPUT-beta chain of vigen's problem collection: n unit masses
 * between fixed walls, springs with force d + beta d^3, started at rest in
 * the first normal mode q_i = sin(pi i/(n+1)).  Integrated with Yoshida's
 * fourth-order triple jump (explicit for this separable H; yoshida4.lua).
 *
 * Prints the largest relative energy error, the smallest share of the
 * energy left in the first normal mode (for beta = 0 the modes do not
 * exchange energy, so it stays 1; for beta > 0 energy flows to the other
 * modes and, famously, comes back), and for beta = 0 the largest distance to
 * the exact solution (the mode oscillating at w = 2 sin(pi/(2(n+1)))).
 * First the problem is checked (vigen/diagnostics.h: its gradients against
 * differences of H, its separability, its Hessian): the program prints the
 * check's sentence (problem-check) or stops with it.
 *
 *   fput [BETA [N [PERIODS [STEPS_PER_PERIOD]]]]      defaults 1, 32, 20, 400
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <vigen/diagnostics.h>
#include <vigen/problems.h>
#include "yoshida4.h"   /* emitted from yoshida4.lua by vigen_add_stepper */

static const double pi = 3.14159265358979323846;

/* Energy of normal mode k: (P_k^2 + w_k^2 Q_k^2)/2 with
 * Q_k = sqrt(2/(n+1)) sum_i q_i sin(pi i k/(n+1)) (likewise P_k). */
static double mode_energy(const double *q, const double *p, size_t n, size_t k)
{
    double Q = 0, P = 0, w = 2 * sin(pi * (double)k / (2.0 * (double)(n + 1)));
    for (size_t i = 1; i <= n; i++) {
        double s = sin(pi * (double)(i * k) / (double)(n + 1));
        Q += q[i - 1] * s;
        P += p[i - 1] * s;
    }
    double c = 2.0 / (double)(n + 1);
    return c * (P * P + w * w * Q * Q) / 2;
}

int main(int argc, char **argv)
{
    double beta = argc > 1 ? atof(argv[1]) : 1;
    long n = argc > 2 ? atol(argv[2]) : 32, periods = argc > 3 ? atol(argv[3]) : 20;
    long per_period = argc > 4 ? atol(argv[4]) : 400;
    char params[100], why[200];
    snprintf(params, sizeof params, "n=%ld,beta=%.17g", n, beta);
    vigen_problem *pb;
    if (periods < 1 || per_period < 1 || vigen_problem_create(&pb, "fput", params, why, sizeof why) != VIGEN_SUCCESS) {
        fprintf(stderr, "%s\nusage: fput [BETA [N [PERIODS [STEPS_PER_PERIOD]]]]\n", periods < 1 || per_period < 1 ? "" : why);
        return 2;
    }
    size_t dim = vigen_problem_dim(pb);
    double t, *q = malloc(2 * dim * sizeof *q), *qr = malloc(2 * dim * sizeof *qr);
    if (q == NULL || qr == NULL) return 1;
    double *p = q + dim, *pr = qr + dim;
    vigen_problem_initial(pb, &t, q, p);
    vigen_problem_report rep;   /* the problem checked before integrating: gradients, separability */
    if (vigen_problem_check(vigen_problem_hamiltonian(pb), t, q, p, &rep) != VIGEN_SUCCESS) {
        fprintf(stderr, "fput: the problem fails its check: %s\n", rep.message);
        return 1;
    }
    printf("problem-check %s\n", rep.message);
    double E0 = vigen_problem_energy(pb, t, q, p), h = vigen_problem_period(pb) / (double)per_period;

    yoshida4_workspace *w = yoshida4_alloc(vigen_problem_hamiltonian(pb), NULL);
    if (w == NULL) return 1;
    double dE = 0, share = 1, dq = 0;
    int exact = vigen_problem_reference(pb, t, qr, pr);   /* beta = 0 only */
    for (long k = 0; k < periods * per_period; k++) {
        int st = yoshida4_step(w, &t, q, p, h);
        if (st != VIGEN_SUCCESS) {
            fprintf(stderr, "step %ld: %s\n", k, vigen_strerror(st));
            return 1;
        }
        double E = vigen_problem_energy(pb, t, q, p);
        dE = fmax(dE, fabs(E / E0 - 1));
        share = fmin(share, mode_energy(q, p, dim, 1) / E);
        if (exact && vigen_problem_reference(pb, t, qr, pr))
            for (size_t i = 0; i < dim; i++) dq = fmax(dq, fabs(q[i] - qr[i]));
    }
    printf("FPUT chain, n = %ld, beta = %g: Yoshida 4, %ld periods of the first mode, h = T/%ld\n", n, beta,
           periods, per_period);
    printf("energy-error %.3e\n", dE);
    printf("mode-1-share-min %.9f\n", share);
    if (exact) printf("reference-error %.3e\n", dq);
    yoshida4_free(w);
    vigen_problem_free(pb);
    free(q);
    free(qr);
    return 0;
}
