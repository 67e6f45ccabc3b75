#!/usr/bin/python3
"""python_bench.py [BUILD] — the speed of vigen.Stepper, in one run:

(a) the cost Python adds per step: the same stepper module (the emitted
    stepper and its force, as vigen.Stepper compiled it) run by
    Stepper.integrate and by a C program (bench/python_overhead.c) calling
    vigen_integrate on it, Kepler e = 0.6, h = 2 pi / 200, 10^4 and 10^5
    steps per call, with every step recorded (every=1) and with the final
    state only (every=0); the force compiled from C source and the problem
    collection's Kepler;
(b) Kepler e = 0.6 over 1000 periods from the pericentre: vigen's
    fourth-order methods from Python against scipy.integrate.solve_ivp
    (method="DOP853") at the tolerances that reach the same largest energy
    error.  Both runs are timed with one output per period (vigen:
    every = steps per period; SciPy: t_eval at every period); the largest
    energy error is taken over every step of an untimed second run (vigen:
    every=1; SciPy: its accepted steps, no t_eval).

Prints the Markdown section of docs/benchmarks.md (between the markers
python:begin and python:end) and, with --write, replaces it there.  Runs
with /usr/bin/python3 (Debian's numpy, cffi, scipy) and the package of the
build tree BUILD (default build/).  Not a test: timings on a shared machine
vary; each figure is the smallest of several repetitions, the median beside
it shows the noise.
"""
import os
import platform
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
ARGS = [a for a in sys.argv[1:] if not a.startswith("--")]
BUILD = os.path.abspath(ARGS[0]) if ARGS else os.path.join(ROOT, "build")
sys.path.insert(0, os.path.join(BUILD, "python"))

import numpy as np  # noqa: E402

import vigen  # noqa: E402
from vigen import _cache  # noqa: E402

KEPLER_C = """
void force(real t, const real *q, real *f, void *ctx)
{
    real r2 = q[0] * q[0] + q[1] * q[1];
    real r3 = r2 * sqrt(r2);
    f[0] = -q[0] / r3;
    f[1] = -q[1] / r3;
}
"""
Q0, P0 = np.array([0.4, 0.0]), np.array([0.0, 2.0])
PERIOD = 2 * np.pi


