/* events_real.h — sign changes of an event function along a run of steps
 * (vigen_integrate_events), repeated for each real type (instantiated by
 * integrate.c after dense_real.h, whose continuous extension it searches).
 *
 * A step whose end values of g have opposite signs is searched in the
 * extension's parameter s in [0, 1] (t = t0 + s h): GSL's Brent solver
 * closes the bracket to double round-off, then a bracketing iteration in
 * the real type (Illinois regula falsi, every third step a bisection so
 * that the bracket at least halves) takes it to the type's round-off. */

/* g along the extension of the current step. */
typedef struct {
    VIGEN_SFX(vigen_dense) *d;
    VIGEN_SFX(vigen_event_fn) g;
    void *ctx;
    VIGEN_REAL t1;
    const VIGEN_REAL *q1, *p1;
    int status;   /* first non-finite extension or value of g */
} VIGEN_SFX(vigen_event_line);

static VIGEN_REAL VIGEN_SFX(vigen_event_at)(VIGEN_SFX(vigen_event_line) *L, VIGEN_REAL s)
{
    VIGEN_SFX(vigen_dense) *d = L->d;
    const VIGEN_REAL t = s == 1 ? L->t1 : d->t0 + s * (L->t1 - d->t0);
    int status = VIGEN_SFX(vigen_dense_eval)(d, L->t1, L->q1, L->p1, s, d->y, d->y + d->n);
    VIGEN_REAL v = 0;
    if (status == VIGEN_SUCCESS) {
        v = L->g(t, d->y, d->y + d->n, L->ctx);
        if (d->st) d->st->event_evals++;
        if (!(v - v == 0)) status = VIGEN_ENONFINITE;
    }
    if (status != VIGEN_SUCCESS) {
        if (L->status == VIGEN_SUCCESS) L->status = status;
        v = 0;   /* ends the search; the status reports it */
    }
    return v;
}

static double VIGEN_SFX(vigen_event_gsl)(double s, void *params)
{
    return (double)VIGEN_SFX(vigen_event_at)(params, (VIGEN_REAL)s);
}

static VIGEN_REAL VIGEN_SFX(vigen_event_abs)(VIGEN_REAL x) { return x < 0 ? -x : x; }

/* Refines the bracket [a, b] (ga, gb of opposite signs) in the real type;
 * *s receives the end with the smaller |g|. */
static int VIGEN_SFX(vigen_event_refine)(VIGEN_SFX(vigen_event_line) *L, VIGEN_REAL a, VIGEN_REAL ga, VIGEN_REAL b,
                                        VIGEN_REAL gb, VIGEN_REAL *s)
{
    for (int it = 0;; it++) {
        const VIGEN_REAL lo = a < b ? a : b, hi = a < b ? b : a;
        const VIGEN_REAL scale = VIGEN_SFX(vigen_event_abs)(hi) + (VIGEN_REAL)0x1p-20;
        if (ga == 0 || gb == 0 || hi - lo <= 4 * VIGEN_EPS * scale) break;
        if (it == 400) return VIGEN_ENOCONV;
        VIGEN_REAL c = (it % 3 == 2) ? lo + (hi - lo) / 2 : b - gb * (b - a) / (gb - ga);
        if (!(c > lo && c < hi)) c = lo + (hi - lo) / 2;
        if (!(c > lo && c < hi)) break;   /* no number between the ends */
        const VIGEN_REAL gc = VIGEN_SFX(vigen_event_at)(L, c);
        if (L->status != VIGEN_SUCCESS) return L->status;
        if (L->d->st) L->d->st->root_iterations++;
        if ((gc < 0) != (gb < 0)) {
            a = b;
            ga = gb;
        } else {
            ga /= 2;   /* Illinois: the end kept twice counts half */
        }
        b = c;
        gb = gc;
    }
    *s = VIGEN_SFX(vigen_event_abs)(gb) <= VIGEN_SFX(vigen_event_abs)(ga) ? b : a;
    return VIGEN_SUCCESS;
}

/* The zero of g on the current step, g0 and g1 its values at the ends
 * (opposite signs, g0 != 0). */
static int VIGEN_SFX(vigen_event_locate)(VIGEN_SFX(vigen_event_line) *L, gsl_root_fsolver **solver,
                                        VIGEN_REAL g0, VIGEN_REAL g1, VIGEN_REAL *s)
{
    double lo = 0, hi = 1;
    if (g1 == 0) {
        *s = 1;
        return VIGEN_SUCCESS;
    }
    /* Brent in double, unless g's values round to zero or to one sign in
     * double (then the real type's bracketing does all the work). */
    if ((double)g0 * (double)g1 < 0) {
        gsl_function F;
        F.function = VIGEN_SFX(vigen_event_gsl);
        F.params = L;
        if (*solver == NULL) *solver = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
        if (*solver == NULL) return VIGEN_ENOMEM;
        gsl_root_fsolver_set(*solver, &F, 0.0, 1.0);
        for (int it = 0;; it++) {
            if (it == 200) return VIGEN_ENOCONV;
            gsl_root_fsolver_iterate(*solver);
            if (L->status != VIGEN_SUCCESS) return L->status;
            if (L->d->st) L->d->st->root_iterations++;
            lo = gsl_root_fsolver_x_lower(*solver);
            hi = gsl_root_fsolver_x_upper(*solver);
            if (gsl_root_test_interval(lo, hi, DBL_EPSILON, DBL_EPSILON) == GSL_SUCCESS) break;
        }
    }
    VIGEN_REAL a = lo, b = hi, ga = g0, gb = g1;
    if (lo > 0) ga = VIGEN_SFX(vigen_event_at)(L, a);
    if (hi < 1) gb = VIGEN_SFX(vigen_event_at)(L, b);
    if (L->status != VIGEN_SUCCESS) return L->status;
    if (ga != 0 && gb != 0 && (ga < 0) == (gb < 0)) {
        /* the double bracket lost the sign change in the real type */
        a = 0, ga = g0, b = 1, gb = g1;
    }
    return VIGEN_SFX(vigen_event_refine)(L, a, ga, b, gb, s);
}

