/* test_diagnostics.c — the problem checks of <vigen/diagnostics.h>, on
 * problems whose derivatives are known in closed form (Kepler, a harmonic
 * chain, the pendulum, a charged particle) with deliberate mistakes planted:
 * a sign error and a factor 2 are flagged naming their component (the factor
 * 2 with the relative mismatch 1/2 that the definition gives); a coupled H
 * marked separable is flagged; a wrong Hessian entry and a wrong second
 * derivative of a Lagrangian are flagged with their row and column; a NaN
 * gradient is reported; H = NULL is a skipped check.  Correct problems are
 * not flagged: Kepler and a harmonic chain rescaled (coordinates near 1e8,
 * masses near 1e-12, and a sweep of scales 1e-8 .. 1e8), every problem of the
 * collection at its initial value and at random states, Hamiltonian and
 * Lagrangian. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <vigen/diagnostics.h>
#include <vigen/problems.h>
#include "testlib.h"

/* ---- Kepler with scales: H = |p|^2/(2 m) - k m/|q| in the plane, with
 * mistakes to plant ------------------------------------------------------- */
enum { OK = 0, SIGN_Q1, FACTOR2_P0, TINY_P1, NAN_Q0, WRONG_HESS, COUPLED, TIME_IN_DHDP };

typedef struct {
    double m, k;      /* mass, gravitational parameter */
    int mistake;
    double C;         /* a constant added to T and taken away again: H loses its digits */
} kepler;

static double kep_H(double t, const double *q, const double *p, void *ctx)
{
    (void)t;
    const kepler *K = ctx;
    double T = (p[0] * p[0] + p[1] * p[1]) / (2 * K->m), V = -K->k * K->m / hypot(q[0], q[1]);
    if (K->mistake == COUPLED) T *= 1 + q[0] * q[0];
    return ((T + K->C) - K->C) + V;
}

static void kep_dHdq(double t, const double *q, const double *p, double *out, void *ctx)
{
    (void)t;
    const kepler *K = ctx;
    double r = hypot(q[0], q[1]), c = K->k * K->m / (r * r * r);
    out[0] = c * q[0];
    out[1] = c * q[1];
    if (K->mistake == COUPLED) out[0] += (p[0] * p[0] + p[1] * p[1]) / (2 * K->m) * 2 * q[0];
    if (K->mistake == SIGN_Q1) out[1] = -out[1];
    if (K->mistake == NAN_Q0) out[0] = NAN;
}

static void kep_dHdp(double t, const double *q, const double *p, double *out, void *ctx)
{
    const kepler *K = ctx;
    double f = K->mistake == COUPLED ? 1 + q[0] * q[0] : 1;
    out[0] = f * p[0] / K->m;
    out[1] = f * p[1] / K->m;
    if (K->mistake == FACTOR2_P0) out[0] *= 2;
    if (K->mistake == TINY_P1) out[1] *= 1 + 1e-6;
    /* a mass that changes with time, in a dH/dp promised to ignore t (H is
     * left as it is: only the separability promise is tested with it) */
    if (K->mistake == TIME_IN_DHDP) out[0] *= 1 + 0.01 * t;
}

/* rows (dH/dq, dH/dp), columns (q, p) */
static void kep_hess(double t, const double *q, const double *p, double *out, void *ctx)
{
    (void)t; (void)p;
    const kepler *K = ctx;
    double r = hypot(q[0], q[1]), c = K->k * K->m;
    memset(out, 0, 16 * sizeof *out);
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++) out[4 * i + j] = c * ((i == j) / (r * r * r) - 3 * q[i] * q[j] / pow(r, 5));
    out[4 * 2 + 2] = out[4 * 3 + 3] = 1 / K->m;
    if (K->mistake == WRONG_HESS) out[4 * 0 + 1] = -out[4 * 0 + 1];   /* d(dH/dq0)/dq1 */
}

static vigen_hamiltonian kepler_system(kepler *K, int hessian)
{
    return (vigen_hamiltonian){ .dim = 2, .dHdq = kep_dHdq, .dHdp = kep_dHdp, .H = kep_H, .ctx = K,
                                .separable = 1, .hessian = hessian ? kep_hess : NULL };
}

