/* test_try.c — the parts of the try module (src/try) that compute without
 * running a compiler: the least-squares drift against closed forms, the
 * options of the command line and their messages, gnuplot quoting, the plan
 * of a run (steps from the period); and a run of two methods (with the
 * system compiler, as `vigen try` does) on the harmonic oscillator against
 * closed forms: Gauss s = 2 is the (2,2) Pade approximant of exp, whose
 * error is z^5 / 720 + O(z^6) (Hairer-Wanner, Solving ODEs II, IV.3), so its
 * phase error at t is t h^4 / 720; Stormer-Verlet conserves exactly the
 * modified energy p^2/2 + (1 - h^2/4) q^2/2, so its relative energy error
 * oscillates with amplitude h^2/4.  The built-in Lagrangian integrators:
 * the registry and the refusal of a problem without a Lagrangian, and a run
 * on the oscillator, where hp-midpoint is the implicit midpoint rule (the
 * (1,1) Pade approximant of exp, error z^3/12: phase error t h^2/12; a
 * quadratic invariant, the energy, conserved) and hp-trapezoidal is
 * Stormer-Verlet (energy error amplitude h^2/4). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "testlib.h"
#include "try/try_internal.h"
#include "vigen/try.h"

static void test_slope(void)
{
    /* y = 3 - 2 x exactly: slope -2 */
    double x[101], y[101];
    for (int i = 0; i <= 100; i++) {
        x[i] = 1e6 + 0.5 * i;  /* a large offset: naive sums of x^2 would lose the slope */
        y[i] = 3 - 2 * (x[i] - 1e6);
    }
    CHECK(fabs(try_lsq_slope(x, y, 101) + 2) < 1e-9);
    /* symmetric alternating noise around a line does not change the slope:
     * sum (x - mean)(+-e) over symmetric pairs cancels for this design */
    for (int i = 0; i <= 100; i++) y[i] = 0.25 * x[i] + ((i % 2) ? 1e-3 : -1e-3) * (i == 50 ? 0 : 1);
    double s = try_lsq_slope(x, y, 101);
    CHECK_MSG(fabs(s - 0.25) < 1e-5, "slope %g", s);
    CHECK(isnan(try_lsq_slope(x, y, 1)));
    /* a constant: slope 0 */
    for (int i = 0; i <= 100; i++) y[i] = 7;
    CHECK(try_lsq_slope(x, y, 101) == 0);
}

static void test_options(void)
{
    vigen_error err;
    vigen_error_init(&err);
    vigen_try_options o;
    CHECK(vigen_try_options_set(&o, "kepler", "e=0.9\nn=3", "0.01", NULL, "50", &err) == VIGEN_OK);
    CHECK(strcmp(o.params, "e=0.9,n=3") == 0 && o.h == 0.01 && o.time == 50 && o.steps_per_period == 0);
    free((char *)o.params);
    CHECK(vigen_try_options_set(&o, "kepler", NULL, "-1", NULL, NULL, &err) == VIGEN_E_USAGE);
    CHECK(err.message && strstr(err.message, "--h takes a positive number"));
    vigen_error_clear(&err);
    CHECK(vigen_try_options_set(&o, "kepler", NULL, "nan", NULL, NULL, &err) == VIGEN_E_USAGE);
    vigen_error_clear(&err);
    CHECK(vigen_try_options_set(&o, "kepler", NULL, NULL, "0", NULL, &err) == VIGEN_E_USAGE);
    CHECK(err.message && strstr(err.message, "--steps-per-period"));
    vigen_error_clear(&err);
    CHECK(vigen_try_options_set(&o, "kepler", NULL, "0.1", "10", NULL, &err) == VIGEN_E_USAGE);
    vigen_error_clear(&err);
    CHECK(vigen_try_options_set(&o, "kepler", NULL, NULL, "10", "1e400", &err) == VIGEN_E_USAGE);
    vigen_error_clear(&err);
}

static void test_quote(void)
{
    char *q = try_gnuplot_quote("a\"b\\c,d\ne");
    CHECK(strcmp(q, "a_b_c_d_e") == 0);
    free(q);
}

static void test_plan(void)
{
    vigen_error err;
    vigen_error_init(&err);
    vigen_try_options o = { .problem = "harmonic-oscillator", .params = "omega=2", .time = 10 };
    try_plan plan;
    CHECK(try_plan_make(&plan, &o, 0, &err) == VIGEN_OK);
    /* period 2 pi / omega = pi; 100 steps per period */
    CHECK(fabs(plan.period - M_PI) < 1e-14 && fabs(plan.h - M_PI / 100) < 1e-15);
    CHECK(plan.steps == (unsigned long)ceil(10 / (M_PI / 100)) && plan.has_reference);
    o.problem = "harmonic-oscilator";
    CHECK(try_plan_make(&plan, &o, 0, &err) == VIGEN_E_USAGE);
    CHECK(err.message && strstr(err.message, "harmonic-oscilator"));
    vigen_error_clear(&err);
    o.problem = "harmonic-oscillator";
    o.params = "omega=-1";
    CHECK(try_plan_make(&plan, &o, 0, &err) == VIGEN_E_USAGE);
    vigen_error_clear(&err);
    o.params = NULL;
    o.h = 1e-12;
    o.time = 1e6;
    CHECK(try_plan_make(&plan, &o, 0, &err) == VIGEN_E_USAGE);
    CHECK(err.message && strstr(err.message, "too many"));
    vigen_error_clear(&err);
}

