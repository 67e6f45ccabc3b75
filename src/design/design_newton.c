/* design_newton.c — the search in double: a square subsystem of independent
 * conditions, and its real roots from many random starts (GSL's hybrid
 * Newton with the exact Jacobian of the polynomials), told apart by
 * distance.  Nothing here is certified: design_krawczyk.c proves what is
 * found. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_multiroots.h>
#include <gsl/gsl_rng.h>
#include "design/design_internal.h"
#include "support/progress.h"

/* a start that has not converged by then rarely does: the budget goes to
 * more starts instead */
#define GSL_ITERATIONS 60
#define RESIDUAL_TOL 1e-11
#define SAME_ROOT 1e-7
#define FAR 1e6

typedef struct {
    const design_system *sys;
    const slong *rows;
} params;

static int f_fn(const gsl_vector *x, void *p, gsl_vector *f)
{
    const params *pa = p;
    design_eval_d(f->data, NULL, pa->sys, pa->rows, pa->sys->k, x->data);
    return GSL_SUCCESS;
}

static int df_fn(const gsl_vector *x, void *p, gsl_matrix *J)
{
    const params *pa = p;
    slong k = pa->sys->k;
    double *jac = malloc((size_t)(k * k) * sizeof(double));
    design_eval_d(NULL, jac, pa->sys, pa->rows, k, x->data);
    for (slong i = 0; i < k; i++)
        for (slong j = 0; j < k; j++) gsl_matrix_set(J, (size_t)i, (size_t)j, jac[i * k + j]);
    free(jac);
    return GSL_SUCCESS;
}

static int fdf_fn(const gsl_vector *x, void *p, gsl_vector *f, gsl_matrix *J)
{
    f_fn(x, p, f);
    return df_fn(x, p, J);
}

/* max |v_i|, or NaN when some v_i is not finite (fmax would drop a NaN) */
static double max_abs(const double *v, slong n)
{
    double m = 0;
    for (slong i = 0; i < n; i++) {
        if (!isfinite(v[i])) return NAN;
        m = fmax(m, fabs(v[i]));
    }
    return m;
}

int design_newton_polish(double *x, const design_system *sys, const slong *rows, int iterations)
{
    slong k = sys->k;
    gsl_matrix *J = gsl_matrix_alloc((size_t)k, (size_t)k);
    gsl_vector *f = gsl_vector_alloc((size_t)k), *dx = gsl_vector_alloc((size_t)k);
    gsl_permutation *perm = gsl_permutation_alloc((size_t)k);
    params pa = {sys, rows};
    gsl_vector_view xv = gsl_vector_view_array(x, (size_t)k);
    int ok = 0;
    for (int it = 0; it < iterations; it++) {
        fdf_fn(&xv.vector, &pa, f, J);
        int sign;
        if (!isfinite(max_abs(f->data, k)) || gsl_linalg_LU_decomp(J, perm, &sign) != GSL_SUCCESS ||
            gsl_linalg_LU_solve(J, perm, f, dx) != GSL_SUCCESS)
            break;
        gsl_vector_sub(&xv.vector, dx);
        if (max_abs(dx->data, k) <= 1e-15 * (1 + max_abs(x, k))) break;
    }
    f_fn(&xv.vector, &pa, f);
    double res = max_abs(f->data, k);
    double size = max_abs(x, k);
    ok = isfinite(res) && res < RESIDUAL_TOL && isfinite(size) && size < FAR;
    gsl_permutation_free(perm);
    gsl_vector_free(dx);
    gsl_vector_free(f);
    gsl_matrix_free(J);
    return ok;
}

slong design_newton_search(double **sols, const design_system *sys, const slong *rows, slong starts,
                           unsigned long seed, double box)
{
    return design_newton_search_anchored(sols, sys, rows, starts, seed, box, NULL, 0);
}

