/* bench_check.c — time the checker in-process: vigen_check_tableau on one
 * tableau file, orders <= P, at the starting precision the checker picks
 * (>= 128 bits), repeated; prints "<median seconds> <runs> <order> <conditions>".
 *
 *   bench_check FILE P
 *
 * Run by bench/run_check.sh, which writes docs/benchmarks.md. */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include "vigen/check.h"
#include "vigen/method.h"

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
        fprintf(stderr, "usage: bench_check FILE P\n");
        return 2;
    }
    vigen_check_options opt;
    vigen_check_options_init(&opt);
    opt.path = argv[1];
    opt.max_order = atoi(argv[2]);
    vigen_error err;
    vigen_error_init(&err);
    double times[51];
    int runs = 0, order = -1;
    long conditions = 0;
    double total = 0;
    while (runs < 51 && (runs < 3 || total < 1.0)) {
        vigen_tableau t;
        if (vigen_source_load(&t, argv[1], 34, &err) != VIGEN_OK) {
            fprintf(stderr, "%s\n", err.message);
            return 1;
        }
        vigen_check_report rep;
        vigen_check_report_init(&rep);
        double t0 = now();
        if (vigen_check_tableau(&rep, &t, NULL, &opt, &err) != VIGEN_OK) {
            fprintf(stderr, "%s\n", err.message);
            return 1;
        }
        times[runs] = now() - t0;
        total += times[runs++];
        order = rep.orders[VIGEN_CHECK_GENERAL].level.value;
        conditions = 0;
        /* the conditions evaluated: those that follow by symplecticity are not */
        for (int p = 1; p <= rep.orders[VIGEN_CHECK_GENERAL].evaluated_to; p++)
            conditions += rep.orders[VIGEN_CHECK_GENERAL].count[p] - rep.orders[VIGEN_CHECK_GENERAL].inferred[p];
        vigen_check_report_clear(&rep);
        vigen_tableau_clear(&t);
    }
    qsort(times, (size_t)runs, sizeof(double), cmp);
    printf("%.6f %d %d %ld\n", times[runs / 2], runs, order, conditions);
    flint_cleanup();
    return 0;
}
