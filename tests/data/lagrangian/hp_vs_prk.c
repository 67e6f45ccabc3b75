/* hp_vs_prk.c — a Lagrangian integrator against an emitted SPRK stepper on
 * the same problem and the same non-uniform grid (built by the tests of the
 * Lagrangian integrators with STEPPER_HEADER / STEPPER_TYPE naming the
 * emitted stepper).
 *
 *   hp_vs_prk hp RULE NSTEPS       vigen_hp_step (rule 0 trapezoidal,
 *                                  1 midpoint) against the stepper
 *   hp_vs_prk grid NSTEPS          vigen_trapezoidal_vi_integrate over the
 *                                  grid against the stepper
 *
 * The problem is L = 1/2 v^T M v - V(q) with a full mass matrix M and
 *   V(q) = 2 - cos q1 - cos q2 + (q1 - q2)^4 / 10,
 * i.e. H = 1/2 p^T M^-1 p + V(q) for the stepper.  Steps h_n lie in
 * [0.05, 0.15] (a fixed linear congruential sequence), each passed to both.
 * Prints status=, steps=, dq= and dp= (largest |difference| over the
 * trajectory, relative to the largest |q| and |p|). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <vigen/lagrangian.h>
#include STEPPER_HEADER

static const double M[4] = { 2.0, 0.5, 0.5, 1.0 };
static const double Minv[4] = { 1.0 / 1.75, -0.5 / 1.75, -0.5 / 1.75, 2.0 / 1.75 };

static void gradV(const double *q, double *g)
{
    double d = q[0] - q[1], c = 0.4 * d * d * d;
    g[0] = sin(q[0]) + c;
    g[1] = sin(q[1]) - c;
}
static void H_dq(double t, const double *q, const double *p, double *o, void *c) { (void)t; (void)p; (void)c; gradV(q, o); }
static void H_dp(double t, const double *q, const double *p, double *o, void *c)
{
    (void)t; (void)q; (void)c;
    o[0] = Minv[0] * p[0] + Minv[1] * p[1];
    o[1] = Minv[2] * p[0] + Minv[3] * p[1];
}
static void L_dq(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)v; (void)c;
    gradV(q, o);
    o[0] = -o[0];
    o[1] = -o[1];
}
static void L_dv(double t, const double *q, const double *v, double *o, void *c)
{
    (void)t; (void)q; (void)c;
    o[0] = M[0] * v[0] + M[1] * v[1];
    o[1] = M[2] * v[0] + M[3] * v[1];
}

static unsigned long lcg = 12345;
static double next_h(void)
{
    lcg = (lcg * 6364136223846793005UL + 1442695040888963407UL) & 0xffffffffffffUL;
    return 0.05 + 0.1 * (double)(lcg >> 16) / 4294967296.0;
}

int main(int argc, char **argv)
{
    if (argc < 3) return 2;
    const int grid = strcmp(argv[1], "grid") == 0;
    const int rule = grid ? VIGEN_HP_TRAPEZOIDAL : atoi(argv[2]);
    const long nsteps = atol(argv[grid ? 2 : 3]);
    vigen_hamiltonian sys = { 2, H_dq, H_dp, NULL, NULL, 1, NULL };
    vigen_lagrangian lag = { 2, L_dq, L_dv, NULL, NULL, NULL, NULL, NULL };
    void *sw = STEPPER_TYPE.alloc(&sys, NULL);
    double ts = 0.0, qs[2] = { 0.9, -0.4 }, ps[2] = { 0.3, 0.8 };
    double tl = 0.0, ql[2] = { 0.9, -0.4 }, pl[2] = { 0.3, 0.8 };
    double *times = malloc((size_t)(nsteps + 1) * sizeof(double));
    double *qg = malloc((size_t)(nsteps + 1) * 2 * sizeof(double)), *pg = malloc((size_t)(nsteps + 1) * 2 * sizeof(double));
    double *hs = malloc((size_t)nsteps * sizeof(double));
    times[0] = 0.0;
    for (long k = 0; k < nsteps; k++) {
        hs[k] = next_h();
        times[k + 1] = times[k] + hs[k];
    }
    int st = 0;
    long done = 0;
    vigen_hp *hp = NULL;
    if (grid) {
        /* the stepper gets h = times[k+1] - times[k], as the grid driver does */
        vigen_trapezoidal_vi *vi = vigen_trapezoidal_vi_alloc(&lag, NULL);
        size_t nd = 0;
        st = vi ? vigen_trapezoidal_vi_integrate(vi, times, (size_t)nsteps + 1, ql, pl, qg, pg, &nd) : -1;
        done = (long)nd;
        vigen_trapezoidal_vi_free(vi);
    } else {
        hp = vigen_hp_alloc(&lag, rule, NULL, NULL);
        if (hp == NULL) st = -1;
    }
    double dq = 0, dp = 0, qmax = 0, pmax = 0;
    for (long k = 0; k < nsteps && st == 0; k++) {
        double h = grid ? times[k + 1] - times[k] : hs[k];
        st = STEPPER_TYPE.step(sw, &ts, qs, ps, h);
        if (st == 0 && !grid) st = vigen_hp_step(hp, &tl, ql, pl, h);
        if (st != 0) break;
        const double *qc = grid ? qg + 2 * (k + 1) : ql, *pc = grid ? pg + 2 * (k + 1) : pl;
        for (int i = 0; i < 2; i++) {
            dq = fmax(dq, fabs(qc[i] - qs[i]));
            dp = fmax(dp, fabs(pc[i] - ps[i]));
            qmax = fmax(qmax, fabs(qs[i]));
            pmax = fmax(pmax, fabs(ps[i]));
        }
        if (!grid) done = k + 1;
    }
    printf("status=%d\nsteps=%ld\ndq=%.6e\ndp=%.6e\ntdiff=%.6e\n", st, done, dq / qmax, dp / pmax,
           grid ? 0.0 : fabs(tl - ts));
    vigen_hp_free(hp);
    STEPPER_TYPE.free(sw);
    free(times);
    free(qg);
    free(pg);
    free(hs);
    return 0;
}