static int one_sentence(const char *s)
{
    size_t n = strlen(s);
    return n > 20 && n < 256 && strchr(s, '\n') == NULL;
}

static void test_kepler_mistakes(void)
{
    kepler K = { 1, 1, OK, 0 };
    vigen_hamiltonian sys = kepler_system(&K, 1);
    double q[2] = { 0.3, 0.5 }, p[2] = { -0.7, 0.4 };
    vigen_problem_report rep, rep2;
    CHECK_MSG(vigen_problem_check(&sys, 0, q, p, &rep) == VIGEN_SUCCESS, "%s", rep.message);
    CHECK(rep.gradient_checked && rep.second_checked && rep.points == 3);
    CHECK(rep.worst_rel_error < 1e-8 && one_sentence(rep.message));
    vigen_problem_check(&sys, 0, q, p, &rep2);   /* deterministic: the same report */
    CHECK(strcmp(rep.message, rep2.message) == 0 && rep.worst_rel_error == rep2.worst_rel_error);

    K.mistake = SIGN_Q1;
    CHECK(vigen_problem_check(&sys, 0, q, p, &rep) == VIGEN_EGRADIENT);
    CHECK_MSG(rep.worst_part == 0 && rep.worst_index == 1 && strstr(rep.message, "dH/dq[1]"), "%s", rep.message);
    CHECK(fabs(rep.worst_rel_error - 2) < 1e-6 && one_sentence(rep.message));   /* |-g - g| / |g| */
    printf("sign error: %s\n", rep.message);

    /* at the pericentre dH/dq[1] = 0: the sign error shows at the nearby points */
    double qa[2] = { 0.4, 0 }, pa[2] = { 0, 2 };
    CHECK(vigen_problem_check(&sys, 0, qa, pa, &rep) == VIGEN_EGRADIENT && rep.worst_index == 1 &&
          strstr(rep.message, "near the state"));

    K.mistake = FACTOR2_P0;
    CHECK(vigen_problem_check(&sys, 0, q, p, &rep) == VIGEN_EGRADIENT);
    CHECK_MSG(rep.worst_part == 1 && rep.worst_index == 0 && strstr(rep.message, "dH/dp[0]"), "%s", rep.message);
    CHECK(fabs(rep.worst_rel_error - 0.5) < 1e-6);   /* |2g - g| / |2g| */
    printf("factor 2: %s\n", rep.message);

    /* a relative error of 1e-6 is far above the differences' accuracy (p1
     * the largest momentum: the mismatch relative to it is 1e-6) */
    K.mistake = TINY_P1;
    double pt[2] = { -0.4, 0.7 };
    CHECK(vigen_problem_check(&sys, 0, q, pt, &rep) == VIGEN_EGRADIENT && rep.worst_part == 1 && rep.worst_index == 1);
    CHECK_MSG(fabs(rep.worst_rel_error - 1e-6) < 1e-8, "%g", rep.worst_rel_error);

    K.mistake = NAN_Q0;
    CHECK(vigen_problem_check(&sys, 0, q, p, &rep) == VIGEN_ENONFINITE);
    CHECK_MSG(rep.worst_part == 0 && rep.worst_index == 0 && strstr(rep.message, "dH/dq[0] is nan"), "%s", rep.message);

    K.mistake = WRONG_HESS;
    CHECK(vigen_problem_check(&sys, 0, q, p, &rep) == VIGEN_EHESSIAN);
    CHECK_MSG(rep.worst_part == 0 && rep.worst_index == 0 && rep.worst_column == 1 &&
              strstr(rep.message, "d(dH/dq[0])/dq[1]"), "%s", rep.message);
    CHECK(fabs(rep.worst_rel_error - 2) < 1e-6);
    printf("Hessian: %s\n", rep.message);

    /* H = |p|^2 (1 + q0^2)/2 - 1/|q| with correct gradients, marked separable */
    K.mistake = COUPLED;
    sys.hessian = NULL;
    CHECK(vigen_problem_check(&sys, 0, q, p, &rep) == VIGEN_ESEPARABLE);
    CHECK_MSG(strstr(rep.message, "marked separable") && one_sentence(rep.message), "%s", rep.message);
    printf("separable: %s\n", rep.message);
    sys.separable = 0;   /* honest: passes */
    CHECK_MSG(vigen_problem_check(&sys, 0, q, p, &rep) == VIGEN_SUCCESS, "%s", rep.message);

    /* dH/dp depending on t, marked separable (the gradient check needs an H
     * that matches: without H only finiteness and separability are checked) */
    K.mistake = TIME_IN_DHDP;
    sys = kepler_system(&K, 0);
    sys.H = NULL;
    CHECK(vigen_problem_check(&sys, 1, q, p, &rep) == VIGEN_ESEPARABLE && rep.worst_part == 1 &&
          rep.worst_index == 0 && strstr(rep.message, "t and q"));

    /* H not given: success, the message says the gradient check was skipped */
    K.mistake = OK;
    CHECK(vigen_problem_check(&sys, 0, q, p, &rep) == VIGEN_SUCCESS && !rep.gradient_checked);
    CHECK_MSG(strstr(rep.message, "skipped"), "%s", rep.message);
    K.mistake = SIGN_Q1;   /* cannot be seen without H */
    CHECK(vigen_problem_check(&sys, 0, q, p, &rep) == VIGEN_SUCCESS);

    /* bad arguments */
    CHECK(vigen_problem_check(NULL, 0, q, p, &rep) == VIGEN_EINVAL && one_sentence(rep.message));
    sys.dHdp = NULL;
    CHECK(vigen_problem_check(&sys, 0, q, p, &rep) == VIGEN_EINVAL && strstr(rep.message, "dHdp"));
    sys = kepler_system(&K, 0);
    double qn[2] = { 0.3, NAN };
    CHECK(vigen_problem_check(&sys, 0, qn, p, &rep) == VIGEN_EINVAL && strstr(rep.message, "q[1]"));
}

