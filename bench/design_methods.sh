#!/bin/bash
# bench/design_methods.sh [VIGEN] [OUTDIR] — the methods vigen design found
# against the library's methods of the same cost, in runs: work-precision
# (`vigen try --work-precision`) on Henon-Heiles (largest relative energy
# error) and Kepler (e = 0.6; global error at the end against the exact
# solution), at equal force evaluations.  Prints one table per problem and,
# when gnuplot is there, OUTDIR/design_methods_<set>_<problem>.png, for
# three sets of methods of equal cost (or the one set METHODS="..." names):
#   s5:   optimal_s5_4 against suzuki_4 and mclachlan_rkn_4 (5 forces per step)
#   s6:   optimal_rkn6_4 and optimal_s6_4 against blanes_moan_s6_4 (6 forces per step)
#   rkn7: optimal_rkn7_6 against yoshida_6 (7 forces per step)
set -u
VIGEN=${1:-build/vigen}
OUT=${2:-bench/out}
mkdir -p "$OUT"
run_set() {
SET=$1
METHODS=$2
for problem in henon-heiles kepler; do
  params=""
  [ "$problem" = kepler ] && params="--param e=0.6"
  # shellcheck disable=SC2086
  "$VIGEN" try $METHODS --problem "$problem" $params --work-precision --levels 6 --steps-per-period 32 --json \
    > "$OUT/design_methods_${SET}_$problem.json" || exit 1
  python3 - "$OUT/design_methods_${SET}_$problem.json" "$problem" "$OUT/design_methods_$SET" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
problem, out = sys.argv[2], sys.argv[3]
by = {m["name"]: m["points"] for m in d["methods"] if m["failed"] is None}
what = "largest relative energy error" if d["error_is_energy"] else "global error"
print("%s: %s against gradient evaluations" % (problem, what))
names = list(by)
print("%-10s" % "evals" + "".join("%18s" % n for n in names))
for i in range(max(len(v) for v in by.values())):
    ev = by[names[0]][i]["evals"]
    print("%-10d" % ev + "".join("%18.3e" % by[n][i]["error"] if i < len(by[n]) else "%18s" % "-" for n in names))
with open("%s_%s.dat" % (out, problem), "w") as f:
    for n in names:
        f.write("%s\n" % n)
        for p in by[n]:
            f.write("%d %.6e\n" % (p["evals"], p["error"]))
        f.write("\n\n")
PY
  if command -v gnuplot >/dev/null; then
    gnuplot <<GP
set terminal pngcairo size 720,480 noenhanced
set output "$OUT/design_methods_${SET}_$problem.png"
set logscale xy
set xlabel "gradient evaluations"
set ylabel "$([ "$problem" = kepler ] && echo "global error" || echo "max relative energy error")"
set title "$problem"
set key bottom left
plot for [i=0:$(($(echo $METHODS | wc -w) - 1))] "$OUT/design_methods_${SET}_$problem.dat" index i using 1:2 with linespoints title columnheader(1)
GP
  fi
done
}
if [ -n "${METHODS:-}" ]; then
  run_set custom "$METHODS"
else
  run_set s5 "optimal_s5_4 suzuki_4 mclachlan_rkn_4"
  run_set s6 "optimal_rkn6_4 optimal_s6_4 blanes_moan_s6_4"
  run_set rkn7 "optimal_rkn7_6 yoshida_6"
fi
