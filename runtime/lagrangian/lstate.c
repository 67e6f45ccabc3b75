/* lstate.c — the saved-state buffer of the Lagrangian integrators
 * (lstate_internal.h): the header, the moves of a payload between workspace
 * and buffer, the FNV-1a trailer, the checks made before anything is
 * loaded, and the state_size/get/set every integrator offers. */
#include <string.h>
#include "lstate_internal.h"

_Static_assert(sizeof(vigen_lstate_header) == 192, "the state header has no padding");

#define FNV_START UINT64_C(0xcbf29ce484222325)

static uint64_t fnv(uint64_t hash, const void *data, size_t len)
{
    const unsigned char *b = data;
    for (size_t i = 0; i < len; i++) hash = (hash ^ b[i]) * UINT64_C(0x100000001b3);
    return hash;
}

/* The header of a state of `name` with these sizes, rule and options,
 * size bytes long. */
static void header_init(vigen_lstate_header *h, const char *name, size_t dim, size_t params, int rule,
                        const vigen_solver_options *opt, size_t size)
{
    memset(h, 0, sizeof *h);
    memcpy(h->magic, "vigen-st", 8);
    h->byte_order = UINT64_C(0x0102030405060708);
    h->format = VIGEN_LSTATE_FORMAT;
    for (size_t i = 0; i < sizeof h->runtime - 1 && VIGEN_RUNTIME_VERSION[i]; i++) h->runtime[i] = VIGEN_RUNTIME_VERSION[i];
    for (size_t i = 0; i < sizeof h->name - 1 && name[i]; i++) h->name[i] = name[i];
    h->identity = fnv(FNV_START, name, strlen(name));
    h->real = 0;
    h->real_bits = 53;
    h->kind = VIGEN_LSTATE_KIND;
    h->dim = dim;
    h->stages = params;
    h->path = (uint64_t)rule;
    h->solver = (uint64_t)opt->solver;
    h->kahan = opt->kahan != 0;
    h->extrapolate = opt->extrapolate != 0;
    h->start_force = opt->start_force != 0;
    h->max_iter = (uint64_t)opt->max_iter;
    h->tol = opt->tol;
    h->fd_step = opt->fd_step;
    h->size = size;
}

void vigen_lstate_begin(vigen_lstate_io *io, void *buf, int save)
{
    io->buf = buf;
    io->pos = sizeof(vigen_lstate_header);
    io->save = save;
}

static void move(vigen_lstate_io *io, void *x, size_t bytes)
{
    if (io->buf && io->save) memcpy(io->buf + io->pos, x, bytes);
    else if (io->buf) memcpy(x, io->buf + io->pos, bytes);
    io->pos += bytes;
}

void vigen_lstate_reals(vigen_lstate_io *io, double *x, size_t n) { move(io, x, n * sizeof *x); }

void vigen_lstate_flag(vigen_lstate_io *io, int *x)
{
    uint64_t u = (uint64_t)*x;
    move(io, &u, sizeof u);
    *x = (int)u;
}

void vigen_lstate_stats(vigen_lstate_io *io, vigen_stats *s)
{
    unsigned long *const counts[] = { &s->steps, &s->failed_steps, &s->iterations, &s->last_iterations,
                                      &s->max_iterations, &s->dHdq_evals, &s->dHdp_evals, &s->hessian_evals,
                                      &s->lu_decompositions, &s->fsal_reuses };
    for (size_t i = 0; i < sizeof counts / sizeof counts[0]; i++) {
        uint64_t u = *counts[i];
        move(io, &u, sizeof u);
        *counts[i] = (unsigned long)u;
    }
}

size_t vigen_lstate_end(vigen_lstate_io *io)
{
    if (io->buf && io->save) {
        const uint64_t sum = fnv(FNV_START, io->buf, io->pos);
        memcpy(io->buf + io->pos, &sum, sizeof sum);
    }
    return io->pos + sizeof(uint64_t);
}

/* VIGEN_SUCCESS when buf starts with `want`, holds want->size bytes whose
 * trailer matches, and its first `nflags` 64-bit flags after the header are
 * at most `flag_max`; VIGEN_ESTATE otherwise. */
static int check(const void *buf, const vigen_lstate_header *want, size_t nflags, uint64_t flag_max)
{
    const unsigned char *b = buf;
    const size_t end = (size_t)want->size - sizeof(uint64_t);
    if (memcmp(b, want, sizeof *want) != 0) return VIGEN_ESTATE;
    uint64_t sum, flag;
    memcpy(&sum, b + end, sizeof sum);
    if (sum != fnv(FNV_START, b, end)) return VIGEN_ESTATE;
    for (size_t i = 0; i < nflags; i++) {
        memcpy(&flag, b + sizeof *want + i * sizeof flag, sizeof flag);
        if (flag > flag_max) return VIGEN_ESTATE;
    }
    return VIGEN_SUCCESS;
}

/* Measuring and saving only read w (the walk takes it without const). */
size_t vigen_lstate_size(const void *w, const vigen_lstate_kind *k) { return k->walk((void *)(uintptr_t)w, NULL, 1); }

static void header_of(const void *w, const vigen_lstate_kind *k, vigen_lstate_header *h)
{
    header_init(h, k->name, k->dim, k->params, k->rule, k->opt, vigen_lstate_size(w, k));
}

int vigen_lstate_get(const void *w, const vigen_lstate_kind *k, void *buf)
{
    if (buf == NULL) return VIGEN_EINVAL;
    vigen_lstate_header h;
    header_of(w, k, &h);
    memcpy(buf, &h, sizeof h);
    k->walk((void *)(uintptr_t)w, buf, 1);
    return VIGEN_SUCCESS;
}

int vigen_lstate_set(void *w, const vigen_lstate_kind *k, const void *buf)
{
    if (buf == NULL) return VIGEN_EINVAL;
    vigen_lstate_header h;
    header_of(w, k, &h);
    int st = check(buf, &h, k->nflags, k->flag_max);
    if (st == VIGEN_SUCCESS) k->walk(w, (void *)(uintptr_t)buf, 0);   /* loading only reads the buffer */
    return st;
}
