#!/bin/bash
# peer_icount.sh VIGEN [BUILD_DIR] — instructions per step of the rows of
# bench/peer_icount.c (the hand-written Verlet and GNI-style Gauss-2, the
# emitted Verlet and Gauss-2 through the general callbacks, Verlet and
# mclachlan_rkn_4 with --dim and direct force) on Kepler, the outer solar
# system and the FPUT chain of n = 1000, as bench/peer_run.sh sets them up:
# callgrind counts of the stepping loop at 2 N and N steps, (c(2N) - c(N))/N.
# Emits with the vigen binary VIGEN, builds into BUILD_DIR (default
# /tmp/vigen-bench-icount; gcc -O2), prints Markdown.  Needs valgrind.  About
# a minute on 2 cores.  Not a test.
set -euo pipefail
VIGEN=$(realpath "${1:?usage: peer_icount.sh VIGEN [BUILD_DIR]}")
SRC=$(cd "$(dirname "$0")/.." && pwd)
OUT=${2:-/tmp/vigen-bench-icount}
rm -rf "$OUT/obj"
mkdir -p "$OUT/obj"
CFLAGS="-std=c11 -O2 -Wall -Wextra -Wpedantic"
INC=(-I"$SRC/runtime/include" -I"$SRC/runtime/problems" -I"$SRC/bench")
# id, collection name, parameters, dimension, unit masses, h, N (the smaller count)
PROBLEMS=(
    "kepler|kepler|e=0.6|2|1|(2 * 3.14159265358979323846 / 200)|2000"
    "outer_solar_system|outer-solar-system||18|0|10.0|200"
    "fput|fput|n=1000|1000|1|0.05|20"
)
for f in "$SRC"/runtime/{core,drive,diagnostics,lagrangian,poincare,nbody}/*.c "$SRC"/runtime/problems/*.c; do
    gcc $CFLAGS "${INC[@]}" -c "$f" -o "$OUT/obj/$(basename "${f%.c}").o"
done
"$VIGEN" emit "$SRC/tableaux/published/gauss_2.lua" --name peer_g2 -o "$OUT" -q
"$VIGEN" emit "$SRC/tableaux/published/stormer_verlet_velocity.lua" --name peer_sv -o "$OUT" -q
for n in g2 sv; do gcc $CFLAGS -I"$SRC/runtime/include" -c "$OUT/peer_$n.c" -o "$OUT/obj/peer_$n.o"; done
count() {   # count BINARY ROW STEPS: instructions of run_loop
    valgrind --tool=callgrind --toggle-collect='run_loop*' --callgrind-out-file="$OUT/cg.out" "$1" "$2" "$3" >/dev/null 2>&1
    sed -n 's/^summary: //p' "$OUT/cg.out"
}
echo "| problem | hsv | gni | svg | svd | g2g | mcld |"
echo "|---|--:|--:|--:|--:|--:|--:|"
for row in "${PROBLEMS[@]}"; do
    IFS='|' read -r id name params dim unit h n <<<"$row"
    dir="$OUT/$id"
    mkdir -p "$dir"
    "$VIGEN" emit "$SRC/tableaux/published/stormer_verlet_velocity.lua" --name peer_svd --dim "$dim" -o "$dir" -q
    "$VIGEN" emit "$SRC/tableaux/published/mclachlan_rkn_4.lua" --name peer_mcld --dim "$dim" -o "$dir" -q
    others=()
    for o in "$OUT"/obj/*.o; do
        case "$(basename "$o")" in problem_$id.o) ;; *) others+=("$o") ;; esac
    done
    gcc $CFLAGS "${INC[@]}" -I"$OUT" -I"$dir" -DPEER_FILE="\"problem_$id.c\"" -DPEER_NAME="\"$name\"" \
        -DPEER_PARAMS="\"$params\"" -DPEER_DIM="$dim" -DPEER_UNIT_MASS="$unit" -DPEER_H="$h" \
        "$SRC/bench/peer_icount.c" "${others[@]}" -lgsl -lgslcblas -lm -o "$dir/peer_icount"
    line="| $id |"
    for r in hsv gni svg svd g2g mcld; do
        a=$(count "$dir/peer_icount" $r "$n")
        b=$(count "$dir/peer_icount" $r $((2 * n)))
        line="$line $(( (b - a) / n )) |"
    done
    echo "$line"
done
