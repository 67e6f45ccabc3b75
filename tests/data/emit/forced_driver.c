/* forced_driver.c — runs an emitted (double) stepper on a time-dependent
 * Hamiltonian with an exact solution, the forced oscillator
 *
 *   H(t, q, p) = p^2/2 + q^2/2 - q F cos(w t),   q' = p,  p' = -q + F cos(w t),
 *
 * and prints key=value lines for tests/unit/test_emit_time.c.  Built with
 *   -DSTEPPER_HEADER='"NAME.h"' -DSTEPPER_TYPE=NAME_type
 * and the runtime.
 *
 * Exact solution (w != 1), by variation of constants: with y = (q, p),
 * y' = J y + f(t), J = [[0, 1], [-1, 0]], f = (0, F cos w t), and
 * exp(tJ) = [[cos t, sin t], [-sin t, cos t]],
 *   y(t) = exp(tJ) y0 + int_0^t exp((t - s)J) f(s) ds,
 * whose q component is int_0^t sin(t - s) F cos(w s) ds
 * = F (cos w t - cos t) / (1 - w^2).  Hence
 *   q(t) = q0 cos t + p0 sin t + F (cos w t - cos t) / (1 - w^2),
 *   p(t) = -q0 sin t + p0 cos t + F (sin t - w sin w t) / (1 - w^2)
 * (p = q'; check: q'' + q = F cos w t, q(0) = q0, q'(0) = p0).
 * H = T(p) + V(t, q) is separable in the sense of vigen/runtime.h.
 *
 *   forced_driver order GRID SEP KAHAN SOLVER T N0 K
 *       for N = N0 2^k (k = 0..K) steps over [0, ~T] on the grid GRID:
 *       0 uniform h = T/N; 1 alternating h, 1.7 h (N even); 2 smooth,
 *       t_j = T g(j/N) with g(x) = x + 0.3 sin(2 pi x)/(2 pi) (steps vary
 *       smoothly between 0.7 and 1.3 times T/N); each call gets its own h.
 *       Prints err_<k>: the largest |(q, p) - exact| over the steps, the
 *       exact solution taken at the sum of the step sizes (double-double);
 *       SEP sets sys.separable (explicit path for tableaux that have one),
 *       KAHAN the compensated updates, SOLVER 0 fixed point, 1 Newton.
 *   forced_driver tsum KAHAN N
 *       N steps alternating 2^-7 and 7 2^-10 (every partial sum exact in
 *       double): tsum_dyadic_diff = t - sum; then N steps alternating 0.001
 *       and 0.0017 (not representable): tsum_ulps = |t - sum| in units of
 *       the last place of the exact sum (double-double), tsum_naive_ulps the
 *       same for the naively summed double, and tsum_vs_naive = t - that
 *       naive sum.
 *   forced_driver stagetimes SEP c_1 ... c_m
 *       records the times at which the gradients are called during 20 steps
 *       of alternating size from t = 1; each must be t0 or t0 + c_i h for the
 *       step's (t0, h): stagetime_bad counts the others, stagetime_nodes the
 *       distinct nodes c_i seen, stagetime_calls every call.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include STEPPER_HEADER

extern const vigen_stepper_type STEPPER_TYPE;
static const vigen_stepper_type *T = &STEPPER_TYPE;

static const double F = 0.8, W = 2.3, Q0 = 0.5, P0 = 0.3;
static const double PI = 3.14159265358979323846;

/* ---- recording of the times the gradients are called at ---------------- */
static double *rec_t;
static size_t rec_n, rec_cap;
static int recording;

static void record(double t)
{
    if (!recording) return;
    if (rec_n == rec_cap) {
        rec_cap = rec_cap ? 2 * rec_cap : 256;
        rec_t = realloc(rec_t, rec_cap * sizeof *rec_t);
        if (rec_t == NULL) exit(1);
    }
    rec_t[rec_n++] = t;
}

static void forced_dq(double t, const double *q, const double *p, double *o, void *c)
{
    (void)p; (void)c;
    record(t);
    o[0] = q[0] - F * cos(W * t);
}
static void forced_dp(double t, const double *q, const double *p, double *o, void *c)
{
    (void)q; (void)c;
    record(t);
    o[0] = p[0];
}
static double forced_H(double t, const double *q, const double *p, void *c)
{
    (void)c;
    return p[0] * p[0] / 2 + q[0] * q[0] / 2 - q[0] * F * cos(W * t);
}

static void exact(double t, double *q, double *p)
{
    double k = F / (1 - W * W);
    *q = Q0 * cos(t) + P0 * sin(t) + k * (cos(W * t) - cos(t));
    *p = -Q0 * sin(t) + P0 * cos(t) + k * (sin(t) - W * sin(W * t));
}

/* ---- an exact running sum of doubles (double-double, Knuth's TwoSum) ---- */
typedef struct { double hi, lo; } dd;
static void dd_add(dd *s, double x)
{
    double hi = s->hi + x, bb = hi - s->hi;
    double err = (s->hi - (hi - bb)) + (x - bb);
    double lo = s->lo + err;
    s->hi = hi + lo;
    s->lo = lo - (s->hi - hi);
}

static double step_size(int grid, double Tend, long N, long j)
{
    if (grid == 1) {
        double h = Tend / ((double)N / 2 * 2.7);
        return j % 2 == 0 ? h : 1.7 * h;
    }
    if (grid == 2) {
        double x0 = (double)j / N, x1 = (double)(j + 1) / N;
        double g0 = x0 + 0.3 * sin(2 * PI * x0) / (2 * PI), g1 = x1 + 0.3 * sin(2 * PI * x1) / (2 * PI);
        return Tend * g1 - Tend * g0;
    }
    return Tend / N;
}

