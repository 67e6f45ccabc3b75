/* design_minimize.c — the best member of a family with free parameters:
 * the conditions leave k - m unknowns free; these are pinned (design_pin.c)
 * and moved by the Nelder-Mead simplex (GSL multimin) to minimise the
 * checker's principal error constant of the method.  At each trial point the
 * dependent unknowns follow the branch the search started on (Newton from
 * the last point), the point is proved in arb (Krawczyk) and written with 25
 * digits, and the checker computes the error constant of that composition
 * file: the objective is exactly what `vigen check` reports.  Several random
 * starts and every real branch found at each start; the best local minimum
 * wins.  With `screen = N` the objective is first evaluated at N random
 * points (every branch), and the descents start from the best distinct ones
 * and are restarted until they stop moving: a cheap global stage before the
 * local ones.  The seed fixes every draw, so a run is reproducible.  It is
 * not a proof: the minimum is the best found, not proved global
 * (docs/design.md). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multimin.h>
#include <gsl/gsl_rng.h>
#include "design/design_internal.h"
#include "design/design_method.h"
#include "design/design_minimize.h"
#include "core/decimal.h"
#include "support/strbuf.h"
#include "vigen/check.h"

#define TRIAL_DIGITS 25
#define TRIAL_PREC 192
#define BRANCH_STARTS 200
#define MAX_BRANCHES 4
#define NM_ITERATIONS 80
#define NM_SIZE 1e-7
#define WORSE 1e10
/* screening: the pins drawn in [-SCREEN_BOX, SCREEN_BOX] (the steps of the
 * published splittings are below about 1.5 in size), a few Newton starts for
 * the dependent unknowns at each; a descent restarted at most RESTARTS times;
 * descents start from points at least SCREEN_APART apart in the pins */
#define SCREEN_BOX 1.5
#define SCREEN_NEWTON_STARTS 20
#define SCREEN_APART 0.25
#define RESTARTS 4
#define SAME_MINIMUM 1e-5
#define PROXY_ITERATIONS 400
#define SCREEN_FAR 3.0

void design_free_unknowns(slong *free_out, const design_system *sys, const slong *rows, slong m, unsigned long seed)
{
    slong k = sys->k, nf = 0, rank = 0;
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, seed + 104729);
    double *x = malloc((size_t)k * sizeof(double)), *jac = malloc((size_t)(m * k) * sizeof(double));
    for (slong j = 0; j < k; j++) x[j] = 2 * gsl_rng_uniform(rng) - 1;
    design_eval_d(NULL, jac, sys, rows, m, x);
    /* columns in order; a column joins the dependent ones when it raises the
     * rank (Gram-Schmidt on the columns of the m x k Jacobian) */
    double *basis = malloc((size_t)(m * (m + 1)) * sizeof(double)), *v = malloc((size_t)m * sizeof(double));
    for (slong j = 0; j < k; j++) {
        double n0 = 0, n1 = 0;
        for (slong i = 0; i < m; i++) v[i] = jac[i * k + j], n0 += v[i] * v[i];
        for (int pass = 0; pass < 2; pass++)
            for (slong b = 0; b < rank; b++) {
                double dot = 0;
                for (slong i = 0; i < m; i++) dot += v[i] * basis[b * m + i];
                for (slong i = 0; i < m; i++) v[i] -= dot * basis[b * m + i];
            }
        for (slong i = 0; i < m; i++) n1 += v[i] * v[i];
        if (rank < m && n0 > 0 && n1 > 1e-16 * n0) {
            for (slong i = 0; i < m; i++) basis[rank * m + i] = v[i] / sqrt(n1);
            rank++;
        } else if (nf < k - m) {
            free_out[nf++] = j;
        }
    }
    free(basis);
    free(v);
    free(x);
    free(jac);
    gsl_rng_free(rng);
}

typedef struct {
    design_system *sys;
    const slong *rows;           /* k: the conditions, then the pins */
    const slong *pin_rows, *free_idx;
    slong nfree;
    double *x;                   /* the point of the branch followed */
    const vigen_design_spec *d;
    const char *base;
    int family;
    long evals;
} objective;

