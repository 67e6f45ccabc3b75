"""Compiled steppers on NumPy arrays: :class:`Stepper`.

A Stepper is a method of the library (or a tableau or spec file) emitted as
C in-process, compiled with the system C compiler together with its force
into a module of the per-user cache (vigen/_cache.py), and loaded with cffi.
Every run is one call of a runtime driver (vigen_integrate,
vigen_integrate_at, vigen_integrate_events, vigen_integrate_ensemble) over
the whole run: no Python runs between steps unless the force itself is a
Python callable.
"""
import sys

import numpy as np

from ._stepper_module import REALS, defines, ffi_for, load
from .errors import Error, InputError

# The runtime's status codes (vigen/runtime.h) that mean bad input rather
# than a failed step.
_EINVAL, _EUNSUPPORTED = 1, 7


# ---- the state of a run -------------------------------------------------------
class StepperState:
    """A saved state of a :class:`Stepper`: the time, positions, momenta and
    everything later steps depend on (compensation, extrapolation history,
    cached forces).  :meth:`Stepper.set_state` puts it back, into the same
    Stepper or a new one made with the same arguments (also in another
    process: it pickles), and the next steps are bit for bit those the
    saved Stepper would have taken.

    Attributes: ``t`` (a NumPy scalar), ``q``, ``p`` (arrays), ``workspace``
    (bytes, the runtime's saved state), ``stepper`` (what made it)."""

    def __init__(self, t, q, p, workspace, stepper):
        self.t, self.q, self.p, self.workspace, self.stepper = t, q, p, workspace, stepper

    def __repr__(self):
        return "StepperState(t=%r, q=%r, p=%r, %d bytes)" % (self.t, self.q, self.p, len(self.workspace))


class StepError(Error, ArithmeticError):
    """A step failed: the stage equations did not converge, the force or the
    new state was not finite, or the Python force raised (then chained as
    ``__cause__``).  The Stepper keeps the state it had before the call;
    ``status`` is the runtime's message, ``steps`` the steps the failed call
    took before the failure."""

    def __init__(self, message, status=None, steps=0):
        super().__init__(message, status, None)
        self.steps = steps


_SOLVERS = {"fixed-point": 0, "newton": 1}
_SOLVER_OPTIONS = ("solver", "max_iter", "tol", "kahan", "extrapolate", "fd_step", "start_force")


