/* dense_real.h — the continuous extension of a run of steps and output at
 * any time (vigen_integrate_at), repeated for each real type (instantiated
 * by integrate.c through core/real_instances.h).  events_real.h uses
 * the extension too.
 *
 * The extension on a step from (t0, y0) to (t1, y1), y = (q, p), is the
 * cubic Hermite polynomial with the flow's slopes f = (q', p') at both ends
 * (the stepper type's vector field, or (dH/dp, -dH/dq) of a given H): with h = t1 - t0 and s = (t - t0) / h,
 *     y(s) = (1 + 2s)(1 - s)^2 y0 + s^2 (3 - 2s) y1 + h s (1 - s)^2 f(y0) - h s^2 (1 - s) f(y1).
 * It reproduces y0 and y1 exactly (the weights are exactly 0 and 1 there)
 * and interpolates a smooth solution with error h^4 max|y''''| / 384; the
 * step ends themselves carry the method's global error.  Neither the stage
 * values nor the collocation polynomial would do better for every method:
 * the s-stage Gauss collocation polynomial has order s only, and the
 * stages of explicit splitting methods are not points of the solution. */

typedef struct {
    const VIGEN_SFX(vigen_stepper_type) *T;
    void *w;
    const VIGEN_SFX(vigen_hamiltonian) *sys;  /* the problem given to a _sys driver, else NULL:
                                                 the slopes come from T->vector_field */
    size_t n;
    VIGEN_REAL *mem;
    VIGEN_REAL *y0, *f0, *f1, *y;      /* 2 n each: start state, slopes at start and end, scratch */
    VIGEN_REAL t0;
    int f0_ok, f1_ok;                  /* the slopes are those of the current step's ends */
    vigen_dense_stats *st;
} VIGEN_SFX(vigen_dense);

/* Takes the flow (sys, or the type's vector field when sys is NULL) and the
 * buffers.  VIGEN_EINVAL when there is no usable flow, VIGEN_ENOMEM. */
static int VIGEN_SFX(vigen_dense_open)(VIGEN_SFX(vigen_dense) *d, const VIGEN_SFX(vigen_stepper_type) *T, void *w,
                                      const VIGEN_SFX(vigen_hamiltonian) *sys, vigen_dense_stats *st)
{
    memset(d, 0, sizeof *d);
    d->st = st;
    d->T = T;
    d->w = w;
    if (sys) {
        if (sys->dHdq == NULL || sys->dHdp == NULL) return VIGEN_EINVAL;
        d->sys = sys;
        d->n = sys->dim;
    } else {
        if (T->vector_field == NULL || T->dim == NULL) return VIGEN_EINVAL;
        d->n = T->dim(w);
    }
    if (d->n == 0) return VIGEN_EINVAL;
    if (d->n > (size_t)-1 / (8 * sizeof(VIGEN_REAL))) return VIGEN_ENOMEM;
    d->mem = malloc(8 * d->n * sizeof(VIGEN_REAL));
    if (d->mem == NULL) return VIGEN_ENOMEM;
    d->y0 = d->mem;
    d->f0 = d->mem + 2 * d->n;
    d->f1 = d->mem + 4 * d->n;
    d->y = d->mem + 6 * d->n;
    return VIGEN_SUCCESS;
}

static void VIGEN_SFX(vigen_dense_close)(VIGEN_SFX(vigen_dense) *d) { free(d->mem); }

/* Remembers the state before a step; the slope at the previous step's end
 * (if it was needed) is the slope at this step's start. */
static void VIGEN_SFX(vigen_dense_begin)(VIGEN_SFX(vigen_dense) *d, VIGEN_REAL t, const VIGEN_REAL *q,
                                        const VIGEN_REAL *p)
{
    VIGEN_REAL *f = d->f0;
    d->f0 = d->f1;
    d->f1 = f;
    d->f0_ok = d->f1_ok;
    d->f1_ok = 0;
    d->t0 = t;
    memcpy(d->y0, q, d->n * sizeof *q);
    memcpy(d->y0 + d->n, p, d->n * sizeof *p);
}

static int VIGEN_SFX(vigen_dense_finite)(const VIGEN_REAL *x, size_t n)
{
    for (size_t k = 0; k < n; k++)
        if (!(x[k] - x[k] == 0)) return 0;   /* NaN and infinities give NaN */
    return 1;
}

