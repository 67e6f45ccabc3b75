/* lstate_internal.h — saved states of the Lagrangian integrators (internal to the
 * runtime): the header, the payload moves and the trailer that
 * vigen_hp_state_* and vigen_midpoint_vi_state_* share.
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

/* The header of a state of `name` (at most 31 characters) with these sizes,
 * rule and options, size bytes long. */
void vigen_lstate_header_init(vigen_lstate_header *h, const char *name, size_t dim, size_t params, int rule,
                              const vigen_solver_options *opt, size_t size);

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

/* After a save pass: the trailer at io->pos.  The buffer's size is then
 * io->pos + 8. */
void vigen_lstate_seal(vigen_lstate_io *io);

/* A payload pass of one integrator: moves its payload between the
 * workspace w and buf (see vigen_lstate_io) and returns the buffer's size,
 * trailer included; it seals the buffer after a save. */
typedef size_t (*vigen_lstate_walk_fn)(void *w, void *buf, int save);

/* The header h and w's payload into buf.  w is only read. */
int vigen_lstate_save(void *w, vigen_lstate_walk_fn walk, const vigen_lstate_header *h, void *buf);
/* The payload of buf into w after vigen_lstate_check(buf, want, nflags,
 * flag_max) passed; its status otherwise, w unchanged.  buf is only read. */
int vigen_lstate_load(void *w, vigen_lstate_walk_fn walk, const vigen_lstate_header *want, const void *buf,
                      size_t nflags, uint64_t flag_max);

/* VIGEN_SUCCESS when buf starts with `want`, holds want->size bytes whose
 * trailer matches, and its first `nflags` 64-bit flags after the header are
 * at most `flag_max`; VIGEN_ESTATE otherwise. */
int vigen_lstate_check(const void *buf, const vigen_lstate_header *want, size_t nflags, uint64_t flag_max);

#endif
