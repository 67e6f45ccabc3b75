#!/bin/bash
# ensemble_count.sh BENCH [N] — instructions per orbit-step of the Kepler
# ensemble configurations of bench/ensemble_bench.c (built by
# ensemble_run.sh), counted by callgrind: (count of 2S steps - count of S
# steps) / (N S), which leaves out the set-up.  Valgrind reports no AVX-512,
# so the batched steps run their AVX2 clone here (4 doubles per vector) and
# the hand-written AVX-512 limit is not counted.  Prints Markdown.
set -euo pipefail
BENCH=${1:?usage: ensemble_count.sh BENCH [N]}
N=${2:-1024}
S=100
count() { # STEPPER ROW STEPS
    local f
    f=$(mktemp)
    valgrind --tool=callgrind --callgrind-out-file="$f" "$BENCH" "$N" "$3" 256 1 "$1:$2" >/dev/null 2>&1
    sed -n 's/^summary: \([0-9]*\).*/\1/p' "$f"
    rm -f "$f"
}
echo "| stepper | configuration | instructions per orbit-step | vs scalar loop |"
echo "|---|---|---|---|"
names=("Störmer–Verlet" "Yoshida 4" "Gauss s = 2")
for s in 0 1 2; do
    base=""
    for r in 0 3 5; do
        a=$(count $s $r $S)
        b=$(count $s $r $((2 * S)))
        per=$(awk -v a="$a" -v b="$b" -v n="$N" -v s="$S" 'BEGIN { printf "%.1f", (b - a) / (n * s) }')
        [ -z "$base" ] && base=$per
        what=$([ $r = 0 ] && echo "scalar loop" || ([ $r = 3 ] && echo "batch, force by callback" || echo "batch, force direct"))
        awk -v n="${names[$s]}" -v w="$what" -v p="$per" -v b="$base" 'BEGIN { printf "| %s | %s | %s | %.2f |\n", n, w, p, b / p }'
    done
done