/* ---- badly scaled problems ---------------------------------------------- */
static void test_kepler_scaled(void)
{
    /* a body of mass 1e-12 at 1e8 from a centre with k = 1.3e20 (SI units
     * of the Sun): speed sqrt(k/r) ~ 1.1e6, momentum ~ 1e-6 */
    kepler K = { 1e-12, 1.327e20, OK, 0 };
    vigen_hamiltonian sys = kepler_system(&K, 1);
    double q[2] = { 1.0e8, 3.1e7 }, p[2] = { -3.0e-7, 1.2e-6 };
    vigen_problem_report rep;
    CHECK_MSG(vigen_problem_check(&sys, 0, q, p, &rep) == VIGEN_SUCCESS, "%s", rep.message);
    CHECK(rep.gradient_checked && rep.second_checked);
    K.mistake = SIGN_Q1;
    CHECK(vigen_problem_check(&sys, 0, q, p, &rep) == VIGEN_EGRADIENT && rep.worst_index == 1);
    K.mistake = FACTOR2_P0;
    CHECK(vigen_problem_check(&sys, 0, q, p, &rep) == VIGEN_EGRADIENT && rep.worst_part == 1);
    K.mistake = WRONG_HESS;
    CHECK(vigen_problem_check(&sys, 0, q, p, &rep) == VIGEN_EHESSIAN);

    /* the same orbit in units scaled by L (lengths), M (masses), S (time):
     * H is exact in every unit system, so no scale may be flagged */
    int flagged = 0;
    for (double L = 1e-8; L <= 1e8; L *= 100)
        for (double M = 1e-12; M <= 1e12; M *= 1e4) {
            double S = sqrt(L * L * L);   /* k scales as L^3 / S^2 */
            kepler Ks = { M, 1.0, OK, 0 };
            sys = kepler_system(&Ks, 1);
            double qs[2] = { 0.3 * L, 0.5 * L }, ps[2] = { -0.7 * M * L / S, 0.4 * M * L / S };
            if (vigen_problem_check(&sys, 0, qs, ps, &rep) != VIGEN_SUCCESS) {
                fprintf(stderr, "L = %g, M = %g: %s\n", L, M, rep.message);
                flagged++;
            }
        }
    CHECK(flagged == 0);

    /* H computed as ((T + C) - C) + V with C = 1e6 |H|: six digits of H are
     * lost to a cancellation that |H| and its terms do not show; the noise
     * measured (fourth differences of H) keeps the correct gradients from
     * being flagged, and a sign error is still found */
    kepler Kc = { 1, 1, OK, 0 };
    sys = kepler_system(&Kc, 0);
    double qc[2] = { 0.3, 0.5 }, pc[2] = { -0.7, 0.4 };
    Kc.C = 1e6 * fabs(kep_H(0, qc, pc, &Kc));
    CHECK_MSG(vigen_problem_check(&sys, 0, qc, pc, &rep) == VIGEN_SUCCESS, "%s", rep.message);
    Kc.mistake = SIGN_Q1;
    CHECK(vigen_problem_check(&sys, 0, qc, pc, &rep) == VIGEN_EGRADIENT && rep.worst_index == 1);
}

