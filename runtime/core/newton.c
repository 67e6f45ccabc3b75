/* newton.c — the linear algebra of simplified Newton for PRK stage equations
 * and for their Nystrom form (GSL LU with GSL's aborting error handler
 * switched off). */
#include <stdlib.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_permutation.h>
#include <gsl/gsl_vector.h>
#include <vigen/runtime.h>

struct vigen_newton {
    size_t s, n, N;           /* stages, dimension, N = 2 s n (s n in Nystrom form) */
    double *hess;             /* (2n)^2, row-major */
    gsl_matrix *M;
    gsl_permutation *perm;
    gsl_vector *rhs, *x;
};

/* The solver with N unknowns in stage blocks of dim. */
static vigen_newton *newton_alloc(size_t stages, size_t dim, size_t N)
{
    if (stages == 0 || dim == 0) return NULL;
    gsl_set_error_handler_off();
    vigen_newton *nw = calloc(1, sizeof *nw);
    if (nw == NULL) return NULL;
    nw->s = stages;
    nw->n = dim;
    nw->N = N;
    nw->hess = calloc(4 * dim * dim, sizeof(double));
    nw->M = gsl_matrix_alloc(nw->N, nw->N);
    nw->perm = gsl_permutation_alloc(nw->N);
    nw->rhs = gsl_vector_alloc(nw->N);
    nw->x = gsl_vector_alloc(nw->N);
    if (!nw->hess || !nw->M || !nw->perm || !nw->rhs || !nw->x) {
        vigen_newton_free(nw);
        return NULL;
    }
    return nw;
}

vigen_newton *vigen_newton_alloc(size_t stages, size_t dim) { return newton_alloc(stages, dim, 2 * stages * dim); }

vigen_newton *vigen_newton_alloc_nystrom(size_t stages, size_t dim) { return newton_alloc(stages, dim, stages * dim); }

void vigen_newton_free(vigen_newton *nw)
{
    if (nw == NULL) return;
    free(nw->hess);
    if (nw->M) gsl_matrix_free(nw->M);
    if (nw->perm) gsl_permutation_free(nw->perm);
    if (nw->rhs) gsl_vector_free(nw->rhs);
    if (nw->x) gsl_vector_free(nw->x);
    free(nw);
}

double *vigen_newton_hessian(vigen_newton *nw) { return nw->hess; }
double *vigen_newton_rhs(vigen_newton *nw) { return nw->rhs->data; }

void vigen_newton_matrix_identity(vigen_newton *nw) { gsl_matrix_set_identity(nw->M); }

/* Q rows of stage i: M[Qi, Qj] -= ha Hpq,  M[Qi, Pj] -= ha Hpp;
 * P rows of stage i: M[Pi, Qj] += hat Hqq, M[Pi, Pj] += hat Hqp.
 * In Nystrom form only the first: M[Qi, Qj] -= ha Hpq. */
void vigen_newton_matrix_block(vigen_newton *nw, size_t i, size_t j, double ha, double hat)
{
    const size_t n = nw->n, s = nw->s, n2 = 2 * n;
    if (nw->N == s * n) {
        for (size_t r = 0; r < n; r++) {
            const double *hp = nw->hess + (n + r) * n2;
            double *mq = gsl_matrix_ptr(nw->M, i * n + r, 0);
            for (size_t k = 0; k < n && ha != 0.0; k++) mq[j * n + k] -= ha * hp[k];
        }
        return;
    }
    const size_t qi = i * n, pi = (s + i) * n, qj = j * n, pj = (s + j) * n;
    for (size_t r = 0; r < n; r++) {
        const double *hq = nw->hess + r * n2;          /* row r of d(dH/dq)/d(q,p) */
        const double *hp = nw->hess + (n + r) * n2;    /* row r of d(dH/dp)/d(q,p) */
        double *mq = gsl_matrix_ptr(nw->M, qi + r, 0);
        double *mp = gsl_matrix_ptr(nw->M, pi + r, 0);
        if (ha != 0.0) {
            for (size_t k = 0; k < n; k++) {
                mq[qj + k] -= ha * hp[k];
                mq[pj + k] -= ha * hp[n + k];
            }
        }
        if (hat != 0.0) {
            for (size_t k = 0; k < n; k++) {
                mp[qj + k] += hat * hq[k];
                mp[pj + k] += hat * hq[n + k];
            }
        }
    }
}

/* Whether x[0 .. n-1] are all finite (x - x is 0 exactly when x is). */
static int all_finite(const double *x, size_t n)
{
    int ok = 1;
    for (size_t k = 0; k < n; k++) ok &= (x[k] - x[k] == 0);
    return ok;
}

/* A NaN or infinity in M (from the Hessian: gradients that are not finite)
 * is VIGEN_ENONFINITE, not a singular matrix; so is a factorisation that
 * overflows.  A zero pivot is VIGEN_ESINGULAR. */
int vigen_newton_factor(vigen_newton *nw)
{
    int signum = 0;
    for (size_t r = 0; r < nw->N; r++)
        if (!all_finite(gsl_matrix_ptr(nw->M, r, 0), nw->N)) return VIGEN_ENONFINITE;
    if (gsl_linalg_LU_decomp(nw->M, nw->perm, &signum) != GSL_SUCCESS) return VIGEN_ESINGULAR;
    for (size_t k = 0; k < nw->N; k++) {
        double d = gsl_matrix_get(nw->M, k, k);
        if (d == 0.0) return VIGEN_ESINGULAR;
        if (!(d - d == 0)) return VIGEN_ENONFINITE;
    }
    return VIGEN_SUCCESS;
}

/* A right-hand side or a solution that is not finite is VIGEN_ENONFINITE. */
int vigen_newton_solve(vigen_newton *nw)
{
    if (!all_finite(nw->rhs->data, nw->N)) return VIGEN_ENONFINITE;
    if (gsl_linalg_LU_solve(nw->M, nw->perm, nw->rhs, nw->x) != GSL_SUCCESS) return VIGEN_ESINGULAR;
    if (!all_finite(nw->x->data, nw->N)) return VIGEN_ENONFINITE;
    gsl_vector_memcpy(nw->rhs, nw->x);
    return VIGEN_SUCCESS;
}
