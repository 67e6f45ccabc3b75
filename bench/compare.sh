#!/usr/bin/env bash
# compare.sh BASE_BUILD NEW_BUILD [ROUNDS] — the generator, checker and
# command-line benchmarks of two builds side by side, in the same run.
#
# For a change to a hot path: build the baseline commit in a second worktree
# (git worktree add /tmp/base COMMIT; cmake -S /tmp/base -B /tmp/base/build
# -DCMAKE_BUILD_TYPE=Release; cmake --build /tmp/base/build), then run
#   bench/compare.sh /tmp/base/build build
# Each case runs ROUNDS times (default 5) for each build, alternating A B A B
# so that a change in the machine's load hits both alike; the table gives the
# median of each and the ratio new / base (below 1: the new build is faster)
# with the spread of the per-round ratios.  Not a test.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$here")
base=${1:?usage: compare.sh BASE_BUILD NEW_BUILD [ROUNDS]}
new=${2:?usage: compare.sh BASE_BUILD NEW_BUILD [ROUNDS]}
rounds=${3:-5}
for b in "$base" "$new"; do cmake --build "$b" --target bench_generate bench_check vigen >/dev/null; done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

printf 'return { name = "gauss8", basis = "lagrange", nodes = gauss_legendre(8) }\n' >"$work/lagrange8.lua"
printf 'return { name = "gauss32", basis = "lagrange", nodes = gauss_legendre(32) }\n' >"$work/lagrange32.lua"
printf 'return { name = "trig10", basis = trig(10), nodes = gauss_legendre(10) }\n' >"$work/trig10.lua"
python3 - >"$work/trigstr10.lua" <<'PY'
fs = ['"1"'] + [('"cos(%d*pi*t)"' if i % 2 else '"sin(%d*pi*t)"') % ((i + 1) // 2) for i in range(1, 10)]
print('return { name = "trigstr", basis = { %s }, nodes = gauss_legendre(10) }' % ", ".join(fs))
PY

# wall time of a command, in seconds (median of 5 runs)
wall() {
  python3 - "$@" <<'PY'
import subprocess, sys, time
ts = []
for _ in range(5):
    t0 = time.perf_counter()
    subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    ts.append(time.perf_counter() - t0)
print(sorted(ts)[2])
PY
}

# one measurement of case $1 with build $2, in seconds
measure() {
  local b=$2
  case $1 in
    gen-lagrange8-1000) "$b/bench/bench_generate" "$work/lagrange8.lua" 1000 | cut -d' ' -f1 ;;
    gen-lagrange32-100) "$b/bench/bench_generate" "$work/lagrange32.lua" 100 | cut -d' ' -f1 ;;
    gen-trig10-1000) "$b/bench/bench_generate" "$work/trig10.lua" 1000 | cut -d' ' -f1 ;;
    gen-trigstrings10-1000) "$b/bench/bench_generate" "$work/trigstr10.lua" 1000 | cut -d' ' -f1 ;;
    check-gauss8-P8) "$b/bench/bench_check" "$root/tableaux/generated/gauss_legendre_s8.lua" 8 | cut -d' ' -f1 ;;
    check-gauss5-P10) "$b/bench/bench_check" "$root/tableaux/generated/gauss_legendre_s5.lua" 10 | cut -d' ' -f1 ;;
    check-lobatto4exact-P8) "$b/bench/bench_check" "$root/tableaux/published/lobatto_iiia_iiib_4.lua" 8 | cut -d' ' -f1 ;;
    cli-generate-ex4) wall "$b/vigen" generate "$root/tableaux/specs/leok_zhang_ex4.lua" -q ;;
    cli-check-yoshida6) wall "$b/vigen" check "$root/tableaux/published/yoshida_6.lua" ;;
    cli-show-gauss3-latex) wall "$b/vigen" show "$root/tableaux/published/gauss_3.lua" --format latex ;;
    cli-emit-gauss2) wall "$b/vigen" emit "$root/tests/data/emit/gauss2.lua" --name g2 -o "$work/out" -q ;;
    cli-emit-spec-float128) wall "$b/vigen" emit "$root/tableaux/specs/gauss_legendre_s3.lua" --name g3 --real float128 -o "$work/out" -q ;;
  esac
}

cases="gen-lagrange8-1000 gen-lagrange32-100 gen-trig10-1000 gen-trigstrings10-1000 check-gauss8-P8 check-gauss5-P10
check-lobatto4exact-P8 cli-generate-ex4 cli-check-yoshida6 cli-show-gauss3-latex cli-emit-gauss2 cli-emit-spec-float128"

echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); $(date -u +%Y-%m-%d)."
echo "Base: $base ($(git -C "$base/.." rev-parse --short HEAD 2>/dev/null || echo '?')); new: $new ($(git -C "$root" rev-parse --short HEAD)); $rounds rounds."
echo
echo "| case | base (s) | new (s) | new / base | per-round range |"
echo "|---|---|---|---|---|"
for c in $cases; do
  a=(); n=()
  for _ in $(seq "$rounds"); do
    a+=("$(measure "$c" "$base")")
    n+=("$(measure "$c" "$new")")
  done
  python3 - "$c" "${a[*]}" "${n[*]}" <<'PY'
import statistics, sys
c, a, n = sys.argv[1], [float(x) for x in sys.argv[2].split()], [float(x) for x in sys.argv[3].split()]
r = [y / x for x, y in zip(a, n)]
print("| %s | %.4f | %.4f | %.2f | %.2f-%.2f |" % (c, statistics.median(a), statistics.median(n),
      statistics.median(n) / statistics.median(a), min(r), max(r)))
PY
done
