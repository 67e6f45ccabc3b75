/* python_overhead.c — the stepper module of a vigen.Stepper driven from C,
 * the reference of bench/python_bench.py for the cost Python adds per step.
 *
 * Compiled by python_bench.py in the module's cache folder, against the
 * module's own C text (vigen_module.c: the emitted stepper and its force),
 * with the module's compiler flags, so that the steps are the same code:
 *
 *   python_overhead KIND NSTEPS EVERY REPS
 *
 * KIND 0: Kepler e = 0.6 through the force compiled into the module (C
 * source), 1: through the problem collection (problem="kepler").  Runs
 * vigen_integrate REPS times from the pericentre, h = 2 pi / 200, recording
 * the state every EVERY steps into arrays allocated for the run (0: no
 * observer), as the Python side does (it returns new arrays), and prints the smallest and the median wall time of one run
 * in seconds. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include "vigen_module.c"

typedef struct {
    size_t next;
    double *t, *q, *p;
} record;

static int observe(unsigned long step, double t, const double *q, const double *p, void *ctx)
{
    (void)step;
    record *r = ctx;
    r->t[r->next] = t;
    memcpy(r->q + 2 * r->next, q, 2 * sizeof *q);
    memcpy(r->p + 2 * r->next, p, 2 * sizeof *p);
    r->next++;
    return 0;
}

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);  /* CPU time: the shared machine's load counts less */
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv)
{
    if (argc != 5) {
        fprintf(stderr, "usage: python_overhead KIND NSTEPS EVERY REPS\n");
        return 2;
    }
    int kind = atoi(argv[1]), reps = atoi(argv[4]);
    unsigned long nsteps = strtoul(argv[2], NULL, 10), every = strtoul(argv[3], NULL, 10);
    void *pb = NULL, *w;
    if (kind == 1) {
        char why[200];
        if (vpy_problem_create(&pb, "kepler", "e=0.6", why, sizeof why) != 0) return 1;
        w = vpy_problem_alloc(pb, NULL);
    } else w = vpy_alloc_mechanical(2, NULL, NULL, NULL, NULL);
    size_t rows = every ? nsteps / every + 2 : 0;
    double *times = malloc(reps * sizeof *times);
    for (int r = 0; r < reps; r++) {
        double t = 0, q[2] = { 0.4, 0.0 }, p[2] = { 0.0, 2.0 };
        double t0 = now();
        record rec = { 0, malloc((rows + 1) * sizeof(double)), malloc(2 * (rows + 1) * sizeof(double)),
                       malloc(2 * (rows + 1) * sizeof(double)) };
        const vigen_stepper_type *T = vpy_type();
        T->reset(w);
        int rc = vigen_integrate(T, w, &t, q, p, 6.283185307179586 / 200, nsteps, every,
                                 every ? observe : NULL, &rec, NULL);
        free(rec.t);
        free(rec.q);
        free(rec.p);
        times[r] = now() - t0;
        if (rc != 0) return 1;
    }
    qsort(times, reps, sizeof *times, cmp);
    printf("%.9g %.9g\n", times[0], times[reps / 2]);
    vstep_free(w);
    if (pb) vpy_problem_free(pb);
    return 0;
}
