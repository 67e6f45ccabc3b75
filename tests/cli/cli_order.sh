#!/bin/bash
# cli_order.sh VIGEN SRC — `vigen order`: the empirical order under step
# halving on Kepler (against its reference solution) is that of the
# literature, 2 for Stormer-Verlet and 4 for Gauss s = 2 (Hairer, Lubich,
# Wanner, Geometric Numerical Integration, II.1 and II.2), within 0.2, and
# the certified order printed beside it is the same; likewise on the
# pendulum and the harmonic oscillator (exact references) and on
# Henon-Heiles, which has no reference (compared with a finer run); the
# built-in hp-midpoint (the implicit midpoint rule for L = T - V, order 2:
# Marsden-West 2.5) gives 2 beside its proven order; the table, JSON, the
# plot and its data; usage errors.
set -u
VIGEN=$1
SRC=$2
T=$(mktemp -d /tmp/vigen-cli-order-XXXXXX)
trap 'rm -rf "$T"' EXIT
export TMPDIR="$T/tmp"
mkdir -p "$TMPDIR"
fail=0
check() { if ! eval "$1"; then echo "FAIL: $2"; fail=1; fi; }

# field of the JSON object, and whether |estimate - p| <= 0.2
cat > "$T/order.py" <<'PY'
import json, sys
o = json.load(open(sys.argv[1]))
p = int(sys.argv[2])
known = o["certified_order"] if o["certified_order"] is not None else o.get("proven_order")
ok = known == p and o["estimate"] is not None and abs(o["estimate"] - p) <= 0.2
errs = [l["error"] for l in o["levels"]]
ok = ok and all(a > b for a, b in zip(errs, errs[1:]))
print("certified/proven %s, estimate %s, errors %s" % (known, o["estimate"], errs))
sys.exit(0 if ok else 1)
PY

for case in "stormer_verlet_velocity 2 kepler" "gauss_2 4 kepler" "stormer_verlet_position 2 pendulum" "gauss_2 4 harmonic-oscillator" "gauss_2 4 henon-heiles" "hp-midpoint 2 kepler"; do
  set -- $case
  "$VIGEN" order "$1" --problem "$3" --json > "$T/o.json" 2> "$T/err"
  rc=$?
  if [ $rc -ne 0 ] || ! python3 "$T/order.py" "$T/o.json" "$2" > "$T/o.txt"; then
    echo "FAIL: $1 on $3: order $2 expected (exit $rc; $(cat "$T/o.txt" "$T/err" 2>/dev/null))"
    fail=1
  fi
done

"$VIGEN" order "$SRC/tableaux/published/gauss_2.lua" --problem harmonic-oscillator --levels 4 --plot "$T/plot" > "$T/table" 2> "$T/err"
rc=$?
check '[ $rc -eq 0 ] && grep -q "certified order (vigen check): 4" "$T/table" && [ "$(grep -c "^ *[0-9.e-]* *[0-9.]*e[-+][0-9]*" "$T/table")" -eq 4 ]' "table: 4 levels and the certified order"
check '[ -s "$T/plot/order.svg" ] && [ -s "$T/plot/order.png" ] && [ "$(wc -l < "$T/plot/order.csv")" -eq 5 ]' "order.svg, order.png, order.csv (4 rows)"
check 'python3 -c "import xml.etree.ElementTree as E,sys; r=E.parse(sys.argv[1]).getroot(); sys.exit(0 if len([g for g in r.iter() if (g.get(\"id\") or \"\").startswith(\"gnuplot_plot_\")]) == 2 else 1)" "$T/plot/order.svg"' "order.svg: the errors and the line of the certified slope"
check 'grep -q "wrote $T/plot/order" "$T/err"' "says where the plot is"

"$VIGEN" order hp-midpoint --problem harmonic-oscillator --levels 3 > "$T/table" 2> "$T/err"
rc=$?
check '[ $rc -eq 0 ] && grep -q "proven order (built-in Lagrangian integrator): 2" "$T/table" && ! grep -q "certified" "$T/table"' "hp-midpoint: the proven order, not a certified one ($(cat "$T/table" "$T/err"))"

"$VIGEN" order gauss_2 2> "$T/err"
rc=$?
check '[ $rc -eq 2 ] && grep -q -- "--problem is required" "$T/err"' "no --problem: exit 2"
"$VIGEN" order gauss_2 --problem kepler --levels 1 2> "$T/err"
rc=$?
check '[ $rc -eq 2 ] && grep -q -- "--levels" "$T/err"' "--levels 1: exit 2"
"$VIGEN" order nosuch --problem kepler 2> "$T/err"
rc=$?
check '[ $rc -eq 2 ] && grep -q "nosuch: no such file or published method" "$T/err"' "unknown method: exit 2"
check '[ -z "$(ls -A "$TMPDIR")" ]' "nothing left in TMPDIR"
exit $fail
