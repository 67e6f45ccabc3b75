/* poincare_stepper.c — a Poincare-transformed stepper as a stepper type
 * (vigen_poincare_type, vigen/poincare.h): a workspace holding the
 * transformed problem and a workspace of the stepper that integrates K,
 * whose step is one fictive step dtau = h that advances the physical time
 * by its own amount.  vigen_poincare_integrate takes the same steps
 * (vigen_poincare_fictive_step) and adds the shortened last one. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "poincare_internal.h"

struct vigen_poincare_stepper {
    const vigen_stepper_type *T;
    vigen_solver_options opt;   /* the inner workspace's (clones are made with them) */
    vigen_poincare *pc;
    void *w;                    /* T's workspace for K */
};

vigen_poincare_stepper *vigen_poincare_stepper_alloc(const vigen_stepper_type *T, const vigen_poincare_problem *pb,
                                                     const vigen_solver_options *opt)
{
    if (T == NULL || T->alloc == NULL || T->step == NULL || T->free == NULL) return NULL;
    vigen_poincare_stepper *s = calloc(1, sizeof *s);
    if (s == NULL) return NULL;
    s->T = T;
    if (opt) s->opt = *opt;
    else vigen_solver_options_default(&s->opt);
    if (vigen_poincare_alloc(&s->pc, pb) == VIGEN_SUCCESS) s->w = T->alloc(vigen_poincare_hamiltonian(s->pc), &s->opt);
    if (s->w == NULL) {
        vigen_poincare_stepper_free(s);
        return NULL;
    }
    return s;
}

void vigen_poincare_stepper_free(vigen_poincare_stepper *s)
{
    if (s == NULL) return;
    if (s->w) s->T->free(s->w);
    vigen_poincare_free(s->pc);
    free(s);
}

vigen_poincare *vigen_poincare_stepper_transform(const vigen_poincare_stepper *s) { return s ? s->pc : NULL; }

int vigen_poincare_stepper_integrate(vigen_poincare_stepper *s, double *t, double *q, double *p, double dtau,
                                     double t_end, unsigned long max_steps, unsigned long every,
                                     vigen_poincare_observer_fn obs, void *obs_ctx, vigen_poincare_result *res)
{
    if (s == NULL) return VIGEN_EINVAL;
    return vigen_poincare_integrate(s->T, s->w, s->pc, t, q, p, dtau, t_end, max_steps, every, obs, obs_ctx, res);
}

static int ps_step(void *ws, double *t, double *q, double *p, double h)
{
    vigen_poincare_stepper *s = ws;
    if (s == NULL || t == NULL || q == NULL || p == NULL || !isfinite(h) || h == 0) return VIGEN_EINVAL;
    vigen_poincare *pc = s->pc;
    pc->msg[0] = 0;
    int st = vigen_poincare_begin(pc, *t, q, p);
    if (st == VIGEN_SUCCESS) st = vigen_poincare_fictive_step(pc, s->T, s->w, h);
    if (st != VIGEN_SUCCESS) return st;
    const size_t n = pc->n;
    memcpy(q, pc->Q, n * sizeof(double));
    memcpy(p, pc->P, n * sizeof(double));
    *t = pc->t_rep = pc->Q[n];
    return VIGEN_SUCCESS;
}

static void ps_reset(void *ws)
{
    vigen_poincare_stepper *s = ws;
    if (s->T->reset) s->T->reset(s->w);
    s->pc->have = 0;   /* the next step starts a trajectory */
}

static const vigen_stats *ps_stats(const void *ws)
{
    const vigen_poincare_stepper *s = ws;
    return s->T->stats ? s->T->stats(s->w) : NULL;
}

static void ps_free(void *ws) { vigen_poincare_stepper_free(ws); }

/* Saved state: a header (magic, dimension, the inner state's size), the
 * trajectory (have, tau, t_rep, Q, P), then the inner workspace's own state
 * (which checks itself: its stepper, options, trailer). */
