/* test_restart_lagrangian.c — saved states of the Lagrangian integrators
 * (vigen_hp_state_*, vigen_midpoint_vi_state_*, vigen_trapezoidal_vi_state_*):
 * a run saved after K steps and continued in a fresh integrator is the
 * uninterrupted run bit for bit.
 *
 * The problem: DIM coupled pendulums of masses m_k = 1 + k/10 in a
 * magnetic-like field B = 0.7 (velocity coupling, so that every block of
 * second derivatives is nonzero; B = 0 and rotating pendulums with the
 * chord map, whose parameter equation needs (q1 - q0).p > 0),
 *   L = sum_k m_k v_k^2 / 2 + B/2 (q_0 v_1 - q_1 v_0) - sum_k (1 - cos q_k)
 *       - sum_k (q_{k+1} - q_k)^2 / 2,
 * with its exact second derivatives or without them (finite differences),
 * and the inverse Legendre map v_k = (p_k - A_k(q)) / m_k for the mid-point
 * integrator.  Steps of 0.0371 (not a power of two).  Asserted, with the
 * uninterrupted run as the truth:
 *   - t, q, p and every counter of vigen_stats equal (memcmp), and for HP
 *     the velocity v_{n+1/2} and the velocity-map parameters too, for both
 *     rules, with exact and difference Jacobians, compensated or not,
 *     extrapolating or not, with the trivial map and with a map with a
 *     parameter (tests/data/lagrangian/chord_map.h), and with the Newton
 *     solve cut at two iterations (so that the predictor, from the saved
 *     velocities and step sizes, decides every bit); state_get right after
 *     state_set gives the same bytes;
 *   - the state matters: without it the compensated runs end elsewhere;
 *   - another integrator, rule, dimension, number of parameters or options,
 *     a changed format number (checksum recomputed here from the documented
 *     FNV-1a 64), any single flipped byte and a truncated buffer give
 *     VIGEN_ESTATE and leave the integrator unchanged; NULL is VIGEN_EINVAL;
 *     the trapezoidal variational integrator's state is its HP stepper's. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <vigen/lagrangian.h>
#include "testlib.h"
#include "../data/lagrangian/chord_map.h"

enum { N = 50, K = 19, MAXDIM = 4 };
static const double H = 0.0371;
static double B = 0.7;   /* 0 with the chord map, whose parameter needs (q1 - q0).p > 0 */
static size_t dim = 3;

static double mass(size_t k) { return 1.0 + (double)k / 10.0; }

static void dLdq(double t, const double *q, const double *v, double *out, void *ctx)
{
    (void)t; (void)ctx;
    for (size_t k = 0; k < dim; k++) {
        double left = k > 0 ? q[k] - q[k - 1] : 0, right = k + 1 < dim ? q[k + 1] - q[k] : 0;
        out[k] = -sin(q[k]) + right - left;
    }
    out[0] += 0.5 * B * v[1];
    out[1] -= 0.5 * B * v[0];
}

static void dLdv(double t, const double *q, const double *v, double *out, void *ctx)
{
    (void)t; (void)ctx;
    for (size_t k = 0; k < dim; k++) out[k] = mass(k) * v[k];
    out[0] -= 0.5 * B * q[1];
    out[1] += 0.5 * B * q[0];
}

static void d2Ldq2(double t, const double *q, const double *v, double *out, void *ctx)
{
    (void)t; (void)v; (void)ctx;
    memset(out, 0, dim * dim * sizeof *out);
    for (size_t k = 0; k < dim; k++) {
        out[k * dim + k] = -cos(q[k]) - (k > 0) - (k + 1 < dim);
        if (k + 1 < dim) out[k * dim + k + 1] = out[(k + 1) * dim + k] = 1.0;
    }
}

static void d2Ldv2(double t, const double *q, const double *v, double *out, void *ctx)
{
    (void)t; (void)q; (void)v; (void)ctx;
    memset(out, 0, dim * dim * sizeof *out);
    for (size_t k = 0; k < dim; k++) out[k * dim + k] = mass(k);
}