class Stepper:
    """A compiled stepper of one method on one problem.

    ``Stepper(method, problem=NAME, **params)``, ``Stepper(method,
    force=F, dim=N)`` or ``Stepper(method, hamiltonian=H, dim=N)``:

    - ``method``: a method of the library (``"yoshida_4"``, as ``vigen list``
      names it), the path of a tableau or spec file, or a
      :class:`vigen.Tableau` (``vigen.generate(...)``).
    - ``problem``: a problem of the collection (``"kepler"``, ``"pendulum"``,
      ... as ``vigen try --problem`` takes them) with its parameters as
      keywords (``e=0.6``); double precision only.
    - ``force``: the force f = -dV/dq of a mechanical problem H = p^T M^-1 p / 2
      + V(t, q), either as C source (the fast path: compiled into the
      stepper and called without a pointer) defining
      ``void force(real t, const real *q, real *f, void *ctx)`` and,
      optionally, the potential ``real V(real t, const real *q, void *ctx)``
      (for :meth:`energy`), or as a Python callable ``force(t, q)`` returning
      an array of dim entries (works, but costs a Python call per force
      evaluation: slow).  ``real`` is the stepper's real type; ``ctx``
      points to the ``params`` array (``const real *``), NULL when none.
      ``inv_mass``: the diagonal of M^-1 (default the identity).
    - ``hamiltonian``: a general H given by its gradients: C source defining
      ``void dHdq(real t, const real *q, const real *p, real *out, void *ctx)``
      and ``dHdp`` likewise (optionally ``real H(real t, const real *q,
      const real *p, void *ctx)``), or a pair of Python callables
      ``(dHdq, dHdp)`` each taking ``(t, q, p)``.  ``separable=True``
      promises H = T(p) + V(t, q) (an explicit method then runs explicitly).
    - ``dim``: the dimension of q (and of p); given by the problem otherwise.
    - ``dtype``: ``np.float64`` (default) or ``np.longdouble``.
    - solver options (vigen_solver_options): ``solver`` ("fixed-point" or
      "newton"), ``max_iter``, ``tol``, ``kahan``, ``extrapolate``,
      ``fd_step``, ``start_force``.
    - ``threads``: threads of an ensemble (0: every core).
    - ``batch``: W > 0 runs ensembles through the batched stepper
      (``vigen emit --batch``), blocks of W trajectories per call, in place
      of threads; double precision, explicit tableaux (implicit ones for
      mechanical problems with the fixed point only).
    - ``allow_inexact``: round decimals of a tableau given with too few
      digits as written (``vigen emit --allow-inexact``; a warning says so).

    ``module_file`` is the compiled module's path in the cache; its folder
    holds the C files it was built from (vigen_module.c, vstep.c, vstep.h).

    The first Stepper of a method, real type and force source compiles it
    (a second or so); later ones, in this or any process, load it from the
    cache.  Errors: :class:`vigen.InputError` for bad arguments, a method
    that cannot be emitted or C source that does not compile."""

    def __init__(self, method, problem=None, force=None, hamiltonian=None, dim=None, dtype=np.float64,
                 inv_mass=None, separable=False, params=None, threads=0, batch=0, allow_inexact=False,
                 **options):
        self._w = None
        self._pb = None
        self._pending = None
        self._dtype = dtype = np.dtype(dtype)
        if dtype not in REALS:
            raise InputError("vigen.Stepper: dtype must be numpy.float64 or numpy.longdouble, not %s" % dtype)
        given = [k for k, v in (("problem", problem), ("force", force), ("hamiltonian", hamiltonian))
                 if v is not None]
        if len(given) != 1:
            raise InputError("vigen.Stepper: give exactly one of problem=, force= and hamiltonian= (got %s)"
                             % (", ".join(given) or "none"))
        solver_opts = {k: options.pop(k) for k in list(options) if k in _SOLVER_OPTIONS}
        if options and problem is None:
            raise InputError("vigen.Stepper: unknown option%s %s" % ("s" if len(options) > 1 else "",
                                                                     ", ".join(sorted(options))))
        self.method = method
        self.threads = int(threads)
        self.batch = self._count(batch, "batch")
        if self.batch and dtype != np.dtype(np.float64):
            raise InputError("vigen.Stepper: the batched stepper (batch=) is double precision only")
        if problem is not None:
            kind, source = "pointer", None
        elif isinstance(force if force is not None else hamiltonian, str):
            kind, source = ("force" if force is not None else "hamiltonian"), (force or hamiltonian)
        else:
            kind, source = "pointer", None
        self._lib, key, self.module_file = load(method, dtype, kind, source, allow_inexact, batch)
        self._ffi, self._native = ffi_for(dtype)
        ffi, sfx = self._ffi, REALS[dtype][1]
        self._call = {name: getattr(self._native, "vigen_python_" + name + sfx)
                      for name in ("integrate", "integrate_at", "integrate_events", "stepper_dim",
                                   "stepper_reset", "stepper_free", "state_size", "state_get", "state_set",
                                   "stepper_stats")}
        self._type = self._lib.vpy_type()
        self._opt = self._solver_options(solver_opts)
        self._keep = []
        self._energy_fn = None
        self._inv_mass = None
        # what vpy_ensemble_batch needs: mechanical, force, dHdq, dHdp, ctx, separable
        self._batch_args = (0, ffi.NULL, ffi.NULL, ffi.NULL, ffi.NULL, 1)
        if problem is not None:
            self._init_problem(problem, options)
        else:
            self.dim = self._dimension(dim)
            self._params = self._array(params if params is not None else [], "params", None)
            ctx = ffi.cast("void *", self._ptr(self._params)) if self._params.size else ffi.NULL
            if force is not None:
                im = None
                if inv_mass is not None:
                    im = self._array(inv_mass, "inv_mass", (self.dim,))
                    if not np.all(np.isfinite(im)) or np.any(im <= 0):
                        raise InputError("vigen.Stepper: inv_mass must be positive and finite")
                self._inv_mass = im
                imp = self._ptr(im) if im is not None else ffi.NULL
                fn = self._python_force(force) if kind == "pointer" else ffi.NULL
                self._w = self._lib.vpy_alloc_mechanical(self.dim, fn, ctx, imp, self._opt)
                self._batch_args = (1, fn, ffi.NULL, ffi.NULL, ctx, 1)
                if kind == "force" and defines(source, "V"):
                    self._energy_fn = self._mechanical_energy
            else:
                if kind == "pointer":
                    if not (isinstance(hamiltonian, (tuple, list)) and len(hamiltonian) == 2
                            and all(callable(f) for f in hamiltonian)):
                        raise InputError("vigen.Stepper: hamiltonian= takes C source or a pair of Python "
                                         "callables (dHdq, dHdp)")
                    fq, fp = (self._python_gradient(f) for f in hamiltonian)
                else:
                    fq = fp = ffi.NULL
                self._w = self._lib.vpy_alloc_hamiltonian(self.dim, fq, fp, ctx, int(bool(separable)), self._opt)
                self._batch_args = (0, ffi.NULL, fq, fp, ctx, int(bool(separable)))
                if kind == "hamiltonian" and defines(source, "H"):
                    self._energy_fn = self._hamiltonian_energy
            self._ctx = ctx
        if self._w == ffi.NULL:
            self._w = None
            self._free = self._release()
            raise InputError("vigen.Stepper: the stepper refused the problem (dimension %d, options %r)"
                             % (self.dim, solver_opts))
        self._free = self._release()
        self._python = kind == "pointer" and problem is None
        # what a saved state must agree with: the module, the problem and its
        # parameters, the dimension, the real type and the options
        problem_params = self._problem_params if problem is not None else [
            [float(x) for x in self._params.ravel()],
            None if self._inv_mass is None else [float(x) for x in self._inv_mass]]
        self._identity = [key, self.dim, str(dtype), sorted(solver_opts.items()), repr(problem), problem_params, kind]
        self._t = None

    # -- construction helpers
    def _solver_options(self, opts):
        o = self._ffi.new("vigen_solver_options *")
        self._lib.vpy_options_default(o)
        for k, v in opts.items():
            if k == "solver":
                if v not in _SOLVERS:
                    raise InputError("vigen.Stepper: solver must be 'fixed-point' or 'newton', not %r" % (v,))
                v = _SOLVERS[v]
            setattr(o, k, v)
        return o

    def _init_problem(self, problem, params):
        ffi = self._ffi
        if self._dtype != np.dtype(np.float64):
            raise InputError("vigen.Stepper: the problems of the collection are double precision; "
                             "give the force as C source for dtype=%s" % self._dtype)
        try:
            text = ",".join("%s=%s" % (k, repr(float(v))) for k, v in sorted(params.items()))
        except (TypeError, ValueError):
            raise InputError("vigen.Stepper: the parameters of a problem are numbers (%r)" % (params,)) from None
        self._problem_params = text
        pb = ffi.new("void **")
        why = ffi.new("char[]", 300)
        if self._lib.vpy_problem_create(pb, str(problem).encode(), text.encode(), why, 300) != 0:
            raise InputError("vigen.Stepper: %s" % ffi.string(why).decode())
        self._pb = pb[0]
        self.dim = self._lib.vpy_problem_dim(self._pb)
        self._w = self._lib.vpy_problem_alloc(self._pb, self._opt)
        self.problem = problem
        self._energy_fn = self._problem_energy

    def _dimension(self, dim):
        if dim is None or isinstance(dim, bool) or not isinstance(dim, (int, np.integer)) or dim < 1:
            raise InputError("vigen.Stepper: dim= must be a positive integer (the dimension of q), not %r"
                             % (dim,))
        return int(dim)

    def _array(self, x, what, shape):
        a = np.array(x, dtype=self._dtype, copy=True, order="C")
        if shape is not None and a.shape != shape:
            raise InputError("vigen.Stepper: %s must have shape %s, not %s" % (what, shape, a.shape))
        return a

    def _ptr(self, a):
        return self._ffi.cast("%s *" % REALS[self._dtype][0], a.ctypes.data)

    def _view(self, ptr, n):
        """A NumPy copy of n reals at ptr."""
        size = n * self._dtype.itemsize
        return np.frombuffer(self._ffi.buffer(ptr, size), dtype=self._dtype).copy()

    def _cell(self, value):
        """A C real holding value bit for bit (cffi would pass a long double
        through a Python float)."""
        c = self._ffi.new("%s *" % REALS[self._dtype][0])
        self._ffi.memmove(c, np.array([value], dtype=self._dtype), self._dtype.itemsize)
        return c

    def _value(self, cell):
        return np.frombuffer(self._ffi.buffer(cell, self._dtype.itemsize), dtype=self._dtype)[0]

    def _fail_in_callback(self, out):
        self._pending = self._pending or sys.exc_info()[1]
        for k in range(self.dim):
            out[k] = float("nan")

    def _python_force(self, fn):
        if not callable(fn):
            raise InputError("vigen.Stepper: force= takes C source or a Python callable, not %r" % (fn,))
        dim = self.dim

        def force(t, q, f, ctx):
            try:
                r = np.asarray(fn(float(t), self._view(q, dim)), dtype=self._dtype)
                if r.shape != (dim,):
                    raise InputError("vigen.Stepper: the force returned shape %s, not (%d,)" % (r.shape, dim))
                self._ffi.memmove(f, r, dim * self._dtype.itemsize)
            except BaseException:  # the step fails on the NaNs; the exception is raised after it
                self._fail_in_callback(f)

        cb = self._ffi.callback("vpy_force_fn", force)
        self._keep.append(cb)
        return cb

    def _python_gradient(self, fn):
        dim = self.dim

        def grad(t, q, p, out, ctx):
            try:
                r = np.asarray(fn(float(t), self._view(q, dim), self._view(p, dim)), dtype=self._dtype)
                if r.shape != (dim,):
                    raise InputError("vigen.Stepper: a gradient returned shape %s, not (%d,)" % (r.shape, dim))
                self._ffi.memmove(out, r, dim * self._dtype.itemsize)
            except BaseException:
                self._fail_in_callback(out)

        cb = self._ffi.callback("vpy_grad_fn", grad)
        self._keep.append(cb)
        return cb

    def __del__(self):
        # Only functions looked up in __init__: a lookup on a cffi library
        # takes the FFI's lock, and the collector may run this while that
        # lock is held by the same thread (a deadlock).
        free = self.__dict__.get("_free")
        if free is not None:
            free()

    def _release(self):
        """Frees the workspace and the problem; called once."""
        w, pb, T = self._w, self._pb, self._type
        stepper_free = self._call["stepper_free"]
        problem_free = self._lib.vpy_problem_free if pb is not None else None  # double modules only

        def free():
            if w is not None:
                stepper_free(T, w)
            if pb is not None:
                problem_free(pb)
        return free

    # -- the state
    def _state_bytes(self):
        n = self._call["state_size"](self._type, self._w)
        buf = self._ffi.new("unsigned char[]", n)
        self._call["state_get"](self._type, self._w, buf)
        return bytes(self._ffi.buffer(buf, n))

    def _restore(self, blob):
        self._call["state_set"](self._type, self._w, blob)

    def state(self):
        """The state reached by the last run, as a picklable
        :class:`StepperState` (see :meth:`set_state`)."""
        if self._t is None:
            raise InputError("vigen.Stepper: no state yet: integrate from an initial value first")
        return StepperState(self._t, self._q.copy(), self._p.copy(), self._state_bytes(), list(self._identity))

    def set_state(self, state):
        """Continues from a :class:`StepperState` saved by this Stepper or one
        made with the same arguments: the next ``integrate(h=..., nsteps=...)``
        without an initial value takes the steps the saved Stepper would have
        taken, bit for bit.  InputError for a state of another stepper."""
        if not isinstance(state, StepperState) or list(state.stepper) != list(self._identity):
            raise InputError("vigen.Stepper: the state belongs to another stepper (method, problem, dimension, "
                             "dtype or options differ)")
        if self._call["state_set"](self._type, self._w, state.workspace) != 0:
            raise InputError("vigen.Stepper: the saved workspace state is damaged or from another version")
        self._t = self._dtype.type(state.t)
        self._q = self._array(state.q, "q", (self.dim,))
        self._p = self._array(state.p, "p", (self.dim,))

    @property
    def t(self):
        """The time the last run reached (None before any run)."""
        return self._t

    def stats(self):
        """The workspace's counters since the last initial value: steps, failed
        steps, stage iterations, force (or dH/dq) and dH/dp evaluations."""
        out = self._ffi.new("unsigned long[5]")
        self._call["stepper_stats"](self._type, self._w, out)
        return dict(zip(("steps", "failed_steps", "iterations", "dHdq_evals", "dHdp_evals"), list(out)))

    # -- arguments of a run
    def _start(self, q0, p0, t0):
        """(t, q, p, fresh) to run from: copies of the initial value, or the
        state the last run reached when both q0 and p0 are None."""
        if q0 is None and p0 is None:
            if self._t is None:
                raise InputError("vigen.Stepper: give q0 and p0 (there is no state to continue from)")
            return self._t, self._q.copy(), self._p.copy(), False
        if q0 is None or p0 is None:
            raise InputError("vigen.Stepper: give both q0 and p0, or neither to continue")
        q = self._array(q0, "q0", None)
        p = self._array(p0, "p0", None)
        if q.shape != p.shape or q.ndim not in (1, 2) or q.shape[-1] != self.dim:
            raise InputError("vigen.Stepper: q0 and p0 must both have shape (%d,) or (n, %d), not %s and %s"
                             % (self.dim, self.dim, q.shape, p.shape))
        t = np.array(t0, dtype=self._dtype)
        if t.ndim > 1 or (t.ndim == 1 and (q.ndim != 2 or t.shape[0] != q.shape[0])):
            raise InputError("vigen.Stepper: t0 must be a number (or one per trajectory), not shape %s" % (t.shape,))
        if not (np.all(np.isfinite(q)) and np.all(np.isfinite(p)) and np.all(np.isfinite(t))):
            raise InputError("vigen.Stepper: the initial value is not finite (NaN or infinity in t0, q0 or p0)")
        return (t if t.ndim else t[()]), q, p, True

    @staticmethod
    def _count(n, what):
        if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 0:
            raise InputError("vigen.Stepper: %s must be a non-negative integer, not %r" % (what, n))
        return int(n)

    def _step_size(self, h):
        try:
            hv = self._dtype.type(h)
        except (TypeError, ValueError):
            raise InputError("vigen.Stepper: h must be a number, not %r" % (h,)) from None
        if not np.isfinite(hv) or hv == 0:
            raise InputError("vigen.Stepper: h must be finite and nonzero, not %r" % (h,))
        return hv

    def _run(self, fresh, body):
        """Runs body() (returning (status, steps)) with the workspace reset when
        fresh; on failure (a status, or an exception of a Python force) puts
        the workspace back and raises."""
        saved = self._state_bytes() if self._t is not None else None
        if fresh:
            self._call["stepper_reset"](self._type, self._w)
        self._pending = None
        status, steps = body()
        pending, self._pending = self._pending, None
        if status != 0 or pending is not None:
            if saved is not None:
                self._restore(saved)
            else:
                self._call["stepper_reset"](self._type, self._w)
            if pending is not None:
                raise StepError("vigen.Stepper: the Python force raised %s: %s (after %d steps; the state is "
                                "unchanged)" % (type(pending).__name__, pending, steps), "force raised",
                                steps) from pending
            why = self._ffi.string(self._native.vigen_python_strerror(status)).decode()
            cls = InputError if status == _EINVAL else StepError
            raise cls("vigen.Stepper: step %d failed: %s (the state is unchanged)" % (steps + 1, why), why, steps)

    def _commit(self, t, q, p):
        self._t, self._q, self._p = t, q, p

    # -- runs
    def integrate(self, q0=None, p0=None, h=None, nsteps=None, every=1, t0=0.0):
        """Takes nsteps steps of size h from (t0, q0, p0), or, with q0 and p0
        None, from the state the last run reached (or :meth:`set_state` put).

        Returns (t, q, p): NumPy arrays of the times (rows,) and states
        (rows, dim) at the start, after every ``every`` steps and after the
        last step: rows = ceil(nsteps / every) + 1 (``every=0``: the start and
        the end only).  With q0 of shape (n, dim) (an ensemble; ``every`` is
        then ignored): the n final states, t (n,), q and p (n, dim), each
        trajectory bit for bit what it gives alone, run on ``threads``
        threads.  Raises StepError (the Stepper's state unchanged) when a
        step fails; the arrays given are never written."""
        h = self._step_size(h)
        nsteps = self._count(nsteps, "nsteps")
        every = self._count(every if every is not None else 0, "every")
        t, q, p, fresh = self._start(q0, p0, t0)
        if q.ndim == 2:
            return self._ensemble(t, q, p, h, nsteps)
        rows = (nsteps + every - 1) // every + 1 if every else (2 if nsteps else 1)
        trec = np.empty(rows, dtype=self._dtype)
        qrec = np.empty((rows, self.dim), dtype=self._dtype)
        prec = np.empty((rows, self.dim), dtype=self._dtype)
        ffi = self._ffi
        tc, hc = self._cell(t), self._cell(h)
        nrows, done = ffi.new("size_t *"), ffi.new("unsigned long *")

        def body():
            st = self._call["integrate"](self._type, self._w, tc, self._ptr(q), self._ptr(p), hc[0], nsteps, every,
                                         self._ptr(trec), self._ptr(qrec), self._ptr(prec), rows, nrows, done)
            return st, done[0]

        self._run(fresh, body)
        self._commit(self._value(tc), q, p)
        n = nrows[0]
        return trec[:n], qrec[:n], prec[:n]

    def _ensemble(self, t, q, p, h, nsteps):
        if self._dtype != np.dtype(np.float64):
            raise InputError("vigen.Stepper: ensembles run in double precision only")
        n = q.shape[0]
        tt = np.empty(n, dtype=self._dtype)
        tt[:] = t
        status = np.zeros(n, dtype=np.intc)
        steps = np.zeros(n, dtype=np.uint64 if self._ffi.sizeof("unsigned long") == 8 else np.uint32)
        self._pending = None
        st_ptr = self._ffi.cast("int *", status.ctypes.data)
        steps_ptr = self._ffi.cast("unsigned long *", steps.ctypes.data)
        if self.batch:
            mech, fn, fq, fp, ctx, separable = self._batch_args
            if not separable:
                raise InputError("vigen.Stepper: the batched stepper needs a separable H (separable=True) "
                                 "or a force")
            pb = self._pb if self._pb is not None else self._ffi.NULL
            im = self._ptr(self._inv_mass) if self._inv_mass is not None else self._ffi.NULL
            rc = self._lib.vpy_ensemble_batch(self.batch, mech, self.dim, fn, fq, fp, ctx, pb, im, self._opt, n,
                                              self._ptr(tt), self._ptr(q), self._ptr(p), float(h), nsteps, st_ptr,
                                              steps_ptr)
        else:
            threads = 1 if self._python else self.threads
            rc = self._native.vigen_python_integrate_ensemble(self._type, self._w, self.dim, threads, n,
                                                              self._ptr(tt), self._ptr(q), self._ptr(p), float(h),
                                                              nsteps, st_ptr, steps_ptr)
        pending, self._pending = self._pending, None
        if pending is not None:
            raise StepError("vigen.Stepper: the Python force raised %s: %s" % (type(pending).__name__, pending),
                            "force raised") from pending
        if rc != 0:
            why = self._ffi.string(self._native.vigen_python_strerror(rc)).decode()
            if rc == _EUNSUPPORTED:
                raise InputError("vigen.Stepper: the batched stepper refuses this problem or these options "
                                 "(%s): an implicit tableau runs batched for a force with the fixed point only" % why)
            bad = int(np.flatnonzero(status)[0]) if np.any(status) else -1
            cls = InputError if rc == _EINVAL else StepError
            raise cls("vigen.Stepper: trajectory %d of the ensemble failed: %s" % (bad, why), why)
        return tt, q, p

    def integrate_at(self, t_out, q0=None, p0=None, h=None, t0=0.0):
        """The states at the times t_out (monotone in the direction of h, not
        before the start), stepping with h from (t0, q0, p0) (or from the
        last state) and reading between step ends through a cubic Hermite
        extension (error O(h^min(p, 4)); a time equal to a step end gets its
        state exactly).  Returns (t_out, q, p) with q and p of shape
        (len(t_out), dim); the run's state is the last step's (at or past
        the last output time)."""
        h = self._step_size(h)
        t, q, p, fresh = self._start(q0, p0, t0)
        if q.ndim != 1:
            raise InputError("vigen.Stepper: integrate_at takes one trajectory (q0 of shape (%d,))" % self.dim)
        tout = self._array(t_out, "t_out", None).reshape(-1)
        if tout.size == 0 or not np.all(np.isfinite(tout)):
            raise InputError("vigen.Stepper: t_out must hold at least one time, every one finite")
        d = np.diff(np.concatenate(([t], tout)))
        if np.any(d * np.sign(h) < 0):
            raise InputError("vigen.Stepper: t_out must be monotone in the direction of h and not before t0")
        qo = np.empty((tout.size, self.dim), dtype=self._dtype)
        po = np.empty_like(qo)
        tc, hc = self._cell(t), self._cell(h)
        done = self._ffi.new("unsigned long *")

        def body():
            st = self._call["integrate_at"](self._type, self._w, tc, self._ptr(q), self._ptr(p), hc[0], self._ptr(tout),
                                            tout.size, self._ptr(qo), self._ptr(po), done)
            return st, done[0]

        self._run(fresh, body)
        self._commit(self._value(tc), q, p)
        return tout, qo, po

    def integrate_events(self, event, q0=None, p0=None, h=None, nsteps=None, t0=0.0, direction=0, terminal=False,
                         max_events=1000):
        """Takes nsteps steps and returns the times (an array) where
        ``event(t, q, p)`` (a Python callable returning a float, evaluated
        once per step end) changes sign: rising only for direction=+1,
        falling only for -1, both for 0; found on the cubic extension and
        refined to round-off.  terminal=True stops the run at the first
        event (the state is then the one there)."""
        h = self._step_size(h)
        nsteps = self._count(nsteps, "nsteps")
        if direction not in (-1, 0, 1):
            raise InputError("vigen.Stepper: direction must be -1, 0 or +1, not %r" % (direction,))
        if not callable(event):
            raise InputError("vigen.Stepper: event must be a callable event(t, q, p)")
        t, q, p, fresh = self._start(q0, p0, t0)
        if q.ndim != 1:
            raise InputError("vigen.Stepper: integrate_events takes one trajectory (q0 of shape (%d,))" % self.dim)
        dim, ffi = self.dim, self._ffi

        def g(tt, qq, pp, ctx):
            try:
                v = float(event(float(tt), self._view(qq, dim), self._view(pp, dim)))
            except BaseException:
                self._pending = self._pending or sys.exc_info()[1]
                return float("nan")
            return v

        cb = ffi.callback("vpy_event_fn", g)
        max_events = self._count(max_events, "max_events")
        tev = np.empty(max(max_events, 1), dtype=self._dtype)
        tc, hc = self._cell(t), self._cell(h)
        nev = ffi.new("size_t *")

        def body():
            st = self._call["integrate_events"](self._type, self._w, tc, self._ptr(q), self._ptr(p), hc[0], nsteps, cb,
                                                ffi.NULL, direction, int(bool(terminal)), self._ptr(tev),
                                                max_events, nev)
            return st, 0

        self._run(fresh, body)
        self._commit(self._value(tc), q, p)
        return tev[:min(nev[0], max_events)].copy()

    # -- what the problem offers
    def initial(self):
        """(t0, q0, p0): the standard initial value of a problem of the collection."""
        self._need_problem("initial")
        t = self._ffi.new("double *")
        q = np.empty(self.dim)
        p = np.empty(self.dim)
        self._lib.vpy_problem_initial(self._pb, t, self._ptr(q), self._ptr(p))
        return t[0], q, p

    def period(self):
        """The characteristic time of a problem of the collection (the period of its standard orbit)."""
        self._need_problem("period")
        return self._lib.vpy_problem_period(self._pb)

    def invariants(self, t, q, p):
        """{name: array} of the further invariants of a problem of the
        collection (angular momentum, ...) along rows of (t, q, p)."""
        self._need_problem("invariants")
        t, q, p = self._rows(t, q, p)
        out = {}
        for k in range(self._lib.vpy_problem_invariant_count(self._pb)):
            name = self._ffi.string(self._lib.vpy_problem_invariant_name(self._pb, k)).decode()
            out[name] = np.array([self._lib.vpy_problem_invariant(self._pb, k, t[i], self._ptr(q[i]),
                                                                  self._ptr(p[i])) for i in range(len(t))])
        return out

    def reference(self, t):
        """The reference solution (q, p) at time t from the standard initial
        value, where the problem has one (else None)."""
        self._need_problem("reference")
        q, p = np.empty(self.dim), np.empty(self.dim)
        if not self._lib.vpy_problem_reference(self._pb, float(t), self._ptr(q), self._ptr(p)):
            return None
        return q, p

    def energy(self, t, q, p):
        """H along rows of (t, q, p) (t of shape (n,), q and p (n, dim)): for a
        problem of the collection, a C force with V, or a C Hamiltonian with H."""
        if self._energy_fn is None:
            raise InputError("vigen.Stepper: no energy: use a problem of the collection, or define V (force) "
                             "or H (hamiltonian) in the C source")
        t, q, p = self._rows(t, q, p)
        return self._energy_fn(t, q, p)

    def _rows(self, t, q, p):
        q = np.ascontiguousarray(q, dtype=self._dtype).reshape(-1, self.dim)
        p = np.ascontiguousarray(p, dtype=self._dtype).reshape(-1, self.dim)
        t = np.broadcast_to(np.asarray(t, dtype=self._dtype), (q.shape[0],))
        return t, q, p

    def _need_problem(self, what):
        if self._pb is None:
            raise InputError("vigen.Stepper: %s() needs a problem of the collection (problem=...)" % what)

    def _problem_energy(self, t, q, p):
        return np.array([self._lib.vpy_problem_energy(self._pb, t[i], self._ptr(q[i]), self._ptr(p[i]))
                         for i in range(len(t))])

    def _mechanical_energy(self, t, q, p):
        im = self._inv_mass if self._inv_mass is not None else np.ones(self.dim, dtype=self._dtype)
        kinetic = 0.5 * np.sum(p * p * im, axis=1)
        return kinetic + np.array([self._lib.vpy_user_V(t[i], self._ptr(q[i]), self._ctx) for i in range(len(t))],
                                  dtype=self._dtype)

    def _hamiltonian_energy(self, t, q, p):
        return np.array([self._lib.vpy_user_H(t[i], self._ptr(q[i]), self._ptr(p[i]), self._ctx)
                         for i in range(len(t))], dtype=self._dtype)

    def __repr__(self):
        return "<vigen.Stepper %s dim=%d dtype=%s>" % (self.method, self.dim, self._dtype)
