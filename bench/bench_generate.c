/* bench_generate.c — time the generator in-process (no process start-up, no
 * file output): what `vigen generate` computes, vigen_galerkin_generate on a
 * spec and the certification of its order and symplecticity
 * (vigen_check_certify), repeated, median wall time.
 *
 *   bench_generate SPEC DIGITS     prints "<median seconds> <runs> <order>"
 *
 * Run by bench/run_generate.sh, which writes docs/benchmarks.md. */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include "method/galerkin.h"
#include "method/spec.h"
#include "vigen/check.h"

static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: bench_generate SPEC DIGITS\n");
        return 2;
    }
    long digits = strtol(argv[2], NULL, 10);
    vigen_error err;
    vigen_error_init(&err);
    vigen_spec *spec = NULL;
    if (vigen_spec_load(&spec, argv[1], NULL, &err) != VIGEN_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    double times[101];
    int runs = 0, order = -1;
    double total = 0;
    /* at least 3 runs and 1 s, fewer when one run takes seconds */
    while (runs < 101 && ((runs < 3 && total < 10.0) || total < 1.0)) {
        vigen_tableau t;
        double t0 = now();
        if (vigen_galerkin_generate(&t, spec, digits, &err) != VIGEN_OK ||
            vigen_check_certify(&t, argv[1], &err) != VIGEN_OK) {
            fprintf(stderr, "%s\n", err.message);
            return 1;
        }
        times[runs] = now() - t0;
        order = t.claim_order;
        total += times[runs++];
        vigen_tableau_clear(&t);
    }
    qsort(times, (size_t)runs, sizeof(double), cmp);
    printf("%.6f %d %d\n", times[runs / 2], runs, order);
    vigen_spec_free(spec);
    flint_cleanup();
    return 0;
}
