#!/bin/bash
# ensemble_run.sh VIGEN [BUILD_DIR] — the ensemble benchmarks, side by side in
# one run (docs/benchmarks.md, "Ensembles"):
#   1. bench/ensemble_bench.c: Kepler ensemble of 4096 orbits, Stormer-Verlet,
#      Yoshida's triple jump and Gauss s = 2 emitted with --batch: the scalar
#      loop, the OpenMP ensemble on 1 and 2 threads, the batch on 1 and 2
#      threads, and the hand-written AVX-512 Verlet (bench/kepler_verlet_avx512.h);
#      once pinned to core 0 (the one-core rows) and once on cores 0 and 1
#      (the two-thread rows against the one-thread rows of the same run),
#      best and median of 7 runs;
#   1b. bench/ensemble_count.sh: callgrind instructions per orbit-step (the
#      batch's AVX2 clone: valgrind has no AVX-512);
#   2. examples/mpi-ensemble (Gauss s = 2, the ensemble spread over ranks):
#      1 and 2 MPI ranks of one thread each, wall-clock time of the
#      integration and the gathering (fastest of three runs), and whether
#      the two outputs are the same bytes.
# VIGEN is a built vigen (its build directory is the package the MPI example
# is configured against).  Prints Markdown; measurements, not tests.
set -euo pipefail
VIGEN=${1:?usage: ensemble_run.sh VIGEN [BUILD_DIR]}
SRC=$(cd "$(dirname "$0")/.." && pwd)
BUILD=$(cd "$(dirname "$VIGEN")" && pwd)
OUT=${2:-/tmp/vigen-bench-ensemble}
mkdir -p "$OUT"
for n in sv svd; do
    "$VIGEN" emit "$SRC/tableaux/published/stormer_verlet_velocity.lua" --name ens_$n --batch -o "$OUT" -q
done
for n in y4 y4d; do
    "$VIGEN" emit "$SRC/tableaux/published/yoshida_4.lua" --name ens_$n --batch -o "$OUT" -q
done
for n in g2 g2d; do
    "$VIGEN" emit "$SRC/tableaux/published/gauss_2.lua" --name ens_$n --batch -o "$OUT" -q
done
# -fno-math-errno: the force's square root in vector registers (with errno
# it is a call per orbit); the batched steps choose their clone at load time
FLAGS="-std=c11 -O3 -fno-math-errno -Wall -Wextra -Wpedantic"
gcc $FLAGS -fopenmp -I"$SRC/runtime/include" -I"$OUT" "$SRC/bench/ensemble_bench.c" "$OUT/ens_sv.c" \
    "$OUT/ens_y4.c" "$OUT/ens_g2.c" "$SRC"/runtime/{core,drive,diagnostics,lagrangian,poincare}/*.c -lgsl -lgslcblas -lm -o "$OUT/ensemble_bench"

echo "## $(date -u '+%Y-%m-%d %H:%M UTC'), $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores, gcc $(gcc -dumpfullversion) ($FLAGS)"
echo "load average before the run: $(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "One core (taskset -c 0):"
echo
taskset -c 0 "$OUT/ensemble_bench" 4096 1000 256 7
echo
echo "load average: $(cut -d' ' -f1-3 /proc/loadavg); two cores (taskset -c 0,1):"
echo
taskset -c 0,1 "$OUT/ensemble_bench" 4096 1000 256 7
echo
echo "load average after the run: $(cut -d' ' -f1-3 /proc/loadavg)"
echo
if command -v valgrind >/dev/null; then
    echo "Instructions per orbit-step (callgrind, 1024 orbits, 200 - 100 steps):"
    echo
    bash "$SRC/bench/ensemble_count.sh" "$OUT/ensemble_bench" 1024
    echo
fi

if ! command -v mpirun >/dev/null; then
    echo "MPI: not installed (libopenmpi-dev openmpi-bin), no MPI rows"
    exit 0
fi
cmake -S "$SRC/examples/mpi-ensemble" -B "$OUT/mpi" -Dvigen_DIR="$BUILD" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$OUT/mpi" -j2 >/dev/null
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
best() { # RANKS: fastest wall-clock of three runs
    local b=""
    for r in 1 2 3; do
        OMP_NUM_THREADS=1 mpirun --oversubscribe -np "$1" "$OUT/mpi/mpi_ensemble" 100000 200 1 \
            >"$OUT/mpi_np$1.out" 2>"$OUT/mpi_np$1.err"
        s=$(sed -n 's/.* \([0-9.]*\) s (integration.*/\1/p' "$OUT/mpi_np$1.err")
        b=$(awk -v a="$b" -v s="$s" 'BEGIN { print (a == "" || s + 0 < a + 0) ? s : a }')
    done
    echo "$b"
}
s1=$(best 1)
s2=$(best 2)
same=no
cmp -s "$OUT/mpi_np1.out" "$OUT/mpi_np2.out" && same=yes
echo "| MPI (examples/mpi-ensemble, Gauss s = 2, 10^5 orbits x 200 steps) | ranks | seconds | ns per orbit-step | vs 1 rank | same bytes |"
echo "|---|---|---|---|---|---|"
awk -v s="$s1" 'BEGIN { printf "| 1 thread per rank | 1 | %.3f | %.1f | 1.00 | |\n", s, s * 1e9 / 2e7 }'
awk -v s="$s2" -v b="$s1" -v same="$same" \
    'BEGIN { printf "| 1 thread per rank | 2 | %.3f | %.1f | %.2f | %s |\n", s, s * 1e9 / 2e7, b / s, same }'
