/* restart_driver.c — saved states of one emitted stepper (NAME_state_size,
 * _get, _set), for tests/unit/test_restart.c.  Built with
 *   -DSTEPPER_HEADER='"NAME.h"' -DSTEPPER_TYPE=NAME_type -DSTEPPER_NAME=NAME_
 * (-DREAL_LD or -DREAL_Q for a stepper emitted for long double or
 * __float128; -DOTHER_HEADER='"OTHER.h"' -DOTHER_NAME=OTHER_ and OTHER.c for
 * a second stepper whose states this one must refuse) and the runtime.
 *
 * The problem: a chain of DIM pendulums with springs between neighbours,
 *   H = sum_k m_k^-1 p_k^2 / 2 + sum_k (1 - cos q_k) + sum_k (q_{k+1} - q_k)^2 / 2,
 * m_k = 1 + k/10, from q_k = 0.5 + 0.1 k, p_k = 0.2 - 0.05 k, steps of
 * h = 0.0371 (not a power of two: the compensation of t matters), as a
 * general problem (dH/dq, dH/dp; separable flag SEP) or as a mechanical one
 * (the force -dV/dq, inv_mass).  The sine of a __float128 is taken in double:
 * the same function in every run is all a restart test needs.
 *
 * Arguments common to every mode:
 *   MODE FILE SEP MECH SOLVER KAHAN EXTRAP START_FORCE DIM N K
 *
 *   check   in one process: run A takes N steps; run B takes K steps and
 *           saves its state (NAME_state_get); a fresh workspace C gets it
 *           (NAME_state_set) and takes the other N - K steps from B's t, q, p.
 *           equal = 1 when t, q, p and the statistics of C are those of A
 *           bit for bit (memcmp); type_equal the same through the stepper
 *           type's state_size/_get/_set; control_equal the same for a fresh
 *           workspace that is NOT given the state (how much the state
 *           matters); reuses = fsal_reuses gained by C, extrapolated = 1 when
 *           C's first step took no starting gradient (dHdq_evals of that step
 *           equal to A's same step); roundtrip = 1 when NAME_state_get of C
 *           right after state_set gives the same bytes; size = state bytes;
 *           null_einval = 1 when every NULL argument gives VIGEN_EINVAL and
 *           state_size(NULL) = 0; other = the status of this stepper's
 *           state_set given the other stepper's state (when linked).
 *   save    runs K steps and writes t, q, p and the state to FILE
 *           (size_t state bytes, the state, then the reals of t, q, p).
 *   load    a fresh workspace takes 3 steps of its own, then reads FILE and
 *           calls state_set: set_status; unchanged = 1 when a refused state
 *           left the workspace's saved state as it was; on success it
 *           continues to N steps from FILE's t, q, p and prints final_<k>
 *           (t, then q, then p, in hexadecimal).
 *   full    N steps without a break: final_<k>.
 *   damage  every single byte of the state after K steps flipped in turn,
 *           and the state with its last 1 .. 16 bytes zeroed (a truncated
 *           file read into a buffer of the full size): refused = how many
 *           of those were refused with VIGEN_ESTATE, tried = how many were
 *           tried, unchanged = 1 when the workspace's state stayed as it was.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include STEPPER_HEADER
#ifdef OTHER_HEADER
#include OTHER_HEADER
#endif

#define CAT_(a, b) a##b
#define CAT(a, b) CAT_(a, b)
#define FN(x) CAT(STEPPER_NAME, x)
#ifdef REAL_LD
typedef long double real;
typedef vigen_hamiltonian_ld ham;
typedef vigen_mechanical_ld mechanical;
typedef vigen_stepper_type_ld stepper_type;
#define RSIN sinl
#define RCOS cosl
#elif defined(REAL_Q)
typedef vigen_float128 real;
typedef vigen_hamiltonian_q ham;
typedef vigen_mechanical_q mechanical;
typedef vigen_stepper_type_q stepper_type;
#define RSIN(x) ((real)sin((double)(x)))
#define RCOS(x) ((real)cos((double)(x)))
#else
typedef double real;
typedef vigen_hamiltonian ham;
typedef vigen_mechanical mechanical;
typedef vigen_stepper_type stepper_type;
#define RSIN sin
#define RCOS cos
#endif
/* real values compared and printed by their significant bytes (long double
 * has padding bytes of no meaning) */
