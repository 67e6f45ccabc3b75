/* poincare_kepler.c — the Poincaré time transformation on Kepler (e = 0.9
 * by default) against constant steps, with the Gauss-2 stepper of
 * tests/data/emit/golden: for each density g = r^alpha and fictive step,
 * the work (calls of the user's functions) and the largest energy error over
 * the run, then constant steps given at least the same work.  Prints a
 * markdown table (docs/simulation.md).  Built and run by
 * bench/poincare_run.sh; usage: poincare_kepler [periods [e [newton]]]. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <vigen/poincare.h>
#include <vigen/problems.h>
#include "gauss2.h"

typedef struct {
    const vigen_problem *pb;
    double H0, worst;
} watch;

static int watch_energy(unsigned long step, double tau, double t, const double *q, const double *p, void *ctx)
{
    watch *wt = ctx;
    (void)step; (void)tau;
    double d = fabs(vigen_problem_energy(wt->pb, t, q, p) - wt->H0);
    if (d > wt->worst) wt->worst = d;
    return 0;
}

/* Position error at t against the reference from Kepler's equation. */
static double position_error(const vigen_problem *pb, double t, const double *q)
{
    double qr[2], pr[2];
    vigen_problem_reference(pb, t, qr, pr);
    return hypot(q[0] - qr[0], q[1] - qr[1]);
}

/* Constant steps of Gauss-2 over [0, T], the fewest (to 1 %) whose gradient
 * calls reach `work`, found by doubling then bisection of the step count. */
static void constant_row(const vigen_problem *pb, double T, unsigned long work, const vigen_solver_options *opt)
{
    const vigen_hamiltonian *sys = vigen_problem_hamiltonian(pb);
    unsigned long N = 64, lo = 0, hi = 0, calls = 0;
    double worst = 0, perr = 0;
    for (int round = 0; round < 40 && (hi == 0 || hi - lo > hi / 100); round++) {
        gauss2_workspace *w = gauss2_alloc(sys, opt);
        watch wt = { pb, 0, 0 };
        double t, q[2], p[2];
        vigen_problem_initial(pb, &t, q, p);
        wt.H0 = vigen_problem_energy(pb, t, q, p);
        int st = VIGEN_SUCCESS;
        for (unsigned long k = 0; k < N && st == VIGEN_SUCCESS; k++) {
            st = gauss2_step(w, &t, q, p, T / (double)N);
            watch_energy(k, 0, t, q, p, &wt);
        }
        unsigned long c = gauss2_stats(w)->dHdq_evals + gauss2_stats(w)->dHdp_evals;
        gauss2_free(w);
        if (st == VIGEN_SUCCESS && c >= work) { hi = N; calls = c; worst = wt.worst; perr = position_error(pb, t, q); }
        else lo = N;                       /* too little work, or steps too large to solve */
        N = hi ? lo + (hi - lo) / 2 : 2 * N;
    }
    if (hi)
        printf("| constant step | h = %.3g | %lu | %lu | %.2e | %.2e |\n", T / (double)hi, hi, calls, worst, perr);
    else
        printf("| constant step | no step size reached the work | | | | |\n");
}

int main(int argc, char **argv)
{
    const double periods = argc > 1 ? atof(argv[1]) : 100;
    char params[64];
    snprintf(params, sizeof params, "e=%s", argc > 2 ? argv[2] : "0.9");
    vigen_problem *pb;
    char why[200];
    if (vigen_problem_create(&pb, "kepler", params, why, sizeof why) != VIGEN_SUCCESS) {
        fprintf(stderr, "poincare_kepler: %s\n", why);
        return 1;
    }
    const double T = periods * vigen_problem_period(pb);
    vigen_solver_options opt;
    vigen_solver_options_default(&opt);
    if (argc > 3 && strcmp(argv[3], "newton") == 0) opt.solver = VIGEN_SOLVER_NEWTON;
    const double alphas[] = { 1, 1.5, 2, 2.5 }, dtaus[] = { 0.4, 0.2, 0.1, 0.05 };
    printf("Kepler %s, %g periods, Gauss-2 (%s)\n\n", params, periods,
           opt.solver == VIGEN_SOLVER_NEWTON ? "simplified Newton" : "fixed-point stage iteration");
    printf("| run | step | steps | work | max energy error | position error at end |\n");
    printf("|---|---|---|---|---|---|\n");
    for (size_t i = 0; i < sizeof alphas / sizeof alphas[0]; i++)
        for (size_t j = 0; j < sizeof dtaus / sizeof dtaus[0]; j++) {
            vigen_poincare_power pw = { alphas[i], 0, 2 };
            vigen_poincare_problem pp = { vigen_problem_hamiltonian(pb), vigen_poincare_density_power, &pw, NULL };
            vigen_poincare *pc;
            if (vigen_poincare_alloc(&pc, &pp) != VIGEN_SUCCESS) return 1;
            void *w = gauss2_type.alloc(vigen_poincare_hamiltonian(pc), &opt);
            double t, q[2], p[2];
            vigen_problem_initial(pb, &t, q, p);
            watch wt = { pb, vigen_problem_energy(pb, t, q, p), 0 };
            vigen_poincare_result res;
            int st = vigen_poincare_integrate(&gauss2_type, w, pc, &t, q, p, dtaus[j], T, 0, 1, watch_energy, &wt,
                                              &res);
            const vigen_poincare_stats *S = vigen_poincare_get_stats(pc);
            /* every call of a user function counts as one gradient */
            unsigned long work = S->dHdq_evals + S->dHdp_evals + S->H_evals + S->density_evals;
            if (st != VIGEN_SUCCESS)
                printf("| g = r^%g | dtau = %g | failed: %s | | | |\n", alphas[i], dtaus[j], vigen_poincare_message(pc));
            else {
                printf("| g = r^%g | dtau = %g | %lu | %lu | %.2e | %.2e |\n", alphas[i], dtaus[j], res.steps, work,
                       wt.worst, position_error(pb, t, q));
                if (j == 2) constant_row(pb, T, work, &opt);
            }
            gauss2_type.free(w);
            vigen_poincare_free(pc);
        }
    vigen_problem_free(pb);
    return 0;
}
