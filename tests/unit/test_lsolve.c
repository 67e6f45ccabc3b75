/* test_lsolve.c — the Newton solver shared by the Lagrangian integrators
 * (runtime/lagrangian/lsolve_internal.h): solutions of systems whose roots are
 * known in closed form, with the caller's Jacobian and with differences,
 * badly scaled equations, singular Jacobians, callbacks that fail or give
 * NaN (damped steps back into the finite region), divergence, the
 * iteration cap, and the statistics. */
#include <math.h>
#include <string.h>
#include <vigen/runtime.h>
#include "lsolve_internal.h"
#include "testlib.h"

/* circle x^2 + y^2 = 4 meets the diagonal x = y at (sqrt 2, sqrt 2) */
static int circ_r(const double *x, double *r, void *c)
{
    (void)c;
    r[0] = x[0] * x[0] + x[1] * x[1] - 4.0;
    r[1] = x[0] - x[1];
    return VIGEN_SUCCESS;
}
static int circ_J(const double *x, double *J, void *c)
{
    (void)c;
    J[0] = 2 * x[0]; J[1] = 2 * x[1];
    J[2] = 1.0;      J[3] = -1.0;
    return VIGEN_SUCCESS;
}

/* r(x) = A (x - xs) + (x - xs)^3 (componentwise cube): the root is xs */
static const double cub_A[9] = { 4, 1, -1, 2, 5, 1, -1, 0, 3 };
static const double cub_xs[3] = { 0.7, -1.3, 2.9 };
static int cub_r(const double *x, double *r, void *c)
{
    (void)c;
    for (int i = 0; i < 3; i++) {
        double d = x[i] - cub_xs[i];
        r[i] = d * d * d;
        for (int j = 0; j < 3; j++) r[i] += cub_A[3 * i + j] * (x[j] - cub_xs[j]);
    }
    return VIGEN_SUCCESS;
}

/* equations and unknowns in wildly different units: root (1e-12, 3e15) */
static int scaled_r(const double *x, double *r, void *c)
{
    (void)c;
    r[0] = 1e20 * (x[0] - 1e-12) + 1e-7 * (x[1] - 3e15) * 1e-15;
    r[1] = 1e-20 * (x[1] * x[1] / 3e15 - 3e15);
    return VIGEN_SUCCESS;
}

/* two equations that are one: the Jacobian has rank 1 */
static int sing_r(const double *x, double *r, void *c)
{
    (void)c;
    r[0] = x[0] + x[1] * x[1] - 1.0;
    r[1] = 2.0 * x[0] + 2.0 * x[1] * x[1] - 2.0;
    return VIGEN_SUCCESS;
}
/* the second unknown does not appear: a zero column */
static int zcol_r(const double *x, double *r, void *c)
{
    (void)c;
    r[0] = x[0] - 1.0;
    r[1] = x[0] * x[0] - 1.0;
    return VIGEN_SUCCESS;
}

/* NaN once x[0] leaves (-2, 2); the call counter lets a test stop later */
static int nan_r(const double *x, double *r, void *c)
{
    (void)c;
    r[0] = fabs(x[0]) < 2.0 ? x[0] - 5.0 : NAN;
    return VIGEN_SUCCESS;
}
/* sqrt(1 - x) = 1/2 at x = 3/4; Newton from -10 first jumps past x = 1,
 * where the square root is NaN, and must come back by damping */
static int sqrt_r(const double *x, double *r, void *c) { (void)c; r[0] = sqrt(1.0 - x[0]) - 0.5; return VIGEN_SUCCESS; }
static int fail_r(const double *x, double *r, void *c)
{
    int *calls = c;
    r[0] = x[0] - 1.0;
    return ++*calls >= 2 ? VIGEN_EUNSUPPORTED : VIGEN_SUCCESS;
}
/* Newton on atan from |x| > 1.39 runs away (the iterates alternate in sign
 * and grow) and converges from smaller |x| */
static int atan_r(const double *x, double *r, void *c) { (void)c; r[0] = atan(x[0]); return VIGEN_SUCCESS; }
/* Newton on the cube root doubles and flips x at every iteration: the
 * relative increment stays at 3/2 */
static int cbrt_r(const double *x, double *r, void *c) { (void)c; r[0] = cbrt(x[0]); return VIGEN_SUCCESS; }
static int cbrt_J(const double *x, double *J, void *c)
{
    (void)c;
    double a = cbrt(fabs(x[0]));
    J[0] = 1.0 / (3.0 * a * a);
    return VIGEN_SUCCESS;
}