/* A harmonic chain of N masses m at positions q_i ~ i a with a = 1e8, springs
 * of stiffness c and rest length a: H = sum p_i^2/(2m) + c/2 sum (q_{i+1} -
 * q_i - a)^2 (free ends). */
enum { CHAIN = 12 };
typedef struct { double m, c, a; int mistake; } chain;

static double chain_H(double t, const double *q, const double *p, void *ctx)
{
    (void)t;
    const chain *C = ctx;
    double s = 0;
    for (int i = 0; i < CHAIN; i++) s += p[i] * p[i] / (2 * C->m);
    for (int i = 0; i + 1 < CHAIN; i++) {
        double d = q[i + 1] - q[i] - C->a;
        s += C->c / 2 * d * d;
    }
    return s;
}

static void chain_dHdq(double t, const double *q, const double *p, double *out, void *ctx)
{
    (void)t; (void)p;
    const chain *C = ctx;
    for (int i = 0; i < CHAIN; i++) {
        double left = i > 0 ? q[i] - q[i - 1] - C->a : 0, right = i + 1 < CHAIN ? q[i + 1] - q[i] - C->a : 0;
        out[i] = C->c * (left - right);
    }
    if (C->mistake) out[7] = -out[7];
}

static void chain_dHdp(double t, const double *q, const double *p, double *out, void *ctx)
{
    (void)t; (void)q;
    const chain *C = ctx;
    for (int i = 0; i < CHAIN; i++) out[i] = p[i] / C->m;
}

static void test_chain_scaled(void)
{
    chain C = { 1e-12, 3e-9, 1e8, 0 };
    vigen_hamiltonian sys = { .dim = CHAIN, .dHdq = chain_dHdq, .dHdp = chain_dHdp, .H = chain_H, .ctx = &C,
                              .separable = 1 };
    double q[CHAIN], p[CHAIN];
    for (int i = 0; i < CHAIN; i++) {
        q[i] = i * C.a + 1e3 * sin(1.7 * i);     /* displacements 1e3 on spacings 1e8 */
        p[i] = 1e-12 * 2e2 * cos(0.9 * i);      /* velocities ~ 2e2 */
    }
    vigen_problem_report rep;
    CHECK_MSG(vigen_problem_check(&sys, 0, q, p, &rep) == VIGEN_SUCCESS, "%s", rep.message);
    C.mistake = 1;
    CHECK(vigen_problem_check(&sys, 0, q, p, &rep) == VIGEN_EGRADIENT && rep.worst_part == 0 &&
          rep.worst_index == 7);
}

/* ---- the collection ------------------------------------------------------ */
static const char *const variants[][2] = {
    { "kepler", "e=0.95" }, { "pendulum", "amplitude=3.1" }, { "harmonic-oscillator", "omega=1000" },
    { "fput", "n=300,beta=3" }, { "point-vortices", "n=7,perturbation=0.2" }, { "henon-heiles", "energy=0.16" },
};

