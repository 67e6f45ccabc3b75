#!/bin/bash
# poincare_run.sh [PERIODS [E]] — builds bench/poincare_kepler.c with the
# golden Gauss-2 stepper of tests/data/emit/golden and the runtime and
# problem sources, and prints its table (docs/simulation.md).
set -euo pipefail
SRC=$(cd "$(dirname "$0")/.." && pwd)
OUT=$(mktemp -d)
trap 'rm -rf "$OUT"' EXIT
gcc -std=c11 -O2 -Wall -Wextra -Wpedantic -I"$SRC/runtime/include" -I"$SRC/tests/data/emit/golden" \
    -I"$SRC/runtime/problems" "$SRC/bench/poincare_kepler.c" "$SRC/tests/data/emit/golden/gauss2.c" \
    "$SRC"/runtime/{core,drive,diagnostics,lagrangian,poincare}/*.c "$SRC"/runtime/problems/*.c \
    -lgsl -lgslcblas -lm -o "$OUT/poincare_kepler"
"$OUT/poincare_kepler" "$@"