static double value(const gsl_vector *t, void *param)
{
    objective *o = param;
    slong k = o->sys->k;
    for (slong i = 0; i < o->nfree; i++) design_system_set_pin(o->sys, o->pin_rows[i], gsl_vector_get(t, (size_t)i));
    double *x = malloc((size_t)k * sizeof(double));
    memcpy(x, o->x, (size_t)k * sizeof(double));
    for (slong i = 0; i < o->nfree; i++) x[o->free_idx[i]] = gsl_vector_get(t, (size_t)i);
    double ec = WORSE;
    arb_ptr box = _arb_vec_init(k);
    if (design_newton_polish(x, o->sys, o->rows, 30) &&
        design_krawczyk_prove(box, o->sys, o->rows, x, TRIAL_PREC)) {
        slong nv = design_family_nvalues(o->d), nd = k;
        char **digits = NULL, **gamma = malloc((size_t)nv * sizeof(char *));
        int ok = 1;
        if (o->d->processed) {
            /* a processed method's error is that of C K C^-1: the kernel
             * with its corrector, proved together at this point */
            char *radius = NULL, *why = NULL;
            vigen_error cerr;
            vigen_error_init(&cerr);
            ok = design_corrector_find(&digits, &radius, &why, o->d, o->sys, o->rows, x, TRIAL_DIGITS, &cerr) == 1;
            vigen_error_clear(&cerr);
            free(radius);
            free(why);
            nd = ok ? k + DESIGN_CORRECTOR_UNKNOWNS : 0;
        } else {
            /* a step held at 0 (a splitting that starts with a kick) has a
             * box around 0, whose sign no digits decide: it is written as 0 */
            digits = calloc((size_t)k, sizeof(char *));
            for (slong j = 0; j < k; j++)
                ok &= (digits[j] = design_pinned_zero(o->sys, o->rows, k, j)
                                       ? vigen_strdup("0")
                                       : vigen_decimal_format(box + j, TRIAL_DIGITS)) != NULL;
        }
        if (ok) {
            for (slong s = 0; s < nv; s++) gamma[s] = digits[design_family_value_unknown(o->d, s)];
            const int claims[3] = {-1, -1, -1};
            char *text = vigen_design_method_text(o->d, o->base, "candidate", 1, 1, gamma, "a candidate", claims, NULL,
                                                  0);
            vigen_error err;
            vigen_error_init(&err);
            double e = -1;
            long force = 0;
            o->evals++;
            if (vigen_design_method_error_constant(&e, &force, text, o->d->order, o->family, &err) == VIGEN_OK &&
                e >= 0) {
                /* the effective error: at the kernel's cost for a processed method */
                ec = o->d->minimize_effective ? e * pow((double)(o->d->processed ? o->d->stages : force), o->d->order)
                                              : e;
                memcpy(o->x, x, (size_t)k * sizeof(double));
            }
            vigen_error_clear(&err);
            free(text);
        }
        for (slong j = 0; j < nd; j++) free(digits[j]);
        free(digits);
        free(gamma);
    }
    _arb_vec_clear(box, k);
    free(x);
    return ec;
}

/* Nelder-Mead from o->x along its branch; the minimum into *best (the
 * point in o->x). */
static void descend(double *best, objective *o)
{
    gsl_multimin_function fn = {value, (size_t)o->nfree, o};
    gsl_vector *t = gsl_vector_alloc((size_t)o->nfree), *step = gsl_vector_alloc((size_t)o->nfree);
    for (slong i = 0; i < o->nfree; i++) gsl_vector_set(t, (size_t)i, o->x[o->free_idx[i]]);
    gsl_vector_set_all(step, 0.05);
    gsl_multimin_fminimizer *s = gsl_multimin_fminimizer_alloc(gsl_multimin_fminimizer_nmsimplex2, (size_t)o->nfree);
    *best = WORSE;
    if (gsl_multimin_fminimizer_set(s, &fn, t, step) == GSL_SUCCESS) {
        int status = GSL_CONTINUE;
        for (int it = 0; it < NM_ITERATIONS && status == GSL_CONTINUE; it++) {
            if (gsl_multimin_fminimizer_iterate(s) != GSL_SUCCESS) break;
            status = gsl_multimin_test_size(gsl_multimin_fminimizer_size(s), NM_SIZE);
        }
        /* the point of the branch at the minimum found */
        *best = value(s->x, o);
    }
    gsl_multimin_fminimizer_free(s);
    gsl_vector_free(t);
    gsl_vector_free(step);
}