static void d2Ldqdv(double t, const double *q, const double *v, double *out, void *ctx)
{
    (void)t; (void)q; (void)v; (void)ctx;
    memset(out, 0, dim * dim * sizeof *out);
    out[0 * dim + 1] = 0.5 * B;
    out[1 * dim + 0] = -0.5 * B;
}

/* the inverse Legendre map: dL/dv(t, q, v) = p */
static void legendre_inverse(double t, const double *q, const double *p, double *v, void *ctx)
{
    (void)t; (void)ctx;
    for (size_t k = 0; k < dim; k++) v[k] = p[k];
    v[0] += 0.5 * B * q[1];
    v[1] -= 0.5 * B * q[0];
    for (size_t k = 0; k < dim; k++) v[k] /= mass(k);
}

/* ---- the integrators behind one interface --------------------------------- */

enum { HP, MVI, TVI };
typedef struct {
    int kind, rule, exact, kahan, extrap, chord;
    size_t dim;
    const char *what;
    int truncated;   /* two Newton iterations to a tolerance of 1e-6: the predictor shows in every bit */
} config;

static double chord_c[CHORD_DIM] = { 0.3, -0.2 };

static void *make(const config *c)
{
    dim = c->dim;
    B = c->chord ? 0.0 : 0.7;
    vigen_lagrangian lag = { c->dim, dLdq, dLdv, NULL, NULL, NULL, NULL, NULL };
    if (c->exact) {
        lag.d2Ldq2 = d2Ldq2;
        lag.d2Ldv2 = d2Ldv2;
        lag.d2Ldqdv = d2Ldqdv;
    }
    vigen_solver_options opt;
    vigen_solver_options_default(&opt);
    opt.kahan = c->kahan;
    opt.extrapolate = c->extrap;
    if (c->truncated) {
        opt.max_iter = 2;
        opt.tol = 1e-6;
    }
    static const double a0[1] = { 0.0 };
    vigen_velocity_map chord = { CHORD_DIM, 1, chord_phi, chord_D1, chord_D2, chord_Da, a0, chord_c };
    switch (c->kind) {
    case HP: return vigen_hp_alloc(&lag, c->rule, c->chord ? &chord : NULL, &opt);
    case MVI: return vigen_midpoint_vi_alloc(&lag, legendre_inverse, &opt);
    default: return vigen_trapezoidal_vi_alloc(&lag, &opt);
    }
}

static int step(const config *c, void *w, double *t, double *q, double *p)
{
    dim = c->dim;
    B = c->chord ? 0.0 : 0.7;
    switch (c->kind) {
    case HP: return vigen_hp_step(w, t, q, p, H);
    case MVI: return vigen_midpoint_vi_step(w, t, q, p, H);
    default: return vigen_trapezoidal_vi_step(w, t, q, p, H);
    }
}

static size_t state_size(const config *c, const void *w)
{
    return c->kind == HP ? vigen_hp_state_size(w) : c->kind == MVI ? vigen_midpoint_vi_state_size(w)
                                                                   : vigen_trapezoidal_vi_state_size(w);
}

static int state_get(const config *c, const void *w, void *buf)
{
    return c->kind == HP ? vigen_hp_state_get(w, buf) : c->kind == MVI ? vigen_midpoint_vi_state_get(w, buf)
                                                                       : vigen_trapezoidal_vi_state_get(w, buf);
}

static int state_set(const config *c, void *w, const void *buf)
{
    return c->kind == HP ? vigen_hp_state_set(w, buf) : c->kind == MVI ? vigen_midpoint_vi_state_set(w, buf)
                                                                       : vigen_trapezoidal_vi_state_set(w, buf);
}

static const vigen_stats *stats(const config *c, const void *w)
{
    return c->kind == HP ? vigen_hp_stats(w) : c->kind == MVI ? vigen_midpoint_vi_stats(w)
                                                              : vigen_trapezoidal_vi_stats(w);
}

static void destroy(const config *c, void *w)
{
    if (c->kind == HP) vigen_hp_free(w);
    else if (c->kind == MVI) vigen_midpoint_vi_free(w);
    else vigen_trapezoidal_vi_free(w);
}

/* ---- runs ------------------------------------------------------------------ */

