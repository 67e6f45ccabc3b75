#!/bin/bash
# mech_icount.sh VIGEN [BUILD_DIR] — instructions per step of the implicit
# mechanical steppers against the hand-written anchors (bench/hand_gni_gauss.h)
# under callgrind: for each stepper of bench/mech_icount.c, the whole
# program's count at 2N steps less that at N steps, over N (start-up and
# set-up cancel), beside the forces and sweeps per step, the energy error and
# the wall time per step (fastest of 3 runs; noise on a loaded machine).
# Emits gauss_2, gauss_3 and lobatto_iiia_iiib_3 with the vigen binary VIGEN
# (with --dim for the direct-force rows, without for the callback rows),
# builds with gcc -O2 into BUILD_DIR (default /tmp/vigen-bench-mech) and
# prints a Markdown table per problem.  MECH_PROBLEMS selects the problems
# (default "kepler"; "fput" is the chain of bench/peer_run.sh; "fput-stiff" is the stiff chain of the Newton rows, run
# with the fixed point and with Newton).  Needs valgrind.  Not a test.
set -euo pipefail
VIGEN=$(realpath "${1:?usage: mech_icount.sh VIGEN [BUILD_DIR]}")
SRC=$(cd "$(dirname "$0")/.." && pwd)
OUT=${2:-/tmp/vigen-bench-mech}
mkdir -p "$OUT/obj"
CFLAGS="-std=c11 -O2 -Wall -Wextra -Wpedantic"
INC=(-I"$SRC/runtime/include" -I"$SRC/runtime/problems" -I"$SRC/bench")

# id|collection name|parameters|dim|unit masses|h|N|steppers|title
declare -A ROWS=(
    [kepler]="kepler|kepler|e=0.6|2|1|(2 * 3.14159265358979323846 / 200)|20000|gni2 g2d g2 gni3 g3d g3 gnil3 l3d l3|Kepler, e = 0.6, h = 2 pi/200"
    [fput]="fput|fput|n=1000|1000|1|0.05|100|gni2 g2d g2 gni3 g3d g3 gnil3 l3d l3|FPUT-beta chain, n = 1000, beta = 1, first normal mode of amplitude 1, h = 0.05 (as bench/peer_run.sh)"
    [fput-stiff]="fput|fput|n=32,beta=1e4|32|1|0.05|500|g2d g2d:newton g3d g3d:newton l3d l3d:newton|FPUT-beta chain, n = 32, beta = 10^4 (stiff: h omega_max about 1.6), amplitude 1, h = 0.05"
)

rm -f "$OUT"/obj/*.o
for f in "$SRC"/runtime/{core,drive,diagnostics,lagrangian,nbody,poincare}/*.c "$SRC"/runtime/problems/*.c; do
    gcc $CFLAGS "${INC[@]}" -c "$f" -o "$OUT/obj/$(basename "${f%.c}").o"
done
declare -A TAB=([g2]=gauss_2 [g3]=gauss_3 [l3]=lobatto_iiia_iiib_3)
for m in g2 g3 l3; do
    "$VIGEN" emit "$SRC/tableaux/published/${TAB[$m]}.lua" --name "mi_$m" -o "$OUT" -q
    gcc $CFLAGS -I"$SRC/runtime/include" -c "$OUT/mi_$m.c" -o "$OUT/obj/mi_$m.o"
done

echo "Machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores;" \
    "$(date -u '+%Y-%m-%d %H:%M UTC'); load average $(cut -d' ' -f1-3 /proc/loadavg); gcc $(gcc -dumpfullversion) ($CFLAGS)."
for key in ${MECH_PROBLEMS:-kepler}; do
    IFS='|' read -r id name params dim unit h n steppers title <<<"${ROWS[$key]}"
    dir="$OUT/$key"
    mkdir -p "$dir"
    for m in g2 g3 l3; do
        "$VIGEN" emit "$SRC/tableaux/published/${TAB[$m]}.lua" --name "mi_${m}d" --dim "$dim" -o "$dir" -q
    done
    others=()
    for o in "$OUT"/obj/*.o; do
        case "$(basename "$o")" in problem_$id.o) ;; *) others+=("$o") ;; esac
    done
    gcc $CFLAGS "${INC[@]}" -I"$OUT" -I"$dir" -DPEER_FILE="\"problem_$id.c\"" -DPEER_NAME="\"$name\"" \
        -DPEER_PARAMS="\"$params\"" -DPEER_DIM="$dim" -DPEER_UNIT_MASS="$unit" -DPEER_H="$h" \
        -g "$SRC/bench/mech_icount.c" "${others[@]}" -lgsl -lgslcblas -lm -o "$dir/mech_icount"
    echo
    echo "#### $title; instructions per step from $n and $((2 * n)) steps"
    echo
    echo "| stepper | instructions / step | forces / step | sweeps / step | rel. energy error | x anchor | ns / step (wall) |"
    echo "|---|--:|--:|--:|--:|--:|--:|"
    declare -A IPS=()
    for s in $steppers; do
        st=${s%%:*} opt=
        [ "$s" != "$st" ] && opt=${s#*:}
        counts=()
        for k in $n $((2 * n)); do
            valgrind --tool=callgrind --callgrind-out-file="$dir/cg.out" "$dir/mech_icount" "$st" "$k" $opt \
                >"$dir/run.txt" 2>"$dir/cg.err" || true
            counts+=("$(sed -n 's/^summary: //p' "$dir/cg.out")")
        done
        read -r _ _ _ forces _ sweeps _ err _ status _ _ _ _ _ _ <"$dir/run.txt"
        # wall time beside the count: the fastest of 3 plain runs of 2N steps
        ns=$(for r in 1 2 3; do "$dir/mech_icount" "$st" $((2 * n)) $opt | awk '{ print $NF }'; done | sort -g | head -1)
        ips=$(awk -v a="${counts[0]}" -v b="${counts[1]}" -v n="$n" 'BEGIN { printf "%.0f", (b - a) / n }')
        IPS[$s]=$ips
        case $st in g2* ) anchor=gni2 ;; g3* ) anchor=gni3 ;; l3* ) anchor=gnil3 ;; *) anchor=$st ;; esac
        ratio=-
        [ -n "${IPS[$anchor]:-}" ] && ratio=$(awk -v a="$ips" -v b="${IPS[$anchor]}" 'BEGIN { printf "%.2f", a / b }')
        [ "$status" = 0 ] || err="failed (status $status)"
        echo "| $s | $ips | $forces | $sweeps | $err | $ratio | $ns |"
    done
    unset IPS
done
