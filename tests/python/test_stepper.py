"""vigen.Stepper against independent truths: the C stepper of `vigen emit`
driven from C, closed-form solutions, invariants, and itself run in pieces,
in batches and from another force."""
import os
import pickle
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import vigen
from vigen import _cache, _paths, _stepper_module

KEPLER_C = textwrap.dedent("""
    void force(real t, const real *q, real *f, void *ctx)
    {
        real r2 = q[0] * q[0] + q[1] * q[1];
        real r3 = r2 * sqrt(r2);
        f[0] = -q[0] / r3;
        f[1] = -q[1] / r3;
    }
    real V(real t, const real *q, void *ctx) { return -1 / sqrt(q[0] * q[0] + q[1] * q[1]); }
""")
OSCILLATOR_C = "void force(real t, const real *q, real *f, void *ctx) { f[0] = -q[0]; }\n"
Q0, P0 = np.array([0.4, 0.0]), np.array([0.0, 2.0])  # Kepler e = 0.6 from its pericentre, period 2 pi


def kepler_py(t, q):
    r2 = q[0] * q[0] + q[1] * q[1]
    r3 = r2 * np.sqrt(r2)
    return np.array([-q[0] / r3, -q[1] / r3])


@pytest.fixture(autouse=True, scope="module")
def private_cache(tmp_path_factory):
    """A cache of this module's own, so that the tests compile what they use."""
    old = os.environ.get("VIGEN_CACHE_DIR")
    os.environ["VIGEN_CACHE_DIR"] = str(tmp_path_factory.mktemp("cache"))
    yield os.environ["VIGEN_CACHE_DIR"]
    if old is None:
        del os.environ["VIGEN_CACHE_DIR"]
    else:
        os.environ["VIGEN_CACHE_DIR"] = old


# ---- the C stepper of the command line, driven from C ---------------------------
C_DRIVER = textwrap.dedent(r"""
    #include <math.h>
    #include <stdio.h>
    #include <vigen/runtime.h>
    #include "y4.h"
    #include "g2.h"
    static void force(double t, const double *q, double *f, void *ctx)
    {
        (void)t; (void)ctx;
        double r2 = q[0] * q[0] + q[1] * q[1];
        double r3 = r2 * sqrt(r2);
        f[0] = -q[0] / r3;
        f[1] = -q[1] / r3;
    }
    static void run(const vigen_stepper_type *T, void *w)
    {
        double t = 0, q[2] = { 0.4, 0.0 }, p[2] = { 0.0, 2.0 };
        int rc = vigen_integrate(T, w, &t, q, p, 6.283185307179586 / 200, 1000, 0, NULL, NULL, NULL);
        printf("%d %a %a %a %a %a\n", rc, t, q[0], q[1], p[0], p[1]);
    }
    int main(void)
    {
        vigen_mechanical sys = { .dim = 2, .force = force };
        void *a = y4_alloc_mechanical(&sys, NULL), *b = g2_alloc_mechanical(&sys, NULL);
        run(&y4_type, a);
        run(&g2_type, b);
        y4_free(a);
        g2_free(b);
        return 0;
    }
""")


def test_bits_equal_the_c_stepper_of_vigen_emit(cli, tmp_path):
    for method, name in (("yoshida_4", "y4"), ("gauss_2", "g2")):
        r = cli("emit", method, "--name", name, "-o", str(tmp_path), "-q")
        assert r.returncode == 0, r.stderr
    (tmp_path / "driver.c").write_text(C_DRIVER)
    cmd = _cache.compiler() + ["-std=c11", "-O2", "-I" + str(tmp_path)] + ["-I" + d for d in _paths.INCLUDE_DIRS]
    cmd += [str(tmp_path / f) for f in ("driver.c", "y4.c", "g2.c")]
    cmd += _cache.link_flags() + ["-o", str(tmp_path / "driver")]
    subprocess.run(cmd, check=True)
    lines = subprocess.run([str(tmp_path / "driver")], capture_output=True, text=True, check=True).stdout.split("\n")
    for line, method in zip(lines, ("yoshida_4", "gauss_2")):
        rc, *values = line.split()
        assert rc == "0"
        want = [float.fromhex(v) for v in values]
        s = vigen.Stepper(method, force=KEPLER_C, dim=2)
        t, q, p = s.integrate(Q0, P0, 2 * np.pi / 200, 1000, every=0)
        got = [t[-1], q[-1, 0], q[-1, 1], p[-1, 0], p[-1, 1]]
        assert [float(x).hex() for x in got] == [x.hex() for x in want], method