typedef struct { double t, q[MAXDIM], p[MAXDIM], v[MAXDIM], a; vigen_stats st; } snapshot;

static void start(const config *c, double *t, double *q, double *p)
{
    *t = 0.0;
    for (size_t k = 0; k < c->dim; k++) {
        q[k] = 0.5 + 0.1 * (double)k;
        /* with the chord map: rotating pendulums, whose kinetic energy stays away from 0 */
        p[k] = (c->chord ? 2.5 : 0.6) - 0.05 * (double)k;
    }
}

static int run(const config *c, void *w, double *t, double *q, double *p, int steps)
{
    for (int i = 0; i < steps; i++) {
        int st = step(c, w, t, q, p);
        if (st != VIGEN_SUCCESS) return st;
    }
    return VIGEN_SUCCESS;
}

static void take(const config *c, snapshot *s, const void *w, double t, const double *q, const double *p)
{
    memset(s, 0, sizeof *s);
    s->t = t;
    memcpy(s->q, q, c->dim * sizeof *q);
    memcpy(s->p, p, c->dim * sizeof *p);
    s->st = *stats(c, w);
    if (c->kind == HP) {
        memcpy(s->v, vigen_hp_velocity(w), c->dim * sizeof *q);
        if (vigen_hp_nparams(w)) s->a = vigen_hp_params(w)[0];
    }
}

/* The state of w after K steps from the start (heap; *size its bytes), with
 * t, q, p there. */
static unsigned char *saved_after_k(const config *c, size_t *size, double *t, double *q, double *p)
{
    void *w = make(c);
    start(c, t, q, p);
    int st = run(c, w, t, q, p, K);
    CHECK_MSG(st == VIGEN_SUCCESS, "%s: a step failed (%d)", c->what, st);
    *size = state_size(c, w);
    unsigned char *buf = malloc(*size);
    CHECK_MSG(state_get(c, w, buf) == VIGEN_SUCCESS, "%s: state_get failed", c->what);
    destroy(c, w);
    return buf;
}

static void check_restart(const config *c)
{
    double t, q[MAXDIM], p[MAXDIM], tk, qk[MAXDIM], pk[MAXDIM];
    snapshot A, C, E;
    void *wa = make(c);
    CHECK_MSG(wa != NULL, "%s: alloc failed", c->what);
    if (!wa) return;
    start(c, &t, q, p);
    int st = run(c, wa, &t, q, p, N);
    CHECK_MSG(st == VIGEN_SUCCESS, "%s: the uninterrupted run failed (%d)", c->what, st);
    take(c, &A, wa, t, q, p);
    size_t size;
    unsigned char *buf = saved_after_k(c, &size, &tk, qk, pk);
    /* a fresh integrator given the state */
    void *wc = make(c);
    CHECK_MSG(state_set(c, wc, buf) == VIGEN_SUCCESS, "%s: its own state refused", c->what);
    unsigned char *again = malloc(size);
    CHECK_MSG(state_size(c, wc) == size && state_get(c, wc, again) == VIGEN_SUCCESS && memcmp(again, buf, size) == 0,
              "%s: state_get after state_set gives other bytes", c->what);
    t = tk; memcpy(q, qk, sizeof q); memcpy(p, pk, sizeof p);
    st = run(c, wc, &t, q, p, N - K);
    take(c, &C, wc, t, q, p);
    CHECK_MSG(st == VIGEN_SUCCESS && memcmp(&A, &C, sizeof A) == 0,
              "%s: the restored run differs from the uninterrupted one (t %.17g vs %.17g, q0 %.17g vs %.17g, steps %lu vs %lu)",
              c->what, A.t, C.t, A.q[0], C.q[0], A.st.steps, C.st.steps);
    /* the control: a fresh integrator without the state */
    void *we = make(c);
    t = tk; memcpy(q, qk, sizeof q); memcpy(p, pk, sizeof p);
    run(c, we, &t, q, p, N - K);
    take(c, &E, we, t, q, p);
    if (c->kahan)
        CHECK_MSG(memcmp(&A.t, &E.t, sizeof A.t) != 0 || memcmp(A.q, E.q, sizeof A.q) != 0 || memcmp(A.p, E.p, sizeof A.p) != 0,
                  "%s: continuing without the state ends at the same point: the test would not see a lost state", c->what);
    /* NULL */
    CHECK_MSG(state_size(c, NULL) == 0 && state_get(c, NULL, buf) == VIGEN_EINVAL && state_get(c, wc, NULL) == VIGEN_EINVAL
              && state_set(c, NULL, buf) == VIGEN_EINVAL && state_set(c, wc, NULL) == VIGEN_EINVAL,
              "%s: a NULL argument is not VIGEN_EINVAL", c->what);
    free(buf);
    free(again);
    destroy(c, wa);
    destroy(c, wc);
    destroy(c, we);
}

