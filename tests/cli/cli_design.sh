#!/bin/bash
# cli_design.sh VIGEN SRC — `vigen design`: Yoshida's sixth-order family
# gives three files (his solutions A, B and C, Phys. Lett. A 150 (1990) 262,
# Table 1), each of which `vigen check` certifies of order 6 exactly, the
# composition of the library's yoshida_6 among them entry by entry (--against,
# its 50 digits recomputed independently); the triple jump of velocity
# Verlet is the library's yoshida_4 (written with the closed form
# 1/(2 - 2^(1/3)), checked --against entry by entry); the symmetric splitting
# with three kicks of order 4 is Forest and Ruth's (Physica D 43 (1990) 105,
# the library's forest_ruth_4); order 6 from five symmetric steps has no
# solution (exit 1, nothing written); McLachlan's RKN method of order 4 (the
# library's mclachlan_rkn_4, closed forms) comes out of its family with his
# two kicks held; Suzuki's fractal composition (suzuki_4) comes out of the
# five-step family with gamma1 = gamma2 tied; RKN order 6 with seven kicks gives methods of order 6 for
# Nystrom H and 4 for separable H (the checker, from Nystrom trees, decides
# both); a processed step C K C^-1 of order 4 whose kernel alone has order 2;
# ill-posed design files are refused with exit 2 and one line naming the
# file and the field, and nothing is written.
set -u
VIGEN=$1
SRC=$2
T=$(mktemp -d /tmp/vigen-cli-design-XXXXXX)
trap 'rm -rf "$T"' EXIT
export TMPDIR="$T/tmp"
mkdir -p "$TMPDIR"
fail=0
bad() { echo "FAIL: $*"; fail=1; }
D=$SRC/tests/data/design

mkdir "$T/y6"
"$VIGEN" design "$D/yoshida6.lua" -o "$T/y6" > "$T/out" 2> "$T/err"
rc=$?
[ $rc = 0 ] || { bad "yoshida6: exit $rc"; cat "$T/err"; }
[ "$(ls "$T/y6" | wc -l)" = 3 ] || bad "yoshida6: not three files: $(ls "$T/y6")"
[ "$(grep -c " certified " "$T/out")" = 3 ] || { bad "yoshida6: not three certified rows"; cat "$T/out"; }
# completeness by the homotopy: every one of the 75 Bezout paths accounted
# for, the real roots among the finite ones exactly Yoshida's three
grep -q "^homotopy    all 75 paths of a total-degree homotopy: [0-9]* distinct roots (3 real)" "$T/out" ||
  { bad "yoshida6: the homotopy does not find 3 real roots"; grep "^homotopy" "$T/out"; }
awk '/^homotopy/ { split($0, a, ": "); n = a[2] + 0; sub(/.*real\), /, "", a[2]); inf = a[2] + 0 } END { exit !(n + inf == 75) }' \
  "$T/out" || bad "yoshida6: the homotopy's paths do not add up to 75"
