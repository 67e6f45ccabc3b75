/* lstate_internal.h — saved states of the Lagrangian integrators (internal
 * to the runtime): the header, the payload moves, the trailer and the
 * state_size, state_get and state_set that vigen_hp_state_* and
 * vigen_midpoint_vi_state_* are.
 *
 * The buffer has the layout of an emitted stepper's saved state
 * (docs/emit.md, "Saved states"): a header of 192 bytes, the payload, and
 * the 64-bit FNV-1a hash of every byte before it.  The header's fields are
 * those of the emitted stepper's, with the kind 2 (a Lagrangian problem),
 * `stages` the number of velocity-map parameters and `path` the
 * integrator's rule. */
#ifndef VIGEN_LAGRANGIAN_STATE_H
#define VIGEN_LAGRANGIAN_STATE_H

#include <stddef.h>
#include <stdint.h>
#include <vigen/runtime.h>

enum { VIGEN_LSTATE_FORMAT = 1, VIGEN_LSTATE_KIND = 2 };

/* Fields of 8 bytes or multiples of 8: no padding, compared as a whole. */
typedef struct {
    char magic[8];             /* "vigen-st" */
    uint64_t byte_order;       /* 0x0102030405060708 */
    uint64_t format;           /* VIGEN_LSTATE_FORMAT */
    char runtime[16];          /* VIGEN_RUNTIME_VERSION, zero-padded */
    char name[32];             /* the integrator, e.g. "vigen_hp" */
    uint64_t identity;         /* FNV-1a of the name */
    uint64_t real, real_bits;  /* 0 (double), 53 */
    uint64_t kind;             /* VIGEN_LSTATE_KIND */
    uint64_t dim, stages, path;
    uint64_t solver, kahan, extrapolate, start_force, max_iter;
    double tol, fd_step;
    uint64_t size;             /* bytes of the whole buffer */
} vigen_lstate_header;

/* A pass over a payload: save (workspace to buffer), load (buffer to
 * workspace) or, with buf NULL, only measure.  pos starts after the header. */
typedef struct {
    unsigned char *buf;
    size_t pos;
    int save;
} vigen_lstate_io;

void vigen_lstate_begin(vigen_lstate_io *io, void *buf, int save);
void vigen_lstate_reals(vigen_lstate_io *io, double *x, size_t n);
void vigen_lstate_flag(vigen_lstate_io *io, int *x);              /* as 64 bits */
void vigen_lstate_stats(vigen_lstate_io *io, vigen_stats *s);     /* ten counters of 64 bits */

/* Ends a pass: after a save into a buffer, writes the trailer at io->pos.
 * Returns the buffer's size, trailer included. */
size_t vigen_lstate_end(vigen_lstate_io *io);

/* A payload pass of one integrator: moves its payload between the
 * workspace w and buf (see vigen_lstate_io), flags first, and returns
 * vigen_lstate_end's size. */
typedef size_t (*vigen_lstate_walk_fn)(void *w, void *buf, int save);

/* What an integrator's saved state is: the header's name (at most 31
 * characters), dimension, parameters, rule and options, the payload walk,
 * and the largest value each of its first nflags flags may take. */
typedef struct {
    const char *name;
    size_t dim, params;
    int rule;
    const vigen_solver_options *opt;
    vigen_lstate_walk_fn walk;
    size_t nflags;
    uint64_t flag_max;
} vigen_lstate_kind;

/* X_state_size, X_state_get and X_state_set of every Lagrangian integrator
 * (vigen/lagrangian.h), given its workspace w (not NULL) and kind.  Sizing
 * and saving only read w.  get: VIGEN_EINVAL for a NULL buf.  set:
 * VIGEN_EINVAL for a NULL buf; VIGEN_ESTATE, w unchanged, unless buf starts
 * with w's header, holds that many bytes whose trailer matches, and its
 * flags are in range; buf is only read. */
size_t vigen_lstate_size(const void *w, const vigen_lstate_kind *k);
int vigen_lstate_get(const void *w, const vigen_lstate_kind *k, void *buf);
int vigen_lstate_set(void *w, const vigen_lstate_kind *k, const void *buf);

#endif