slong design_newton_search_anchored(double **sols, const design_system *sys, const slong *rows, slong starts,
                                    unsigned long seed, double box, const double *anchor, slong nanchor)
{
    slong k = sys->k, n = 0, alloc = 8;
    *sols = malloc((size_t)(alloc * k) * sizeof(double));
    gsl_error_handler_t *old = gsl_set_error_handler_off();
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, seed);
    params pa = {sys, rows};
    gsl_multiroot_function_fdf fdf = {f_fn, df_fn, fdf_fn, (size_t)k, &pa};
    gsl_multiroot_fdfsolver *s = gsl_multiroot_fdfsolver_alloc(gsl_multiroot_fdfsolver_hybridsj, (size_t)k);
    gsl_vector *x0 = gsl_vector_alloc((size_t)k);
    double *x = malloc((size_t)k * sizeof(double));
    for (slong st = 0; st < starts; st++) {
        if (st % 64 == 0) vigen_progress_set("Newton start %ld of %ld: %ld roots", (long)st, (long)starts, (long)n);
        for (slong j = 0; j < k; j++)
            gsl_vector_set(x0, (size_t)j, j < nanchor ? anchor[j] : (2 * gsl_rng_uniform(rng) - 1) * box);
        gsl_multiroot_fdfsolver_set(s, &fdf, x0);
        int status = GSL_CONTINUE;
        for (int it = 0; it < GSL_ITERATIONS && status == GSL_CONTINUE; it++) {
            if (gsl_multiroot_fdfsolver_iterate(s) != GSL_SUCCESS) break;
            status = gsl_multiroot_test_residual(s->f, RESIDUAL_TOL);
        }
        memcpy(x, s->x->data, (size_t)k * sizeof(double));
        if (!design_newton_polish(x, sys, rows, 20)) continue;
        int seen = 0;
        for (slong r = 0; r < n && !seen; r++) {
            double d = 0;
            for (slong j = 0; j < k; j++) d = fmax(d, fabs(x[j] - (*sols)[r * k + j]) / (1 + fabs(x[j])));
            seen = d < SAME_ROOT;
        }
        if (seen) continue;
        if (n == alloc) {
            alloc *= 2;
            *sols = realloc(*sols, (size_t)(alloc * k) * sizeof(double));
        }
        memcpy(*sols + n * k, x, (size_t)k * sizeof(double));
        n++;
    }
    free(x);
    gsl_vector_free(x0);
    gsl_multiroot_fdfsolver_free(s);
    gsl_rng_free(rng);
    gsl_set_error_handler(old);
    return n;
}

slong design_square_rows(slong *rows, const design_system *sys, unsigned long seed)
{
    slong k = sys->k, m = 0;
    gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
    gsl_rng_set(rng, seed + 7919);
    double *x = malloc((size_t)k * sizeof(double)), *jac = malloc((size_t)(sys->n * k) * sizeof(double));
    for (slong j = 0; j < k; j++) x[j] = 2 * gsl_rng_uniform(rng) - 1;
    design_eval_d(NULL, jac, sys, NULL, sys->n, x);
    /* Gram-Schmidt on the rows, in order: a row is kept when its part
     * orthogonal to the rows kept is not negligible */
    double *basis = malloc((size_t)(k * k) * sizeof(double)), *v = malloc((size_t)k * sizeof(double));
    for (slong i = 0; i < sys->n && m < k; i++) {
        memcpy(v, jac + i * k, (size_t)k * sizeof(double));
        double norm0 = 0;
        for (slong j = 0; j < k; j++) norm0 += v[j] * v[j];
        for (int pass = 0; pass < 2; pass++)
            for (slong b = 0; b < m; b++) {
                double dot = 0;
                for (slong j = 0; j < k; j++) dot += v[j] * basis[b * k + j];
                for (slong j = 0; j < k; j++) v[j] -= dot * basis[b * k + j];
            }
        double norm = 0;
        for (slong j = 0; j < k; j++) norm += v[j] * v[j];
        if (norm0 == 0 || norm <= 1e-16 * norm0) continue;
        for (slong j = 0; j < k; j++) basis[m * k + j] = v[j] / sqrt(norm);
        rows[m++] = i;
    }
    free(basis);
    free(v);
    free(x);
    free(jac);
    gsl_rng_free(rng);
    return m;
}
