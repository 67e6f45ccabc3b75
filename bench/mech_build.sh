#!/bin/bash
# mech_build.sh VIGEN [BUILD_DIR] — emits the steppers of bench/mech_bench.c
# (Gauss-2 and Stormer-Verlet, with and without --dim 2) with the vigen
# binary VIGEN and builds BUILD_DIR/mech_bench (default /tmp/vigen-bench-mech).
set -euo pipefail
VIGEN=${1:?usage: mech_build.sh VIGEN [BUILD_DIR]}
SRC=$(cd "$(dirname "$0")/.." && pwd)
OUT=${2:-/tmp/vigen-bench-mech}
mkdir -p "$OUT"
"$VIGEN" emit "$SRC/tests/data/emit/gauss2.lua" --name mech_g2 -o "$OUT" -q
"$VIGEN" emit "$SRC/tests/data/emit/gauss2.lua" --name mech_g2d --dim 2 -o "$OUT" -q
"$VIGEN" emit "$SRC/tests/data/emit/verlet.lua" --name mech_sv -o "$OUT" -q
"$VIGEN" emit "$SRC/tests/data/emit/verlet.lua" --name mech_svd --dim 2 -o "$OUT" -q
gcc -std=c11 -O2 -Wall -Wextra -Wpedantic -I"$SRC/runtime/include" -I"$OUT" -I"$SRC/bench" \
    "$SRC/bench/mech_bench.c" "$OUT/mech_g2.c" "$OUT/mech_sv.c" "$SRC"/runtime/src/*.c \
    -lgsl -lgslcblas -lm -o "$OUT/mech_bench"
echo "built $OUT/mech_bench"
