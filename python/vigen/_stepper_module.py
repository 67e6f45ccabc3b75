"""The stepper modules of vigen.Stepper: their C text, their cffi
declarations, and building and loading them.

A stepper module is one shared library of the per-user cache (_cache.py):
the stepper emitted in-process (vstep.c, vstep.h: `vigen emit` with the name
"vstep") and a main file (vigen_module.c, the text below) that includes it
with the force and gives Python uniform functions: the stepper type, the
allocation of a workspace for a force or a Hamiltonian, the problems of the
collection, ensembles through the batched stepper.  Python drives the
workspaces through the runtime's drivers in libvigen_python
(python/native/stepper.h), declared here with the module's functions in one
cffi FFI per real type.
"""
import hashlib
import os
import re
import tempfile

import cffi
import numpy as np

from . import _cache, _native, _paths
from .tableau import Tableau

# ---- the C declarations, per real type ---------------------------------------
# Drivers of libvigen_python (python/native/stepper.h) and the functions of a
# stepper module (the glue below): one cffi FFI per real type, so that
# `real` means one C type in each.
_CDEF = """
typedef struct {
    int solver; int max_iter; double tol; int kahan; int extrapolate; double fd_step; int start_force;
} vigen_solver_options;
typedef void (*vpy_force_fn)(REAL t, const REAL *q, REAL *f, void *ctx);
typedef void (*vpy_grad_fn)(REAL t, const REAL *q, const REAL *p, REAL *out, void *ctx);
typedef REAL (*vpy_event_fn)(REAL t, const REAL *q, const REAL *p, void *ctx);
int vigen_python_integrateSFX(const void *type, void *w, REAL *t, REAL *q, REAL *p, REAL h,
    unsigned long nsteps, unsigned long every, REAL *t_rec, REAL *q_rec, REAL *p_rec, size_t rows,
    size_t *nrows, unsigned long *done);
int vigen_python_integrate_atSFX(const void *type, void *w, REAL *t, REAL *q, REAL *p, REAL h,
    const REAL *t_out, size_t n_out, REAL *q_out, REAL *p_out, unsigned long *done);
int vigen_python_integrate_eventsSFX(const void *type, void *w, REAL *t, REAL *q, REAL *p, REAL h,
    unsigned long nsteps, vpy_event_fn g, void *ctx, int direction, int terminal, REAL *t_events,
    size_t max_events, size_t *n_events);
size_t vigen_python_stepper_dimSFX(const void *type, const void *w);
void vigen_python_stepper_resetSFX(const void *type, void *w);
void vigen_python_stepper_freeSFX(const void *type, void *w);
size_t vigen_python_state_sizeSFX(const void *type, const void *w);
int vigen_python_state_getSFX(const void *type, const void *w, void *buf);
int vigen_python_state_setSFX(const void *type, void *w, const void *buf);
void vigen_python_stepper_statsSFX(const void *type, const void *w, unsigned long *out);
int vigen_python_integrate_ensemble(const void *type, const void *prototype, size_t dim, int threads,
    size_t ntraj, double *t, double *q, double *p, double h, unsigned long nsteps, int *status,
    unsigned long *steps);
int vigen_python_ensemble_threads(void);
const char *vigen_python_strerror(int status);

const void *vpy_type(void);
void vpy_options_default(vigen_solver_options *opt);
void *vpy_alloc_mechanical(size_t dim, vpy_force_fn force, void *ctx, const REAL *inv_mass,
                           const vigen_solver_options *opt);
void *vpy_alloc_hamiltonian(size_t dim, vpy_grad_fn dHdq, vpy_grad_fn dHdp, void *ctx, int separable,
                            const vigen_solver_options *opt);
REAL vpy_user_V(REAL t, const REAL *q, void *ctx);
REAL vpy_user_H(REAL t, const REAL *q, const REAL *p, void *ctx);
int vpy_problem_create(void **pb, const char *name, const char *params, char *why, size_t why_size);
void vpy_problem_free(void *pb);
size_t vpy_problem_dim(const void *pb);
void *vpy_problem_alloc(const void *pb, const vigen_solver_options *opt);
void vpy_problem_initial(const void *pb, double *t, double *q, double *p);
double vpy_problem_period(const void *pb);
double vpy_problem_energy(const void *pb, double t, const double *q, const double *p);
size_t vpy_problem_invariant_count(const void *pb);
const char *vpy_problem_invariant_name(const void *pb, size_t k);
double vpy_problem_invariant(const void *pb, size_t k, double t, const double *q, const double *p);
int vpy_problem_reference(const void *pb, double t, double *q, double *p);
int vpy_ensemble_batch(size_t W, int mechanical, size_t dim, vpy_force_fn force, vpy_grad_fn dHdq, vpy_grad_fn dHdp,
                       void *ctx, const void *pb, const double *inv_mass, const vigen_solver_options *opt,
                       size_t ntraj, double *t, double *q, double *p, double h, unsigned long nsteps, int *status,
                       unsigned long *steps);
"""

