"""vigen.plot: the figures of vigen try drawn with matplotlib, and a clear
ImportError without it."""
import os
import sys

import numpy as np
import pytest

import vigen
import vigen.plot


@pytest.fixture(autouse=True, scope="module")
def private_cache(tmp_path_factory):
    old = os.environ.get("VIGEN_CACHE_DIR")
    os.environ["VIGEN_CACHE_DIR"] = str(tmp_path_factory.mktemp("cache"))
    yield
    if old is None:
        del os.environ["VIGEN_CACHE_DIR"]
    else:
        os.environ["VIGEN_CACHE_DIR"] = old


def test_without_matplotlib_the_error_says_what_to_install(monkeypatch):
    monkeypatch.setitem(sys.modules, "matplotlib", None)  # import matplotlib then fails
    with pytest.raises(ImportError, match="python3-matplotlib"):
        vigen.plot.energy(([0.0, 1.0], [1.0, 1.5]))


def test_energy_figure(tmp_path):
    pytest.importorskip("matplotlib")
    s = vigen.Stepper("yoshida_4", problem="kepler", e=0.6)
    t0, q0, p0 = s.initial()
    t, q, p = s.integrate(q0, p0, s.period() / 200, 2000, every=10)
    H = s.energy(t, q, p)
    path = tmp_path / "energy.png"
    fig = vigen.plot.energy({"yoshida_4": (t, H)}, title="kepler e=0.6", path=str(path))
    ax = fig.axes[0]
    assert ax.get_yscale() == "log" and ax.get_xlabel() == "t" and ax.get_ylabel() == "|H - H0| / |H0|"
    assert ax.get_title() == "kepler e=0.6"
    x, y = ax.lines[0].get_data()
    want = np.abs(H - H[0]) / abs(H[0])
    assert np.array_equal(y, want[want > 0]) and np.array_equal(x, t[want > 0])
    assert path.stat().st_size > 1000
    fig2 = vigen.plot.orbit({"yoshida_4": q}, path=str(tmp_path / "orbit.svg"))
    assert fig2.axes[0].get_aspect() == 1.0 and (tmp_path / "orbit.svg").exists()


def test_work_precision_shows_the_order(tmp_path):
    pytest.importorskip("matplotlib")
    fig = vigen.plot.work_precision(["yoshida_4", "stormer_verlet_velocity"], problem="kepler", e=0.6, periods=1,
                                    base=256, levels=3, path=str(tmp_path / "wp.png"))
    data = fig.vigen_data
    for method, order in (("yoshida_4", 4), ("stormer_verlet_velocity", 2)):
        h, evals, seconds, err = map(np.array, zip(*data[method]))
        assert len(h) == 3 and np.all(np.diff(h) < 0)
        slope = np.polyfit(np.log(h), np.log(err), 1)[0]  # the global error against the reference solution
        assert abs(slope - order) < 0.4, (method, slope)
        assert np.all(np.diff(evals) > 0)
    ax = fig.axes[0]
    assert ax.get_xscale() == "log" and ax.get_yscale() == "log" and len(ax.lines) == 2
    assert (tmp_path / "wp.png").exists()
    with pytest.raises(ValueError):
        vigen.plot.work_precision(data, x="minutes")