/* The screening objective: the sum of squares of the family's conditions of
 * the first degree above the order (the principal error's coefficients on
 * the Lyndon words, exact polynomials evaluated in double: microseconds
 * where the checker takes milliseconds), at pins t along the branch through
 * x (Newton from x; x moves there).  Its minima are near the checker's but
 * not at them: it only chooses where the descents on the checker start. */
typedef struct {
    design_system *sys;          /* the family's conditions and the pins */
    const slong *rows;
    const slong *pin_rows;
    slong nfree;
    design_system hi;            /* the conditions of the next degrees */
    slong *hi_rows;
    slong nhi;
    double *x;
} proxy;

static double proxy_value(const gsl_vector *t, void *param)
{
    proxy *p = param;
    slong k = p->sys->k;
    for (slong i = 0; i < p->nfree; i++) design_system_set_pin(p->sys, p->pin_rows[i], gsl_vector_get(t, (size_t)i));
    double *x = malloc((size_t)(k + p->nhi) * sizeof(double)), *f = x + k, v = WORSE;
    memcpy(x, p->x, (size_t)k * sizeof(double));
    if (design_newton_polish(x, p->sys, p->rows, 30)) {
        design_eval_d(f, NULL, &p->hi, p->hi_rows, p->nhi, x);
        v = 0;
        for (slong i = 0; i < p->nhi; i++) v += f[i] * f[i];
        if (!isfinite(v)) v = WORSE;
        else memcpy(p->x, x, (size_t)k * sizeof(double));
    }
    free(x);
    return v;
}

/* the conditions of the first degree above the order among those of order
 * d->order + 2 (a symmetric family has no even ones); 0 when there are none */
static int proxy_init(proxy *p, const vigen_design_spec *d, int q)
{
    vigen_design_spec up = *d;
    up.order = d->order + 2;
    vigen_error err;
    vigen_error_init(&err);
    p->nhi = 0;
    p->hi_rows = NULL;
    if (up.order > VIGEN_DESIGN_MAX_ORDER || design_family_conditions(&p->hi, &up, q, &err) != VIGEN_OK) {
        vigen_error_clear(&err);
        return 0;
    }
    vigen_error_clear(&err);
    int deg = 0;
    for (slong i = 0; i < p->hi.n; i++)
        if (p->hi.h_degree[i] > d->order && (deg == 0 || p->hi.h_degree[i] < deg)) deg = p->hi.h_degree[i];
    p->hi_rows = malloc((size_t)(p->hi.n + 1) * sizeof(slong));
    for (slong i = 0; i < p->hi.n; i++)
        if (p->hi.h_degree[i] == deg) p->hi_rows[p->nhi++] = i;
    if (p->nhi > 0) return 1;
    design_system_clear(&p->hi);
    free(p->hi_rows);
    p->hi_rows = NULL;
    return 0;
}

/* Nelder-Mead on the screening objective from p->x; its value there */
static double proxy_descend(proxy *p, const slong *free_idx)
{
    gsl_multimin_function fn = {proxy_value, (size_t)p->nfree, p};
    gsl_vector *t = gsl_vector_alloc((size_t)p->nfree), *step = gsl_vector_alloc((size_t)p->nfree);
    for (slong i = 0; i < p->nfree; i++) gsl_vector_set(t, (size_t)i, p->x[free_idx[i]]);
    gsl_vector_set_all(step, 0.05);
    gsl_multimin_fminimizer *s = gsl_multimin_fminimizer_alloc(gsl_multimin_fminimizer_nmsimplex2, (size_t)p->nfree);
    double v = WORSE;
    if (gsl_multimin_fminimizer_set(s, &fn, t, step) == GSL_SUCCESS) {
        for (int it = 0; it < PROXY_ITERATIONS; it++) {
            if (gsl_multimin_fminimizer_iterate(s) != GSL_SUCCESS) break;
            if (gsl_multimin_test_size(gsl_multimin_fminimizer_size(s), NM_SIZE) != GSL_CONTINUE) break;
        }
        v = proxy_value(s->x, p);
    }
    gsl_multimin_fminimizer_free(s);
    gsl_vector_free(t);
    gsl_vector_free(step);
    return v;
}