static void test_solutions(void)
{
    vigen_lsolve *s = vigen_lsolve_alloc(2);
    CHECK(s != NULL && vigen_lsolve_dim(s) == 2);
    CHECK(vigen_lsolve_alloc(0) == NULL);
    vigen_stats st;
    for (int fd = 0; fd < 2; fd++) {
        memset(&st, 0, sizeof st);
        double x[2] = { 3.0, 0.5 };
        int rc = vigen_lsolve_run(s, x, circ_r, fd ? NULL : circ_J, NULL, NULL, &st);
        CHECK(rc == VIGEN_SUCCESS);
        CHECK_MSG(fabs(x[0] - sqrt(2.0)) < 4e-16 && fabs(x[1] - sqrt(2.0)) < 4e-16, "%.17g %.17g", x[0], x[1]);
        CHECK(st.iterations == st.last_iterations && st.last_iterations <= 10 && st.max_iterations == st.iterations);
        CHECK(st.hessian_evals >= 1 && st.lu_decompositions == st.hessian_evals);
        /* the Jacobian is kept once the iteration is fast: fewer than iterations */
        CHECK_MSG(st.hessian_evals < st.iterations, "%lu Jacobians, %lu iterations", st.hessian_evals, st.iterations);
    }
    /* statistics accumulate over runs */
    double x[2] = { 1.0, 2.0 };
    unsigned long before = st.iterations;
    CHECK(vigen_lsolve_run(s, x, circ_r, circ_J, NULL, NULL, &st) == VIGEN_SUCCESS);
    CHECK(st.iterations == before + st.last_iterations);
    /* badly scaled equations and unknowns */
    double y[2] = { 3e-12, 1e15 };
    CHECK(vigen_lsolve_run(s, y, scaled_r, NULL, NULL, NULL, NULL) == VIGEN_SUCCESS);
    CHECK_MSG(fabs(y[0] / 1e-12 - 1) < 1e-12 && fabs(y[1] / 3e15 - 1) < 1e-14, "%.17g %.17g", y[0], y[1]);
    vigen_lsolve_free(s);

    s = vigen_lsolve_alloc(3);
    for (int fd = 0; fd < 2; fd++) {
        double z[3] = { 0.0, 0.0, 0.0 };
        CHECK(vigen_lsolve_run(s, z, cub_r, NULL, NULL, NULL, NULL) == VIGEN_SUCCESS);
        for (int i = 0; i < 3; i++) CHECK_MSG(fabs(z[i] - cub_xs[i]) < 1e-15 * 4, "%d: %.17g", i, z[i]);
    }
    vigen_lsolve_free(s);
}

static void test_failures(void)
{
    vigen_lsolve *s = vigen_lsolve_alloc(2);
    vigen_stats st;
    memset(&st, 0, sizeof st);
    double x[2] = { 0.3, 0.4 };
    CHECK(vigen_lsolve_run(s, x, sing_r, NULL, NULL, NULL, &st) == VIGEN_ESINGULAR);
    x[0] = 0.3; x[1] = 0.4;
    CHECK(vigen_lsolve_run(s, x, zcol_r, NULL, NULL, NULL, &st) == VIGEN_ESINGULAR);
    x[0] = NAN;
    CHECK(vigen_lsolve_run(s, x, circ_r, circ_J, NULL, NULL, &st) == VIGEN_ENONFINITE);
    CHECK(vigen_lsolve_run(s, NULL, circ_r, circ_J, NULL, NULL, &st) == VIGEN_EINVAL);
    CHECK(vigen_lsolve_run(NULL, x, circ_r, circ_J, NULL, NULL, &st) == VIGEN_EINVAL);
    vigen_lsolve_free(s);

    s = vigen_lsolve_alloc(1);
    double z[1] = { 0.0 };
    /* the root x = 5 lies where the residual is NaN: every full step lands
     * there, the damped ones only approach the edge x = 2 until ten
     * halvings are not enough */
    vigen_stats st1;
    memset(&st1, 0, sizeof st1);
    CHECK(vigen_lsolve_run(s, z, nan_r, NULL, NULL, NULL, &st1) == VIGEN_ENONFINITE && st1.last_iterations > 1);
    /* NaN at the start */
    z[0] = 3.0;
    CHECK(vigen_lsolve_run(s, z, nan_r, NULL, NULL, NULL, &st1) == VIGEN_ENONFINITE && st1.last_iterations == 0);
    /* a step into the NaN region on the way to a root in the finite one */
    z[0] = -10.0;
    CHECK(vigen_lsolve_run(s, z, sqrt_r, NULL, NULL, NULL, NULL) == VIGEN_SUCCESS);
    CHECK_MSG(fabs(z[0] - 0.75) < 4e-16, "%.17g", z[0]);
    /* a callback's own status stops the solve and is returned */
    int calls = 0;
    z[0] = 0.0;
    CHECK(vigen_lsolve_run(s, z, fail_r, NULL, &calls, NULL, NULL) == VIGEN_EUNSUPPORTED);
    /* divergence: increments that stop decreasing far above tol */
    z[0] = 10.0;
    int rc = vigen_lsolve_run(s, z, cbrt_r, cbrt_J, NULL, NULL, NULL);
    CHECK_MSG(rc == VIGEN_ENOCONV, "status %d", rc);
    /* on atan the relative increments decrease towards 1 until 1 + x^2
     * overflows and the Jacobian (differences of atan, flat there) is 0 */
    z[0] = 10.0;
    rc = vigen_lsolve_run(s, z, atan_r, NULL, NULL, NULL, NULL);
    CHECK_MSG(rc == VIGEN_ESINGULAR, "status %d", rc);
    /* the iteration cap: from 1.3 Newton on atan converges, but not in 2 */
    vigen_solver_options o;
    vigen_solver_options_default(&o);
    o.max_iter = 2;
    z[0] = 1.3;
    memset(&st, 0, sizeof st);
    CHECK(vigen_lsolve_run(s, z, atan_r, NULL, NULL, &o, &st) == VIGEN_EMAXITER);
    CHECK(st.last_iterations == 2);
    o.max_iter = 0;
    z[0] = 1.3;
    CHECK(vigen_lsolve_run(s, z, atan_r, NULL, NULL, &o, &st) == VIGEN_SUCCESS && z[0] == 0.0);
    vigen_lsolve_free(s);
}

int main(void)
{
    test_solutions();
    test_failures();
    TEST_MAIN_END();
}