/* The state of `from` offered to `to`: refused (VIGEN_ESTATE) with the
 * target unchanged, or taken when accept is set. */
static void check_offer(const char *what, const config *from, const config *to, int accept)
{
    double t, q[MAXDIM], p[MAXDIM];
    size_t size;
    unsigned char *buf = saved_after_k(from, &size, &t, q, p);
    void *w = make(to);
    start(to, &t, q, p);
    run(to, w, &t, q, p, 3);
    size_t before_size = state_size(to, w), cap = (before_size > size ? before_size : size);
    unsigned char *before = malloc(before_size), *after = malloc(before_size), *offer = calloc(cap, 1);
    memcpy(offer, buf, size);
    state_get(to, w, before);
    int st = state_set(to, w, offer);
    state_get(to, w, after);
    if (accept)
        CHECK_MSG(st == VIGEN_SUCCESS, "%s: refused (%d)", what, st);
    else
        CHECK_MSG(st == VIGEN_ESTATE && memcmp(before, after, before_size) == 0,
                  "%s: status %d, expected VIGEN_ESTATE with the integrator unchanged", what, st);
    free(buf); free(before); free(after); free(offer);
    destroy(to, w);
}

static uint64_t fnv1a(const unsigned char *b, size_t n)
{
    uint64_t hash = UINT64_C(0xcbf29ce484222325);
    for (size_t i = 0; i < n; i++) hash = (hash ^ b[i]) * UINT64_C(0x100000001b3);
    return hash;
}

/* Every single flipped byte, the last 1 .. 16 bytes lost, and the format
 * number changed with the hash recomputed (docs/emit.md: format at offset
 * 16, the trailer FNV-1a 64 of all bytes before it). */
static void check_damage(const config *c)
{
    double t, q[MAXDIM], p[MAXDIM];
    size_t size;
    unsigned char *buf = saved_after_k(c, &size, &t, q, p);
    uint64_t stored;
    memcpy(&stored, buf + size - 8, 8);
    CHECK_MSG(stored == fnv1a(buf, size - 8), "%s: the trailer is not the FNV-1a 64 hash of the bytes before it", c->what);
    void *w = make(c);
    start(c, &t, q, p);
    run(c, w, &t, q, p, 2);
    unsigned char *before = malloc(size), *now = malloc(size), *bad = malloc(size);
    state_get(c, w, before);
    long tried = 0, refused = 0;
    int unchanged = 1;
    for (size_t i = 0; i <= size + 16; i++) {
        memcpy(bad, buf, size);
        if (i < size) bad[i] ^= (unsigned char)(1u << (i % 8));
        else if (i < size + 16) memset(bad + size - (i - size + 1), 0, i - size + 1);
        else {
            uint64_t v = 2, h;
            memcpy(bad + 16, &v, 8);
            h = fnv1a(bad, size - 8);
            memcpy(bad + size - 8, &h, 8);
        }
        if (memcmp(bad, buf, size) == 0) continue;
        tried++;
        refused += state_set(c, w, bad) == VIGEN_ESTATE;
        state_get(c, w, now);
        unchanged &= memcmp(now, before, size) == 0;
    }
    CHECK_MSG(tried > 300 && refused == tried, "%s: %ld of %ld damaged states refused", c->what, refused, tried);
    CHECK_MSG(unchanged, "%s: a refused state changed the integrator", c->what);
    CHECK_MSG(state_set(c, w, buf) == VIGEN_SUCCESS, "%s: the intact state refused afterwards", c->what);
    free(buf); free(before); free(now); free(bad);
    destroy(c, w);
}