#ifdef REAL_LD
#define RBYTES 10
#else
#define RBYTES sizeof(real)
#endif

enum { MAXDIM = 16 };
static size_t dim;
static real inv_mass[MAXDIM];

static void force(real t, const real *q, real *f, void *ctx)
{
    (void)t; (void)ctx;
    for (size_t k = 0; k < dim; k++) {
        real left = k > 0 ? q[k] - q[k - 1] : 0, right = k + 1 < dim ? q[k + 1] - q[k] : 0;
        f[k] = -RSIN(q[k]) + right - left;
    }
}

static void dHdq(real t, const real *q, const real *p, real *out, void *ctx)
{
    (void)p;
    force(t, q, out, ctx);
    for (size_t k = 0; k < dim; k++) out[k] = -out[k];
}

static void dHdp(real t, const real *q, const real *p, real *out, void *ctx)
{
    (void)t; (void)q; (void)ctx;
    for (size_t k = 0; k < dim; k++) out[k] = inv_mass[k] * p[k];
}

static real potential(real t, const real *q, void *ctx)
{
    (void)t; (void)ctx;
    real v = 0;
    for (size_t k = 0; k < dim; k++) {
        v += 1 - RCOS(q[k]);
        if (k + 1 < dim) v += (q[k + 1] - q[k]) * (q[k + 1] - q[k]) / 2;
    }
    return v;
}

typedef struct { int sep, mech, solver, kahan, extrap, start_force; long n, k; } setup;

static void start(real *t, real *q, real *p)
{
    *t = 0;
    for (size_t k = 0; k < dim; k++) {
        q[k] = (real)0.5 + (real)0.1 * (real)k;
        p[k] = (real)0.2 - (real)0.05 * (real)k;
    }
}

static FN(workspace) *alloc(const setup *s)
{
    vigen_solver_options opt;
    vigen_solver_options_default(&opt);
    opt.solver = s->solver;
    opt.kahan = s->kahan;
    opt.extrapolate = s->extrap;
    opt.start_force = s->start_force;
    if (s->mech) {
        mechanical m = { dim, force, potential, NULL, inv_mass };
        return FN(alloc_mechanical)(&m, &opt);
    }
    ham g = { dim, dHdq, dHdp, NULL, NULL, s->sep, NULL };
    return FN(alloc)(&g, &opt);
}

static const real h = (real)0.0371;

/* Steps from step `from` to step `to`; the status of the first failure. */
static int run(FN(workspace) *w, real *t, real *q, real *p, long from, long to)
{
    for (long i = from; i < to; i++) {
        int st = FN(step)(w, t, q, p, h);
        if (st != VIGEN_SUCCESS) return st;
    }
    return VIGEN_SUCCESS;
}

static int same_reals(const real *a, const real *b, size_t n)
{
    for (size_t k = 0; k < n; k++)
        if (memcmp(&a[k], &b[k], RBYTES) != 0) return 0;
    return 1;
}

typedef struct { real t, q[MAXDIM], p[MAXDIM]; vigen_stats st; } snapshot;

static void take(snapshot *s, FN(workspace) *w, real t, const real *q, const real *p)
{
    s->t = t;
    memcpy(s->q, q, dim * sizeof *q);
    memcpy(s->p, p, dim * sizeof *p);
    s->st = *FN(stats)(w);
}

static int same(const snapshot *a, const snapshot *b)
{
    return same_reals(&a->t, &b->t, 1) && same_reals(a->q, b->q, dim) && same_reals(a->p, b->p, dim)
           && memcmp(&a->st, &b->st, sizeof a->st) == 0;
}