# ---- closed forms and invariants ----------------------------------------------------
def oscillator_error(method, h, T=4.0, dtype=np.float64):
    s = vigen.Stepper(method, force=OSCILLATOR_C, dim=1, dtype=dtype)
    n = int(round(T / float(h)))
    hh = dtype(T) / n
    t, q, p = s.integrate([1], [0], hh, n, every=0)
    return max(abs(q[-1, 0] - np.cos(t[-1])), abs(p[-1, 0] + np.sin(t[-1])))


@pytest.mark.parametrize("method,order", [("yoshida_4", 4), ("stormer_verlet_velocity", 2), ("gauss_2", 4)])
def test_order_on_the_harmonic_oscillator(method, order):
    e1, e2 = oscillator_error(method, 0.1), oscillator_error(method, 0.05)
    assert abs(np.log2(e1 / e2) - order) < 0.3


def test_long_double_reaches_below_double_round_off():
    # Gauss order 6 at h = 2^-6 and 2^-7: errors near 1e-16 and 2e-18, below
    # double's round-off, where only the 64-bit significand still shows the order
    e1 = oscillator_error("gauss_3", 2.0 ** -6, T=1.0, dtype=np.longdouble)
    e2 = oscillator_error("gauss_3", 2.0 ** -7, T=1.0, dtype=np.longdouble)
    assert e2 < 1e-17
    assert abs(np.log2(float(e1 / e2)) - 6) < 0.5


def test_kepler_invariants():
    s = vigen.Stepper("yoshida_4", problem="kepler", e=0.6)
    t0, q0, p0 = s.initial()
    assert np.allclose(q0, Q0) and np.allclose(p0, P0) and s.period() == pytest.approx(2 * np.pi)
    t, q, p = s.integrate(q0, p0, s.period() / 500, 500 * 40, every=25)
    E = s.energy(t, q, p)
    # exact values of the orbit: H = -1/(2a) with a = 1, L = sqrt(a (1 - e^2))
    assert E[0] == pytest.approx(-0.5, abs=1e-15)
    dE = np.abs(E - E[0])
    half = len(dE) // 2
    assert 0 < dE.max() < 1e-4
    assert dE[half:].max() < 2 * dE[:half].max()  # bounded: no drift over 40 periods
    L = s.invariants(t, q, p)["angular-momentum"]
    assert L[0] == pytest.approx(0.8, abs=1e-15)
    assert np.max(np.abs(L - L[0])) < 1e-12  # a splitting conserves it to round-off


def test_output_at_any_time_and_events_on_the_oscillator():
    s = vigen.Stepper("yoshida_4", force=OSCILLATOR_C, dim=1)
    times = np.array([0.123, 1.0, 2.5, 3.14159])
    t, q, p = s.integrate_at(times, [1], [0], h=0.01)
    assert np.max(np.abs(q[:, 0] - np.cos(times))) < 1e-7
    assert np.max(np.abs(p[:, 0] + np.sin(times))) < 1e-7
    rising = s.integrate_events(lambda t, q, p: q[0], [1], [0], h=0.01, nsteps=1200, direction=1)
    assert np.allclose(rising, [1.5 * np.pi, 3.5 * np.pi], atol=1e-7)
    both = s.integrate_events(lambda t, q, p: q[0], [1], [0], h=0.01, nsteps=800)
    assert np.allclose(both, [0.5 * np.pi, 1.5 * np.pi, 2.5 * np.pi], atol=1e-7)


