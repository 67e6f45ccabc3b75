"""vigen.generate() and vigen.Tableau against the command line and against
closed forms: the digits of `vigen generate`, the tableau file it writes
(byte for byte, through to_file and from_file), the LaTeX of `vigen show`,
and the 2-stage Gauss method's entries (1/4, 1/4 -+ sqrt(3)/6, 1/2 -+
sqrt(3)/6; Hairer, Lubich & Wanner, GNI sec. II.1.3) computed here with
Python's decimal module."""
import json
import os
from decimal import Decimal, getcontext

import numpy as np
import pytest

import vigen

SPEC = "tableaux/specs/gauss_legendre_s2.lua"


def gauss2_exact(prec=80):
    """The Gauss s = 2 tableau to prec digits, from its closed form."""
    getcontext().prec = prec
    r = Decimal(3).sqrt() / 6
    q = Decimal(1) / 4
    h = Decimal(1) / 2
    return {"c": [h - r, h + r], "A": [[q, q - r], [q + r, q]], "b": [h, h]}


def ulp(text):
    """Half a unit in the last digit of a decimal text (0 for an integer)."""
    d = Decimal(text)
    return Decimal(1).scaleb(d.as_tuple().exponent) / 2


@pytest.mark.parametrize("digits", [5, 34, 60])
def test_generate_is_vigen_generate(cli, tmp_path, digits):
    out = tmp_path / "cli.lua"
    proc = cli("generate", SPEC, "--digits", str(digits), "-o", str(out), check=True)
    t = vigen.generate(SPEC, digits=digits)
    assert t.text == out.read_text(encoding="utf-8")
    assert t.summary == proc.stderr.splitlines()[0]
    # the entries are the file's digits, as `vigen show --format json` reads them
    shown = json.loads(cli("show", str(out), "--format", "json", "--digits", str(digits), check=True).stdout)
    for key in ("c", "A", "b", "ct", "At", "bt"):
        assert getattr(t, key) == shown.get(key), key
    assert (t.name, t.s, t.digits) == ("gauss_legendre_s2", 2, digits)


@pytest.mark.parametrize("digits", [20, 50])
def test_generated_digits_are_the_closed_form_correctly_rounded(digits):
    t = vigen.generate(SPEC, digits=digits)
    exact = gauss2_exact(digits + 30)
    for key in ("c", "b"):
        for text, x in zip(getattr(t, key), exact[key]):
            assert abs(Decimal(text) - x) <= ulp(text), (key, text)
    for row, xrow in zip(t.A, exact["A"]):
        for text, x in zip(row, xrow):
            assert abs(Decimal(text) - x) <= ulp(text), text
            # significant digits as asked (an exact 0.25 is written with them too)
            assert len(Decimal(text).as_tuple().digits) >= digits


def test_to_numpy_matches_the_closed_form():
    t = vigen.generate(SPEC, digits=34)
    a = t.to_numpy()
    s3 = np.sqrt(3.0)
    assert a["A"].dtype == np.float64 and a["A"].shape == (2, 2)
    np.testing.assert_allclose(a["A"], [[0.25, 0.25 - s3 / 6], [0.25 + s3 / 6, 0.25]], rtol=0, atol=1e-16)
    np.testing.assert_allclose(a["c"], a["A"].sum(axis=1), rtol=0, atol=1e-16)
    # At, bt, ct of a Galerkin method with At = A
    np.testing.assert_array_equal(a["At"], a["A"])
    ld = t.to_numpy(dtype=np.longdouble)
    assert ld["b"].dtype == np.longdouble


def test_one_part_tableau_fills_the_second_part():
    t = vigen.Tableau.from_file("gauss_2")
    assert t.At is None or t.At == t.A
    arrays = t.to_numpy()
    np.testing.assert_array_equal(arrays["bt"], arrays["b"])


def test_to_mpmath_holds_the_digits():
    mpmath = pytest.importorskip("mpmath")
    t = vigen.generate(SPEC, digits=50)
    with mpmath.workdps(60):
        m = t.to_mpmath()
        exact = 0.25 - mpmath.sqrt(3) / 6
        assert abs(m["A"][0, 1] - exact) < mpmath.mpf(10) ** -50
        assert abs(m["b"][0] + m["b"][1] - 1) < mpmath.mpf(10) ** -50


def test_to_file_is_byte_identical_to_the_command_line_s(cli, tmp_path):
    ref = tmp_path / "cli.lua"
    cli("generate", SPEC, "--digits", "40", "-o", str(ref), "-q", check=True)
    mine = tmp_path / "py.lua"
    t = vigen.generate(SPEC, digits=40)
    t.to_file(mine)
    assert mine.read_bytes() == ref.read_bytes()
    # and back: the file read and written again is the same file
    again = vigen.Tableau.from_file(str(ref), digits=40)
    assert again == t and again.A == t.A and again.path == str(ref)
    out = tmp_path / "again.lua"
    again.to_file(str(out))
    assert out.read_bytes() == ref.read_bytes()
    # the written file checks as the generated tableau does
    assert vigen.check(str(mine))["order"] == 4


def test_to_file_replaces_atomically_and_names_a_dash_as_a_file(tmp_path, monkeypatch):
    t = vigen.generate(SPEC, digits=10)
    target = tmp_path / "t.lua"
    target.write_text("old")
    t.to_file(target)
    assert target.read_text(encoding="utf-8") == t.text
    monkeypatch.chdir(tmp_path)
    t.to_file("-")                      # a file called "-", not standard output
    assert (tmp_path / "-").read_text(encoding="utf-8") == t.text
    assert sorted(os.listdir(tmp_path)) == ["-", "t.lua"]      # no temporary file left


def test_from_file_of_a_spec_generates_it(cli):
    t = vigen.Tableau.from_file(SPEC, digits=25)
    assert t.text == cli("show", SPEC, "--format", "lua", "--digits", "25", check=True).stdout
    assert t.A == vigen.generate(SPEC, digits=25).A


def test_latex_and_show_are_vigen_show_s(cli, tmp_path):
    ref = tmp_path / "g.lua"
    cli("generate", SPEC, "--digits", "20", "-o", str(ref), "-q", check=True)
    t = vigen.generate(SPEC, digits=20)
    assert t.latex() == cli("show", str(ref), "--format", "latex", "--digits", "20", check=True).stdout
    assert t.show() == cli("show", str(ref), "--digits", "20", check=True).stdout
    assert "\\begin{array}" in t.latex()


def test_published_tableau_entries_are_certified_decimals(cli):
    t = vigen.Tableau.from_file("gauss_2", digits=30)
    shown = json.loads(cli("show", "gauss_2", "--format", "json", "--digits", "30", check=True).stdout)
    assert t.A == shown["A"] and t.b == shown["b"] and t.c == shown["c"]
    exact = gauss2_exact(60)
    assert abs(Decimal(t.A[0][1]) - exact["A"][0][1]) <= ulp(t.A[0][1])
