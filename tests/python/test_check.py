"""vigen.check() and vigen.compare() against the command line: the dict is
the JSON `vigen check --json` prints for the same file and options, for
tableau files, a spec, a failing claim and rounded data; the verdicts agree
with facts known independently of vigen (Gauss s = 2 is symplectic of order
4, RK4 is not symplectic)."""
import json
from fractions import Fraction

import pytest

import vigen

CASES = [
    ("gauss_2", ()),                                               # exact entries, sqrt(3)
    ("yoshida_4", ()),                                             # a composition
    ("tableaux/specs/gauss_legendre_s2.lua", ()),                  # a spec, generated first
    ("tests/data/check/rk4_claimed_symplectic.lua", ()),           # a claim that fails
    ("tests/data/check/gauss2_6digits.lua", ()),                   # rounded data
    ("tests/data/check/gauss3_40.lua", ("--max-order", "7")),
    ("stormer_verlet_velocity", ("--prec", "200")),
]


def options(args):
    kw = {}
    for opt, value in zip(args[::2], args[1::2]):
        kw[opt.lstrip("-").replace("-", "_")] = int(value)
    return kw


@pytest.mark.parametrize("method,args", CASES)
def test_check_is_vigen_check_json(cli, method, args):
    proc = cli("check", "--json", method, *args)
    assert proc.returncode in (0, 1), proc.stderr
    expected = json.loads(proc.stdout)
    got = vigen.check(method, **options(args))
    assert got == expected
    assert got["exit"] == proc.returncode


def test_check_against(cli):
    a, b = "tests/data/check/gauss2_sqrt3_1e-60.lua", "gauss_2"
    proc = cli("check", "--json", a, "--against", vigen.resolve(b))
    got = vigen.check(a, against=vigen.resolve(b))
    assert got == json.loads(proc.stdout)


def test_rk4_is_not_symplectic():
    # independently: for RK4 the pair (1, 1) of b_i a_ij + b_j a_ji - b_i b_j is -b_1^2 = -1/36
    b1 = Fraction(1, 6)
    assert 2 * b1 * 0 - b1 * b1 == Fraction(-1, 36)
    report = vigen.check("tests/data/check/rk4_claimed_symplectic.lua")
    assert report["symplectic"] is False
    assert report["claims"]["symplectic"]["holds"] is False
    assert report["claims"]["order"]["holds"] is True          # RK4 has order 4
    assert report["exit"] == 1
    first = report["problems"][0]
    assert (first["kind"], first["row"], first["col"]) == ("symplectic", 1, 1)
    assert abs(float(first["value"].strip("[").split()[0]) - float(Fraction(-1, 36))) < 1e-15


def test_gauss_2_is_symplectic_of_order_4():
    report = vigen.check("gauss_2")
    assert (report["order"], report["symplectic"], report["consistent"]) == (4, True, True)
    assert report["exit"] == 0


def test_compare_is_vigen_compare(cli):
    methods = ("yoshida_4", "suzuki_4", "gauss_2")
    for fmt in ("json", "text", "latex"):
        proc = cli("compare", *methods, "--format", fmt, check=True)
        got = vigen.compare(*methods, format=fmt)
        if fmt == "json":
            assert got == json.loads(proc.stdout)
        else:
            assert got == proc.stdout
    assert vigen.compare(list(methods)) == vigen.compare(*methods)
    assert vigen.compare(*methods, max_order=6) == json.loads(
        cli("compare", *methods, "--format", "json", "--max-order", "6", check=True).stdout)


def test_compare_errors_are_the_command_line_s(cli):
    with pytest.raises(vigen.InputError) as e:
        vigen.compare("gauss_2", format="csv")
    assert str(e.value) == cli("compare", "gauss_2", "--format", "csv").stderr.splitlines()[0]
    with pytest.raises(vigen.InputError) as e:
        vigen.compare("gauss_2", "no_such_method")
    assert str(e.value) == cli("compare", "gauss_2", "no_such_method").stderr.splitlines()[0]


@pytest.mark.parametrize("kw,args", [({"max_order": 0}, ("--max-order", "0")),
                                     ({"max_order": 13}, ("--max-order", "13")),
                                     ({"prec": 8}, ("--prec", "8"))])
def test_check_options_out_of_range(cli, kw, args):
    proc = cli("check", "gauss_2", *args)
    assert proc.returncode == 2
    with pytest.raises(vigen.InputError) as e:
        vigen.check("gauss_2", **kw)
    assert str(e.value) == proc.stderr.splitlines()[0]
    assert e.value.exit_status == 2


def test_check_a_tableau_object_checks_its_file():
    t = vigen.Tableau.from_file("gauss_2")
    assert vigen.check(t) == vigen.check("gauss_2")


def test_check_a_generated_tableau(cli, tmp_path):
    spec = "tableaux/specs/gauss_legendre_s2.lua"
    t = vigen.generate(spec, digits=30)
    path = tmp_path / "gauss_legendre_s2.lua"
    cli("generate", spec, "--digits", "30", "-q", "-o", str(path), check=True)
    expected = json.loads(cli("check", "--json", str(path)).stdout)
    got = vigen.check(t)
    assert got.pop("file") != expected.pop("file")      # a temporary copy was checked
    assert got == expected
    assert vigen.compare(t, "gauss_2")["methods"][0]["order"] == 4


def test_wrong_types_are_type_errors():
    with pytest.raises(TypeError):
        vigen.check(42)
    with pytest.raises(TypeError):
        vigen.check("gauss_2", max_order="4")


def test_threads_get_what_one_thread_gets():
    # the calls are serialised inside; each thread's answer is its own
    from concurrent.futures import ThreadPoolExecutor

    names = ["gauss_2", "yoshida_4", "stormer_verlet_velocity", "tests/data/check/rk4_claimed_symplectic.lua"] * 2
    serial = [vigen.check(n) for n in names]
    with ThreadPoolExecutor(max_workers=4) as pool:
        parallel = list(pool.map(vigen.check, names))
    assert parallel == serial
