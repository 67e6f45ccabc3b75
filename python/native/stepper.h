/* stepper.h — the C side of vigen.Stepper (python/vigen/stepper.py): the
 * stepper emitted in-process, and the runtime's drivers called on a stepper
 * type and workspace that a compiled stepper module hands out.
 *
 * A stepper module (built by python/vigen/_cache.py into the per-user cache)
 * holds one emitted stepper, its force and the problem collection; it gives
 * Python its vigen_stepper_type and workspaces.  Everything that drives them
 * lives here, once, in libvigen_python: each call below is one call of a
 * runtime driver (vigen_integrate, vigen_integrate_at,
 * vigen_integrate_events, vigen_integrate_ensemble) with the arrays given,
 * so that Python costs one foreign call per run, not per step.
 *
 * The drivers come in double (no suffix) and long double (suffix _ld); type
 * and workspace are passed as void * (the module's NAME_type and a
 * workspace of it).  Status codes are the runtime's (vigen/runtime.h). */
#ifndef VIGEN_PYTHON_STEPPER_H
#define VIGEN_PYTHON_STEPPER_H

#include <stddef.h>
/* vigen_python_result: include "vigen_python.h" (which has no guard) first */

/* The stepper of method (a file, or a name of the method library, resolved
 * as `vigen emit` resolves it) for real type real (0 double, 1 long double),
 * rendered with the emitter's name "vstep", with templates from
 * template_dir (NULL: as the command line finds them), with the batched
 * stepper when batch is nonzero, rounding decimals given with too few
 * digits as written when allow_inexact is nonzero (`--allow-inexact`): text = vstep.c, extra = vstep.h, message on
 * failure as `vigen emit` prints it.  The resolved path is not returned:
 * vigen_python_resolve gives it. */
int vigen_python_stepper_emit(vigen_python_result *r, const char *method, int real, int batch, int allow_inexact,
                              const char *template_dir);

/* Runs nsteps steps of size h from (*t, q, p) with vigen_integrate and
 * records the state at step 0, after every `every` steps and after the last
 * one into row k of t_rec (rows entries), q_rec and p_rec (rows x dim):
 * *nrows rows written, *done steps taken.  Returns the runtime's status; on
 * failure (t, q, p) hold the last good step. */
int vigen_python_integrate(const void *type, void *w, double *t, double *q, double *p, double h,
                           unsigned long nsteps, unsigned long every, double *t_rec, double *q_rec,
                           double *p_rec, size_t rows, size_t *nrows, unsigned long *done);
int vigen_python_integrate_ld(const void *type, void *w, long double *t, long double *q, long double *p,
                              long double h, unsigned long nsteps, unsigned long every, long double *t_rec,
                              long double *q_rec, long double *p_rec, size_t rows, size_t *nrows,
                              unsigned long *done);

/* vigen_integrate_at: the state at the n_out times t_out into q_out, p_out
 * (n_out x dim). */
int vigen_python_integrate_at(const void *type, void *w, double *t, double *q, double *p, double h,
                              const double *t_out, size_t n_out, double *q_out, double *p_out,
                              unsigned long *done);
int vigen_python_integrate_at_ld(const void *type, void *w, long double *t, long double *q, long double *p,
                                 long double h, const long double *t_out, size_t n_out, long double *q_out,
                                 long double *p_out, unsigned long *done);

/* vigen_integrate_events with the event function g (ctx passed to it). */
int vigen_python_integrate_events(const void *type, void *w, double *t, double *q, double *p, double h,
                                  unsigned long nsteps, double (*g)(double, const double *, const double *, void *),
                                  void *ctx, int direction, int terminal, double *t_events, size_t max_events,
                                  size_t *n_events);
int vigen_python_integrate_events_ld(const void *type, void *w, long double *t, long double *q, long double *p,
                                     long double h, unsigned long nsteps,
                                     long double (*g)(long double, const long double *, const long double *,
                                                      void *),
                                     void *ctx, int direction, int terminal, long double *t_events,
                                     size_t max_events, size_t *n_events);

/* The workspace through its type: dimension, reset, free, saved state
 * (size, get, set: VIGEN_ESTATE for a state of another stepper), and the
 * statistics as steps, failed steps, iterations, force or dH/dq calls,
 * dH/dp calls (out: 5 entries). */
size_t vigen_python_stepper_dim(const void *type, const void *w);
void vigen_python_stepper_reset(const void *type, void *w);
void vigen_python_stepper_free(const void *type, void *w);
size_t vigen_python_state_size(const void *type, const void *w);
int vigen_python_state_get(const void *type, const void *w, void *buf);
int vigen_python_state_set(const void *type, void *w, const void *buf);
void vigen_python_stepper_stats(const void *type, const void *w, unsigned long *out);
size_t vigen_python_stepper_dim_ld(const void *type, const void *w);
void vigen_python_stepper_reset_ld(const void *type, void *w);
void vigen_python_stepper_free_ld(const void *type, void *w);
size_t vigen_python_state_size_ld(const void *type, const void *w);
int vigen_python_state_get_ld(const void *type, const void *w, void *buf);
int vigen_python_state_set_ld(const void *type, void *w, const void *buf);
void vigen_python_stepper_stats_ld(const void *type, const void *w, unsigned long *out);

/* vigen_integrate_ensemble over ntraj trajectories (t: ntraj, q and p:
 * ntraj x dim), every one from a fresh clone of the workspace prototype;
 * threads 0 = every core, 1 = serial.  status (ntraj) and steps (ntraj). */
int vigen_python_integrate_ensemble(const void *type, const void *prototype, size_t dim, int threads,
                                    size_t ntraj, double *t, double *q, double *p, double h,
                                    unsigned long nsteps, int *status, unsigned long *steps);
/* The number of threads threads = 0 means. */
int vigen_python_ensemble_threads(void);

/* vigen_strerror of the runtime (static text). */
const char *vigen_python_strerror(int status);

#endif
