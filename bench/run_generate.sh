#!/usr/bin/env bash
# run_generate.sh [BUILD [OLD_BUILD]] — benchmark of `vigen generate`:
# in-process time of the generation and the certification of the order and
# symplecticity (median of repeated runs) for Lagrange at Gauss-Legendre
# nodes, s in {2,4,8,16,32} x digits in {16,100,1000,2000}, and trig(s) at
# Gauss-Legendre nodes, s in {3,5,10}, with the mpmath peer (same tableau,
# uncertified) in the same run.  OLD_BUILD: a build of another revision
# (with this revision's bench/bench_generate.c, so that it certifies too)
# timed beside it, row by row.  Rewrites the "Generator" section of
# docs/benchmarks.md (OLD_LABEL names the old build there).  Not a test:
# timings on a shared machine vary.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$here")
build=${1:-$root/build}
old=${2:-}
cmake --build "$build" --target bench_generate >/dev/null
bench=$build/bench/bench_generate
[ -z "$old" ] || cmake --build "$old" --target bench_generate >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
have_mpmath=0
python3 -c "import mpmath" 2>/dev/null && have_mpmath=1

row() { # kind s digits
  local kind=$1 s=$2 d=$3 spec=$work/$1_$2.lua
  if [ "$kind" = lagrange ]; then
    printf 'return { name = "gauss%s", basis = "lagrange", nodes = gauss_legendre(%s) }\n' "$s" "$s" >"$spec"
  elif [ "$kind" = trig-strings ]; then
    # the same trig(s) basis written as expression strings: vigen finds their
    # exact antiderivatives itself (src/core/expr_integrate.c), not the family's code path
    python3 - "$s" >"$spec" <<'PY'
import sys
s = int(sys.argv[1])
fs = ['"1"'] + [('"cos(%d*pi*t)"' if i % 2 else '"sin(%d*pi*t)"') % ((i + 1) // 2) for i in range(1, s)]
print('return { name = "trigstr", basis = { %s }, nodes = gauss_legendre(%d) }' % (", ".join(fs), s))
PY
  else
    printf 'return { name = "trig%s", basis = trig(%s), nodes = gauss_legendre(%s) }\n' "$s" "$s" "$s" >"$spec"
  fi
  local v m="n/a" ratio="n/a" p o="" out
  out=$("$bench" "$spec" "$d")
  v=$(echo "$out" | cut -d' ' -f1)
  p=$(echo "$out" | cut -d' ' -f3)
  if [ -n "$old" ]; then
    out=$("$old/bench/bench_generate" "$spec" "$d")
    o=$(printf '%.4f | %s | ' "$(echo "$out" | cut -d' ' -f1)" "$(python3 -c "print('%.1f' % ($(echo "$out" | cut -d' ' -f1) / $v))")")
    [ "$(echo "$out" | cut -d' ' -f3)" = "$p" ] || p="$p (old: $(echo "$out" | cut -d' ' -f3))"
  fi
  if [ $have_mpmath = 1 ]; then
    m=$(python3 "$here/generate_mpmath.py" "$s" "$d" $([ "$kind" != lagrange ] && echo trig) | cut -d' ' -f1)
    ratio=$(python3 -c "print('%.2f' % ($v / $m))")
    m=$(python3 -c "print('%.4f' % $m)")
  fi
  printf '| %s | %s | %s | %s | %.4f | %s%s | %s |\n' "$kind" "$s" "$d" "$p" "$v" "$o" "$m" "$ratio"
}

{
  echo "<!-- generator:begin (written by bench/run_generate.sh) -->"
  echo "## Generator: \`vigen generate\`"
  echo
  echo "Median wall time in-process of what \`vigen generate\` computes: the tableau"
  echo "(\`vigen_galerkin_generate\`, every digit certified) and the certification of its"
  echo "order and symplecticity (\`vigen_check_certify\`, whose order the column 'order'"
  echo "gives: the file's \`order = p\`, -1 when undecided), against the mpmath peer"
  echo "\`bench/generate_mpmath.py\` computing the same tableau at \`mp.dps = digits + 10\`"
  echo "without any certification, in the same run$([ -n "$old" ] && echo ", beside the build ${OLD_LABEL:-$old} ('old')")."
  echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'); load average"
  echo "$(cut -d' ' -f1-3 /proc/loadavg) at the start (the machine is shared: figures vary by about 20-50% between runs,"
  echo "the ratios in one row less, as both sides run within seconds of each other); $(date -u +%Y-%m-%d)."
  echo
  if [ -n "$old" ]; then
    echo "| basis | s | digits | order | vigen (s) | old (s) | old / vigen | mpmath (s) | vigen / mpmath |"
    echo "|---|---|---|---|---|---|---|---|---|"
  else
    echo "| basis | s | digits | order | vigen (s) | mpmath (s) | vigen / mpmath |"
    echo "|---|---|---|---|---|---|---|"
  fi
  for s in 2 4 8 16 32; do for d in 16 100 1000 2000; do row lagrange $s $d; done; done
  row lagrange 10 1000
  for s in 3 5 10; do for d in 16 100 1000 2000; do row trig $s $d; done; done
  for d in 16 100 1000; do row trig-strings 10 $d; done
  echo
  echo "\`trig\` is the family \`trig(s)\` (closed-form antiderivatives); \`trig-strings\` is the same"
  echo "basis written as expression strings (cos(2*pi*t), ...), whose exact antiderivatives vigen"
  echo "finds itself (with acb_calc_integrate instead, trig(10) at 1000 digits took 1.24 s)."
  echo "The order is certified by Butcher's theorem on the generator's balls where it"
  echo "decides (B(p), C, D and a failing bushy tree of order p + 1, at the precision of the"
  echo "digits up to 1024 bits: src/check/certify_theorem.c), by"
  echo "the walk over every tree to order 8 otherwise."
  echo "Where the time goes (callgrind, \`vigen generate\` of Gauss s = 10 at 1000 digits, the"
  echo "whole process, measured once on 2026-11-28): with the tree walk 26.7e9 instructions,"
  echo "96.6% in \`chk_orders\` (every tree to order 8 on the 1000-digit decimals at 3,426"
  echo "bits) and 90.3% in its mean-value enclosure \`chk_tree_enclose\`; with the theorem"
  echo "0.086e9: the generation 0.044e9, the file's text 0.011e9, the certification 0.018e9."
  echo "Rows where the old and the new order differ say so ('32 (old: -1)')."
  echo "Targets: Gauss s = 10 at 1000 digits, certification included, under 0.1 times"
  echo "mpmath; no generated tableau slower than before; trig(10) at 1000 digits under 1 s."
  echo "<!-- generator:end -->"
} >"$work/section.md"

doc=$root/docs/benchmarks.md
[ -f "$doc" ] || printf '# Benchmarks\n\nEvery figure here is written by a script in bench/; rerun it to refresh.\n\n' >"$doc"
python3 - "$doc" "$work/section.md" <<'PY'
import re, sys
doc, sec = sys.argv[1], open(sys.argv[2]).read()
text = open(doc).read()
pat = re.compile(r"<!-- generator:begin.*?<!-- generator:end -->\n?", re.S)
text = pat.sub(lambda m: sec, text) if pat.search(text) else text.rstrip("\n") + "\n\n" + sec
open(doc, "w").write(text)
PY
cat "$work/section.md"
