#!/bin/bash
# rebound_run.sh [REBOUND_SRC] [BUILD_DIR] — the runtime's N-body flows in a
# Wisdom-Holman loop side by side with REBOUND's WHFast, with and without
# symplectic correctors, on the outer solar system over 10^6 days
# (bench/nbody_whfast.c; docs/benchmarks.md, "Kepler splittings against
# WHFast").  REBOUND_SRC is a checkout of github.com/hannorein/rebound
# (default bench/peers/rebound, ignored by git; cloned there when missing),
# built with its own Makefile (make -C REBOUND_SRC, gcc -O3); vigen's runtime
# and problem library are built with CMake (Release) into BUILD_DIR
# (default /tmp/vigen-bench-nbody), the driver with gcc -O3.  Prints the
# table (method, corrector order, step in days, steps, maximum relative
# energy error over 100 outputs, best and median wall time of
# NBODY_REPEATS runs (default 5), ns per step), then the instructions per
# step under callgrind when valgrind is installed.  A few minutes on 2 cores.
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
gcc -O3 -std=c11 -D_POSIX_C_SOURCE=200809L -I"$REB/src" -I"$SRC/runtime/include" \
    "$SRC/bench/nbody_whfast.c" -o "$OUT/nbody_whfast" \
    "$OUT/runtime/problems/libvigen_problems.a" "$OUT/runtime/libvigen_runtime.a" \
    -L"$REB/src" -Wl,-rpath,"$(cd "$REB/src" && pwd)" -lrebound -lgsl -lgslcblas -lm
echo "# $(grep -m1 'model name' /proc/cpuinfo | sed 's/.*: //'), $(nproc) cores; REBOUND $(cat "$REB/version.txt") ($(git -C "$REB" rev-parse --short HEAD 2>/dev/null || echo unknown))"
"$OUT/nbody_whfast" "${NBODY_REPEATS:-5}"
# instructions per step, free of the machine's load: callgrind's count of a
# run of 2N steps less that of N steps, over N (N = 5000, h = 200 days)
if command -v valgrind >/dev/null; then
    echo "# instructions per step (callgrind, h = 200 days, runs of 10000 less 5000 steps)"
    for m in whfast vigen; do
        for c in 0 11; do
            ir() { valgrind --tool=callgrind --callgrind-out-file=/dev/null "$OUT/nbody_whfast" one $m 200 $c "$1" 2>&1 |
                   sed -n 's/.*refs: *//p' | tr -d ,; }
            a=$(ir 5000); b=$(ir 10000)
            echo "$m corrector $c: $(( (b - a) / 5000 ))"
        done
    done
fi