typedef struct {
    char magic[8];              /* "vigen-pc" */
    uint64_t dim, inner;
    uint64_t have;
    double tau, t_rep;
} ps_head;

static size_t ps_state_size(const void *ws)
{
    const vigen_poincare_stepper *s = ws;
    if (s->T->state_size == NULL) return 0;
    return sizeof(ps_head) + 2 * (s->pc->n + 1) * sizeof(double) + s->T->state_size(s->w);
}

static int ps_state_get(const void *ws, void *buf)
{
    const vigen_poincare_stepper *s = ws;
    if (s == NULL || buf == NULL) return VIGEN_EINVAL;
    if (s->T->state_get == NULL) return VIGEN_EUNSUPPORTED;
    const vigen_poincare *pc = s->pc;
    const size_t bytes = (pc->n + 1) * sizeof(double);
    ps_head h;
    memset(&h, 0, sizeof h);
    memcpy(h.magic, "vigen-pc", 8);
    h.dim = pc->n;
    h.inner = s->T->state_size(s->w);
    h.have = (uint64_t)pc->have;
    h.tau = pc->tau;
    h.t_rep = pc->t_rep;
    unsigned char *b = buf;
    memcpy(b, &h, sizeof h);
    memcpy(b + sizeof h, pc->Q, bytes);
    memcpy(b + sizeof h + bytes, pc->P, bytes);
    return s->T->state_get(s->w, b + sizeof h + 2 * bytes);
}

static int ps_state_set(void *ws, const void *buf)
{
    vigen_poincare_stepper *s = ws;
    if (s == NULL || buf == NULL) return VIGEN_EINVAL;
    if (s->T->state_set == NULL) return VIGEN_EUNSUPPORTED;
    vigen_poincare *pc = s->pc;
    const size_t bytes = (pc->n + 1) * sizeof(double);
    const unsigned char *b = buf;
    ps_head h;
    memcpy(&h, b, sizeof h);
    if (memcmp(h.magic, "vigen-pc", 8) != 0 || h.dim != pc->n || h.inner != s->T->state_size(s->w) || h.have > 1)
        return VIGEN_ESTATE;
    const int st = s->T->state_set(s->w, b + sizeof h + 2 * bytes);
    if (st != VIGEN_SUCCESS) return st;   /* the workspace unchanged */
    memcpy(pc->Q, b + sizeof h, bytes);
    memcpy(pc->P, b + sizeof h + bytes, bytes);
    pc->have = (int)h.have;
    pc->tau = h.tau;
    pc->t_rep = h.t_rep;
    pc->cache_ok = 0;
    return VIGEN_SUCCESS;
}

static size_t ps_dim(const void *ws) { return ((const vigen_poincare_stepper *)ws)->pc->n; }

/* The physical flow q' = dH/dp, p' = -dH/dq: the drivers interpolate in the
 * physical times the steps return. */
static int ps_field(void *ws, double t, const double *q, const double *p, double *dq, double *dp)
{
    const vigen_hamiltonian *sys = ((vigen_poincare_stepper *)ws)->pc->pb.sys;
    sys->dHdp(t, q, p, dq, sys->ctx);
    sys->dHdq(t, q, p, dp, sys->ctx);
    for (size_t k = 0; k < sys->dim; k++) dp[k] = -dp[k];
    return VIGEN_SUCCESS;
}

static void *ps_clone(const void *ws)
{
    const vigen_poincare_stepper *s = ws;
    return vigen_poincare_stepper_alloc(s->T, &s->pc->pb, &s->opt);
}

const vigen_stepper_type vigen_poincare_type = {
    "vigen_poincare", 0, -1, 0,
    NULL, ps_step, ps_reset, ps_stats, ps_free,
    ps_state_size, ps_state_get, ps_state_set,
    ps_dim, ps_field, ps_clone
};