static void check_problem(const char *name, const char *params)
{
    vigen_problem *pb;
    char why[200];
    if (vigen_problem_create(&pb, name, params, why, sizeof why) != VIGEN_SUCCESS) {
        CHECK_MSG(0, "%s", why);
        return;
    }
    size_t n = vigen_problem_dim(pb);
    double t, *q = malloc(3 * n * sizeof *q), *p = q + n, *v = p + n;
    vigen_problem_initial(pb, &t, q, p);
    const vigen_hamiltonian *H = vigen_problem_hamiltonian(pb);
    vigen_problem_report rep;
    CHECK_MSG(vigen_problem_check(H, t, q, p, &rep) == VIGEN_SUCCESS, "%s %s: %s", name, params, rep.message);
    CHECK(rep.gradient_checked && one_sentence(rep.message));
    CHECK(rep.second_checked == (H->hessian != NULL && n <= 1024));
    printf("%s %s: %s\n", name, params, rep.message);
    /* random states around the initial value, 10 percent of each part's size */
    unsigned long long s = 12345;
    for (int trial = 0; trial < 20; trial++) {
        double sq = 0, sp = 0;
        vigen_problem_initial(pb, &t, q, p);
        for (size_t i = 0; i < n; i++) sq = fmax(sq, fabs(q[i])), sp = fmax(sp, fabs(p[i]));
        for (size_t i = 0; i < 2 * n; i++) {
            s = s * 6364136223846793005ULL + 1442695040888963407ULL;
            double u = (double)(s >> 11) / 9007199254740992.0 * 2 - 1;
            q[i] += 0.1 * u * (i < n ? sq : (sp > 0 ? sp : sq));
        }
        if (vigen_problem_check(H, t, q, p, &rep) != VIGEN_SUCCESS) {
            CHECK_MSG(0, "%s %s, random state %d: %s", name, params, trial, rep.message);
            break;
        }
    }
    vigen_lgrad_fn g = NULL;
    const vigen_lagrangian *L = vigen_problem_lagrangian(pb, &g);
    if (L) {
        vigen_problem_initial(pb, &t, q, p);
        g(t, q, p, v, L->ctx);
        CHECK_MSG(vigen_lagrangian_check(L, t, q, v, &rep) == VIGEN_SUCCESS, "%s %s (Lagrangian): %s", name, params,
                  rep.message);
        CHECK(rep.gradient_checked && rep.second_checked == (n <= 1024));
    }
    vigen_problem_free(pb);
    free(q);
}

/* fput with n = 300 (parts sampled) and one component's sign wrong, at
 * every position in turn among a few: flagged by the components compared or
 * along the random directions */
static const vigen_hamiltonian *fput_H;
static size_t fput_wrong;
static void fput_dHdq_wrong(double t, const double *q, const double *p, double *out, void *ctx)
{
    fput_H->dHdq(t, q, p, out, ctx);
    out[fput_wrong] = -out[fput_wrong];
}

static void test_sampled(void)
{
    vigen_problem *pb;
    if (vigen_problem_create(&pb, "fput", "n=300,beta=3", NULL, 0) != VIGEN_SUCCESS) {
        CHECK(0);
        return;
    }
    double t, q[300], p[300];
    vigen_problem_initial(pb, &t, q, p);
    for (int i = 0; i < 300; i++) p[i] = 0.3 * cos(0.1 * i);   /* moving */
    fput_H = vigen_problem_hamiltonian(pb);
    vigen_hamiltonian sys = *fput_H;
    sys.dHdq = fput_dHdq_wrong;
    vigen_problem_report rep;
    for (fput_wrong = 1; fput_wrong < 300; fput_wrong += 37) {
        CHECK_MSG(vigen_problem_check(&sys, t, q, p, &rep) == VIGEN_EGRADIENT, "component %zu: %s", fput_wrong,
                  rep.message);
        CHECK(rep.worst_part == -1 ? strstr(rep.message, "random direction") != NULL : rep.worst_index == fput_wrong);
    }
    printf("sampled: %s\n", rep.message);
    vigen_problem_free(pb);
}

static void test_collection(void)
{
    for (size_t i = 0; i < vigen_problem_count(); i++) check_problem(vigen_problem_info_at(i)->name, "");
    for (size_t i = 0; i < sizeof variants / sizeof variants[0]; i++) check_problem(variants[i][0], variants[i][1]);
}

