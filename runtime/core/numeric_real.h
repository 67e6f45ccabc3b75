/* numeric_real.h — finite-difference Jacobians, the type's epsilon and
 * compensated sums, repeated for each real type (instantiated by numeric.c
 * through real_instances.h). */

/* Moves *x by a step relative to max(|*x|, 1) and returns the step actually
 * represented. */
static VIGEN_REAL VIGEN_SFX(vigen_fd_bump)(VIGEN_REAL *x, double rel_step)
{
    const VIGEN_REAL xc = *x, ax = xc < 0 ? -xc : xc;
    *x = xc + (VIGEN_REAL)rel_step * (ax > 1 ? ax : 1);
    return *x - xc;
}

/* Column c of the Hessian is (grad(x + d e_c) - grad(x)) / d with
 * grad = (dH/dq, dH/dp) and x = (q, p); d is relative to |x_c|. */
void VIGEN_SFX(vigen_hessian_fd)(const VIGEN_SFX(vigen_hamiltonian) *sys, VIGEN_REAL t,
                                 const VIGEN_REAL *q, const VIGEN_REAL *p, double *hess,
                                 VIGEN_REAL *work, double rel_step, unsigned long *nq,
                                 unsigned long *np)
{
    const size_t n = sys->dim, n2 = 2 * n;
    VIGEN_REAL *x = work;              /* (q, p) perturbed in one component */
    VIGEN_REAL *g0 = work + n2;        /* gradients at (q, p) */
    VIGEN_REAL *g1 = work + 2 * n2;    /* gradients at the perturbed point */
    if (rel_step <= 0.0) rel_step = (double)VIGEN_SQRT(VIGEN_EPS);
    for (size_t k = 0; k < n; k++) { x[k] = q[k]; x[n + k] = p[k]; }
    sys->dHdq(t, x, x + n, g0, sys->ctx);
    sys->dHdp(t, x, x + n, g0 + n, sys->ctx);
    *nq += 1;
    *np += 1;
    for (size_t c = 0; c < n2; c++) {
        const VIGEN_REAL xc = x[c], d = VIGEN_SFX(vigen_fd_bump)(x + c, rel_step);
        sys->dHdq(t, x, x + n, g1, sys->ctx);
        sys->dHdp(t, x, x + n, g1 + n, sys->ctx);
        *nq += 1;
        *np += 1;
        for (size_t r = 0; r < n2; r++) hess[r * n2 + c] = (double)((g1[r] - g0[r]) / d);
        x[c] = xc;
    }
}

/* Column c is M^-1 (f(q + d e_c) - f(q)) / d; the step d as in
 * vigen_hessian_fd. */
void VIGEN_SFX(vigen_mechanical_jacobian_fd)(const VIGEN_SFX(vigen_mechanical) *sys, const VIGEN_REAL *inv_mass,
                                             VIGEN_REAL t, const VIGEN_REAL *q, double *hess, VIGEN_REAL *work,
                                             double rel_step, unsigned long *nf)
{
    const size_t n = sys->dim, n2 = 2 * n;
    VIGEN_REAL *x = work, *f0 = work + n, *f1 = work + 2 * n;
    if (rel_step <= 0.0) rel_step = (double)VIGEN_SQRT(VIGEN_EPS);
    for (size_t k = 0; k < n2 * n2; k++) hess[k] = 0.0;
    for (size_t k = 0; k < n; k++) x[k] = q[k];
    sys->force(t, x, f0, sys->ctx);
    *nf += 1;
    for (size_t c = 0; c < n; c++) {
        const VIGEN_REAL xc = x[c], d = VIGEN_SFX(vigen_fd_bump)(x + c, rel_step);
        sys->force(t, x, f1, sys->ctx);
        *nf += 1;
        for (size_t r = 0; r < n; r++) hess[(n + r) * n2 + c] = (double)(inv_mass[r] * (f1[r] - f0[r]) / d);
        x[c] = xc;
    }
}

double VIGEN_SFX(vigen_epsilon)(void) { return (double)VIGEN_EPS; }
double VIGEN_SFX(vigen_default_tol)(void) { return 1048576.0 * (double)VIGEN_EPS; }

VIGEN_REAL VIGEN_SFX(vigen_sum_kahan)(const VIGEN_REAL *x, size_t n)
{
    VIGEN_REAL s = 0, c = 0;
    for (size_t i = 0; i < n; i++) {
        VIGEN_REAL t = s + x[i];
        VIGEN_REAL bb = t - s;
        c += (s - (t - bb)) + (x[i] - bb);   /* TwoSum error, Neumaier style */
        s = t;
    }
    return s + c;
}
