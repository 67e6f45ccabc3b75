"""Figures of steppers' runs, the ones ``vigen try`` draws, with matplotlib.

- :func:`energy`: the relative energy error |H - H0| / |H0| against time,
  log scale, one curve per method (``vigen try --plot``'s energy figure);
- :func:`orbit`: two coordinates against each other, equal axes (its orbit
  figure);
- :func:`work_precision`: the error against the work, log-log, one curve
  per method (``vigen try --work-precision``): each method run on a problem
  of the collection at step sizes halving from level to level.

Each returns the matplotlib Figure (drawn with the Agg backend when no
backend was chosen, so that it works without a display) and saves it when
``path`` is given (the format from the suffix: .png, .svg, .pdf).
matplotlib is needed only here (Debian: python3-matplotlib); without it
these functions raise ImportError saying so.
"""
import time

import numpy as np


def _pyplot():
    try:
        import matplotlib
    except ImportError:
        raise ImportError("vigen.plot needs matplotlib, which is not installed (Debian: apt-get install "
                          "python3-matplotlib; elsewhere: pip install matplotlib)") from None
    import sys
    if "matplotlib.pyplot" not in sys.modules:
        matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


def _finish(fig, ax, title, path):
    if title:
        ax.set_title(title)
    if ax.get_legend_handles_labels()[0]:
        ax.legend(loc="best", fontsize="small")
    fig.tight_layout()
    if path is not None:
        fig.savefig(path)
    return fig


def _curves(curves, what):
    """{label: data} from a dict, a list of (label, data...) or one unlabelled data tuple."""
    if isinstance(curves, dict):
        return [(k, v if isinstance(v, tuple) else (v,)) for k, v in curves.items()]
    if isinstance(curves, tuple):
        return [(None, curves)]
    try:
        return [(c[0], tuple(c[1:])) for c in curves]
    except (TypeError, IndexError):
        raise TypeError("vigen.plot.%s takes {label: data}, a list of (label, data...) or one data tuple" % what)


def energy(curves, title=None, path=None):
    """The relative energy error |H(t) - H(t0)| / |H(t0)| against t, log y.

    curves: ``{label: (t, H)}`` (t and H arrays of one run, e.g. ``t`` from
    :meth:`vigen.Stepper.integrate` and ``H = stepper.energy(t, q, p)``), a
    list of ``(label, t, H)``, or one ``(t, H)``.  Points where the error is
    exactly zero are left out (a log scale has no zero), as vigen try does.
    Returns the Figure; saves it to path when given."""
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for label, data in _curves(curves, "energy"):
        t, H = (np.asarray(x, dtype=float) for x in data[:2])
        scale = abs(H[0]) if H.size and H[0] != 0 else 1.0
        err = np.abs(H - H[0]) / scale
        keep = err > 0
        ax.semilogy(t[keep], err[keep], lw=1, label=label)
    ax.set_xlabel("t")
    ax.set_ylabel("|H - H0| / |H0|")
    return _finish(fig, ax, title, path)


def orbit(curves, x=0, y=1, title=None, path=None, xlabel="q[0]", ylabel="q[1]"):
    """Coordinates x and y of q against each other, equal axes (the orbit of
    a planar problem).  curves: ``{label: q}`` (q of shape (n, dim)), a list
    of ``(label, q)`` or one ``(q,)``."""
    plt = _pyplot()
    fig, ax = plt.subplots(figsize=(5.5, 5.5))
    for label, data in _curves(curves, "orbit"):
        q = np.asarray(data[0], dtype=float)
        ax.plot(q[:, x], q[:, y], lw=1, label=label)
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    return _finish(fig, ax, title, path)


def measure(methods, problem="kepler", periods=10, base=64, levels=5, **params):
    """The work-precision data of ``vigen try --work-precision``: each method
    run on the problem for ``periods`` periods of its standard orbit at
    base, 2 base, ..., 2^(levels-1) base steps per period.  The error is the
    global error at the final time against the problem's reference solution
    when it has one, else the largest relative energy error over the run
    (sampled at every step).  Returns ``{method: [(h, evals, seconds,
    error), ...]}`` (evals: force or gradient evaluations)."""
    from .stepper import Stepper, StepError
    out = {}
    for m in methods:
        s = Stepper(m, problem=problem, **params)
        t0, q0, p0 = s.initial()
        T = periods * s.period()
        ref = s.reference(t0 + T)
        points = []
        for k in range(levels):
            n = int(round(periods * base * 2 ** k))
            h = T / n
            start = time.perf_counter()
            try:
                t, q, p = s.integrate(q0, p0, h, n, every=0 if ref is not None else 1, t0=t0)
            except StepError:
                continue
            seconds = time.perf_counter() - start
            st = s.stats()
            evals = st["dHdq_evals"] + st["dHdp_evals"]
            if ref is not None:
                err = float(np.max(np.abs(np.concatenate([q[-1] - ref[0], p[-1] - ref[1]]))))
            else:
                H = s.energy(t, q, p)
                err = float(np.max(np.abs(H - H[0])) / (abs(H[0]) or 1.0))
            points.append((h, evals, seconds, err))
        out[m] = points
    return out


def work_precision(data, x="evals", title=None, path=None, error_label=None, **measure_args):
    """The error against the work, log-log, one curve per method.

    data: ``{label: [(h, evals, seconds, error), ...]}`` (what :func:`measure`
    returns; any other curve, SciPy's for instance, in the same form), or a
    list of method names, which are measured first (``measure_args`` go to
    :func:`measure`: problem, periods, base, levels and the problem's
    parameters).  x: "evals" (force evaluations) or "seconds".  The
    measured data is attached to the Figure as ``fig.vigen_data``."""
    if x not in ("evals", "seconds"):
        raise ValueError("vigen.plot.work_precision: x must be 'evals' or 'seconds', not %r" % (x,))
    plt = _pyplot()
    if not isinstance(data, dict):
        data = measure(list(data), **measure_args)
    col = 1 if x == "evals" else 2
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for label, points in data.items():
        pts = [(pt[col], pt[3]) for pt in points if pt[3] > 0 and pt[col] > 0]
        if pts:
            xs, ys = zip(*pts)
            ax.loglog(xs, ys, marker="o", lw=1.5, label=label)
    ax.set_xlabel("force evaluations" if x == "evals" else "seconds")
    ax.set_ylabel(error_label or "error (global at the final time, or max relative energy error)")
    fig.vigen_data = data
    return _finish(fig, ax, title, path)