/* f = (q', p') at (t, q, p): (dH/dp, -dH/dq) of the given problem, or the
 * type's vector field. */
static int VIGEN_SFX(vigen_dense_slope)(VIGEN_SFX(vigen_dense) *d, VIGEN_REAL t, const VIGEN_REAL *q,
                                       const VIGEN_REAL *p, VIGEN_REAL *f)
{
    const size_t n = d->n;
    int status = VIGEN_SUCCESS;
    if (d->sys) {
        d->sys->dHdp(t, q, p, f, d->sys->ctx);
        d->sys->dHdq(t, q, p, f + n, d->sys->ctx);
        for (size_t k = 0; k < n; k++) f[n + k] = -f[n + k];
    } else {
        status = d->T->vector_field(d->w, t, q, p, f, f + n);
    }
    if (d->st) {
        d->st->dHdp_evals++;
        d->st->dHdq_evals++;
    }
    if (status != VIGEN_SUCCESS) return status;
    return VIGEN_SFX(vigen_dense_finite)(f, 2 * n) ? VIGEN_SUCCESS : VIGEN_ENONFINITE;
}

/* Both slopes of the step that ended at (t1, q1, p1), evaluated once. */
static int VIGEN_SFX(vigen_dense_slopes)(VIGEN_SFX(vigen_dense) *d, VIGEN_REAL t1, const VIGEN_REAL *q1,
                                        const VIGEN_REAL *p1)
{
    int status;
    if (!d->f0_ok) {
        status = VIGEN_SFX(vigen_dense_slope)(d, d->t0, d->y0, d->y0 + d->n, d->f0);
        if (status != VIGEN_SUCCESS) return status;
        d->f0_ok = 1;
    }
    if (!d->f1_ok) {
        status = VIGEN_SFX(vigen_dense_slope)(d, t1, q1, p1, d->f1);
        if (status != VIGEN_SUCCESS) return status;
        d->f1_ok = 1;
    }
    return VIGEN_SUCCESS;
}

/* The extension at s in [0, 1] of the step ending at (t1, q1, p1) (slopes
 * available) into qo, po. */
static int VIGEN_SFX(vigen_dense_eval)(const VIGEN_SFX(vigen_dense) *d, VIGEN_REAL t1, const VIGEN_REAL *q1,
                                      const VIGEN_REAL *p1, VIGEN_REAL s, VIGEN_REAL *qo, VIGEN_REAL *po)
{
    const size_t n = d->n;
    const VIGEN_REAL h = t1 - d->t0, r = 1 - s;
    const VIGEN_REAL w0 = (1 + 2 * s) * r * r, w1 = s * s * (3 - 2 * s);
    const VIGEN_REAL v0 = h * s * r * r, v1 = -h * s * s * r;
    for (size_t k = 0; k < n; k++) {
        qo[k] = w0 * d->y0[k] + w1 * q1[k] + (v0 * d->f0[k] + v1 * d->f1[k]);
        po[k] = w0 * d->y0[n + k] + w1 * p1[k] + (v0 * d->f0[n + k] + v1 * d->f1[n + k]);
    }
    return VIGEN_SFX(vigen_dense_finite)(qo, n) && VIGEN_SFX(vigen_dense_finite)(po, n) ? VIGEN_SUCCESS
                                                                                       : VIGEN_ENONFINITE;
}

/* Common argument checks of the drivers. */
static int VIGEN_SFX(vigen_dense_args)(const VIGEN_SFX(vigen_stepper_type) *T, const void *w, const VIGEN_REAL *t,
                                      const VIGEN_REAL *q, const VIGEN_REAL *p, VIGEN_REAL h)
{
    if (T == NULL || T->step == NULL || w == NULL || t == NULL || q == NULL || p == NULL) return VIGEN_EINVAL;
    if (!(h - h == 0) || h == 0 || !(*t - *t == 0)) return VIGEN_EINVAL;
    return VIGEN_SUCCESS;
}