_EMIT_CDEF = """
int vigen_python_stepper_emit(vigen_python_result *r, const char *method, int real, int batch, int allow_inexact,
                              const char *template_dir);
"""

# real type -> (C type, driver suffix, emitter's real type, module glue suffix)
REALS = {np.dtype(np.float64): ("double", "", 0, ""),
         np.dtype(np.longdouble): ("long double", "_ld", 1, "_ld")}
_ffis = {}
#: The modules loaded by this process: cache key -> (cffi library, key, file).
LOADED = {}
_emit_declared = []


def ffi_for(dtype):
    """(ffi, libvigen_python) for the real type dtype."""
    if dtype not in _ffis:
        ctype, sfx = REALS[dtype][0], REALS[dtype][1]
        ffi = cffi.FFI()
        ffi.cdef(_CDEF.replace("REAL", ctype).replace("SFX", sfx))
        _ffis[dtype] = (ffi, ffi.dlopen(_paths.NATIVE_LIBRARY))
    return _ffis[dtype]


# ---- the module's C text ------------------------------------------------------
_GLUE = r"""/* A stepper module of vigen.Stepper: the emitted stepper vstep (vstep.c)
 * with its force, and the problem collection.  Generated; do not edit. */
#include <math.h>
#include <stddef.h>
#include <vigen/runtime.h>
@PROBLEMS_INCLUDE@
typedef @REAL@ real;
@USER@
#line 8 "vigen_module.c"
@DIRECT@
#include "vstep.c"

const void *vpy_type(void) { return &vstep_type; }
void vpy_options_default(vigen_solver_options *opt) { vigen_solver_options_default(opt); }

void *vpy_alloc_mechanical(size_t dim, vigen_force_fn@SFX@ fn, void *ctx, const real *inv_mass,
                           const vigen_solver_options *opt)
{
    vigen_mechanical@SFX@ sys = { dim, fn ? fn : @USER_FORCE@, NULL, ctx, inv_mass };
    return vstep_alloc_mechanical(&sys, opt);
}

void *vpy_alloc_hamiltonian(size_t dim, vigen_grad_fn@SFX@ fq, vigen_grad_fn@SFX@ fp, void *ctx, int separable,
                            const vigen_solver_options *opt)
{
    vigen_hamiltonian@SFX@ sys = { .dim = dim, .dHdq = fq ? fq : @USER_DHDQ@, .dHdp = fp ? fp : @USER_DHDP@,
                                   .ctx = ctx, .separable = separable };
    return vstep_alloc(&sys, opt);
}
@EXTRA@
"""

