/* testlib.h — the few assertions the unit tests need.
 * A failed check prints file:line and the condition and makes the test fail;
 * the test keeps going so that one run shows every failure. */
#ifndef VIGEN_TESTLIB_H
#define VIGEN_TESTLIB_H

#include <stdio.h>
#include <arb.h>

static int testlib_failures = 0;

#define CHECK(cond) do { if (!(cond)) { \
    fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
    testlib_failures++; } } while (0)

#define CHECK_MSG(cond, ...) do { if (!(cond)) { \
    fprintf(stderr, "%s:%d: check failed: %s: ", __FILE__, __LINE__, #cond); \
    fprintf(stderr, __VA_ARGS__); fputc('\n', stderr); testlib_failures++; } } while (0)

/* |x - y| <= 10^-digits * max(1, |y|), certified (the ball of x - y lies inside). */
static inline int testlib_arb_close(const arb_t x, const arb_t y, slong digits, slong prec)
{
    arb_t d, tol, one;
    arb_init(d); arb_init(tol); arb_init(one);
    arb_sub(d, x, y, prec);
    arb_abs(d, d);
    arb_abs(tol, y);
    arb_one(one);
    arb_max(tol, tol, one, prec);
    arb_t p; arb_init(p);
    arb_ui_pow_ui(p, 10, (ulong)digits, prec);
    arb_div(tol, tol, p, prec);
    int ok = arb_lt(d, tol);
    arb_clear(p); arb_clear(d); arb_clear(tol); arb_clear(one);
    return ok;
}

#define CHECK_CLOSE(x, y, digits, prec) do { if (!testlib_arb_close((x), (y), (digits), (prec))) { \
    fprintf(stderr, "%s:%d: not equal to %ld digits: ", __FILE__, __LINE__, (long)(digits)); \
    arb_fprintd(stderr, (x), 50); fputs("  vs  ", stderr); arb_fprintd(stderr, (y), 50); \
    fputc('\n', stderr); testlib_failures++; } } while (0)

#define TEST_MAIN_END() do { flint_cleanup(); \
    if (testlib_failures) { fprintf(stderr, "%d check(s) failed\n", testlib_failures); return 1; } \
    printf("ok\n"); return 0; } while (0)

#endif
