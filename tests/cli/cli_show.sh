#!/usr/bin/env bash
# cli_show.sh VIGEN SRCDIR — `vigen show` in its four formats.  The truths:
# the JSON values are the closed forms of the 2-stage Gauss method (GNI
# Table II.1.1) to the digits printed; LaTeX has the two Butcher arrays; the
# Lua format reads back to the same tableau; a hand-written exact tableau is
# printed as certified decimals; a spec file is generated on the fly.
set -u
vigen=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

gen=$src/tableaux/generated/gauss_legendre_s2.lua
pub=$src/tableaux/published/gauss_2.lua

# JSON: keys, shapes, and values against the closed forms
"$vigen" show "$gen" --format json >"$work/g.json" || fail "show --format json exit status"
python3 - "$work/g.json" <<'PY' || fail "JSON content"
import json, sys
from fractions import Fraction
from decimal import Decimal, getcontext
getcontext().prec = 80
d = json.load(open(sys.argv[1]))
assert d["name"] == "gauss_legendre_s2" and d["s"] == 2, d
for k in ("c", "A", "b", "At", "ct"):
    assert k in d, k
r3 = Decimal(3).sqrt()
exact = {"A": [[Decimal(1)/4, Decimal(1)/4 - r3/6], [Decimal(1)/4 + r3/6, Decimal(1)/4]],
         "b": [Decimal(1)/2, Decimal(1)/2], "c": [Decimal(1)/2 - r3/6, Decimal(1)/2 + r3/6]}
def close(text, value):
    x = Decimal(text)
    digits = len(text.lstrip("-").replace(".", "").split("e")[0].lstrip("0"))
    return abs(x - value) <= abs(value) * Decimal(10) ** (1 - digits)
for i in range(2):
    assert close(d["b"][i], exact["b"][i]) and close(d["c"][i], exact["c"][i]) and close(d["ct"][i], exact["c"][i])
    for j in range(2):
        assert close(d["A"][i][j], exact["A"][i][j]), (i, j)
        assert close(d["At"][i][j], exact["A"][i][j]), (i, j)
PY

# the same for the hand-written exact tableau, printed with --digits 40
"$vigen" show "$pub" --format json --digits 40 >"$work/p.json" || fail "show published exit status"
python3 - "$work/p.json" <<'PY' || fail "JSON of an exact tableau"
import json, sys
from decimal import Decimal, getcontext
getcontext().prec = 80
d = json.load(open(sys.argv[1]))
a12 = Decimal(1)/4 - Decimal(3).sqrt()/6
x = d["A"][0][1]
assert len(x.lstrip("-").replace(".", "").lstrip("0")) == 40, x
assert abs(Decimal(x) - a12) <= abs(a12) * Decimal(10) ** -39, x
PY

# LaTeX: two arrays separated by \qquad
"$vigen" show "$gen" --format latex >"$work/g.tex" || fail "show --format latex exit status"
[ "$(grep -c 'begin{array}' "$work/g.tex")" = 2 ] && grep -q 'qquad' "$work/g.tex" && grep -q 'hline' "$work/g.tex" ||
  fail "LaTeX output"
# the exact entries of a hand-written tableau as formulas (GNI Table II.1.1), decimals of generated ones
"$vigen" show "$pub" --format latex >"$work/p.tex" || fail "show --format latex of an exact tableau"
grep -qF '\frac{1}{2} - \frac{\sqrt{3}}{6} & \frac{1}{4} & \frac{1}{4} - \frac{\sqrt{3}}{6} \\' "$work/p.tex" ||
  fail "LaTeX of exact entries: $(cat "$work/p.tex")"
grep -q 'frac' "$work/g.tex" && fail "LaTeX of a generated tableau should show decimals"

# Lua: reads back as the same tableau (byte-identical to the generated file)
"$vigen" show "$gen" --format lua >"$work/g.lua" || fail "show --format lua exit status"
cmp -s "$work/g.lua" "$gen" || fail "show --format lua differs from the file it read"

# text: arrays, row sums and the symplecticity residual containing 0
"$vigen" show "$gen" >"$work/g.txt" || fail "show text exit status"
grep -q "symplecticity" "$work/g.txt" && grep -q "contains 0" "$work/g.txt" || fail "text output lacks the residual"

# a spec file is generated on the fly
"$vigen" show "$src/tableaux/specs/leok_zhang_ex2_c12.lua" --format json >"$work/m.json" || fail "show of a spec"
python3 -c "import json,sys; d=json.load(open(sys.argv[1])); assert d['A'][0][0].startswith('0.5000') and d['At'][0][0].startswith('0.5000')" "$work/m.json" ||
  fail "midpoint rule from Example 2 (ii)"
"$vigen" show "$src/tableaux/specs/leok_zhang_ex2_c12.lua" --digits 20 >"$work/m.txt" || fail "text show of a spec"
grep -q "^generated from the spec by vigen .*: 20 certified digits" "$work/m.txt" || fail "a spec's show says it was generated now: $(head -3 "$work/m.txt")"
grep -q "^the file states: 50 certified digits" "$work/g.txt" || fail "a generated file's show quotes its metadata"

# exact expressions whose value is 0 (sin(pi), sqrt(2)^2 - 2): certified 0e-N, not a failure
"$vigen" show "$src/tests/data/show/zero_exprs.lua" --format json --digits 20 >"$work/z.json" || fail "show of exact zeros"
python3 -c "import json,sys; d=json.load(open(sys.argv[1])); assert d['c'] == ['0e-20'] and d['A'] == [['0e-20']], d" "$work/z.json" ||
  fail "exact zeros: $(cat "$work/z.json")"

# bad input: unknown format, missing file
"$vigen" show "$gen" --format yaml >/dev/null 2>&1; [ $? = 2 ] || fail "unknown format should exit 2"
"$vigen" show "$work/none.lua" >/dev/null 2>"$work/err"; [ $? = 2 ] && grep -q none.lua "$work/err" || fail "missing file"

[ $failures -gt 0 ] && { echo "$failures failure(s)"; exit 1; }
echo ok