def test_rows_of_every():
    s = vigen.Stepper("yoshida_4", force=OSCILLATOR_C, dim=1)
    t, q, p = s.integrate([1], [0], 0.1, 10, every=3)
    assert q.shape == (5, 1) and p.shape == (5, 1) and t.shape == (5,)  # steps 0 3 6 9 10
    assert np.allclose(t, [0, 0.3, 0.6, 0.9, 1.0])
    t, q, p = s.integrate([1], [0], 0.1, 10, every=5)
    assert t.shape == (10 // 5 + 1,)


# ---- forces from Python -----------------------------------------------------------
def test_python_force_gives_the_c_force_trajectory():
    a = vigen.Stepper("yoshida_4", force=KEPLER_C, dim=2)
    b = vigen.Stepper("yoshida_4", force=kepler_py, dim=2)
    _, qa, pa = a.integrate(Q0, P0, 2 * np.pi / 300, 600, every=50)
    _, qb, pb = b.integrate(Q0, P0, 2 * np.pi / 300, 600, every=50)
    assert np.allclose(qa, qb, rtol=0, atol=1e-13) and np.allclose(pa, pb, rtol=0, atol=1e-13)


def test_a_generated_tableau_runs_as_its_method_file(source_dir):
    # Gauss-Legendre s = 2 generated from its spec is the published gauss_2:
    # the same order on the oscillator
    t = vigen.generate(os.path.join(source_dir, "tableaux", "specs", "gauss_legendre_s2.lua"), digits=40)
    e = []
    for h in (0.1, 0.05):
        s = vigen.Stepper(t, force=OSCILLATOR_C, dim=1)
        _, q, p = s.integrate([1], [0], h, int(round(4 / h)), every=0)
        e.append(abs(q[-1, 0] - np.cos(4.0)))
    assert abs(np.log2(e[0] / e[1]) - 4) < 0.3


def test_python_hamiltonian_gradients():
    # H = p^2/2 + q^2/2 as a general (not separable) H through Newton
    s = vigen.Stepper("gauss_2", hamiltonian=(lambda t, q, p: q, lambda t, q, p: p), dim=1, solver="newton")
    t, q, p = s.integrate([1], [0], 0.05, 80, every=0)
    assert abs(q[-1, 0] - np.cos(4.0)) < 1e-6


def test_a_raising_force_is_an_exception_and_changes_nothing():
    calls = []

    def force(t, q):
        calls.append(t)
        if len(calls) > 40:
            raise KeyError("boom")
        return -q

    s = vigen.Stepper("yoshida_4", force=force, dim=1)
    s.integrate([1], [0], 0.1, 5)
    before = s.state()
    with pytest.raises(vigen.StepError) as info:
        s.integrate(h=0.1, nsteps=100)
    assert isinstance(info.value.__cause__, KeyError)
    after = s.state()
    assert after.t == before.t and np.array_equal(after.q, before.q) and after.workspace == before.workspace


# ---- bad input ----------------------------------------------------------------------
def test_bad_input_raises_and_writes_nothing():
    s = vigen.Stepper("yoshida_4", force=KEPLER_C, dim=2)
    s.integrate(Q0, P0, 0.01, 10)
    state = s.state()
    q_nan = np.array([np.nan, 0.0])
    bad = [dict(q0=[1.0, 2.0, 3.0], p0=[1.0, 2.0, 3.0]), dict(q0=q_nan, p0=P0.copy()), dict(q0=Q0.copy(), p0=None),
           dict(q0=np.zeros((2, 3)), p0=np.zeros((2, 3)))]
    for kw in bad:
        copies = {k: (None if v is None else np.array(v, copy=True)) for k, v in kw.items()}
        with pytest.raises(vigen.InputError):
            s.integrate(h=0.01, nsteps=10, **kw)
        for k, v in kw.items():
            assert v is None or np.array_equal(np.asarray(v), copies[k], equal_nan=True)
    for h in (0.0, np.inf, np.nan):
        with pytest.raises(vigen.InputError):
            s.integrate(Q0, P0, h, 10)
    with pytest.raises(vigen.InputError):
        s.integrate(Q0, P0, 0.01, -1)
    assert s.state().workspace == state.workspace and s.t == state.t


def test_bad_construction():
    with pytest.raises(vigen.InputError):
        vigen.Stepper("no_such_method_xyz", force=KEPLER_C, dim=2)
    with pytest.raises(vigen.InputError):
        vigen.Stepper("yoshida_4", problem="no-such-problem")
    with pytest.raises(vigen.InputError):
        vigen.Stepper("yoshida_4", force=KEPLER_C)  # no dim
    with pytest.raises(vigen.InputError):
        vigen.Stepper("yoshida_4", force="void force(real t, const real *q, real *f, void *ctx) { oops }", dim=2)
    with pytest.raises(vigen.InputError):
        vigen.Stepper("yoshida_4", force=kepler_py, problem="kepler")


def test_a_diverging_solve_is_an_exception_with_the_state_kept():
    s = vigen.Stepper("gauss_2", force=OSCILLATOR_C, dim=1)
    s.integrate([1], [0], 0.1, 3)
    before = s.state()
    with pytest.raises(vigen.StepError):
        s.integrate(h=50.0, nsteps=1)  # the fixed point cannot converge for h >> 1
    assert s.state().workspace == before.workspace and np.array_equal(s.state().q, before.q)


def test_a_non_finite_force_is_an_exception():
    s = vigen.Stepper("yoshida_4", force="void force(real t, const real *q, real *f, void *c) { f[0] = 1 / (q[0] - q[0]); }",
                      dim=1)
    with pytest.raises(vigen.StepError):
        s.integrate([1], [0], 0.1, 3)


# ---- restart, ensembles -------------------------------------------------------------
def test_restart_bit_for_bit_after_pickle():
    h = 2 * np.pi / 300
    whole = vigen.Stepper("gauss_2", force=KEPLER_C, dim=2)
    _, qw, pw = whole.integrate(Q0, P0, h, 700, every=0)
    first = vigen.Stepper("gauss_2", force=KEPLER_C, dim=2)
    first.integrate(Q0, P0, h, 300, every=0)
    saved = pickle.dumps(first.state())
    second = vigen.Stepper("gauss_2", force=KEPLER_C, dim=2)
    second.set_state(pickle.loads(saved))
    t, q, p = second.integrate(h=h, nsteps=400, every=0)
    assert np.array_equal(q[-1], qw[-1]) and np.array_equal(p[-1], pw[-1]) and t[-1] == whole.t
    for other in (vigen.Stepper("yoshida_4", force=KEPLER_C, dim=2),
                  vigen.Stepper("gauss_2", force=KEPLER_C, dim=2, params=[1.0]),
                  vigen.Stepper("gauss_2", force=KEPLER_C, dim=2, solver="newton")):
        with pytest.raises(vigen.InputError):
            other.set_state(pickle.loads(saved))
    a = vigen.Stepper("yoshida_4", problem="kepler", e=0.6)
    a.integrate(Q0, P0, h, 10)
    with pytest.raises(vigen.InputError):
        vigen.Stepper("yoshida_4", problem="kepler", e=0.9).set_state(a.state())


def test_ensemble_equals_single_runs():
    rng = np.random.default_rng(1)
    q0 = Q0 + 0.05 * rng.standard_normal((7, 2))
    p0 = P0 + 0.05 * rng.standard_normal((7, 2))
    s = vigen.Stepper("yoshida_4", force=KEPLER_C, dim=2, threads=2)
    t, q, p = s.integrate(q0, p0, 0.01, 500)
    assert q.shape == (7, 2) and t.shape == (7,)
    for i in range(7):
        ti, qi, pi = s.integrate(q0[i], p0[i], 0.01, 500, every=0)
        assert np.array_equal(qi[-1], q[i]) and np.array_equal(pi[-1], p[i]) and ti[-1] == t[i]


@pytest.mark.parametrize("make", [
    lambda: vigen.Stepper("yoshida_4", force=KEPLER_C, dim=2, batch=4),
    lambda: vigen.Stepper("yoshida_4", force=kepler_py, dim=2, batch=3),
    lambda: vigen.Stepper("yoshida_4", problem="kepler", e=0.6, batch=4),
    lambda: vigen.Stepper("gauss_2", force=KEPLER_C, dim=2, batch=4),
], ids=["c-force", "python-force", "problem", "implicit"])
def test_batched_ensemble_equals_single_runs(make):
    rng = np.random.default_rng(2)
    q0 = Q0 + 0.05 * rng.standard_normal((7, 2))  # 7 = 4 + 3: a short, padded last block
    p0 = P0 + 0.05 * rng.standard_normal((7, 2))
    s = make()
    t, q, p = s.integrate(q0, p0, 0.01, 300)
    for i in range(7):
        ti, qi, pi = s.integrate(q0[i], p0[i], 0.01, 300, every=0)
        assert np.array_equal(qi[-1], q[i]) and np.array_equal(pi[-1], p[i]) and ti[-1] == t[i]


def test_batched_stepper_refuses_what_it_cannot_run():
    s = vigen.Stepper("gauss_2", force=KEPLER_C, dim=2, batch=4, solver="newton")
    with pytest.raises(vigen.InputError):
        s.integrate(np.tile(Q0, (3, 1)), np.tile(P0, (3, 1)), 0.01, 10)
    with pytest.raises(vigen.InputError):
        vigen.Stepper("yoshida_4", force=KEPLER_C, dim=2, batch=4, dtype=np.longdouble)


# ---- the cache ----------------------------------------------------------------------
def test_the_second_stepper_compiles_nothing(monkeypatch):
    vigen.Stepper("stormer_verlet_velocity", force=OSCILLATOR_C, dim=1)
    _stepper_module.LOADED.clear()

    def no_compiler(*args, **kwargs):
        raise AssertionError("compiled again")

    monkeypatch.setattr(_cache.subprocess, "run", no_compiler)
    s = vigen.Stepper("stormer_verlet_velocity", force=OSCILLATOR_C, dim=1)
    assert s.integrate([1], [0], 0.1, 10)[1].shape == (11, 1)


RACE = textwrap.dedent("""
    import sys, numpy as np, vigen
    s = vigen.Stepper("forest_ruth_4", force=sys.argv[1], dim=1)
    t, q, p = s.integrate([1.0], [0.0], 0.01, 1000, every=0)
    print(float(q[-1, 0]).hex())
""")


def test_two_processes_compiling_the_same_stepper_at_once(tmp_path):
    env = dict(os.environ, VIGEN_CACHE_DIR=str(tmp_path / "cache"))
    # a force of its own, so that no earlier test compiled it
    source = "void force(real t, const real *q, real *f, void *ctx) { f[0] = -q[0] * (1 + 0 * %d); }" % os.getpid()
    procs = [subprocess.Popen([sys.executable, "-c", RACE, source], env=env, stdout=subprocess.PIPE,
                              stderr=subprocess.PIPE, text=True) for _ in range(2)]
    outs = [proc.communicate(timeout=120) for proc in procs]
    for proc, (out, err) in zip(procs, outs):
        assert proc.returncode == 0, err
    assert outs[0][0] == outs[1][0] and outs[0][0].strip()
    entries = os.listdir(tmp_path / "cache")
    assert len(entries) == 1 and not entries[0].startswith(".")  # one module, no half-built folder left
    assert os.path.isfile(tmp_path / "cache" / entries[0] / _cache.MODULE_FILE)
