#!/bin/bash
# emit_build.sh VIGEN [BUILD_DIR] — emits the benchmark steppers with the
# vigen binary VIGEN and builds bench/emit_bench into BUILD_DIR (default
# /tmp/vigen-bench), and bench/emit_icount (instruction counts under
# callgrind).  Run BUILD_DIR/emit_bench [KEPLER_STEPS] [FPUT_STEPS], or
# bench/run_emit.sh for everything.
set -euo pipefail
VIGEN=${1:?usage: emit_build.sh VIGEN [BUILD_DIR]}
SRC=$(cd "$(dirname "$0")/.." && pwd)
OUT=${2:-/tmp/vigen-bench}
mkdir -p "$OUT"
for n in emit_g2 emit_g2k emit_g2f; do "$VIGEN" emit "$SRC/tests/data/emit/gauss2.lua" --name $n -o "$OUT" -q; done
for n in emit_sv emit_svk emit_svf; do "$VIGEN" emit "$SRC/tests/data/emit/verlet.lua" --name $n -o "$OUT" -q; done
for prog in emit_bench emit_icount; do
    gcc -std=c11 -O2 -g -Wall -Wextra -Wpedantic -I"$SRC/runtime/include" -I"$OUT" -I"$SRC/bench" \
        "$SRC/bench/$prog.c" "$OUT/emit_g2.c" "$OUT/emit_sv.c" "$SRC"/runtime/{core,drive,diagnostics,lagrangian,poincare}/*.c \
        -lgsl -lgslcblas -lm -o "$OUT/$prog"
    echo "built $OUT/$prog"
done