int main(void)
{
    const config hp_trap = { HP, VIGEN_HP_TRAPEZOIDAL, 1, 1, 1, 0, 3, "HP trapezoidal, exact Jacobian", 0 };
    const config hp_mid = { HP, VIGEN_HP_MIDPOINT, 1, 1, 1, 0, 3, "HP midpoint, exact Jacobian", 0 };
    const config cases[] = {
        hp_trap,
        { HP, VIGEN_HP_TRAPEZOIDAL, 0, 0, 1, 0, 3, "HP trapezoidal, differences, plain", 0 },
        { HP, VIGEN_HP_TRAPEZOIDAL, 1, 1, 0, 0, 3, "HP trapezoidal, no extrapolation", 0 },
        hp_mid,
        { HP, VIGEN_HP_MIDPOINT, 0, 1, 1, 0, 3, "HP midpoint, differences", 0 },
        { HP, VIGEN_HP_MIDPOINT, 1, 0, 0, 0, 3, "HP midpoint, plain, no extrapolation", 0 },
        { HP, VIGEN_HP_TRAPEZOIDAL, 0, 1, 1, 1, 2, "HP trapezoidal, chord map", 0 },
        { HP, VIGEN_HP_MIDPOINT, 0, 1, 1, 1, 2, "HP midpoint, chord map", 0 },
        { MVI, 0, 1, 1, 1, 0, 3, "mid-point VI, exact Jacobian", 0 },
        { MVI, 0, 0, 1, 1, 0, 3, "mid-point VI, differences", 0 },
        { MVI, 0, 1, 0, 0, 0, 3, "mid-point VI, plain, no extrapolation", 0 },
        { HP, VIGEN_HP_TRAPEZOIDAL, 1, 1, 1, 0, 3, "HP trapezoidal, truncated solve", 1 },
        { HP, VIGEN_HP_MIDPOINT, 0, 1, 1, 0, 3, "HP midpoint, truncated solve", 1 },
        { MVI, 0, 1, 1, 1, 0, 3, "mid-point VI, truncated solve", 1 },
        { TVI, 0, 1, 1, 1, 0, 3, "trapezoidal VI", 0 },
        { TVI, 0, 0, 0, 1, 0, 3, "trapezoidal VI, differences, plain", 0 },
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) check_restart(&cases[i]);

    const config mvi = { MVI, 0, 1, 1, 1, 0, 3, "mid-point VI", 0 };
    const config tvi = { TVI, 0, 1, 1, 1, 0, 3, "trapezoidal VI", 0 };
    const config hp_trap2 = { HP, VIGEN_HP_TRAPEZOIDAL, 1, 1, 1, 0, 2, "HP trapezoidal, dim 2", 0 };
    const config hp_plain = { HP, VIGEN_HP_TRAPEZOIDAL, 1, 0, 1, 0, 3, "HP trapezoidal, plain", 0 };
    const config hp_chord = { HP, VIGEN_HP_TRAPEZOIDAL, 1, 1, 1, 1, 2, "HP trapezoidal, chord map", 0 };
    const config mvi_plain = { MVI, 0, 1, 0, 1, 0, 3, "mid-point VI, plain", 0 };
    check_offer("HP trapezoidal into HP midpoint", &hp_trap, &hp_mid, 0);
    check_offer("HP into the mid-point VI", &hp_mid, &mvi, 0);
    check_offer("mid-point VI into HP", &mvi, &hp_mid, 0);
    check_offer("HP dimension 3 into 2", &hp_trap, &hp_trap2, 0);
    check_offer("HP compensated into plain", &hp_trap, &hp_plain, 0);
    check_offer("HP with a map parameter into the trivial map", &hp_chord, &hp_trap2, 0);
    check_offer("mid-point VI compensated into plain", &mvi, &mvi_plain, 0);
    check_offer("trapezoidal VI into its HP stepper", &tvi, &hp_trap, 1);
    check_damage(&hp_trap);
    check_damage(&hp_chord);
    check_damage(&mvi);
    TEST_MAIN_END();
}