grep -q "^complete    yes, by the homotopy" "$T/out" || bad "yoshida6: completeness by the homotopy not stated"
for f in "$T"/y6/*.lua; do
  "$VIGEN" check "$f" > "$T/chk" 2>&1 || { bad "check $(basename "$f") exits $?"; tail -3 "$T/chk"; }
  grep -q "^order         6 within the precision of the data" "$T/chk" || { bad "$(basename "$f"): not order 6"; grep "^order" "$T/chk"; }
  grep -q "first failing tree: .*(order 7)" "$T/chk" || bad "$(basename "$f"): no failing tree of order 7"
done
# Yoshida's solution A is the library's yoshida_6 (recomputed to 50 digits there)
found=0
for f in "$T"/y6/*.lua; do
  "$VIGEN" check "$f" --against "$SRC/tableaux/published/yoshida_6.lua" > "$T/chk" 2>&1 && grep -q "^against       0 entries differ" "$T/chk" && found=1
done
[ $found = 1 ] || bad "no solution is the library's yoshida_6"

# the triple jump of velocity Verlet is the library's yoshida_4
mkdir "$T/tj"
"$VIGEN" design "$D/triple_jump.lua" -o "$T/tj" --digits 50 > "$T/out" 2>&1 || { bad "triple jump: exit $?"; cat "$T/out"; }
# its conditions reduce to 2 g^3 + (1 - 2g)^3 = 0: a cubic with one real root
# and two complex ones, none at infinity
grep -q "^homotopy    all 3 paths of a total-degree homotopy: 3 distinct roots (1 real), 0 at infinity" "$T/out" ||
  { bad "triple jump: the homotopy does not find the cubic's roots"; grep "^homotopy" "$T/out"; }
"$VIGEN" check "$T/tj/tj_1.lua" --against "$SRC/tableaux/published/yoshida_4.lua" > "$T/chk" 2>&1 && grep -q "^against       0 entries differ" "$T/chk" \
  || { bad "triple jump is not yoshida_4"; grep -E "against|order" "$T/chk"; }

# symmetric splittings with three kicks, order 4: Forest and Ruth's method
mkdir "$T/fr"
"$VIGEN" design "$D/forest_ruth.lua" -o "$T/fr" > "$T/out" 2>&1 || { bad "forest_ruth: exit $?"; cat "$T/out"; }
"$VIGEN" check "$T/fr/fr_1.lua" --against "$SRC/tableaux/published/forest_ruth_4.lua" > "$T/chk" 2>&1 && grep -q "^against       0 entries differ" "$T/chk" \
  || { bad "the three-kick splitting is not forest_ruth_4"; grep -E "against|order" "$T/chk"; }
grep -q "order_separable = 4" "$T/fr/fr_1.lua" || bad "forest_ruth: no order_separable claim"

# Suzuki's fractal composition: five symmetric steps with gamma1 = gamma2
# tied (`equal`), one real solution, the library's suzuki_4 entry by entry,
# and each of its 40 digits the rounding of the closed form 1/(4 - 4^(1/3))
mkdir "$T/suz"
"$VIGEN" design "$D/suzuki4.lua" -o "$T/suz" > "$T/out" 2>&1 || { bad "suzuki: exit $?"; cat "$T/out"; }
"$VIGEN" check "$T/suz/suzuki_1.lua" --against "$SRC/tableaux/published/suzuki_4.lua" > "$T/chk" 2>&1 &&
  grep -q "^against       0 entries differ" "$T/chk" || { bad "the tied composition is not suzuki_4"; grep -E "against" "$T/chk"; }
[ "$(ls "$T/suz" | wc -l)" = 1 ] || bad "suzuki: $(ls "$T/suz" | wc -l) files, expected 1"
python3 - "$T/suz/suzuki_1.lua" <<'PY' || bad "suzuki: digits are not the closed form's"
import re, sys
from mpmath import mp, mpf, cbrt
mp.dps = 60
g = re.findall(r'"(-?[0-9]\.[0-9]+)"', open(sys.argv[1]).read())
p = 1 / (4 - cbrt(4))
want = [p, p, 1 - 4 * p, p, p]
ok = len(g) == 5 and all(len(t.split(".")[1]) >= 38 and abs(mpf(t) - x) <= mpf(10) ** -len(t.split(".")[1]) / 2
                         for t, x in zip(g, want))
sys.exit(0 if ok else 1)
PY

# no solution: exit 1, nothing written
mkdir "$T/none"
"$VIGEN" design "$D/no_solution.lua" -o "$T/none" > "$T/out" 2>&1
rc=$?
[ $rc = 1 ] || bad "no_solution: exit $rc, expected 1"
grep -q "^no solution" "$T/out" || bad "no_solution: no 'no solution' line"
[ -z "$(ls "$T/none")" ] || bad "no_solution wrote $(ls "$T/none")"

# RKN splittings: McLachlan's order-4 method with five kicks (the library's
# mclachlan_rkn_4, its closed forms) from its family with his two kicks held
# at -3/73 and 17/59; seven symmetric kicks of order 6 for Nystrom H: more
# real roots than for separable H, which has only Yoshida's three
mkdir "$T/rkn"
"$VIGEN" design "$D/mclachlan_rkn4.lua" -o "$T/rkn" > "$T/out" 2>&1 || { bad "mclachlan_rkn4: exit $?"; cat "$T/out"; }
found=0
for f in "$T"/rkn/mrkn4_*.lua; do
  "$VIGEN" check "$f" --against "$SRC/tableaux/published/mclachlan_rkn_4.lua" > "$T/chk" 2>&1 && grep -q "^against       0 entries differ" "$T/chk" && found=1
  grep -q "order_nystrom = 4" "$f" || bad "$(basename "$f"): no order_nystrom claim"
done
[ $found = 1 ] || bad "no solution is the library's mclachlan_rkn_4"
mkdir "$T/rkn6"
"$VIGEN" design "$D/rkn6.lua" -o "$T/rkn6" > "$T/out" 2>&1 || { bad "rkn6: exit $?"; cat "$T/out"; }
[ "$(grep -l "order_nystrom = 6" "$T"/rkn6/*.lua | wc -l)" = "$(ls "$T/rkn6" | wc -l)" ] || bad "rkn6: a file without order_nystrom = 6"
n4=$(grep -l "order_separable = 4" "$T"/rkn6/*.lua | wc -l)
[ "$n4" -ge 4 ] || bad "rkn6: $n4 methods of order 6 for Nystrom H only, expected several"
for f in $(grep -l "order_separable = 4" "$T"/rkn6/*.lua | head -2); do
  "$VIGEN" check "$f" > "$T/chk" 2>&1 || bad "check $(basename "$f") exits $?"
  grep -q "^order for Nystrom H = p^2/2 + V(q): 6 within" "$T/chk" || bad "$(basename "$f"): not Nystrom order 6"
  grep -q "^order for separable H = T(p) + V(q): 4 within" "$T/chk" || bad "$(basename "$f"): not separable order 4"
done

# minimize among finitely many roots by the effective error (Nystrom
# constant x forces^order): Yoshida's three, only the smallest written; each
# figure printed is the table's constant times 7^6
mkdir "$T/y6e"
printf 'return { name = "y6e", design = "composition", base = "stormer_verlet_position", stages = 7, order = 6, symmetric = true, minimize = "effective_error_nystrom" }\n' > "$T/y6e.lua"
"$VIGEN" design "$T/y6e.lua" -o "$T/y6e" > "$T/out" 2>&1 || { bad "y6e: exit $?"; cat "$T/out"; }
[ "$(ls "$T/y6e")" = y6e_1.lua ] || bad "y6e: files $(ls "$T/y6e")"
awk '$2 == "certified" { c = $6; f = $7; file = $8; n++ }
     /effective_error_nystrom = / { v = $3; want = c * f ^ 6; if (f != 7 || v < want * (1 - 1e-5) || v > want * (1 + 1e-5)) bad = 1
                                   if (best == "" || v < best) { best = v; bestfile = file } }
     END { if (n != 3 || bad || bestfile == "-" || bestfile == "") { print "effective figures wrong"; exit 1 } }' "$T/out" ||
  { bad "y6e: effective figures"; cat "$T/out"; }

# processed: the step C K C^-1 of order 4, the kernel alone of order 2
mkdir "$T/pk"
"$VIGEN" design "$D/processed.lua" -o "$T/pk" > "$T/out" 2>&1 || { bad "processed: exit $?"; cat "$T/out"; }
for f in "$T"/pk/*.lua; do
  "$VIGEN" check "$f" > "$T/chk" 2>&1 || bad "check $(basename "$f") exits $?"
  grep -q "^order         4 within" "$T/chk" || bad "$(basename "$f"): processed step not of order 4"
  sed '/^  corrector = {/,/^  },/d; /order/d' "$f" > "$T/kernel.lua"
  "$VIGEN" check "$T/kernel.lua" > "$T/chk" 2>&1
  grep -q "^order         2 within" "$T/chk" || { bad "$(basename "$f"): kernel alone not of order 2"; grep "^order" "$T/chk"; }
done
[ -n "$(ls "$T/pk")" ] || bad "processed: no file"

# ill-posed design files: exit 2, one line naming the file and the field
refuse() {  # name field-regex lua-body
  printf 'return { %s }\n' "$3" > "$T/$1.lua"
  "$VIGEN" design "$T/$1.lua" -o "$T/none" > "$T/out" 2> "$T/err"
  rc=$?
  [ $rc = 2 ] || bad "$1: exit $rc, expected 2"
  [ "$(wc -l < "$T/err")" = 1 ] && head -1 "$T/err" | grep -q "^vigen design: $T/$1.lua: $2" \
    || { bad "$1: message"; cat "$T/err"; }
}
C='name = "x", design = "composition", symmetric = true, solutions = "all"'
refuse order20 "order: 20 is impossible with 3 stages: it asks for [0-9]* conditions of 2 unknowns" \
  "$C, base = \"stormer_verlet_position\", stages = 3, order = 20"
refuse negative "stages: must be a whole number" "$C, base = \"stormer_verlet_position\", stages = -3, order = 4"
refuse unknown_base "base: stormer_verlet_positon: .*did you mean 'stormer_verlet_position'" \
  "$C, base = \"stormer_verlet_positon\", stages = 3, order = 4"
refuse typo "unknown field 'stage'; did you mean 'stages'" "$C, base = \"stormer_verlet_position\", stage = 3, order = 4"
refuse homotopy_limit "homotopy: must be a whole number from 0 to 10000000" \
  "$C, base = \"stormer_verlet_position\", stages = 3, order = 4, homotopy = -1"
refuse effective_typo "minimize: must be \"error_constant\"" \
  "name = \"x\", design = \"composition\", base = \"stormer_verlet_position\", stages = 5, order = 4, symmetric = true, minimize = \"effective\""
refuse free "solutions: the 2 conditions leave 1 of the 3 unknowns free" \
  "$C, base = \"stormer_verlet_position\", stages = 5, order = 4"
refuse not_symmetric "base: symplectic_euler_q_first is not a symmetric splitting" \
  "$C, base = \"symplectic_euler_q_first\", stages = 3, order = 4"
refuse splitting_base "base: a splitting has no base" 'name = "x", design = "splitting", base = "gauss_1", stages = 3, order = 4, solutions = "all"'
refuse float_stages "stages: must be a whole number" "$C, base = \"stormer_verlet_position\", stages = 3.0, order = 4"
R='name = "x", design = "rkn", symmetric = true, solutions = "all"'
refuse rkn_order20 "order: 20 is impossible with 3 stages: it asks for at least [0-9]* conditions of 4 unknowns" \
  "$R, stages = 3, order = 20"
refuse rkn_typo "unknown field 'kernal'; did you mean 'kernel'" \
  'name = "x", design = "processed", kernal = "rkn", stages = 3, order = 4, symmetric = true, solutions = "all"'
refuse rkn_fix_name "fix: 'c1' is not an unknown of this family" "$R, stages = 5, order = 4, fix = { c1 = \"1/2\" }"
refuse rkn_fix_value "fix: b1: must be an exact rational" "$R, stages = 5, order = 4, fix = { b1 = \"0.5\" }"
refuse rkn_fix_zero "fix: b1: must be an exact rational" "$R, stages = 5, order = 4, fix = { b1 = \"1/0\" }"
refuse processed_order6 "order: the effective order of a processed kernel must be 4" \
  'name = "x", design = "processed", kernel = "rkn", stages = 3, order = 6, symmetric = true, solutions = "all"'
refuse processed_nonsym "symmetric: a processed kernel must be symmetric" \
  'name = "x", design = "processed", kernel = "splitting", stages = 3, order = 4, solutions = "all"'
refuse rkn_kernel "kernel: only a processed design has a kernel" "$R, kernel = \"rkn\", stages = 5, order = 4"
[ -z "$(ls "$T/none")" ] || bad "refused files wrote $(ls "$T/none")"
exit $fail