/* ---- mechanical ---------------------------------------------------------- */
/* Kepler as V = -k/|q| with the force -k q/|q|^3 */
static double mech_V(double t, const double *q, void *ctx)
{
    (void)t;
    const kepler *K = ctx;
    return -K->k / hypot(q[0], q[1]);
}

static void mech_force(double t, const double *q, double *f, void *ctx)
{
    (void)t;
    const kepler *K = ctx;
    double r = hypot(q[0], q[1]), c = -K->k / (r * r * r);
    f[0] = c * q[0];
    f[1] = c * q[1];
    if (K->mistake == SIGN_Q1) f[1] = -f[1];
    if (K->mistake == FACTOR2_P0) f[0] *= 2;
    if (K->mistake == NAN_Q0) f[0] = NAN;
}

static void test_mechanical(void)
{
    kepler K = { 1, 1, OK, 0 };
    double im[2] = { 1e12, 1e12 };
    vigen_mechanical sys = { .dim = 2, .force = mech_force, .V = mech_V, .ctx = &K, .inv_mass = im };
    double q[2] = { 0.3, 0.5 };
    vigen_problem_report rep;
    CHECK_MSG(vigen_mechanical_check(&sys, 0, q, &rep) == VIGEN_SUCCESS, "%s", rep.message);
    CHECK(rep.gradient_checked && one_sentence(rep.message));
    K.mistake = SIGN_Q1;
    CHECK(vigen_mechanical_check(&sys, 0, q, &rep) == VIGEN_EGRADIENT);
    CHECK_MSG(rep.worst_part == 0 && rep.worst_index == 1 && strstr(rep.message, "force[1]") &&
              fabs(rep.worst_rel_error - 2) < 1e-6, "%s", rep.message);
    printf("force: %s\n", rep.message);
    K.mistake = FACTOR2_P0;
    CHECK(vigen_mechanical_check(&sys, 0, q, &rep) == VIGEN_EGRADIENT && rep.worst_index == 0 &&
          fabs(rep.worst_rel_error - 0.5) < 1e-6);
    K.mistake = NAN_Q0;
    CHECK(vigen_mechanical_check(&sys, 0, q, &rep) == VIGEN_ENONFINITE && strstr(rep.message, "force[0]"));
    K = (kepler){ 1, 1.327e20, OK, 0 };   /* scaled: positions near 1e8 */
    double qs[2] = { 1e8, -4e7 };
    CHECK_MSG(vigen_mechanical_check(&sys, 0, qs, &rep) == VIGEN_SUCCESS, "%s", rep.message);
    K.mistake = SIGN_Q1;
    CHECK(vigen_mechanical_check(&sys, 0, qs, &rep) == VIGEN_EGRADIENT && rep.worst_index == 1);
    sys.V = NULL;
    CHECK(vigen_mechanical_check(&sys, 0, qs, &rep) == VIGEN_SUCCESS && strstr(rep.message, "skipped"));
    im[1] = NAN;
    CHECK(vigen_mechanical_check(&sys, 0, qs, &rep) == VIGEN_EINVAL && strstr(rep.message, "inv_mass[1]"));
}

/* ---- Lagrangian: the pendulum L = m v^2/2 + m cos q, in a plane pair ------ */
typedef struct { double m; int mistake; } pend;

static double pend_L(double t, const double *q, const double *v, void *ctx)
{
    (void)t;
    const pend *P = ctx;
    return P->m * (v[0] * v[0] + v[1] * v[1]) / 2 + P->m * (cos(q[0]) + cos(q[1])) + P->m * q[0] * v[1];
}

static void pend_dLdq(double t, const double *q, const double *v, double *out, void *ctx)
{
    (void)t;
    const pend *P = ctx;
    out[0] = -P->m * sin(q[0]) + P->m * v[1];
    out[1] = -P->m * sin(q[1]);
    if (P->mistake == 3) out[0] = NAN;
}

static void pend_dLdv(double t, const double *q, const double *v, double *out, void *ctx)
{
    (void)t;
    const pend *P = ctx;
    out[0] = P->m * v[0];
    out[1] = P->m * (v[1] + q[0]);
    if (P->mistake == 1) out[1] *= 2;
}

