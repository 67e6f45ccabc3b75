/* design_minimize.c — the best member of a family with free parameters:
 * the conditions leave k - m unknowns free; these are pinned (design_pin.c)
 * and moved by the Nelder-Mead simplex (GSL multimin) to minimise the
 * checker's principal error constant of the method.  At each trial point the
 * dependent unknowns follow the branch the search started on (Newton from
 * the last point), the point is proved in arb (Krawczyk) and written with 25
 * digits, and the checker computes the error constant of that composition
 * file: the objective is exactly what `vigen check` reports.  Several random
 * starts and every real branch found at each start; the best local minimum
 * wins.  It is a local search: the minimum is the best found, not proved
 * global (docs/design.md). */
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
#include "vigen/check.h"

#define TRIAL_DIGITS 25
#define TRIAL_PREC 192
#define BRANCH_STARTS 200
#define MAX_BRANCHES 4
#define NM_ITERATIONS 80
#define NM_SIZE 1e-7
#define WORSE 1e10

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
        slong nv = design_family_nvalues(o->d);
        char **digits = calloc((size_t)k, sizeof(char *)), **gamma = malloc((size_t)nv * sizeof(char *));
        int ok = 1;
        for (slong j = 0; j < k; j++) ok &= (digits[j] = vigen_decimal_format(box + j, TRIAL_DIGITS)) != NULL;
        if (ok) {
            for (slong s = 0; s < nv; s++) gamma[s] = digits[design_family_value_unknown(o->d, s)];
            const int claims[3] = {-1, -1, -1};
            char *text = vigen_design_method_text(o->d, o->base, "candidate", 1, 1, gamma, "a candidate", claims);
            vigen_error err;
            vigen_error_init(&err);
            double e = -1;
            o->evals++;
            if (vigen_design_method_error_constant(&e, text, o->d->order, o->family, &err) == VIGEN_OK && e >= 0) {
                ec = e;
                memcpy(o->x, x, (size_t)k * sizeof(double));
            }
            vigen_error_clear(&err);
            free(text);
        }
        for (slong j = 0; j < k; j++) free(digits[j]);
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

int design_minimize(double *xbest, double *ecbest, slong *nminima, long *evals, design_system *sys, slong *rows,
                    slong m, const vigen_design_spec *d, const char *base, double box)
{
    slong k = sys->k, nfree = k - m;
    slong *free_idx = malloc((size_t)nfree * sizeof(slong)), *pin_rows = malloc((size_t)nfree * sizeof(slong));
    design_free_unknowns(free_idx, sys, rows, m, d->seed);
    for (slong i = 0; i < nfree; i++) {
        pin_rows[i] = design_system_add_pin(sys, free_idx[i]);
        rows[m + i] = pin_rows[i];
    }
    int family = strcmp(d->minimize, "error_constant_separable") == 0 ? VIGEN_CHECK_EC_SEPARABLE
               : strcmp(d->minimize, "error_constant_nystrom") == 0 ? VIGEN_CHECK_EC_NYSTROM
                                                                    : VIGEN_CHECK_EC_GENERAL;
    gsl_error_handler_t *old = gsl_set_error_handler_off();
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, d->seed);
    double *x = malloc((size_t)k * sizeof(double)), *minima = malloc((size_t)(d->starts * MAX_BRANCHES * k + 1) *
                                                                           sizeof(double));
    objective o = {sys, rows, pin_rows, free_idx, nfree, x, d, base, family, 0};
    *ecbest = WORSE;
    *nminima = 0;
    for (long st = 0; st < d->starts; st++) {
        for (slong i = 0; i < nfree; i++) design_system_set_pin(sys, pin_rows[i], (2 * gsl_rng_uniform(rng) - 1) * box);
        double *roots = NULL;
        slong nb = design_newton_search(&roots, sys, rows, BRANCH_STARTS, d->seed + (unsigned long)st * 31, box);
        for (slong b = 0; b < nb && b < MAX_BRANCHES; b++) {
            memcpy(x, roots + b * k, (size_t)k * sizeof(double));
            double ec;
            descend(&ec, &o);
            if (ec >= WORSE) continue;
            int seen = 0;
            for (slong r = 0; r < *nminima && !seen; r++) {
                double dist = 0;
                for (slong j = 0; j < k; j++) dist = fmax(dist, fabs(x[j] - minima[r * k + j]));
                seen = dist < 1e-5;
            }
            if (!seen) memcpy(minima + (*nminima)++ * k, x, (size_t)k * sizeof(double));
            if (ec < *ecbest) {
                *ecbest = ec;
                memcpy(xbest, x, (size_t)k * sizeof(double));
            }
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
