#!/usr/bin/env bash
# run.sh — runs the libFuzzer harnesses of tests/fuzz/ for a bounded time each.
#
#   tests/fuzz/run.sh [--build] BUILD_DIR SECONDS [HARNESS...]
#
# BUILD_DIR is a build configured with -DCMAKE_C_COMPILER=clang -DVIGEN_FUZZ=ON
# and built with --target vigen_fuzz (README.md); with --build, run.sh
# configures and builds it first (the build's log is shown when it fails).
# Each harness (default: all
# of expr decimal spec tableau template) runs for SECONDS, from its seeds
# (corpus/NAME, and the repository's spec or tableau files; read only: new
# inputs go to a scratch directory) with its dictionary.  Exit status 1 when any harness reports a crash, a leak, a
# timeout, running out of memory or a sanitizer error; the reproducer is kept
# in BUILD_DIR/fuzz-artifacts/ and the log of the run is printed.
set -uo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
build_first=0
if [ "${1:-}" = --build ]; then
  build_first=1
  shift
fi
if [ $# -lt 2 ]; then
  echo "usage: tests/fuzz/run.sh [--build] BUILD_DIR SECONDS [HARNESS...]" >&2
  exit 2
fi
if [ $build_first = 1 ]; then
  cmake -S "$here/../.." -B "$1" -DCMAKE_C_COMPILER=clang -DCMAKE_BUILD_TYPE=RelWithDebInfo -DVIGEN_FUZZ=ON \
        -DBUILD_TESTING=OFF -DVIGEN_BUILD_EXAMPLES=OFF >/dev/null || exit 1
  if ! cmake --build "$1" -j"$(nproc)" --target vigen_fuzz >"$1/fuzz-build.log" 2>&1; then
    cat "$1/fuzz-build.log" >&2
    echo "run.sh: the fuzz build failed (log: $1/fuzz-build.log)" >&2
    exit 1
  fi
fi
build="$(cd "$1" && pwd)"
seconds="$2"
shift 2
harnesses=("$@")
[ ${#harnesses[@]} -gt 0 ] || harnesses=(expr decimal spec tableau template)

artifacts="$build/fuzz-artifacts"
mkdir -p "$artifacts"
scratch="$(mktemp -d)"
trap 'rm -rf "$scratch"' EXIT

export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0:allocator_may_return_null=0}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"

# Seeds: corpus/NAME (hand-made and extracted inputs) and, read in place, the
# repository's own files of that kind.
seeds() {
  local root="$here/../.."
  echo "$here/corpus/$1"
  case "$1" in
    spec) echo "$root/tableaux/specs" "$root/tests/data/bad_specs" "$root/tests/data/leok_zhang" ;;
    tableau) echo "$root/tableaux/published" "$root/tableaux/generated" "$root/tests/data/bad_tableaux" \
                  "$root/tests/data/check" "$root/tests/data/show" ;;
  esac
}

max_len() {
  case "$1" in
    expr) echo 256 ;;
    decimal) echo 128 ;;
    *) echo 4096 ;;
  esac
}

failed=0
for h in "${harnesses[@]}"; do
  exe="$build/tests/fuzz/fuzz_$h"
  if [ ! -x "$exe" ]; then
    echo "run.sh: $exe is missing; build it with: cmake --build $1 --target vigen_fuzz" >&2
    exit 2
  fi
  dict="$here/dict/$h.dict"
  [ -f "$dict" ] || dict="$here/dict/lua.dict"
  mkdir -p "$scratch/$h"
  log="$scratch/$h.log"
  start=$(date +%s)
  # a fixed seed (VIGEN_FUZZ_SEED, default 1) makes a run reproducible: CI
  # gives the same verdict on the same tree; long runs vary it
  "$exe" -seed="${VIGEN_FUZZ_SEED:-1}" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
         -max_len="$(max_len "$h")" \
         -dict="$dict" -artifact_prefix="$artifacts/$h-" -print_final_stats=1 \
         "$scratch/$h" $(seeds "$h") >"$log" 2>&1
  status=$?
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$')
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1)
  echo "fuzz $h: ${runs:-?} executions in $(( $(date +%s) - start )) s, ${cov:-cov: ?}, exit $status"
  if [ $status -ne 0 ]; then
    tail -n 60 "$log"
    echo "fuzz $h: FAILED (reproducer in $artifacts/; run $exe FILE to replay it)" >&2
    failed=1
  fi
done
exit $failed