/* Runs need the system compiler, as `vigen try` does. */
static void test_run(void)
{
    vigen_error err;
    vigen_error_init(&err);
    const char *methods[] = { "tableaux/published/gauss_2.lua", "stormer_verlet_velocity" };
    vigen_try_options o = { .problem = "harmonic-oscillator", .h = 0.1, .time = 10 };
    vigen_try_result *r = NULL;
    int rc = vigen_try_run(2, methods, &o, &r, &err);
    CHECK_MSG(rc == VIGEN_OK, "%s", err.message ? err.message : "");
    if (rc != VIGEN_OK) return;
    CHECK(strcmp(r[0].label, "gauss_2") == 0 && strcmp(r[1].label, "stormer_verlet_velocity") == 0);
    CHECK(r[0].steps == 100 && fabs(r[0].t_end - 10) < 1e-12 && r[0].has_reference);
    /* Gauss s = 2 on q'' = -q: the phase error per unit time is h^4/720 (the
     * leading term of the error of the (2,2) Pade approximant of exp(i h)),
     * so the global error at t is about t h^4 / 720 per unit amplitude */
    double want = 10 * pow(0.1, 4) / 720;
    CHECK_MSG(fabs(r[0].global_error / want - 1) < 0.05, "Gauss-2 global error %g, expected %g", r[0].global_error, want);
    /* Gauss methods conserve quadratic invariants: the energy here */
    CHECK_MSG(r[0].energy_max < 1e-13, "Gauss-2 energy error %g", r[0].energy_max);
    /* Stormer-Verlet conserves the modified energy H + O(h^2): the energy
     * error of q'' = -q oscillates with amplitude h^2/4 relative (exactly:
     * the shadow Hamiltonian p^2/2 + (1 - h^2/4) q^2/2) */
    CHECK_MSG(fabs(r[1].energy_max / (0.01 / 4) - 1) < 0.05, "Verlet energy error %g", r[1].energy_max);
    /* the oscillator is mechanical: stepped in Nystrom form, velocity Verlet
     * (kick-drift-kick) costs one force per step, the last force of a step
     * being the first of the next: 100 steps, 101 forces */
    CHECK(r[0].path && strcmp(r[0].path, "mechanical") == 0 && r[1].path && strcmp(r[1].path, "mechanical") == 0);
    CHECK_MSG(fabs(r[1].grad_per_step - 1.01) < 1e-9, "Verlet forces per step %g", r[1].grad_per_step);
    CHECK(r[0].nsamples == 101 && r[0].ts[0] == 0 && r[0].energy[0] == 0);
    CHECK(r[0].norbit == 101 && r[0].x[0] == 1 && r[0].y[0] == 0);
    vigen_try_results_free(r, 2);
    /* a charged particle in a magnetic field (H not separable) is not
     * mechanical: the general path, dH/dq and dH/dp */
    vigen_try_options c = { .problem = "charged-particle", .h = 0.05, .time = 1 };
    rc = vigen_try_run(1, methods, &c, &r, &err);
    CHECK_MSG(rc == VIGEN_OK, "%s", err.message ? err.message : "");
    if (rc != VIGEN_OK) return;
    CHECK(r[0].path && strcmp(r[0].path, "general") == 0 && r[0].grad_per_step > 2);
    vigen_try_results_free(r, 1);
}

static void test_lagrangian(void)
{
    const char *names[] = { "hp-trapezoidal", "hp-midpoint", "midpoint-vi", "trapezoidal-vi" };
    int seen = 0;
    for (size_t k = 0; k < 4; k++) {
        const try_lagrangian_method *m = try_lagrangian_find(names[k]);
        CHECK_MSG(m && m->order == 2 && m->description && *m->description, "%s", names[k]);
        if (m && m->kind >= 0 && m->kind < 4) seen |= 1 << m->kind;
        CHECK(try_lagrangian_name(k) != NULL);
    }
    CHECK(seen == 15 && try_lagrangian_name(4) == NULL);
    CHECK(try_lagrangian_find("gauss_1") == NULL && try_lagrangian_find(NULL) == NULL);

    vigen_error err;
    vigen_error_init(&err);
    const char *methods[] = { "hp-midpoint", "hp-trapezoidal" };
    vigen_try_options pv = { .problem = "point-vortices" };
    CHECK(try_lagrangian_check(2, methods, &pv, &err) == VIGEN_E_USAGE);
    CHECK_MSG(err.message && strstr(err.message, "hp-midpoint") && strstr(err.message, "point-vortices"), "%s",
              err.message ? err.message : "");
    vigen_error_clear(&err);
    const char *tableau[] = { "gauss_1" };
    CHECK(try_lagrangian_check(1, tableau, &pv, &err) == VIGEN_OK);

    vigen_try_options o = { .problem = "harmonic-oscillator", .h = 0.1, .time = 10 };
    vigen_try_result *r = NULL;
    int rc = vigen_try_run(2, methods, &o, &r, &err);
    CHECK_MSG(rc == VIGEN_OK, "%s", err.message ? err.message : "");
    if (rc != VIGEN_OK) return;
    CHECK(strcmp(r[0].label, "hp-midpoint") == 0 && r[0].steps == 100 && !r[0].failed);
    double want = 10 * 0.01 / 12;
    CHECK_MSG(fabs(r[0].global_error / want - 1) < 0.05, "hp-midpoint global error %g, expected %g",
              r[0].global_error, want);
    CHECK_MSG(r[0].energy_max < 1e-13, "hp-midpoint energy error %g", r[0].energy_max);
    CHECK_MSG(fabs(r[1].energy_max / (0.01 / 4) - 1) < 0.05, "hp-trapezoidal energy error %g", r[1].energy_max);
    CHECK(r[0].grad_per_step > 0 && r[1].grad_per_step > 0);
    vigen_try_results_free(r, 2);
}

int main(void)
{
    test_slope();
    test_options();
    test_quote();
    test_plan();
    test_run();
    test_lagrangian();
    return testlib_failures ? 1 : 0;
}