/* the minimum x (value ec) among the distinct ones found, and the best */
static void record(double *minima, slong *nminima, double *xbest, double *ecbest, const double *x, double ec, slong k)
{
    int seen = 0;
    for (slong r = 0; r < *nminima && !seen; r++) {
        double dist = 0;
        for (slong j = 0; j < k; j++) dist = fmax(dist, fabs(x[j] - minima[r * k + j]));
        seen = dist < SAME_MINIMUM;
    }
    if (!seen) memcpy(minima + (*nminima)++ * k, x, (size_t)k * sizeof(double));
    if (ec < *ecbest) {
        *ecbest = ec;
        memcpy(xbest, x, (size_t)k * sizeof(double));
    }
}

typedef struct {
    double ec;
    double *x;
    int taken;
} candidate;

static int by_value(const void *a, const void *b)
{
    double u = ((const candidate *)a)->ec, v = ((const candidate *)b)->ec;
    return (u > v) - (u < v);
}

/* the objective at the pins t along the branch through o->x (o->x moves to
 * the point proved there) */
static double value_at(objective *o, const double *t)
{
    gsl_vector *v = gsl_vector_alloc((size_t)o->nfree);
    for (slong i = 0; i < o->nfree; i++) gsl_vector_set(v, (size_t)i, t[i]);
    double ec = value(v, o);
    gsl_vector_free(v);
    return ec;
}

/* the largest change of a pin between the points x and y */
static double pin_distance(const objective *o, const double *x, const double *y)
{
    double dist = 0;
    for (slong i = 0; i < o->nfree; i++) dist = fmax(dist, fabs(x[o->free_idx[i]] - y[o->free_idx[i]]));
    return dist;
}

/* d->screen random pin points, every branch at each evaluated; descents from
 * the d->starts best points SCREEN_APART apart, each restarted from where it
 * stopped until it moves less than SAME_MINIMUM */