static void print_final(real t, const real *q, const real *p)
{
    int i = 0;
    const real *v[3] = { &t, q, p };
    const size_t len[3] = { 1, dim, dim };
    for (int part = 0; part < 3; part++)
        for (size_t k = 0; k < len[part]; k++) {
            const unsigned char *b = (const unsigned char *)&v[part][k];
            printf("final_%d=", i++);
            for (size_t j = 0; j < RBYTES; j++) printf("%02x", b[j]);
            printf("\n");
        }
}

/* The state of w, freshly allocated (caller frees). */
static unsigned char *state_of(const FN(workspace) *w, size_t *size)
{
    *size = FN(state_size)(w);
    unsigned char *b = malloc(*size);
    if (b && FN(state_get)(w, b) != VIGEN_SUCCESS) { free(b); return NULL; }
    return b;
}

static int check(const setup *s)
{
    const stepper_type *T = &STEPPER_TYPE;
    real t, q[MAXDIM], p[MAXDIM], tb, qb[MAXDIM], pb[MAXDIM];
    snapshot A, C, D, E;
    /* A: uninterrupted, with the statistics of step K + 1 noted */
    FN(workspace) *wa = alloc(s);
    if (!wa) { printf("alloc_failed=1\n"); return 1; }
    start(&t, q, p);
    int st = run(wa, &t, q, p, 0, s->k);
    unsigned long a_before = FN(stats)(wa)->dHdq_evals;
    if (st == VIGEN_SUCCESS) st = run(wa, &t, q, p, s->k, s->k + 1);
    unsigned long a_first = FN(stats)(wa)->dHdq_evals - a_before;
    if (st == VIGEN_SUCCESS) st = run(wa, &t, q, p, s->k + 1, s->n);
    take(&A, wa, t, q, p);
    /* B: K steps, then its state */
    FN(workspace) *wb = alloc(s);
    start(&tb, qb, pb);
    if (st == VIGEN_SUCCESS) st = run(wb, &tb, qb, pb, 0, s->k);
    size_t size;
    unsigned char *buf = state_of(wb, &size);
    /* C: a fresh workspace given the state */
    FN(workspace) *wc = alloc(s);
    int set = FN(state_set)(wc, buf);
    size_t size2;
    unsigned char *again = state_of(wc, &size2);
    int roundtrip = set == VIGEN_SUCCESS && size2 == size && memcmp(again, buf, size) == 0;
    unsigned long reuses0 = FN(stats)(wc)->fsal_reuses, c_before = FN(stats)(wc)->dHdq_evals;
    t = tb; memcpy(q, qb, sizeof q); memcpy(p, pb, sizeof p);
    if (st == VIGEN_SUCCESS) st = run(wc, &t, q, p, s->k, s->k + 1);
    unsigned long c_first = FN(stats)(wc)->dHdq_evals - c_before;
    if (st == VIGEN_SUCCESS) st = run(wc, &t, q, p, s->k + 1, s->n);
    take(&C, wc, t, q, p);
    unsigned long reuses = FN(stats)(wc)->fsal_reuses - reuses0;
    /* D: the same through the stepper type */
    FN(workspace) *wd2 = alloc(s);
    void *wd = wd2;
    unsigned char *tbuf = malloc(T->state_size(wb));
    int tset = tbuf && T->state_get(wb, tbuf) == VIGEN_SUCCESS ? T->state_set(wd, tbuf) : -1;
    t = tb; memcpy(q, qb, sizeof q); memcpy(p, pb, sizeof p);
    if (st == VIGEN_SUCCESS && tset == VIGEN_SUCCESS) st = run(wd2, &t, q, p, s->k, s->n);
    take(&D, wd2, t, q, p);
    /* E: a fresh workspace without the state (the control) */
    FN(workspace) *we = alloc(s);
    t = tb; memcpy(q, qb, sizeof q); memcpy(p, pb, sizeof p);
    if (st == VIGEN_SUCCESS) st = run(we, &t, q, p, s->k, s->n);
    take(&E, we, t, q, p);
    /* NULL arguments */
    int null_einval = FN(state_size)(NULL) == 0 && FN(state_get)(NULL, buf) == VIGEN_EINVAL
                      && FN(state_get)(wb, NULL) == VIGEN_EINVAL && FN(state_set)(NULL, buf) == VIGEN_EINVAL
                      && FN(state_set)(wc, NULL) == VIGEN_EINVAL;
    printf("status=%d\nset_status=%d\nsize=%zu\nequal=%d\ntype_equal=%d\ncontrol_equal=%d\n", st, set, size,
           same(&A, &C), tset == VIGEN_SUCCESS && same(&A, &D), same(&A, &E));
    printf("control_same_point=%d\n", same_reals(&A.t, &E.t, 1) && same_reals(A.q, E.q, dim) && same_reals(A.p, E.p, dim));
    printf("reuses=%lu\nextrapolated=%d\nfirst_evals=%lu\nroundtrip=%d\nnull_einval=%d\n", reuses,
           c_first == a_first, c_first, roundtrip, null_einval);
#ifdef OTHER_HEADER
    {
        vigen_solver_options opt;
        vigen_solver_options_default(&opt);
        ham g = { dim, dHdq, dHdp, NULL, NULL, s->sep, NULL };
        CAT(OTHER_NAME, workspace) *wo = CAT(OTHER_NAME, alloc)(&g, &opt);
        real to;
        real qo[MAXDIM], po[MAXDIM];
        start(&to, qo, po);
        CAT(OTHER_NAME, step)(wo, &to, qo, po, h);
        unsigned char *ob = malloc(CAT(OTHER_NAME, state_size)(wo) + size);
        CAT(OTHER_NAME, state_get)(wo, ob);
        printf("other=%d\n", FN(state_set)(wc, ob));
        free(ob);
        CAT(OTHER_NAME, free)(wo);
    }
#endif
    free(buf);
    free(again);
    free(tbuf);
    FN(free)(wa);
    FN(free)(wb);
    FN(free)(wc);
    FN(free)(wd2);
    FN(free)(we);
    return 0;
}