static void pend_Lqq(double t, const double *q, const double *v, double *out, void *ctx)
{
    (void)t; (void)v;
    const pend *P = ctx;
    out[0] = -P->m * cos(q[0]);
    out[1] = out[2] = 0;
    out[3] = -P->m * cos(q[1]);
    if (P->mistake == 2) out[3] = -out[3];
}

static void pend_Lvv(double t, const double *q, const double *v, double *out, void *ctx)
{
    (void)t; (void)q; (void)v;
    const pend *P = ctx;
    out[0] = out[3] = P->m;
    out[1] = out[2] = 0;
}

static void pend_Lqv(double t, const double *q, const double *v, double *out, void *ctx)
{
    (void)t; (void)q; (void)v;
    const pend *P = ctx;
    out[0] = out[2] = out[3] = 0;
    out[1] = P->m;   /* d(dL/dq0)/dv1 */
    if (P->mistake == 4) out[1] = 0;
}

static void test_lagrangian(void)
{
    pend P = { 1e-12, 0 };
    vigen_lagrangian lag = { .dim = 2, .dLdq = pend_dLdq, .dLdv = pend_dLdv, .L = pend_L, .ctx = &P,
                             .d2Ldq2 = pend_Lqq, .d2Ldv2 = pend_Lvv, .d2Ldqdv = pend_Lqv };
    double q[2] = { 0.7, -2.1 }, v[2] = { 0, 0 };   /* at rest */
    vigen_problem_report rep;
    CHECK_MSG(vigen_lagrangian_check(&lag, 0, q, v, &rep) == VIGEN_SUCCESS, "%s", rep.message);
    CHECK(rep.gradient_checked && rep.second_checked && one_sentence(rep.message));
    P.mistake = 1;
    CHECK(vigen_lagrangian_check(&lag, 0, q, v, &rep) == VIGEN_EGRADIENT);
    CHECK_MSG(rep.worst_part == 1 && rep.worst_index == 1 && strstr(rep.message, "dL/dv[1]") &&
              fabs(rep.worst_rel_error - 0.5) < 1e-6, "%s", rep.message);
    P.mistake = 2;
    CHECK(vigen_lagrangian_check(&lag, 0, q, v, &rep) == VIGEN_EHESSIAN);
    CHECK_MSG(rep.worst_part == 0 && rep.worst_index == 1 && rep.worst_column == 1 &&
              strstr(rep.message, "d2Ldq2 entry d(dL/dq[1])/dq[1]"), "%s", rep.message);
    printf("Lagrangian: %s\n", rep.message);
    P.mistake = 4;
    CHECK(vigen_lagrangian_check(&lag, 0, q, v, &rep) == VIGEN_EHESSIAN);
    CHECK_MSG(rep.worst_part == 0 && rep.worst_index == 0 && rep.worst_column == 3 &&
              strstr(rep.message, "d2Ldqdv entry d(dL/dq[0])/dv[1]"), "%s", rep.message);
    P.mistake = 3;
    CHECK(vigen_lagrangian_check(&lag, 0, q, v, &rep) == VIGEN_ENONFINITE && strstr(rep.message, "dL/dq[0]"));
    P.mistake = 1;
    lag.L = NULL;   /* without L: the second derivatives still check the first */
    CHECK(vigen_lagrangian_check(&lag, 0, q, v, &rep) == VIGEN_EHESSIAN);
    lag.d2Ldq2 = lag.d2Ldv2 = lag.d2Ldqdv = NULL;
    CHECK(vigen_lagrangian_check(&lag, 0, q, v, &rep) == VIGEN_SUCCESS && strstr(rep.message, "skipped"));
    lag.dLdv = NULL;
    CHECK(vigen_lagrangian_check(&lag, 0, q, v, &rep) == VIGEN_EINVAL);
}

int main(void)
{
    test_kepler_mistakes();
    test_kepler_scaled();
    test_chain_scaled();
    test_collection();
    test_sampled();
    test_mechanical();
    test_lagrangian();
    TEST_MAIN_END();
}
