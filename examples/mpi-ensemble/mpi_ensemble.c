/* mpi_ensemble.c — an ensemble of Kepler orbits over MPI ranks and cores.
 *
 * Orbit i (0 <= i < ORBITS) has eccentricity e_i = 0.8 i / ORBITS, semi-major
 * axis 1 and period 2 pi, and starts at its pericentre:
 *   q = (1 - e, 0),  p = (0, sqrt((1 + e)/(1 - e))),  H = |p|^2/2 - 1/|q| = -1/2.
 * Every orbit is integrated for PERIODS periods with STEPS_PER_PERIOD steps of
 * the 2-stage Gauss method (gauss2.lua, emitted at build time), as a
 * mechanical problem (the force only).
 *
 * Rank r of R takes the orbits [floor(r N / R), floor((r + 1) N / R)) (a block
 * distribution by global index) and spreads them over its cores with
 * vigen_integrate_ensemble; rank 0 gathers the final states in the order of
 * the orbits and prints them.  Each orbit's result depends on its own data
 * only (a reset workspace per orbit), so the output is the same, byte for
 * byte, for any number of ranks and threads.  FAIL (optional) is the index
 * of an orbit started at NaN, to show a failing orbit reported while the
 * others finish.
 *
 *   mpirun -np R mpi_ensemble ORBITS [STEPS_PER_PERIOD [PERIODS [FAIL]]]
 *       defaults: STEPS_PER_PERIOD 200, PERIODS 1, FAIL none
 *
 * Output (rank 0; the number of ranks and threads and the wall-clock time
 * of the integration and the gathering go to stderr): one line
 *   orbit I E STATUS STEPS T Q1 Q2 P1 P2
 * per orbit (%.17g: the exact doubles), then the largest energy error
 * |H + 1/2| and distance to the start (after whole periods the exact orbit
 * is back at its start) over the orbits that finished, and the number of
 * orbits that failed.
 */
#include <limits.h>
#include <math.h>
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include <vigen/ensemble.h>
#include "gauss2.h"

enum { PACK = 7 };   /* doubles per orbit: t, q1, q2, p1, p2, status, steps */
static const double pi = 3.14159265358979323846;

static void kepler_force(double t, const double *q, double *f, void *ctx)
{
    (void)t; (void)ctx;
    const double r2 = q[0] * q[0] + q[1] * q[1], r3 = r2 * sqrt(r2);
    f[0] = -q[0] / r3;
    f[1] = -q[1] / r3;
}

static void *alloc_gauss2(void *sys) { return gauss2_alloc_mechanical(sys, NULL); }

static double eccentricity(long i, long n) { return 0.8 * (double)i / (double)n; }

/* A positive integer argument, or -1 with a message. */
static long parse(const char *text, const char *what, long lo, long hi, int rank)
{
    char *end;
    long v = strtol(text, &end, 10);
    if (*text == '\0' || *end != '\0' || v < lo || v > hi) {
        if (rank == 0) fprintf(stderr, "mpi_ensemble: %s must be an integer from %ld to %ld, not '%s'\n", what, lo, hi, text);
        return -1;
    }
    return v;
}