int VIGEN_SFX(vigen_integrate_at_sys)(const VIGEN_SFX(vigen_stepper_type) *T, void *w,
                                      const VIGEN_SFX(vigen_hamiltonian) *sys, VIGEN_REAL *t, VIGEN_REAL *q,
                                      VIGEN_REAL *p, VIGEN_REAL h, const VIGEN_REAL *t_out, size_t n_out,
                                      VIGEN_REAL *q_out, VIGEN_REAL *p_out, unsigned long *done,
                                      vigen_dense_stats *st)
{
    const VIGEN_REAL dir = h > 0 ? 1 : -1;
    unsigned long steps = 0;
    size_t k = 0;
    VIGEN_SFX(vigen_dense) d;
    if (done) *done = 0;
    if (st) memset(st, 0, sizeof *st);
    int status = VIGEN_SFX(vigen_dense_args)(T, w, t, q, p, h);
    if (status != VIGEN_SUCCESS) return status;
    if (n_out > 0 && (t_out == NULL || q_out == NULL || p_out == NULL)) return VIGEN_EINVAL;
    for (size_t j = 0; j < n_out; j++) {
        const VIGEN_REAL before = j ? t_out[j - 1] : *t;
        if (!(t_out[j] - t_out[j] == 0) || dir * (t_out[j] - before) < 0) return VIGEN_EINVAL;
    }
    /* The steps needed, with room for the rounding of t; a step too small
     * to move t would otherwise never reach the last output time. */
    const VIGEN_REAL t_start = *t;
    VIGEN_REAL needed = n_out ? (t_out[n_out - 1] - *t) / h : 0;
    if (!(needed < (VIGEN_REAL)(ULONG_MAX / 2))) return VIGEN_EINVAL;
    unsigned long cap = (unsigned long)(needed + needed / 4) + 16;
    if (n_out == 0) return VIGEN_SUCCESS;
    status = VIGEN_SFX(vigen_dense_open)(&d, T, w, sys, st);
    if (status != VIGEN_SUCCESS) {
        VIGEN_SFX(vigen_dense_close)(&d);
        return status;
    }
    const size_t n = d.n;
    for (; k < n_out && t_out[k] == *t; k++) {
        memcpy(q_out + k * n, q, n * sizeof *q);
        memcpy(p_out + k * n, p, n * sizeof *p);
    }
    while (k < n_out && status == VIGEN_SUCCESS) {
        if (steps == cap) {
            /* A step that does not advance t by h (a Poincare workspace
             * steps in fictive time) is judged by the average advance of
             * the steps taken: none, or too little to finish, is h too
             * small to move t. */
            const VIGEN_REAL rate = (*t - t_start) / (VIGEN_REAL)steps;
            needed = dir * rate > 0 ? (t_out[n_out - 1] - *t) / rate : (VIGEN_REAL)ULONG_MAX;
            if (!(needed < (VIGEN_REAL)(ULONG_MAX / 4))) {
                status = VIGEN_EINVAL;
                break;
            }
            cap = steps + (unsigned long)(needed + needed / 4) + 16;
        }
        VIGEN_SFX(vigen_dense_begin)(&d, *t, q, p);
        status = T->step(w, t, q, p, h);
        if (status != VIGEN_SUCCESS) break;
        steps++;
        for (; k < n_out && dir * (t_out[k] - *t) <= 0; k++) {
            if (t_out[k] == *t) {
                memcpy(q_out + k * n, q, n * sizeof *q);
                memcpy(p_out + k * n, p, n * sizeof *p);
                continue;
            }
            status = VIGEN_SFX(vigen_dense_slopes)(&d, *t, q, p);
            if (status == VIGEN_SUCCESS)
                status = VIGEN_SFX(vigen_dense_eval)(&d, *t, q, p, (t_out[k] - d.t0) / (*t - d.t0), q_out + k * n,
                                                     p_out + k * n);
            if (status != VIGEN_SUCCESS) break;
        }
    }
    VIGEN_SFX(vigen_dense_close)(&d);
    if (done) *done = steps;
    if (st) st->steps = steps;
    return status;
}

int VIGEN_SFX(vigen_integrate_at)(const VIGEN_SFX(vigen_stepper_type) *T, void *w, VIGEN_REAL *t, VIGEN_REAL *q,
                                  VIGEN_REAL *p, VIGEN_REAL h, const VIGEN_REAL *t_out, size_t n_out,
                                  VIGEN_REAL *q_out, VIGEN_REAL *p_out, unsigned long *done)
{
    return VIGEN_SFX(vigen_integrate_at_sys)(T, w, NULL, t, q, p, h, t_out, n_out, q_out, p_out, done, NULL);
}
