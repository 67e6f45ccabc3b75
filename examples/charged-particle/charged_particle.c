/* charged_particle.c — a charged particle in the static magnetic field
 * B = (0, 0, sqrt(x^2 + y^2)) and electric potential 1/(100 sqrt(x^2 + y^2))
 * (the "charged-particle" problem of vigen's collection, H = |p - A(q)|^2/2
 * + phi(q) with the canonical momentum p), integrated with the 3-stage Gauss
 * method (gauss3.lua, order 6) using Newton's method for the stage equations.
 *
 * Prints the largest relative energy error, the largest change of the
 * canonical angular momentum x p_y - y p_x (a quadratic invariant, which
 * Gauss methods conserve up to round-off), and the range of the distance
 * from the z axis the particle explores (its gyration and drift).
 * First the problem is checked (vigen/diagnostics.h: its gradients against
 * differences of H, its separability, its Hessian): the program prints the
 * check's sentence (problem-check) or stops with it.
 *
 *   charged_particle [TIME [H]]      defaults 10000 and 0.1
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <vigen/diagnostics.h>
#include <vigen/problems.h>
#include "gauss3.h"   /* emitted from gauss3.lua by vigen_add_stepper */

int main(int argc, char **argv)
{
    double T = argc > 1 ? atof(argv[1]) : 10000, h = argc > 2 ? atof(argv[2]) : 0.1;
    if (!(T > 0 && h > 0 && T / h < 1e9)) {
        fprintf(stderr, "usage: charged_particle [TIME [H]]  (positive, TIME/H < 1e9)\n");
        return 2;
    }
    vigen_problem *pb;
    char why[200];
    if (vigen_problem_create(&pb, "charged-particle", NULL, why, sizeof why) != VIGEN_SUCCESS) {
        fprintf(stderr, "%s\n", why);
        return 1;
    }
    double t, q[3], p[3];
    vigen_problem_initial(pb, &t, q, p);
    vigen_problem_report rep;   /* the problem checked before integrating: gradients, separability */
    if (vigen_problem_check(vigen_problem_hamiltonian(pb), t, q, p, &rep) != VIGEN_SUCCESS) {
        fprintf(stderr, "charged_particle: the problem fails its check: %s\n", rep.message);
        return 1;
    }
    printf("problem-check %s\n", rep.message);
    double E0 = vigen_problem_energy(pb, t, q, p), J0 = vigen_problem_invariant(pb, 0, t, q, p);

    vigen_solver_options opt;
    vigen_solver_options_default(&opt);
    opt.solver = VIGEN_SOLVER_NEWTON;   /* Jacobian by finite differences (no Hessian given) */
    gauss3_workspace *w = gauss3_alloc(vigen_problem_hamiltonian(pb), &opt);
    if (w == NULL) return 1;
    double dE = 0, dJ = 0, rmin = INFINITY, rmax = 0;
    unsigned long n = (unsigned long)(T / h + 0.5);
    for (unsigned long k = 0; k < n; k++) {
        int st = gauss3_step(w, &t, q, p, h);
        if (st != VIGEN_SUCCESS) {
            fprintf(stderr, "step %lu: %s\n", k, vigen_strerror(st));
            return 1;
        }
        dE = fmax(dE, fabs(vigen_problem_energy(pb, t, q, p) / E0 - 1));
        dJ = fmax(dJ, fabs(vigen_problem_invariant(pb, 0, t, q, p) - J0));
        double r = hypot(q[0], q[1]);
        rmin = fmin(rmin, r);
        rmax = fmax(rmax, r);
    }
    printf("charged particle: 3-stage Gauss (Newton), h = %g, %lu steps\n", h, n);
    printf("energy-error %.3e\n", dE);
    printf("%s-error %.3e\n", vigen_problem_invariant_name(pb, 0), dJ);
    printf("radius-range %.4f %.4f\n", rmin, rmax);
    gauss3_free(w);
    vigen_problem_free(pb);
    return 0;
}