_PROBLEM_GLUE = r"""
int vpy_problem_create(void **pb, const char *name, const char *params, char *why, size_t why_size)
{
    vigen_problem *p = NULL;
    int rc = vigen_problem_create(&p, name, params, why, why_size);
    *pb = p;
    return rc;
}
void vpy_problem_free(void *pb) { vigen_problem_free(pb); }
size_t vpy_problem_dim(const void *pb) { return vigen_problem_dim(pb); }
void *vpy_problem_alloc(const void *pb, const vigen_solver_options *opt)
{
    return vstep_alloc(vigen_problem_hamiltonian(pb), opt);
}
void vpy_problem_initial(const void *pb, double *t, double *q, double *p) { vigen_problem_initial(pb, t, q, p); }
double vpy_problem_period(const void *pb) { return vigen_problem_period(pb); }
double vpy_problem_energy(const void *pb, double t, const double *q, const double *p)
{
    return vigen_problem_energy(pb, t, q, p);
}
size_t vpy_problem_invariant_count(const void *pb) { return vigen_problem_invariant_count(pb); }
const char *vpy_problem_invariant_name(const void *pb, size_t k) { return vigen_problem_invariant_name(pb, k); }
double vpy_problem_invariant(const void *pb, size_t k, double t, const double *q, const double *p)
{
    return vigen_problem_invariant(pb, k, t, q, p);
}
int vpy_problem_reference(const void *pb, double t, double *q, double *p)
{
    return vigen_problem_reference(pb, t, q, p);
}
"""