static int save(const setup *s, const char *file)
{
    real t, q[MAXDIM], p[MAXDIM];
    FN(workspace) *w = alloc(s);
    if (!w) { printf("alloc_failed=1\n"); return 1; }
    start(&t, q, p);
    int st = run(w, &t, q, p, 0, s->k);
    size_t size;
    unsigned char *buf = state_of(w, &size);
    FILE *f = fopen(file, "wb");
    int ok = f && buf && fwrite(&size, sizeof size, 1, f) == 1 && fwrite(buf, 1, size, f) == size
             && fwrite(&t, sizeof t, 1, f) == 1 && fwrite(q, sizeof *q, dim, f) == dim && fwrite(p, sizeof *p, dim, f) == dim;
    if (f && fclose(f) != 0) ok = 0;
    printf("status=%d\nsaved=%d\nsize=%zu\n", st, ok, size);
    free(buf);
    FN(free)(w);
    return ok ? 0 : 1;
}

static int load(const setup *s, const char *file)
{
    real t, q[MAXDIM], p[MAXDIM];
    FN(workspace) *w = alloc(s);
    if (!w) { printf("alloc_failed=1\n"); return 1; }
    start(&t, q, p);
    run(w, &t, q, p, 0, 3);
    size_t mine_size, size = 0;
    unsigned char *mine = state_of(w, &mine_size);
    FILE *f = fopen(file, "rb");
    if (!f || fread(&size, sizeof size, 1, f) != 1 || size > (1u << 24)) { printf("read_failed=1\n"); return 1; }
    /* at least as many bytes as this workspace's state reads */
    unsigned char *buf = calloc(size > mine_size ? size : mine_size, 1);
    if (!buf || fread(buf, 1, size, f) != size) { printf("read_failed=1\n"); return 1; }
    int set = FN(state_set)(w, buf);
    /* t, q, p follow in the saved run's type and dimension: read them only for a state taken */
    if (set == VIGEN_SUCCESS && (fread(&t, sizeof t, 1, f) != 1 || fread(q, sizeof *q, dim, f) != dim
                                 || fread(p, sizeof *p, dim, f) != dim)) { printf("read_failed=1\n"); return 1; }
    fclose(f);
    size_t after_size;
    unsigned char *after = state_of(w, &after_size);
    printf("set_status=%d\nestate=%d\nunchanged=%d\n", set, set == VIGEN_ESTATE,
           set != VIGEN_SUCCESS && after_size == mine_size && memcmp(after, mine, mine_size) == 0);
    if (set == VIGEN_SUCCESS) {
        int st = run(w, &t, q, p, s->k, s->n);
        printf("status=%d\n", st);
        print_final(t, q, p);
    }
    free(buf);
    free(mine);
    free(after);
    FN(free)(w);
    return 0;
}

