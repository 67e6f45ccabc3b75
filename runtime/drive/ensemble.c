/* ensemble.c — vigen_integrate_ensemble: independent trajectories of one
 * problem shared among OpenMP threads, one workspace per thread, a status
 * per trajectory (vigen/ensemble.h), through the stepper type only.
 * Without OpenMP the same loop runs serially. */
#include <stdlib.h>
#include "vigen/ensemble.h"

#ifdef _OPENMP
#include <omp.h>
#endif

int vigen_ensemble_max_threads(void)
{
#ifdef _OPENMP
    return omp_get_max_threads();
#else
    return 1;
#endif
}

static void *make_workspace(const vigen_ensemble *e)
{
    if (e->alloc) return e->alloc(e->alloc_ctx);
    if (e->prototype) return e->type->clone(e->prototype);
    return e->type->alloc(e->sys, e->opt);
}

int vigen_integrate_ensemble(const vigen_ensemble *e, size_t ntraj, double *t, double *q, double *p, double h,
                             unsigned long nsteps, int *status, unsigned long *steps)
{
    if (e == NULL || e->type == NULL || e->type->reset == NULL || status == NULL) return VIGEN_EINVAL;
    if (e->alloc == NULL && e->prototype == NULL && (e->sys == NULL || e->type->alloc == NULL)) return VIGEN_EINVAL;
    if (e->alloc == NULL && e->prototype && e->type->clone == NULL) return VIGEN_EINVAL;
    size_t dim = e->dim;
    if (dim == 0 && e->sys) dim = e->sys->dim;
    if (dim == 0 && e->prototype && e->type->dim) dim = e->type->dim(e->prototype);
    if (dim == 0 || (e->sys && e->sys->dim != dim) || !(h - h == 0)) return VIGEN_EINVAL;
    if (ntraj == 0) return VIGEN_SUCCESS;
    if (t == NULL || q == NULL || p == NULL) return VIGEN_EINVAL;

    int nt = e->threads > 0 ? e->threads : vigen_ensemble_max_threads();
    if ((size_t)nt > ntraj) nt = (int)ntraj;
#ifndef _OPENMP
    nt = 1;
#endif
    /* the workspaces are made here, before any trajectory moves, so that a
     * failure leaves everything as it was */
    void **ws = calloc((size_t)nt, sizeof *ws);
    if (ws == NULL) return VIGEN_ENOMEM;
    int rc = VIGEN_SUCCESS;
    for (int k = 0; k < nt && rc == VIGEN_SUCCESS; k++)
        if ((ws[k] = make_workspace(e)) == NULL) rc = VIGEN_ENOMEM;

    if (rc == VIGEN_SUCCESS) {
        const long long n = (long long)ntraj;
#ifdef _OPENMP
#pragma omp parallel for num_threads(nt) schedule(static)
#endif
        for (long long i = 0; i < n; i++) {
#ifdef _OPENMP
            void *w = ws[omp_get_thread_num()];
#else
            void *w = ws[0];
#endif
            unsigned long done = 0;
            /* a fresh start: no compensation, history or cached gradient
             * of the trajectory this workspace ran before */
            e->type->reset(w);
            status[i] = vigen_integrate(e->type, w, t + i, q + (size_t)i * dim, p + (size_t)i * dim, h, nsteps, 0,
                                        NULL, NULL, &done);
            if (steps) steps[i] = done;
        }
        for (size_t i = 0; i < ntraj; i++)
            if (status[i] != VIGEN_SUCCESS) {
                rc = status[i];
                break;
            }
    }
    for (int k = 0; k < nt; k++)
        if (ws[k]) e->type->free(ws[k]);
    free(ws);
    return rc;
}