def timed(fn, reps):
    """(smallest, median) CPU time of the process for fn() over reps runs
    (every run here is single-threaded; CPU time is less sensitive than
    wall time to the other jobs of a shared machine)."""
    ts = []
    for _ in range(reps):
        t0 = time.process_time()
        fn()
        ts.append(time.process_time() - t0)
    ts.sort()
    return ts[0], ts[len(ts) // 2]


def c_driver(stepper, workdir):
    """The C program driving the stepper module of stepper, built into
    workdir from the module's C files (in its cache folder)."""
    folder = os.path.dirname(stepper.module_file)
    exe = os.path.join(workdir, "python_overhead_%s" % os.path.basename(folder))
    cmd = _cache.compile_command(_cache.compiler(), os.path.join(HERE, "python_overhead.c"), exe)
    cmd.remove("-shared")
    cmd.remove("-fPIC")
    subprocess.run(cmd, cwd=folder, check=True)
    return exe


def overhead_rows(workdir, rounds=8, reps=5):
    """C and Python taking turns, rounds times reps runs each, so that both
    see the same load of the machine."""
    rows = []
    for label, kind, make in (("C force", 0, lambda: vigen.Stepper("yoshida_4", force=KEPLER_C, dim=2)),
                              ("problem kepler", 1, lambda: vigen.Stepper("yoshida_4", problem="kepler", e=0.6))):
        s = make()
        exe = c_driver(s, workdir)
        for nsteps in (10_000, 100_000):
            for every in (1, 0):
                s.integrate(Q0, P0, PERIOD / 200, nsteps, every=every)  # warm up
                cs, ps = [], []
                for _ in range(rounds):
                    out = subprocess.run([exe, str(kind), str(nsteps), str(every), str(reps)], capture_output=True,
                                         text=True, check=True).stdout.split()
                    cs.append(float(out[0]))
                    ps.append(timed(lambda: s.integrate(Q0, P0, PERIOD / 200, nsteps, every=every), reps)[0])
                cs.sort()
                ps.sort()
                rows.append((label, nsteps, every, cs[0], cs[rounds // 2], ps[0], ps[rounds // 2]))
    return rows


def kepler_energy(q, p):
    return 0.5 * np.sum(p * p, axis=-1) - 1 / np.sqrt(np.sum(q * q, axis=-1))


E0 = float(kepler_energy(Q0, P0))


def vigen_point(method, per_period, periods, reps):
    # the published Blanes-Moan and McLachlan tableaux give some entries with
    # 16 digits: rounded as written, as `vigen emit --allow-inexact` does
    s = vigen.Stepper(method, force=KEPLER_C, dim=2, allow_inexact=True)
    n = per_period * periods
    h = periods * PERIOD / n
    t, q, p = s.integrate(Q0, P0, h, n, every=1)
    err = float(np.max(np.abs(kepler_energy(q, p) - E0)) / abs(E0))
    best, med = timed(lambda: s.integrate(Q0, P0, h, n, every=per_period), reps)
    evals = s.stats()["dHdq_evals"]
    return err, best, med, evals


def scipy_point(tol, periods, reps):
    from scipy.integrate import solve_ivp

    def f(t, y):
        r2 = y[0] * y[0] + y[1] * y[1]
        r3 = r2 * np.sqrt(r2)
        return np.array([y[2], y[3], -y[0] / r3, -y[1] / r3])

    y0 = np.concatenate([Q0, P0])
    T = periods * PERIOD
    sol = solve_ivp(f, (0, T), y0, method="DOP853", rtol=tol, atol=tol)
    err = float(np.max(np.abs(kepler_energy(sol.y[:2].T, sol.y[2:].T) - E0)) / abs(E0))
    t_eval = np.linspace(0, T, periods + 1)
    best, med = timed(lambda: solve_ivp(f, (0, T), y0, method="DOP853", rtol=tol, atol=tol, t_eval=t_eval), reps)
    return err, best, med, sol.nfev


def kepler_rows(periods=1000):
    methods = ("yoshida_4", "blanes_moan_s6_4", "mclachlan_rkn_4")
    vig = []
    for m in methods:
        for per_period in (100, 200, 400):
            err, best, med, evals = vigen_point(m, per_period, periods, 7)
            vig.append((m, per_period, err, best, med, evals))
    sci = []
    for tol in (1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12):
        err, best, med, nfev = scipy_point(tol, periods, 3)
        sci.append((tol, err, best, med, nfev))
    return vig, sci


def scipy_at(err, sci):
    """SciPy's time at the energy error err: interpolated log-log between the
    tolerances that bracket it (None beyond the range measured), and the
    cheapest measured run reaching err or better (None if none does)."""
    pts = sorted((e, b) for _, e, b, _, _ in sci)
    reach = [b for e, b in pts if e <= err]
    cheapest = min(reach) if reach else None
    interp = None
    for (e1, b1), (e2, b2) in zip(pts, pts[1:]):
        if e1 <= err <= e2 and e1 > 0:
            w = (np.log(err) - np.log(e1)) / (np.log(e2) - np.log(e1))
            interp = float(np.exp(np.log(b1) + w * (np.log(b2) - np.log(b1))))
    return interp, cheapest


def cpu():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"


def section():
    import scipy
    lines = ["<!-- python:begin (written by bench/python_bench.py) -->", "## Python: `vigen.Stepper`", ""]
    lines.append("Written by `/usr/bin/python3 bench/python_bench.py --write` in one run. Machine: %d cores, %s; "
                 "Python %s, NumPy %s, SciPy %s; %s. The machine is shared: each figure is the smallest of "
                 "several runs of CPU time (one thread; less sensitive than wall time to the other jobs), with the "
                 "median beside it for the noise."
                 % (os.cpu_count(), cpu(), platform.python_version(), np.__version__, scipy.__version__,
                    time.strftime("%Y-%m-%d", time.gmtime())))
    lines += ["", "### The cost of Python per step", "",
              "The same stepper module (Yoshida-4 on Kepler e = 0.6, h = 2 pi/200), run by `Stepper.integrate` and "
              "by a C program calling `vigen_integrate` on it (bench/python_overhead.c), from the pericentre "
              "each call; `every=1` records every step into arrays allocated for the run (NumPy arrays; the "
              "C program mallocs its own), `every=0` only the end; C and Python take turns (8 rounds of 5 runs "
              "each). Target: Python at most 10% over C from 10^4 steps per call.", "",
              "| force | steps/call | every | C (ms) min / median | Python (ms) min / median | Python / C - 1 |",
              "|---|---|---|---|---|---|"]
    with tempfile.TemporaryDirectory() as workdir:
        overhead = overhead_rows(workdir)
    for label, n, every, cmin, cmed, pmin, pmed in overhead:
        lines.append("| %s | %d | %d | %.3f / %.3f | %.3f / %.3f | %+.1f%% |"
                     % (label, n, every, 1e3 * cmin, 1e3 * cmed, 1e3 * pmin, 1e3 * pmed, 100 * (pmin / cmin - 1)))
    vig, sci = kepler_rows()
    lines += ["", "### Kepler e = 0.6, 1000 periods: against SciPy's DOP853", "",
              "Largest relative energy error over every step, and CPU time of the run with one output per "
              "period. vigen: the force as C source (compiled into the stepper). SciPy: `solve_ivp(f, ..., "
              "method=\"DOP853\", rtol=tol, atol=tol)` with a NumPy right-hand side.", "",
              "| SciPy tol | max energy error | seconds min / median | f evaluations |", "|---|---|---|---|"]
    for tol, err, best, med, nfev in sci:
        lines.append("| %.0e | %.2e | %.3f / %.3f | %d |" % (tol, err, best, med, nfev))
    lines += ["", "| vigen method | steps/period | max energy error | seconds min / median | forces | SciPy at that "
              "error (s, interpolated) | speed-up | cheapest SciPy run reaching it (s) | speed-up |",
              "|---|---|---|---|---|---|---|---|---|"]
    for m, per, err, best, med, evals in vig:
        interp, cheapest = scipy_at(err, sci)
        lines.append("| %s | %d | %.2e | %.4f / %.4f | %d | %s | %s | %s | %s |" % (
            m, per, err, best, med, evals, "%.3f" % interp if interp else "out of range",
            "%.0f×" % (interp / best) if interp else "-", "%.3f" % cheapest if cheapest else "none",
            "%.0f×" % (cheapest / best) if cheapest else "-"))
    lines += ["<!-- python:end -->"]
    return "\n".join(lines) + "\n"


def main():
    text = section()
    print(text)
    if "--write" in sys.argv:
        path = os.path.join(ROOT, "docs", "benchmarks.md")
        with open(path, encoding="utf-8") as f:
            doc = f.read()
        begin, end = doc.find("<!-- python:begin"), doc.find("<!-- python:end -->")
        if begin >= 0 and end >= 0:
            doc = doc[:begin] + text + doc[end + len("<!-- python:end -->\n"):]
        else:
            doc = doc.rstrip("\n") + "\n\n" + text
        with open(path, "w", encoding="utf-8") as f:
            f.write(doc)


if __name__ == "__main__":
    main()