int VIGEN_SFX(vigen_integrate_events_sys)(const VIGEN_SFX(vigen_stepper_type) *T, void *w,
                                          const VIGEN_SFX(vigen_hamiltonian) *sys, VIGEN_REAL *t, VIGEN_REAL *q,
                                          VIGEN_REAL *p, VIGEN_REAL h, unsigned long nsteps,
                                          VIGEN_SFX(vigen_event_fn) g, int direction, int terminal, void *ctx,
                                          VIGEN_REAL *t_events, size_t max_events, size_t *n_events,
                                          vigen_dense_stats *st)
{
    VIGEN_SFX(vigen_dense) d;
    VIGEN_SFX(vigen_event_line) L;
    gsl_root_fsolver *solver = NULL;
    unsigned long steps = 0;
    size_t found = 0;
    if (n_events) *n_events = 0;
    if (st) memset(st, 0, sizeof *st);
    int status = VIGEN_SFX(vigen_dense_args)(T, w, t, q, p, h);
    if (status != VIGEN_SUCCESS) return status;
    if (g == NULL || n_events == NULL || (max_events > 0 && t_events == NULL) || direction < -1 || direction > 1)
        return VIGEN_EINVAL;
    status = VIGEN_SFX(vigen_dense_open)(&d, T, w, sys, st);
    if (status != VIGEN_SUCCESS) {
        VIGEN_SFX(vigen_dense_close)(&d);
        return status;
    }
    L.d = &d;
    L.g = g;
    L.ctx = ctx;
    L.status = VIGEN_SUCCESS;
    VIGEN_REAL g0 = g(*t, q, p, ctx);
    if (st) st->event_evals++;
    if (!(g0 - g0 == 0)) status = VIGEN_ENONFINITE;
    while (steps < nsteps && status == VIGEN_SUCCESS) {
        VIGEN_SFX(vigen_dense_begin)(&d, *t, q, p);
        status = T->step(w, t, q, p, h);
        if (status != VIGEN_SUCCESS) break;
        steps++;
        const VIGEN_REAL g1 = g(*t, q, p, ctx);
        if (st) st->event_evals++;
        if (!(g1 - g1 == 0)) {
            status = VIGEN_ENONFINITE;
            break;
        }
        const int rising = g0 < 0 && g1 >= 0, falling = g0 > 0 && g1 <= 0;
        if ((rising && direction >= 0) || (falling && direction <= 0)) {
            VIGEN_REAL s = 1;
            L.t1 = *t;
            L.q1 = q;
            L.p1 = p;
            status = VIGEN_SFX(vigen_dense_slopes)(&d, *t, q, p);
            if (status == VIGEN_SUCCESS) status = VIGEN_SFX(vigen_event_locate)(&L, &solver, g0, g1, &s);
            if (status != VIGEN_SUCCESS) break;
            const VIGEN_REAL te = s == 1 ? *t : (s == 0 ? d.t0 : d.t0 + s * (*t - d.t0));
            if (found < max_events) t_events[found] = te;
            found++;
            if (terminal) {
                status = VIGEN_SFX(vigen_dense_eval)(&d, *t, q, p, s, d.y, d.y + d.n);
                if (status == VIGEN_SUCCESS) {
                    memcpy(q, d.y, d.n * sizeof *q);
                    memcpy(p, d.y + d.n, d.n * sizeof *p);
                    *t = te;
                }
                break;
            }
        }
        g0 = g1;
    }
    if (solver) gsl_root_fsolver_free(solver);
    VIGEN_SFX(vigen_dense_close)(&d);
    *n_events = found;
    if (st) st->steps = steps;
    return status;
}

int VIGEN_SFX(vigen_integrate_events)(const VIGEN_SFX(vigen_stepper_type) *T, void *w, VIGEN_REAL *t,
                                      VIGEN_REAL *q, VIGEN_REAL *p, VIGEN_REAL h, unsigned long nsteps,
                                      VIGEN_SFX(vigen_event_fn) g, int direction, int terminal, void *ctx,
                                      VIGEN_REAL *t_events, size_t max_events, size_t *n_events)
{
    return VIGEN_SFX(vigen_integrate_events_sys)(T, w, NULL, t, q, p, h, nsteps, g, direction, terminal, ctx,
                                                 t_events, max_events, n_events, NULL);
}