_BATCH_GLUE = r"""
/* Ensembles through the batched stepper vstep_step_batch, blocks of W
 * trajectories in structure-of-arrays layout.  The batched force (or
 * gradients) evaluates the scalar one trajectory by trajectory, the same
 * expression per trajectory, so that each gets the bits vstep_step gives it
 * alone. */
typedef struct {
    size_t dim;
    vigen_force_fn force;
    vigen_grad_fn dHdq, dHdp;
    void *ctx;
    double *x, *y, *z;  /* one trajectory's q, p and result */
} vpy_batch_ctx;

static void vpy_gather(double *x, const double *soa, size_t dim, size_t W, size_t j)
{
    for (size_t k = 0; k < dim; k++) x[k] = soa[k * W + j];
}

static void vpy_scatter(double *soa, const double *x, size_t dim, size_t W, size_t j)
{
    for (size_t k = 0; k < dim; k++) soa[k * W + j] = x[k];
}

static void vpy_force_batch(const double *t, const double *q, double *f, size_t W, void *ctx)
{
    vpy_batch_ctx *c = ctx;
    for (size_t j = 0; j < W; j++) {
        vpy_gather(c->x, q, c->dim, W, j);
        c->force(t[j], c->x, c->z, c->ctx);
        vpy_scatter(f, c->z, c->dim, W, j);
    }
}

static void vpy_grad_batch(vigen_grad_fn g, const double *t, const double *q, const double *p, double *out,
                           size_t W, vpy_batch_ctx *c)
{
    for (size_t j = 0; j < W; j++) {
        vpy_gather(c->x, q, c->dim, W, j);
        vpy_gather(c->y, p, c->dim, W, j);
        g(t[j], c->x, c->y, c->z, c->ctx);
        vpy_scatter(out, c->z, c->dim, W, j);
    }
}

static void vpy_dhdq_batch(const double *t, const double *q, const double *p, double *out, size_t W, void *ctx)
{
    vpy_batch_ctx *c = ctx;
    vpy_grad_batch(c->dHdq, t, q, p, out, W, c);
}

static void vpy_dhdp_batch(const double *t, const double *q, const double *p, double *out, size_t W, void *ctx)
{
    vpy_batch_ctx *c = ctx;
    vpy_grad_batch(c->dHdp, t, q, p, out, W, c);
}

/* ntraj trajectories (row-major t[i], q[i dim ..], p[i dim ..]), each from a
 * fresh start, nsteps steps of h, in blocks of W: a mechanical problem
 * (fn; NULL: the module's C force) or a Hamiltonian (fq, fp; NULL: the
 * module's; pb: a problem of the collection).  status[i] and steps[i]
 * per trajectory; returns VIGEN_SUCCESS, the status of the first failed
 * trajectory, VIGEN_EUNSUPPORTED when the batched stepper refuses the
 * problem (an implicit tableau for a general H, Newton), VIGEN_ENOMEM. */
int vpy_ensemble_batch(size_t W, int mechanical, size_t dim, vigen_force_fn fn, vigen_grad_fn fq, vigen_grad_fn fp,
                       void *ctx, const void *pb, const double *inv_mass, const vigen_solver_options *opt,
                       size_t ntraj, double *t, double *q, double *p, double h, unsigned long nsteps, int *status,
                       unsigned long *steps)
{
    /* fn, fq, fp: not named force, dHdq, dHdp, which may be the module's C functions */
    vpy_batch_ctx c = { dim, fn ? fn : @USER_FORCE@, fq ? fq : @USER_DHDQ@, fp ? fp : @USER_DHDP@, ctx, NULL, NULL,
                        NULL };
@PROBLEM_BATCH@
    double *work = malloc((3 * dim + W * (1 + 2 * dim)) * sizeof *work);
    int *st = malloc(W * sizeof *st);
    unsigned long *done = malloc(W * sizeof *done);
    vstep_batch *b = NULL;
    if (mechanical) {
        vigen_mechanical_batch ms = { dim, vpy_force_batch, &c, inv_mass };
        b = vstep_batch_alloc_mechanical(&ms, W, opt);
    } else {
        vigen_hamiltonian_batch hs = { dim, vpy_dhdq_batch, vpy_dhdp_batch, &c };
        b = vstep_batch_alloc(&hs, W, opt);
    }
    int rc = VIGEN_SUCCESS;
    if (!work || !st || !done) rc = VIGEN_ENOMEM;
    else if (!b) rc = VIGEN_EUNSUPPORTED;
    for (size_t s = 0; rc == VIGEN_SUCCESS && s < ntraj; s += W) {
        size_t m = ntraj - s < W ? ntraj - s : W;
        c.x = work;
        c.y = work + dim;
        c.z = work + 2 * dim;
        double *tb = work + 3 * dim, *qb = tb + W, *pbk = qb + W * dim;
        for (size_t j = 0; j < W; j++) {
            size_t i = s + (j < m ? j : m - 1);  /* a short block is padded with its last trajectory */
            tb[j] = t[i];
            vpy_scatter(qb, q + i * dim, dim, W, j);
            vpy_scatter(pbk, p + i * dim, dim, W, j);
            st[j] = VIGEN_SUCCESS;
            done[j] = 0;
        }
        vstep_batch_reset(b);
        for (unsigned long n = 0; n < nsteps; n++) {
            vstep_step_batch(b, tb, qb, pbk, h, st);
            size_t alive = 0;
            for (size_t j = 0; j < W; j++)
                if (st[j] == VIGEN_SUCCESS) {
                    done[j]++;
                    alive++;
                }
            if (alive == 0) break;
        }
        for (size_t j = 0; j < m; j++) {
            t[s + j] = tb[j];
            vpy_gather(q + (s + j) * dim, qb, dim, W, j);
            vpy_gather(p + (s + j) * dim, pbk, dim, W, j);
            status[s + j] = st[j];
            steps[s + j] = done[j];
        }
    }
    for (size_t i = 0; rc == VIGEN_SUCCESS && i < ntraj; i++)
        if (status[i] != VIGEN_SUCCESS) rc = status[i];
    if (b) vstep_batch_free(b);
    free(work);
    free(st);
    free(done);
    return rc;
}
"""

_PROBLEM_BATCH = """    if (pb) {
        /* the batched gradients take the explicit path: a separable H only */
        const vigen_hamiltonian *H = vigen_problem_hamiltonian(pb);
        if (!H->separable) return VIGEN_EUNSUPPORTED;
        c.dHdq = H->dHdq;
        c.dHdp = H->dHdp;
        c.ctx = H->ctx;
    }"""


def defines(source, name):
    """Whether C source defines a function called name (returning a value or void)."""
    return re.search(r"(^|[\s*])" + name + r"\s*\([^;{]*\)\s*\{", source, re.M) is not None


