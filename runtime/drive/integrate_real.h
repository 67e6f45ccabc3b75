/* integrate_real.h — vigen_integrate, n equal steps through a stepper type,
 * repeated for each real type (instantiated by integrate.c through
 * core/real_instances.h). */

int VIGEN_SFX(vigen_integrate)(const VIGEN_SFX(vigen_stepper_type) *T, void *w, VIGEN_REAL *t,
                               VIGEN_REAL *q, VIGEN_REAL *p, VIGEN_REAL h, unsigned long nsteps,
                               unsigned long every, VIGEN_SFX(vigen_observer_fn) obs, void *obs_ctx,
                               unsigned long *done)
{
    unsigned long k = 0;
    int status = VIGEN_SUCCESS;
    if (done) *done = 0;
    if (T == NULL || w == NULL || t == NULL || q == NULL || p == NULL) return VIGEN_EINVAL;
    if (obs && obs(0, *t, q, p, obs_ctx)) return VIGEN_ESTOPPED;
    while (k < nsteps) {
        status = T->step(w, t, q, p, h);
        if (status != VIGEN_SUCCESS) break;
        k++;
        if (obs && ((every && k % every == 0) || k == nsteps)) {
            if (obs(k, *t, q, p, obs_ctx)) { status = VIGEN_ESTOPPED; break; }
        }
    }
    if (done) *done = k;
    return status;
}