static int full(const setup *s)
{
    real t, q[MAXDIM], p[MAXDIM];
    FN(workspace) *w = alloc(s);
    if (!w) { printf("alloc_failed=1\n"); return 1; }
    start(&t, q, p);
    int st = run(w, &t, q, p, 0, s->n);
    printf("status=%d\n", st);
    print_final(t, q, p);
    FN(free)(w);
    return 0;
}

static int damage(const setup *s)
{
    real t, q[MAXDIM], p[MAXDIM];
    FN(workspace) *w = alloc(s), *target = alloc(s);
    if (!w || !target) { printf("alloc_failed=1\n"); return 1; }
    start(&t, q, p);
    run(w, &t, q, p, 0, s->k);
    start(&t, q, p);
    run(target, &t, q, p, 0, 2);
    size_t size, before_size;
    unsigned char *buf = state_of(w, &size), *before = state_of(target, &before_size);
    unsigned char *bad = malloc(size);
    long tried = 0, refused = 0;
    int unchanged = 1;
    for (size_t i = 0; i < size + 16; i++) {
        memcpy(bad, buf, size);
        if (i < size) bad[i] ^= (unsigned char)(1u << (i % 8));
        else memset(bad + size - (i - size + 1), 0, i - size + 1);   /* last 1 .. 16 bytes lost */
        if (i >= size && memcmp(bad, buf, size) == 0) continue;       /* they were zeros already */
        tried++;
        refused += FN(state_set)(target, bad) == VIGEN_ESTATE;
        size_t n2;
        unsigned char *now = state_of(target, &n2);
        unchanged &= n2 == before_size && memcmp(now, before, n2) == 0;
        free(now);
    }
    printf("tried=%ld\nrefused=%ld\nunchanged=%d\nintact=%d\n", tried, refused, unchanged,
           FN(state_set)(target, buf) == VIGEN_SUCCESS);
    free(buf);
    free(before);
    free(bad);
    FN(free)(w);
    FN(free)(target);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc != 12) {
        fprintf(stderr, "usage: %s MODE FILE SEP MECH SOLVER KAHAN EXTRAP START_FORCE DIM N K\n", argv[0]);
        return 2;
    }
    setup s = { atoi(argv[3]), atoi(argv[4]), atoi(argv[5]), atoi(argv[6]), atoi(argv[7]), atoi(argv[8]),
                atol(argv[10]), atol(argv[11]) };
    dim = (size_t)atol(argv[9]);
    if (dim == 0 || dim > MAXDIM || s.k < 1 || s.k >= s.n) return 2;
    for (size_t k = 0; k < dim; k++) inv_mass[k] = 1 / (1 + (real)k / 10);   /* copied at alloc */
    const char *mode = argv[1];
    if (strcmp(mode, "check") == 0) return check(&s);
    if (strcmp(mode, "save") == 0) return save(&s, argv[2]);
    if (strcmp(mode, "load") == 0) return load(&s, argv[2]);
    if (strcmp(mode, "full") == 0) return full(&s);
    if (strcmp(mode, "damage") == 0) return damage(&s);
    return 2;
}
