#!/bin/bash
# cli_mpi_ensemble.sh VIGEN SRC — examples/mpi-ensemble as a user builds it:
# install this build of vigen into a temporary prefix, configure the example
# against it (find_package(vigen), find_package(MPI)), build, and run it
# with mpirun.  Checked:
#   - the output is the same, byte for byte, for 1, 2 and 3 ranks and for 1
#     and 2 OpenMP threads per rank (the ensemble's results do not depend on
#     how the orbits are shared out; 3 ranks over 5 orbits give blocks of
#     unequal sizes);
#   - every orbit is printed once, in order, and the orbit started at NaN is
#     the only one reported failed (VIGEN_ENONFINITE, 0 steps) while the
#     others take every step;
#   - the orbits are right (Kepler's problem in closed form: period 2 pi,
#     energy -1/2): after one period each is back at its start to the
#     method's error, which shrinks like h^4 (Gauss s = 2 is of order 4)
#     when the steps per period double (400 to 800, where the
#     largest eccentricity 0.79 is resolved);
#   - a bad argument: one line naming it, exit status 2.
# Skipped (exit status 77, which ctest reports as skipped) only when no MPI
# is installed: mpicc and mpirun from Open MPI (Debian: libopenmpi-dev
# openmpi-bin).
set -u
VIGEN=$1
SRC=$2
if ! command -v mpirun >/dev/null || ! command -v mpicc >/dev/null; then
    echo "SKIP: no MPI (mpirun and mpicc not found; install libopenmpi-dev and openmpi-bin)"
    exit 77
fi
BUILD=$(cd "$(dirname "$VIGEN")" && pwd)
T=$(mktemp -d /tmp/vigen-cli-mpi-XXXXXX)
trap 'rm -rf "$T"' EXIT
unset VIGEN_TEMPLATE_DIR
fail=0
check() { if ! eval "$1"; then echo "FAIL: $2"; fail=1; fi; }
die() { echo "FAIL: $1"; [ -f "$T/log" ] && tail -30 "$T/log"; exit 1; }

[ -f "$BUILD/CMakeCache.txt" ] || die "no CMakeCache.txt next to $VIGEN"
cmake --install "$BUILD" --prefix "$T/prefix" >"$T/log" 2>&1 || die "cmake --install"
cp -r "$SRC/examples/mpi-ensemble" "$T/src"
cmake -S "$T/src" -B "$T/build" -DCMAKE_PREFIX_PATH="$T/prefix" -DCMAKE_BUILD_TYPE=Release \
    >"$T/log" 2>&1 || die "configure examples/mpi-ensemble against the installed vigen"
cmake --build "$T/build" -j2 >"$T/log" 2>&1 || die "build examples/mpi-ensemble"
EXE=$T/build/mpi_ensemble

# Open MPI refuses root without these; --oversubscribe: more ranks than cores
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# In a sanitized build the example is instrumented too (the exported targets
# carry -fsanitize); the leak checker would report the allocations Open MPI
# keeps until exit, so it is off for these runs (every other check stays on).
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
mpi() { # OUT THREADS RANKS ARGS...
    local out=$1 threads=$2 ranks=$3
    shift 3
    OMP_NUM_THREADS=$threads mpirun --oversubscribe --bind-to none -np "$ranks" "$EXE" "$@" >"$out" 2>"$T/err" \
        || { cat "$T/err"; die "mpirun -np $ranks mpi_ensemble $* (OMP_NUM_THREADS=$threads)"; }
}

N=61
FAIL=17
mpi "$T/r1t1" 1 1 $N 200 1 $FAIL
mpi "$T/r2t1" 1 2 $N 200 1 $FAIL
mpi "$T/r1t2" 2 1 $N 200 1 $FAIL
mpi "$T/r2t2" 2 2 $N 200 1 $FAIL
for o in r2t1 r1t2 r2t2; do
    check 'cmp -s "$T/r1t1" "$T/$o"' "output of $o differs from 1 rank, 1 thread"
done
mpi "$T/s1" 1 1 5 50
mpi "$T/s3" 1 3 5 50
check 'cmp -s "$T/s1" "$T/s3"' "5 orbits: 3 ranks differ from 1"
check '[ "$(grep -c "^orbit " "$T/s3")" = 5 ]' "5 orbits: 5 orbit lines with 3 ranks"

check '[ "$(grep -c "^orbit " "$T/r1t1")" = $N ]' "$N orbit lines"
check '[ "$(awk "/^orbit / { printf \"%s \", \$2 }" "$T/r1t1")" = "$(seq -s " " 0 $((N - 1))) " ]' \
    "the orbits in order 0 .. $((N - 1))"
check 'awk -v f=$FAIL "/^orbit / && \$2 == f { exit !(\$4 == 6 && \$5 == 0) }" "$T/r1t1"' \
    "orbit $FAIL (NaN start) reported with status 6 (VIGEN_ENONFINITE) after 0 steps"
check 'awk -v f=$FAIL "/^orbit / && \$2 != f && (\$4 != 0 || \$5 != 200) { bad = 1 } END { exit bad }" "$T/r1t1"' \
    "every other orbit takes its 200 steps with status 0"
check 'grep -qx "failed 1" "$T/r1t1"' "one orbit failed"

value() { awk -v k="$1" '$1 == k { print $2 }' "$2"; }
mpi "$T/h400" 1 2 $N 400 1 $FAIL
mpi "$T/h800" 1 2 $N 800 1 $FAIL
d200=$(value max-distance-to-start "$T/r1t1")
d400=$(value max-distance-to-start "$T/h400")
d800=$(value max-distance-to-start "$T/h800")
e200=$(value max-energy-error "$T/r1t1")
check 'awk -v a="$d400" -v b="$d800" "BEGIN { r = a / b; exit !(b > 0 && r > 13 && r < 19) }"' \
    "distance to the start after one period: 400 / 800 steps per period = $d400 / $d800, about 2^4"
check 'awk -v a="$d200" -v e="$e200" "BEGIN { exit !(a < 3e-3 && e < 1e-6) }"' \
    "one period, 200 steps, e <= 0.8: distance $d200 < 3e-3, energy error $e200 < 1e-6"

# a bad argument: one line naming it, exit status 2, nothing on stdout
OMP_NUM_THREADS=1 mpirun --oversubscribe -np 1 "$EXE" 0 >"$T/bad" 2>"$T/err"
rc=$?
check '[ $rc = 2 ] && grep -q "ORBITS must be an integer from 1" "$T/err" && [ ! -s "$T/bad" ]' \
    "ORBITS 0: exit status $rc, message: $(cat "$T/err")"
exit $fail