static vigen_hamiltonian forced_system(int sep)
{
    vigen_hamiltonian sys = { 1, forced_dq, forced_dp, forced_H, NULL, sep, NULL };
    return sys;
}

static int run_order(int grid, int sep, int kahan, int solver, double Tend, long n0, int K)
{
    vigen_hamiltonian sys = forced_system(sep);
    vigen_solver_options opt;
    vigen_solver_options_default(&opt);
    opt.kahan = kahan;
    opt.solver = solver ? VIGEN_SOLVER_NEWTON : VIGEN_SOLVER_FIXED_POINT;
    for (int k = 0; k <= K; k++) {
        long N = n0 << k;
        double t = 0, q[1] = { Q0 }, p[1] = { P0 }, qe, pe, emax = 0;
        dd S = { 0, 0 };
        void *w = T->alloc(&sys, &opt);
        if (w == NULL) { printf("alloc=failed\n"); return 1; }
        int st = 0;
        for (long j = 0; j < N && st == 0; j++) {
            double h = step_size(grid, Tend, N, j);
            st = T->step(w, &t, q, p, h);
            dd_add(&S, h);
            exact(S.hi + S.lo, &qe, &pe);
            double e = hypot(q[0] - qe, p[0] - pe);
            if (e > emax) emax = e;
        }
        printf("status_%d=%d\nerr_%d=%.6e\nsteps_%d=%ld\nsweeps_%d=%.3f\n", k, st, k, emax, k, N, k,
               (double)T->stats(w)->iterations / (double)N);
        T->free(w);
    }
    return 0;
}

static double ulp(double x) { return nextafter(fabs(x), INFINITY) - fabs(x); }

static int run_tsum(int kahan, long N)
{
    vigen_hamiltonian sys = forced_system(1);
    vigen_solver_options opt;
    vigen_solver_options_default(&opt);
    opt.kahan = kahan;
    /* dyadic steps: every partial sum is a multiple of 2^-10 below 2^40 */
    void *w = T->alloc(&sys, &opt);
    double t = 0, q[1] = { Q0 }, p[1] = { P0 }, sum = 0;
    int st = 0;
    for (long j = 0; j < N && st == 0; j++) {
        double h = j % 2 ? 0x1p-7 : 7 * 0x1p-10;
        st = T->step(w, &t, q, p, h);
        sum += h;
    }
    printf("tsum_status=%d\ntsum_dyadic_diff=%.17g\n", st, t - sum);
    T->free(w);
    /* steps that are not representable: 0.001 and 0.0017 as doubles */
    w = T->alloc(&sys, &opt);
    t = 0; q[0] = Q0; p[0] = P0;
    dd S = { 0, 0 };
    double naive = 0;
    for (long j = 0; j < N && st == 0; j++) {
        double h = j % 2 ? 0.0017 : 0.001;
        st = T->step(w, &t, q, p, h);
        dd_add(&S, h);
        naive += h;
    }
    double exact_sum = S.hi + S.lo, u = ulp(exact_sum);
    printf("tsum_status2=%d\ntsum=%.17g\ntsum_exact=%.17g\ntsum_ulps=%.3f\ntsum_naive_ulps=%.3f\ntsum_vs_naive=%.17g\n",
           st, t, exact_sum, fabs((t - S.hi) - S.lo) / u, fabs((naive - S.hi) - S.lo) / u, t - naive);
    T->free(w);
    return 0;
}

static int run_stagetimes(int sep, int m, const double *c)
{
    vigen_hamiltonian sys = forced_system(sep);
    void *w = T->alloc(&sys, NULL);
    double t = 1, q[1] = { Q0 }, p[1] = { P0 };
    long bad = 0, calls = 0;
    int seen[64] = { 0 };
    for (int j = 0; j < 20; j++) {
        double h = j % 2 ? 0.05 : 0.085, t0 = t;
        rec_n = 0;
        recording = 1;
        int st = T->step(w, &t, q, p, h);
        recording = 0;
        if (st != 0) { printf("stagetime_status=%d\n", st); return 1; }
        for (size_t k = 0; k < rec_n; k++) {
            int ok = fabs(rec_t[k] - t0) <= 1e-14;
            for (int i = 0; i < m; i++)
                if (fabs(rec_t[k] - (t0 + c[i] * h)) <= 1e-14) { ok = 1; seen[i] = 1; }
            if (!ok) {
                bad++;
                if (bad <= 3) fprintf(stderr, "gradient at t = %.17g, step from %.17g by %.17g: (t - t0)/h = %.17g\n",
                                      rec_t[k], t0, h, (rec_t[k] - t0) / h);
            }
            calls++;
        }
    }
    int nodes = 0;
    for (int i = 0; i < m; i++) nodes += seen[i];
    printf("stagetime_calls=%ld\nstagetime_bad=%ld\nstagetime_nodes=%d\n", calls, bad, nodes);
    T->free(w);
    free(rec_t);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 2) return 2;
    if (strcmp(argv[1], "order") == 0 && argc == 9)
        return run_order(atoi(argv[2]), atoi(argv[3]), atoi(argv[4]), atoi(argv[5]), atof(argv[6]), atol(argv[7]),
                         atoi(argv[8]));
    if (strcmp(argv[1], "tsum") == 0 && argc == 4) return run_tsum(atoi(argv[2]), atol(argv[3]));
    if (strcmp(argv[1], "stagetimes") == 0 && argc >= 4 && argc - 3 <= 64) {
        double c[64];
        int m = argc - 3;
        for (int i = 0; i < m; i++) c[i] = atof(argv[3 + i]);
        return run_stagetimes(atoi(argv[2]), m, c);
    }
    return 2;
}