int main(int argc, char **argv)
{
    MPI_Init(&argc, &argv);
    int rank, size;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    if (argc < 2 || argc > 5) {
        if (rank == 0) fprintf(stderr, "usage: mpirun -np R mpi_ensemble ORBITS [STEPS_PER_PERIOD [PERIODS [FAIL]]]\n");
        MPI_Finalize();
        return 2;
    }
    const long n = parse(argv[1], "ORBITS", 1, INT_MAX / PACK, rank);
    const long per = argc > 2 ? parse(argv[2], "STEPS_PER_PERIOD", 1, 1000000000, rank) : 200;
    const long periods = argc > 3 ? parse(argv[3], "PERIODS", 1, 1000000, rank) : 1;
    const long fail = argc > 4 ? parse(argv[4], "FAIL (an orbit index)", 0, n > 0 ? n - 1 : 0, rank) : -2;
    if (n < 0 || per < 0 || periods < 0 || fail == -1) {
        MPI_Finalize();
        return 2;
    }

    /* this rank's block of orbits */
    const long lo = (long)((long long)n * rank / size), hi = (long)((long long)n * (rank + 1) / size);
    const size_t m = (size_t)(hi - lo);
    double *t = calloc(m + 1, sizeof *t), *q = calloc(2 * m + 1, sizeof *q), *p = calloc(2 * m + 1, sizeof *p);
    double *mine = calloc(PACK * m + 1, sizeof *mine);
    int *status = calloc(m + 1, sizeof *status);
    unsigned long *steps = calloc(m + 1, sizeof *steps);
    if (!t || !q || !p || !mine || !status || !steps) {
        fprintf(stderr, "mpi_ensemble: rank %d: out of memory for %zu orbits\n", rank, m);
        MPI_Abort(MPI_COMM_WORLD, 1);
    }
    for (size_t j = 0; j < m; j++) {
        const double e = eccentricity(lo + (long)j, n);
        q[2 * j] = 1 - e;
        p[2 * j + 1] = sqrt((1 + e) / (1 - e));
        if (lo + (long)j == fail) q[2 * j] = NAN;
    }

    vigen_mechanical sys = { .dim = 2, .force = kepler_force };
    vigen_ensemble ens = { .type = &gauss2_type, .alloc = alloc_gauss2, .alloc_ctx = &sys, .dim = 2 };
    const double h = 2 * pi / (double)per;
    MPI_Barrier(MPI_COMM_WORLD);
    const double wall0 = MPI_Wtime();
    int rc = vigen_integrate_ensemble(&ens, m, t, q, p, h, (unsigned long)(per * periods), status, steps);
    if (rc == VIGEN_EINVAL || rc == VIGEN_ENOMEM) {
        fprintf(stderr, "mpi_ensemble: rank %d: %s\n", rank, vigen_strerror(rc));
        MPI_Abort(MPI_COMM_WORLD, 1);
    }
    for (size_t j = 0; j < m; j++) {
        double *o = mine + PACK * j;
        o[0] = t[j];
        o[1] = q[2 * j];
        o[2] = q[2 * j + 1];
        o[3] = p[2 * j];
        o[4] = p[2 * j + 1];
        o[5] = status[j];
        o[6] = (double)steps[j];
    }

    /* rank 0 gathers the blocks in rank order, which is the orbits' order */
    int *counts = NULL, *displs = NULL;
    double *all = NULL;
    if (rank == 0) {
        counts = malloc((size_t)size * sizeof *counts);
        displs = malloc((size_t)size * sizeof *displs);
        all = malloc((size_t)(PACK * n) * sizeof *all);
        if (!counts || !displs || !all) {
            fprintf(stderr, "mpi_ensemble: out of memory for %ld orbits\n", n);
            MPI_Abort(MPI_COMM_WORLD, 1);
        }
        for (int r = 0; r < size; r++) {
            const long rlo = (long)((long long)n * r / size), rhi = (long)((long long)n * (r + 1) / size);
            counts[r] = (int)(PACK * (rhi - rlo));
            displs[r] = (int)(PACK * rlo);
        }
    }
    MPI_Gatherv(mine, (int)(PACK * m), MPI_DOUBLE, all, counts, displs, MPI_DOUBLE, 0, MPI_COMM_WORLD);
    const double wall = MPI_Wtime() - wall0;

    if (rank == 0) {
        fprintf(stderr, "mpi_ensemble: %d rank(s), %d thread(s) per rank, %.3f s (integration and gathering)\n", size,
                vigen_ensemble_max_threads(), wall);
        double max_dh = 0, max_dist = 0;
        long failed = 0;
        printf("orbits %ld steps-per-period %ld periods %ld\n", n, per, periods);
        for (long i = 0; i < n; i++) {
            const double *o = all + PACK * i, e = eccentricity(i, n);
            printf("orbit %ld %.17g %d %.0f %.17g %.17g %.17g %.17g %.17g\n", i, e, (int)o[5], o[6], o[0], o[1], o[2],
                   o[3], o[4]);
            if ((int)o[5] != VIGEN_SUCCESS) {
                failed++;
                continue;
            }
            const double H = 0.5 * (o[3] * o[3] + o[4] * o[4]) - 1 / hypot(o[1], o[2]);
            const double dist = hypot(o[1] - (1 - e), o[2]);
            if (fabs(H + 0.5) > max_dh) max_dh = fabs(H + 0.5);
            if (dist > max_dist) max_dist = dist;
        }
        printf("max-energy-error %.3e\n", max_dh);
        printf("max-distance-to-start %.3e\n", max_dist);
        printf("failed %ld\n", failed);
    }
    free(counts);
    free(displs);
    free(all);
    free(t);
    free(q);
    free(p);
    free(mine);
    free(status);
    free(steps);
    MPI_Finalize();
    return 0;
}