static void screen_and_descend(double *xbest, double *ecbest, slong *nminima, double *minima, objective *o,
                               const vigen_design_spec *d, int q, gsl_rng *rng)
{
    design_system *sys = o->sys;
    slong k = sys->k, nf = o->nfree;
    candidate *cand = malloc((size_t)(d->screen * MAX_BRANCHES + 1) * sizeof *cand);
    long nc = 0;
    double *t = malloc((size_t)nf * sizeof(double)), *prev = malloc((size_t)k * sizeof(double));
    proxy px = {sys, o->rows, o->pin_rows, nf, {0}, NULL, 0, o->x};
    int use_proxy = proxy_init(&px, d, q);
    for (long st = 0; st < d->screen; st++) {
        for (slong i = 0; i < nf; i++) {
            t[i] = (2 * gsl_rng_uniform(rng) - 1) * SCREEN_BOX;
            design_system_set_pin(sys, o->pin_rows[i], t[i]);
        }
        double *roots = NULL;
        slong nb = design_newton_search(&roots, sys, o->rows, SCREEN_NEWTON_STARTS, d->seed + (unsigned long)st * 31,
                                        SCREEN_BOX);
        for (slong b = 0; b < nb && b < MAX_BRANCHES; b++) {
            memcpy(o->x, roots + b * k, (size_t)k * sizeof(double));
            double ec = use_proxy ? proxy_descend(&px, o->free_idx) : value_at(o, t);
            double size = 0;
            for (slong j = 0; j < k; j++) size = fmax(size, fabs(o->x[j]));
            if (ec >= WORSE || size > SCREEN_FAR) continue;       /* a method of huge steps */
            int seen = 0;
            for (long c = 0; c < nc && !seen; c++) seen = pin_distance(o, o->x, cand[c].x) < SAME_MINIMUM * 100;
            if (seen) continue;
            cand[nc].ec = ec;
            cand[nc].taken = 0;
            cand[nc].x = malloc((size_t)k * sizeof(double));
            memcpy(cand[nc++].x, o->x, (size_t)k * sizeof(double));
        }
        free(roots);
    }
    qsort(cand, (size_t)nc, sizeof *cand, by_value);
    if (use_proxy) {
        design_system_clear(&px.hi);
        free(px.hi_rows);
    }
    long used = 0;
    for (long c = 0; c < nc && used < d->starts; c++) {
        int near = 0;
        for (long u = 0; u < c && !near; u++) near = cand[u].taken && pin_distance(o, cand[c].x, cand[u].x) < SCREEN_APART;
        if (near) continue;
        cand[c].taken = 1;
        used++;
        memcpy(o->x, cand[c].x, (size_t)k * sizeof(double));
        double ec = WORSE;
        for (int r = 0; r <= RESTARTS; r++) {
            memcpy(prev, o->x, (size_t)k * sizeof(double));
            descend(&ec, o);
            if (ec >= WORSE || pin_distance(o, o->x, prev) < SAME_MINIMUM) break;
        }
            if (ec < WORSE) record(minima, nminima, xbest, ecbest, o->x, ec, k);
    }
    for (long c = 0; c < nc; c++) free(cand[c].x);
    free(cand);
    free(t);
    free(prev);
}

int design_minimize(double *xbest, double *ecbest, slong *nminima, long *evals, design_system *sys, slong *rows,
                    slong m, const vigen_design_spec *d, const char *base, int q, double box)
{
    slong k = sys->k, nfree = k - m;
    slong *free_idx = malloc((size_t)nfree * sizeof(slong)), *pin_rows = malloc((size_t)nfree * sizeof(slong));
    design_free_unknowns(free_idx, sys, rows, m, d->seed);
    for (slong i = 0; i < nfree; i++) {
        pin_rows[i] = design_system_add_pin(sys, free_idx[i]);
        rows[m + i] = pin_rows[i];
    }
    int family = d->minimize_family;
    gsl_error_handler_t *old = gsl_set_error_handler_off();
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, d->seed);
    double *x = malloc((size_t)k * sizeof(double)), *minima = malloc((size_t)(d->starts * MAX_BRANCHES * k + 1) *
                                                                           sizeof(double));
    objective o = {sys, rows, pin_rows, free_idx, nfree, x, d, base, family, 0};
    *ecbest = WORSE;
    *nminima = 0;
    if (d->screen > 0) screen_and_descend(xbest, ecbest, nminima, minima, &o, d, q, rng);
    for (long st = 0; st < d->starts && d->screen == 0; st++) {
        for (slong i = 0; i < nfree; i++) design_system_set_pin(sys, pin_rows[i], (2 * gsl_rng_uniform(rng) - 1) * box);
        double *roots = NULL;
        slong nb = design_newton_search(&roots, sys, rows, BRANCH_STARTS, d->seed + (unsigned long)st * 31, box);
        for (slong b = 0; b < nb && b < MAX_BRANCHES; b++) {
            memcpy(x, roots + b * k, (size_t)k * sizeof(double));
            double ec;
            descend(&ec, &o);
            if (ec < WORSE) record(minima, nminima, xbest, ecbest, x, ec, k);
        }
        free(roots);
    }
    /* the pins at the best point, for the proof that follows */
    if (*ecbest < WORSE)
        for (slong i = 0; i < nfree; i++) design_system_set_pin(sys, pin_rows[i], xbest[free_idx[i]]);
    *evals = o.evals;
    free(x);
    free(minima);
    gsl_rng_free(rng);
    gsl_set_error_handler(old);
    free(free_idx);
    free(pin_rows);
    return *ecbest < WORSE;
}
