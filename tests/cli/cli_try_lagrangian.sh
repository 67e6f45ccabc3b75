#!/bin/bash
# cli_try_lagrangian.sh VIGEN SRC — the Lagrangian integrators of the runtime
# (docs/lagrangian.md) as built-in methods of `vigen try`:
#  - on Kepler and the charged particle each keeps its energy error bounded
#    (a symplectic method: the second half of the run at most 1.5 times the
#    first, read from the CSV beside the energy plot);
#  - for L = T - V the midpoint discrete Lagrangian gives the implicit
#    midpoint rule and the trapezoidal one Stormer-Verlet (velocity form)
#    (Marsden-West, Discrete mechanics and variational integrators, 2.5;
#    Hairer-Lubich-Wanner VI.6), so on Kepler hp-midpoint and midpoint-vi
#    have the global error of the published gauss_1 and hp-trapezoidal and
#    trapezoidal-vi that of stormer_verlet_velocity, to round-off (relative
#    1e-10: the implicit solves stop at round-off, differently);
#  - the listing names them with a description; a problem without a
#    Lagrangian (point vortices) is refused in one line naming the method
#    and the problem, exit 2, nothing on stdout, nothing compiled or left.
set -u
VIGEN=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
SRC=$2
T=$(mktemp -d /tmp/vigen-cli-try-lag-XXXXXX)
trap 'rm -rf "$T"' EXIT
export TMPDIR="$T/tmp"
mkdir -p "$TMPDIR"
fail=0
check() { if ! eval "$1"; then echo "FAIL: $2"; fail=1; fi; }
LAG="hp-trapezoidal hp-midpoint midpoint-vi trapezoidal-vi"

"$VIGEN" try --list-methods > "$T/methods.txt"
for m in $LAG; do
  check 'grep -q "^$m  *[A-Za-z]" "$T/methods.txt"' "--list-methods lists $m with a description"
done

cat > "$T/bounded.py" <<'PY'
import csv, sys
rows = list(csv.reader(open(sys.argv[1] + "/energy.csv")))
head, data = rows[0], [[float(x) for x in r] for r in rows[1:]]
bad = []
for j, name in enumerate(head[1:], 1):
    e = [abs(r[j]) for r in data]
    h1, h2 = max(e[1:len(e) // 2]), max(e[len(e) // 2:])
    if not (h2 <= 1.5 * h1 or max(e) < 1e-11):
        bad.append("%s: energy error grows: first half %g, second half %g" % (name, h1, h2))
if sorted(head[1:]) != sorted(sys.argv[2:]):
    bad.append("energy.csv columns %r" % head[1:])
print("; ".join(bad))
sys.exit(1 if bad else 0)
PY
for p in kepler charged-particle; do
  "$VIGEN" try $LAG --problem "$p" --time 200 --plot "$T/plot-$p" > "$T/$p.txt" 2> "$T/$p.err"
  rc=$?
  check '[ $rc -eq 0 ]' "$p: exit $rc ($(cat "$T/$p.err"))"
  python3 "$T/bounded.py" "$T/plot-$p" $LAG > "$T/$p.check" 2>&1
  check '[ $? -eq 0 ]' "$p: $(cat "$T/$p.check")"
done

"$VIGEN" try hp-midpoint midpoint-vi gauss_1 hp-trapezoidal trapezoidal-vi stormer_verlet_velocity \
  --problem kepler --time 20 --steps-per-period 200 --json > "$T/same.json" 2> "$T/same.err"
rc=$?
check '[ $rc -eq 0 ]' "same maps: exit $rc ($(cat "$T/same.err"))"
cat > "$T/same.py" <<'PY'
import json, sys
m = {x["name"]: x for x in json.load(open(sys.argv[1]))["methods"]}
bad = []
for a, b in (("hp-midpoint", "gauss_1"), ("midpoint-vi", "gauss_1"),
             ("hp-trapezoidal", "stormer_verlet_velocity"), ("trapezoidal-vi", "stormer_verlet_velocity")):
    ea, eb = m[a]["global_error"], m[b]["global_error"]
    if not (eb > 1e-6 and abs(ea / eb - 1) <= 1e-10):
        bad.append("%s %r vs %s %r" % (a, ea, b, eb))
    if m[a]["grad_evals_per_step"] <= 0 or m[a]["failed"] is not None:
        bad.append("%s: statistics %r" % (a, m[a]))
print("; ".join(bad))
sys.exit(1 if bad else 0)
PY
python3 "$T/same.py" "$T/same.json" > "$T/same.check" 2>&1
check '[ $? -eq 0 ]' "same maps on Kepler: $(cat "$T/same.check")"

for m in hp-midpoint trapezoidal-vi; do
  "$VIGEN" try gauss_1 "$m" --problem point-vortices > "$T/pv.out" 2> "$T/pv.err"
  rc=$?
  check '[ $rc -eq 2 ] && [ ! -s "$T/pv.out" ] && [ "$(wc -l < "$T/pv.err")" -eq 1 ] && grep -q "$m" "$T/pv.err" && grep -q "point-vortices" "$T/pv.err" && grep -q "Lagrangian" "$T/pv.err"' "$m on point-vortices: exit 2, one line naming both (exit $rc: $(cat "$T/pv.err"))"
done
"$VIGEN" order midpoint-vi --problem point-vortices > "$T/pv.out" 2> "$T/pv.err"
rc=$?
check '[ $rc -eq 2 ] && [ ! -s "$T/pv.out" ] && grep -q "midpoint-vi: the problem point-vortices has no Lagrangian" "$T/pv.err"' "vigen order refuses point-vortices too (exit $rc: $(cat "$T/pv.err"))"

# a file of the same name is the user's tableau, not the built-in method
cp "$SRC/tableaux/published/gauss_1.lua" "$T/hp-trapezoidal"
(cd "$T" && "$VIGEN" try hp-trapezoidal --problem point-vortices --time 1 > "$T/file.out" 2> "$T/file.err")
rc=$?
check '[ $rc -eq 0 ] && grep -q "^hp-trapezoidal " "$T/file.out"' "a file named hp-trapezoidal is a tableau file (exit $rc: $(cat "$T/file.err"))"

check '[ -z "$(ls -A "$TMPDIR")" ]' "nothing left in TMPDIR"
exit $fail
