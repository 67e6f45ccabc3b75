#!/usr/bin/env bash
# drivers_compare.sh BASE_TREE NEW_TREE — the runtime's drivers of two source
# trees side by side (each with its own vigen build in TREE/build):
# bench/drivers_bench.c (from NEW_TREE) is built against each tree's runtime
# and the steppers each tree's vigen emits, then run under callgrind, which
# counts instructions (repeatable whatever else the machine is doing).  For
# each stepper and driver: instructions inside the driver case of each tree,
# their ratio new / base, and whether the final states agree bit for bit.
# Prints Markdown.  A few minutes.  Not a test.
set -euo pipefail
base=$(realpath "${1:?usage: drivers_compare.sh BASE_TREE NEW_TREE}")
new=$(realpath "${2:?usage: drivers_compare.sh BASE_TREE NEW_TREE}")
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for side in base new; do
  tree=${!side}
  mkdir -p "$work/$side"
  "$tree/build/vigen" emit "$new/tests/data/emit/gauss2.lua" --name drv_g2 -o "$work/$side" -q
  "$tree/build/vigen" emit "$new/tests/data/emit/verlet.lua" --name drv_sv -o "$work/$side" -q
  # the runtime's sources wherever the tree keeps them, the problem collection left out
  mapfile -t rt < <(find "$tree/runtime" -name '*.c' -not -path '*/problems/*' | sort)
  gcc -std=c11 -O2 -g -fopenmp -I"$tree/runtime/include" -I"$work/$side" "$here/drivers_bench.c" \
    "$work/$side/drv_g2.c" "$work/$side/drv_sv.c" "${rt[@]}" -lgsl -lgslcblas -lm -o "$work/$side/drivers_bench"
done
icount() { # side stepper case steps -> instructions of the case, and its output in $work/side.out
  valgrind --tool=callgrind --callgrind-out-file="$work/cg.out" '--toggle-collect=driver_case_*' \
    "$work/$1/drivers_bench" "$2" "$3" "$4" >"$work/$1.out" 2>"$work/vg.log" || { cat "$work/vg.log" >&2; exit 1; }
  awk '/^(summary|totals):/ { print $2; exit }' "$work/cg.out"
}
echo "| stepper | driver | steps | base instructions | new instructions | new / base | same bits |"
echo "|---|---|---:|---:|---:|---:|---|"
for s in verlet gauss2; do
  for c in integrate at events ensemble; do
    n=20000
    a=$(icount base "$s" "$c" "$n")
    b=$(icount new "$s" "$c" "$n")
    same=no
    cmp -s "$work/base.out" "$work/new.out" && same=yes
    printf '| %s | %s | %d | %d | %d | %.4f | %s |\n' "$s" "$c" "$n" "$a" "$b" "$(awk -v a="$a" -v b="$b" 'BEGIN { print b / a }')" "$same"
  done
done
