#!/bin/sh
# drift_run.sh [BUILD_DIR] — the runtime's Kepler drift alone
# (bench/kepler_drift_bench.c, compiled here against BUILD_DIR's
# libvigen_runtime.a, default build/):
#   1. instructions per drift (callgrind: 20000 drifts less 10000) on orbits
#      of e = 0, 0.05, 0.5, 0.9 at steps of 0.002..0.5 periods;
#   2. the relative energy error against the steps, rms over 8 orbits, for
#      e = 0 and 0.5 at h = 0.10101, 0.30303, 0.50505, 0.80808 periods over
#      10^6 steps (the last column, rms/(eps sqrt(steps)), stays about
#      constant under Brouwer's law and grows like sqrt(steps) under a
#      drift).  The steps are kept off the exact fractions of the period:
#      with h = period/10 the doubles of the state fall, after some 10^7
#      steps, into an exact cycle, and the error stops changing;
#   3. with LONG=1, one run of 10^9 drifts (e = 0.5, h = 0.10101 periods;
#      some 20 minutes unloaded), its rows printed as they come.
# docs/benchmarks.md ("The Kepler drift: instructions and energy error")
# gives the figures.
set -e
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../build}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
cc -O2 -I"$here/../runtime/include" "$here/kepler_drift_bench.c" "$build/runtime/libvigen_runtime.a" -lm \
   -o "$out/kdb"
count() {
    n1=$(valgrind --tool=callgrind --callgrind-out-file=/dev/null "$out/kdb" count "$1" "$2" 20000 2>&1 >/dev/null \
         | sed -n 's/.*refs: *\([0-9,]*\).*/\1/p' | tr -d ,)
    n2=$(valgrind --tool=callgrind --callgrind-out-file=/dev/null "$out/kdb" count "$1" "$2" 10000 2>&1 >/dev/null \
         | sed -n 's/.*refs: *\([0-9,]*\).*/\1/p' | tr -d ,)
    echo "e = $1, h = $2 periods: $(( (n1 - n2) / 10000 )) instructions per drift"
}
if command -v valgrind >/dev/null; then
    for c in "0 0.002" "0 0.016" "0.05 0.03" "0.5 0.1" "0.9 0.05" "0.5 0.5"; do
        # shellcheck disable=SC2086
        count $c
    done
fi
for e in 0 0.5; do
    for h in 0.10101 0.30303 0.50505 0.80808; do
        nice -n 10 "$out/kdb" energy "$e" "$h" 1000000 8 | awk 'NR == 1 || /^(1000|10000|100000|1000000) /'
    done
done
if [ "${LONG:-0}" = 1 ]; then
    nice -n 10 "$out/kdb" energy 0.5 0.10101 1000000000 1
fi
