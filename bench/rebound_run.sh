#!/bin/bash
# rebound_run.sh [REBOUND_SRC] [BUILD_DIR] — vigen's emitted Kepler
# splittings (wisdom_holman with and without the runtime's correctors,
# saba_2..4, saba_10_6_4, wisdom_holman_corrected; the split variant over the
# runtime's Jacobi N-body flows) side by side with REBOUND's WHFast, with and
# without symplectic correctors, on the outer solar system over 10^6 days
# (bench/nbody_whfast.c; docs/benchmarks.md, "Kepler splittings against
# WHFast").  REBOUND_SRC is a checkout of github.com/hannorein/rebound
# (default bench/peers/rebound, ignored by git; cloned there when missing),
# built with its own Makefile (make -C REBOUND_SRC, gcc -O3); vigen and its
# runtime are built with CMake (Release) into BUILD_DIR (default
# /tmp/vigen-bench-nbody), the methods emitted there by that vigen, the
# driver and the emitted code compiled with gcc -O3.  Prints the table
# (method, corrector order, step in days, steps, maximum relative energy
# error over 100 outputs, best and median wall time of NBODY_REPEATS runs
# (default 7), ns per step), then the instructions per step under callgrind
# when valgrind is installed, and how those of an emitted step divide among
# the runtime's flows.  The emitted steppers take the steps between two
# outputs in one call of NAME_advance.  About a minute on 2 cores (idle).
# Not a test.
set -euo pipefail
SRC=$(cd "$(dirname "$0")/.." && pwd)
REB=${1:-$SRC/bench/peers/rebound}
OUT=${2:-/tmp/vigen-bench-nbody}
if [ ! -f "$REB/src/rebound.h" ]; then
    mkdir -p "$(dirname "$REB")"
    git clone --depth 1 https://github.com/hannorein/rebound "$REB" >&2
fi
make -s -C "$REB" >&2
cmake -S "$SRC" -B "$OUT" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$OUT" -j2 --target vigen_problems >&2
cmake --build "$OUT" -j2 --target vigen >&2
# the Kepler splittings of the library, emitted by the build's vigen (split
# variant: their files name the flows "kepler" and "interaction")
METHODS="wisdom_holman saba_2 saba_3 saba_4 saba_10_6_4 wisdom_holman_corrected sabac_2 sabac_3 wh_modified_kick
         wh_modified_kick_corrected"
mkdir -p "$OUT/emitted"
for m in $METHODS; do
    "$OUT/vigen" emit "$SRC/tableaux/published/$m.lua" --name "$m" -o "$OUT/emitted" >&2
done
gcc -O3 -std=c11 -D_POSIX_C_SOURCE=200809L -I"$REB/src" -I"$SRC/runtime/include" -I"$OUT/emitted" \
    "$SRC/bench/nbody_whfast.c" $(for m in $METHODS; do echo "$OUT/emitted/$m.c"; done) -o "$OUT/nbody_whfast" \
    "$OUT/runtime/problems/libvigen_problems.a" "$OUT/runtime/libvigen_runtime.a" \
    -L"$REB/src" -Wl,-rpath,"$(cd "$REB/src" && pwd)" -lrebound -lgsl -lgslcblas -lm
echo "# $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //'), $(nproc) cores; REBOUND $(cat "$REB/version.txt") ($(git -C "$REB" rev-parse --short HEAD 2>/dev/null || echo unknown))"
"$OUT/nbody_whfast" "${NBODY_REPEATS:-7}"
# the rows of the ratios at 1e-8 and 1e-10 (docs/benchmarks.md): the best
# wall time of 31 single runs each, less exposed to a shared machine's
# bursts than the best of the table's 7
echo "# best of 31 single runs (ms): method corrector steps"
for mcs in whfast:11:4000 wisdom_holman:11:4500 whfast:3:25000 saba_10_6_4:0:1800; do
    IFS=: read -r m c n <<< "$mcs"
    h=$(awk -v n="$n" 'BEGIN { printf "%.15g", 1e6 / n }')
    best=$(for k in $(seq 31); do "$OUT/nbody_whfast" one "$m" "$h" "$c" "$n"; done | sort -g | head -1)
    echo "$m $c $n $best"
done
# instructions per step, free of the machine's load: callgrind's count of a
# run of 2N steps less that of N steps, over N (N = 2000), at h = 200 days
# for every method, then at the steps of the cheapest runs that reach 1e-8
# and 1e-10 (the Kepler solver's iterations, hence the count, grow a little
# with the step)
if command -v valgrind >/dev/null; then
    echo "# instructions per step (callgrind, runs of 4000 less 2000 steps): method corrector h/d instructions"
    ir() { valgrind --tool=callgrind --callgrind-out-file=/dev/null "$OUT/nbody_whfast" one "$1" "$3" "$2" "$4" 2>&1 |
           sed -n 's/.*refs: *//p' | tr -d ,; }
    for mch in whfast:0:200 whfast:3:200 whfast:11:200 whfast:17:200 wisdom_holman:0:200 wisdom_holman:3:200 \
               wisdom_holman:11:200 saba_2:0:200 saba_3:0:200 saba_4:0:200 saba_10_6_4:0:200 \
               wisdom_holman_corrected:0:200 \
               whfast:11:250 whfast:3:40 whfast:11:33.3333333333333 wisdom_holman:11:222.222222222222 \
               saba_10_6_4:0:555.555555555556; do
        IFS=: read -r m c h <<< "$mch"
        a=$(ir "$m" "$c" "$h" 2000); b=$(ir "$m" "$c" "$h" 4000)
        echo "$m $c $h $(( (b - a) / 2000 ))"
    done
    # where an emitted step's instructions go: the runtime's flows (the
    # Kepler flow, within it the Kepler drift of one body, the interaction
    # kick) per step, inclusive, by the same difference of two runs
    if command -v callgrind_annotate >/dev/null; then
        echo "# per step, inclusive (callgrind_annotate): method h/d step kepler-flow kepler-drift interaction"
        fn() { callgrind_annotate --inclusive=yes "$1" 2>/dev/null | grep -m1 ":$2 " | awk '{print $1}' | tr -d ,; }
        for mh in wisdom_holman:200 saba_10_6_4:200 saba_10_6_4:555.555555555556; do
            IFS=: read -r m h <<< "$mh"
            line="$m $h"
            for n in 2000 4000; do
                valgrind --tool=callgrind --callgrind-out-file="$OUT/cg.$n" "$OUT/nbody_whfast" one "$m" "$h" 0 "$n" \
                    >/dev/null 2>&1
            done
            for f in "${m}_advance" vigen_nbody_jacobi_kepler vigen_kepler_drift vigen_nbody_jacobi_interaction; do
                line="$line $(( ($(fn "$OUT/cg.4000" "$f") - $(fn "$OUT/cg.2000" "$f")) / 2000 ))"
            done
            echo "$line"
        done
        rm -f "$OUT/cg.2000" "$OUT/cg.4000"
    fi
fi
