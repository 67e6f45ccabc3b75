#!/bin/bash
# cli_compare.sh VIGEN SRC — `vigen compare`: every figure of the table is the
# one `vigen check --json` certifies for the same file, and the efficiency is
# evals * C^(1/p) recomputed here; Yoshida's and Forest & Ruth's fourth-order
# methods, published independently in 1990, are one method (the triple
# jump) and get identical rows; Stormer-Verlet is stable exactly for
# h omega < 2 and Gauss methods for every h omega (Hairer, Lubich & Wanner,
# GNI sec. I.5 and VI.4 / A-stability); LaTeX and JSON forms; bad input.
set -u
VIGEN=$1
SRC=$2
P=$SRC/tableaux/published
T=$(mktemp -d /tmp/vigen-cli-compare-XXXXXX)
trap 'rm -rf "$T"' EXIT
fail=0
bad() { echo "FAIL: $*"; fail=1; }

files="$P/stormer_verlet_velocity.lua $P/yoshida_4.lua $P/forest_ruth_4.lua $P/suzuki_4.lua $P/gauss_2.lua"
# shellcheck disable=SC2086
"$VIGEN" compare $files --format json > "$T/c.json" 2> "$T/err" || bad "compare --format json: exit $? ($(cat "$T/err"))"
for f in $files; do
  "$VIGEN" check "$f" --json > "$T/$(basename "$f").json" 2>/dev/null
done
python3 - "$T" $files <<'PY' || fail=1
import json, os, sys
T, files = sys.argv[1], sys.argv[2:]
rows = json.load(open(os.path.join(T, "c.json")))["methods"]
ok = len(rows) == len(files)
by = {}
for f, r in zip(files, rows):
    c = json.load(open(os.path.join(T, os.path.basename(f) + ".json")))
    by[r["name"]] = r
    for key in ("error_constant", "stability_interval", "evaluations_per_step"):
        if r[key] != c[key]:
            print("FAIL: %s: %s %r, check says %r" % (r["name"], key, r[key], c[key])); ok = False
    if r["order"] != c["design_order"]["order"]:
        print("FAIL: %s: order %r, check says %r" % (r["name"], r["order"], c["design_order"])); ok = False
    if r["explicit"]:
        e = r["evaluations_per_step"] * r["error_constant"] ** (1.0 / r["order"])
        if abs(r["efficiency"] - e) > 1e-12 * e:
            print("FAIL: %s: efficiency %r, evals * C^(1/p) = %r" % (r["name"], r["efficiency"], e)); ok = False
    elif r["efficiency"] is not None:
        print("FAIL: %s: an implicit method has an efficiency" % r["name"]); ok = False
y, fr = dict(by["yoshida_4"]), dict(by["forest_ruth_4"])
for d in (y, fr):
    d.pop("name"); d.pop("path")
if y != fr:
    print("FAIL: Yoshida's and Forest & Ruth's methods differ: %r %r" % (y, fr)); ok = False
sv = by["stormer_verlet_velocity"]
if sv["stability"] != "bounded" or abs(sv["stability_interval"] - 2) > 1e-15 or sv["order"] != 2:
    print("FAIL: Stormer-Verlet: %r" % sv); ok = False
g = by["gauss_2"]
if g["stability"] != "unbounded" or g["stability_interval"] is not None or g["order"] != 4 or g["explicit"]:
    print("FAIL: Gauss s = 2: %r" % g); ok = False
sys.exit(0 if ok else 1)
PY

# text: one row per method after the header, the legend after
"$VIGEN" compare "$P/yoshida_4.lua" "$P/gauss_2.lua" > "$T/c.txt" 2>&1 || bad "compare text: exit $?"
grep -q "^yoshida_4 " "$T/c.txt" && grep -q "^gauss_2 .* unbounded " "$T/c.txt" && grep -q "^efficiency " "$T/c.txt" \
  || { bad "text table"; cat "$T/c.txt"; }
# LaTeX: a tabular, TeX's specials escaped in names
"$VIGEN" compare "$P/stormer_verlet_velocity.lua" "$P/gauss_2.lua" --format latex > "$T/c.tex" 2>&1 || bad "latex: exit $?"
grep -q '^\\begin{tabular}' "$T/c.tex" && grep -q '^stormer\\_verlet\\_velocity & 2 & 2 ' "$T/c.tex" \
  && grep -q '\$\\infty\$' "$T/c.tex" && grep -q '^\\end{tabular}' "$T/c.tex" || { bad "latex table"; cat "$T/c.tex"; }

# bad input: a missing file (named, exit 2, nothing on stdout), a bad format
"$VIGEN" compare "$P/gauss_2.lua" "$T/missing.lua" > "$T/out" 2> "$T/err"
rc=$?
[ $rc = 2 ] && [ ! -s "$T/out" ] && grep -q "missing.lua" "$T/err" && [ "$(wc -l < "$T/err")" -le 2 ] \
  || bad "missing file: exit $rc, stdout $(wc -c < "$T/out") bytes, $(cat "$T/err")"
"$VIGEN" compare "$P/gauss_2.lua" --format html > "$T/out" 2> "$T/err"
rc=$?
[ $rc = 2 ] && grep -q "text, latex or json" "$T/err" || bad "bad format: exit $rc, $(cat "$T/err")"
"$VIGEN" compare > "$T/out" 2> "$T/err"
[ $? = 2 ] || bad "no file: not a usage error"

[ $fail = 0 ] && echo "cli_compare: ok"
exit $fail