def _glue(dtype, kind, source, batch=False):
    """The module's main C file: kind 'pointer' (the force through a pointer: a
    problem or Python callables), 'force' or 'hamiltonian' (C source with
    force, or dHdq and dHdp, called directly by the stepper)."""
    ctype, _, _, sfx = REALS[dtype]
    extra, user, direct = "", "", ""
    force = dhdq = dhdp = "NULL"
    if kind == "force":
        user, direct, force = source, "#define VSTEP_DIRECT_FORCE force", "force"
        if defines(source, "V"):
            extra += "real vpy_user_V(real t, const real *q, void *ctx) { return V(t, q, ctx); }\n"
    elif kind == "hamiltonian":
        user, dhdq, dhdp = source, "dHdq", "dHdp"
        direct = "#define VSTEP_DIRECT_DHDQ dHdq\n#define VSTEP_DIRECT_DHDP dHdp"
        if defines(source, "H"):
            extra += ("real vpy_user_H(real t, const real *q, const real *p, void *ctx)"
                      " { return H(t, q, p, ctx); }\n")
    problems = ""
    if dtype == np.dtype(np.float64):
        problems = "#include <vigen/problems.h>"
        extra += _PROBLEM_GLUE
        if batch:
            extra += _BATCH_GLUE.replace("@PROBLEM_BATCH@", _PROBLEM_BATCH)
    if user:
        user = '#line 1 "force"\n' + user + "\n"
    text = (_GLUE.replace("@EXTRA@", extra).replace("@PROBLEMS_INCLUDE@", problems).replace("@REAL@", ctype)
            .replace("@SFX@", sfx).replace("@DIRECT@", direct).replace("@USER_FORCE@", force)
            .replace("@USER_DHDQ@", dhdq).replace("@USER_DHDP@", dhdp))
    return text.replace("@USER@", user)  # last: the user's text is not searched for slots


def _tableau_file(tableau):
    """A file holding a vigen.Tableau's text: written once into the cache
    (tableaux/HASH/NAME.lua, by rename, so that a reader never sees half of
    it), where the emitter reads it as it reads any tableau file."""
    data = tableau.text.encode("utf-8", "surrogateescape")
    name = re.sub(r"[^A-Za-z0-9_.-]", "_", str(tableau.name or "tableau"))[:64] or "tableau"
    folder = os.path.join(_cache.cache_dir(), "tableaux", hashlib.sha256(data).hexdigest()[:32])
    path = os.path.join(folder, name + ".lua")
    if not os.path.isfile(path):
        os.makedirs(folder, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=folder, prefix=".tmp-")
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        os.replace(tmp, path)
    return path


def _method_file(method):
    """(path, bytes) of a method given by name or path, resolved as `vigen
    emit` resolves it, or given as a vigen.Tableau."""
    if isinstance(method, Tableau):
        method = _tableau_file(method)
    path = _native.call("vigen_python_resolve", b"emit", _native.encode(method, "method", "emit"))[0]
    with open(path, "rb") as f:
        return path, f.read()


def _emit(path, dtype, allow_inexact, batch):
    """(vstep.c, vstep.h) of the method file path for the real type dtype."""
    if not _emit_declared:
        _native.declare(_EMIT_CDEF)
        _emit_declared.append(True)
    c, h, _, _ = _native.call("vigen_python_stepper_emit", _native.encode(path, "method", "emit"),
                              REALS[dtype][2], int(bool(batch)), int(bool(allow_inexact)),
                              _native.encode(_paths.TEMPLATE_DIR))
    return c, h


def load(method, dtype, kind, source, allow_inexact, batch):
    """(cffi library, cache key, file) of the stepper module for the method,
    real type and force, compiled on a miss."""
    path, data = _method_file(method)
    glue = _glue(dtype, kind, source, batch)
    material = {"method": data.decode("utf-8", "surrogateescape"), "real": REALS[dtype][0], "glue": glue,
                "allow_inexact": bool(allow_inexact), "batch": bool(batch)}
    key = _cache.key_of(material)
    if key not in LOADED:
        def sources():
            c, h = _emit(path, dtype, allow_inexact, batch)
            return "vigen_module.c", {"vigen_module.c": glue, "vstep.c": c, "vstep.h": h}
        so = _cache.module_path(material, sources)
        ffi, _ = ffi_for(dtype)
        LOADED[key] = (ffi.dlopen(so), key, so)
    return LOADED[key]
