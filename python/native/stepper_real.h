/* stepper_real.h — the drivers of stepper.h for one real type.
 *
 * Included by stepper_drive.c only, once per type, with VPY_REAL the type
 * and VPY_SFX(name) adding its suffix (none, _ld), like the runtime's
 * runtime_real.h.  No include guard on purpose. */
#if !defined(VPY_REAL) || !defined(VPY_SFX)
#error "included by stepper_drive.c only"
#endif

typedef VIGEN_SFX_OF(vigen_stepper_type) VPY_SFX(vpy_type);

/* Where the observer of vigen_integrate writes its rows. */
typedef struct {
    size_t dim, rows, next;
    VPY_REAL *t, *q, *p;
} VPY_SFX(vpy_record);

static int VPY_SFX(vpy_observe)(unsigned long step, VPY_REAL t, const VPY_REAL *q, const VPY_REAL *p, void *ctx)
{
    (void)step;
    VPY_SFX(vpy_record) *r = ctx;
    if (r->next >= r->rows) return 1; /* more rows than the caller counted: stop, never overrun */
    r->t[r->next] = t;
    memcpy(r->q + r->next * r->dim, q, r->dim * sizeof *q);
    memcpy(r->p + r->next * r->dim, p, r->dim * sizeof *p);
    r->next++;
    return 0;
}

int VPY_SFX(vigen_python_integrate)(const void *type, void *w, VPY_REAL *t, VPY_REAL *q, VPY_REAL *p, VPY_REAL h,
                                    unsigned long nsteps, unsigned long every, VPY_REAL *t_rec, VPY_REAL *q_rec,
                                    VPY_REAL *p_rec, size_t rows, size_t *nrows, unsigned long *done)
{
    const VPY_SFX(vpy_type) *T = type;
    VPY_SFX(vpy_record) rec = { T->dim(w), rows, 0, t_rec, q_rec, p_rec };
    int rc = VPY_SFX(vigen_integrate)(T, w, t, q, p, h, nsteps, every, rows ? VPY_SFX(vpy_observe) : NULL,
                                      &rec, done);
    *nrows = rec.next;
    return rc;
}

int VPY_SFX(vigen_python_integrate_at)(const void *type, void *w, VPY_REAL *t, VPY_REAL *q, VPY_REAL *p,
                                       VPY_REAL h, const VPY_REAL *t_out, size_t n_out, VPY_REAL *q_out,
                                       VPY_REAL *p_out, unsigned long *done)
{
    return VPY_SFX(vigen_integrate_at)(type, w, t, q, p, h, t_out, n_out, q_out, p_out, done);
}

int VPY_SFX(vigen_python_integrate_events)(const void *type, void *w, VPY_REAL *t, VPY_REAL *q, VPY_REAL *p,
                                           VPY_REAL h, unsigned long nsteps,
                                           VPY_REAL (*g)(VPY_REAL, const VPY_REAL *, const VPY_REAL *, void *),
                                           void *ctx, int direction, int terminal, VPY_REAL *t_events,
                                           size_t max_events, size_t *n_events)
{
    return VPY_SFX(vigen_integrate_events)(type, w, t, q, p, h, nsteps, g, direction, terminal, ctx, t_events,
                                           max_events, n_events);
}

size_t VPY_SFX(vigen_python_stepper_dim)(const void *type, const void *w)
{
    return ((const VPY_SFX(vpy_type) *)type)->dim(w);
}

void VPY_SFX(vigen_python_stepper_reset)(const void *type, void *w)
{
    ((const VPY_SFX(vpy_type) *)type)->reset(w);
}

void VPY_SFX(vigen_python_stepper_free)(const void *type, void *w)
{
    if (w) ((const VPY_SFX(vpy_type) *)type)->free(w);
}

size_t VPY_SFX(vigen_python_state_size)(const void *type, const void *w)
{
    return ((const VPY_SFX(vpy_type) *)type)->state_size(w);
}

int VPY_SFX(vigen_python_state_get)(const void *type, const void *w, void *buf)
{
    return ((const VPY_SFX(vpy_type) *)type)->state_get(w, buf);
}

int VPY_SFX(vigen_python_state_set)(const void *type, void *w, const void *buf)
{
    return ((const VPY_SFX(vpy_type) *)type)->state_set(w, buf);
}

void VPY_SFX(vigen_python_stepper_stats)(const void *type, const void *w, unsigned long *out)
{
    const vigen_stats *s = ((const VPY_SFX(vpy_type) *)type)->stats(w);
    out[0] = s->steps;
    out[1] = s->failed_steps;
    out[2] = s->iterations;
    out[3] = s->dHdq_evals;
    out[4] = s->dHdp_evals;
}
