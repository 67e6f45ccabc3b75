#!/usr/bin/env bash
# run_emit.sh [BUILD [OUT]] — benchmarks of the emitted steppers.  Builds bench/emit_bench and bench/emit_icount against the vigen of
# the build directory BUILD (default build/) into OUT (default
# /tmp/vigen-bench) with bench/emit_build.sh, then
#   1. runs emit_bench: wall time per step, gradient evaluations, energy
#      error, the gradient share measured by timing every callback, the ideal
#      sweep bound, and Kepler at equal accuracy against GSL's rk4imp;
#   2. runs emit_icount under valgrind --tool=callgrind: instructions per
#      step of the stepping loop (repeatable, unlike wall time on a shared
#      machine) and the instructions spent inside the gradient callbacks;
# and rewrites the block between the emit-figures markers in the "Emitted
# steppers" section of docs/benchmarks.md (the text around it is by hand).
# Takes a few minutes (rk4imp on the n = 1000 chain: one step ~ 10 s; set
# EMIT_BENCH_SKIP_FPUT_GSL=1 to skip it).  Not a test.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(dirname "$here")
build=${1:-$root/build}
out=${2:-/tmp/vigen-bench}
cmake --build "$build" --target vigen >/dev/null
bash "$here/emit_build.sh" "$build/vigen" "$out" >/dev/null
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# instructions collected while inside the functions matching $1
icount() { # pattern stepper problem steps
    valgrind --tool=callgrind --callgrind-out-file="$work/cg.out" "--toggle-collect=$1" \
        "$out/emit_icount" "$2" "$3" "$4" >/dev/null 2>"$work/vg.log" || { cat "$work/vg.log" >&2; exit 1; }
    awk '/^(summary|totals):/ { print $2; exit }' "$work/cg.out"
}
declare -A I G
steps_for() { # stepper problem
    case "$1:$2" in
        *g2*:kepler) echo 20001 ;; *g2*:fput) echo 201 ;; *:kepler) echo 100001 ;; *) echo 2001 ;;
    esac
}
rows="emit_sv_cb hand_sv_cb emit_sv_direct hand_sv_direct emit_sv_cb_nokahan hand_sv_cb_nokahan emit_g2_cb hand_g2_cb emit_g2_direct hand_g2_direct"
for s in $rows; do
    for pr in kepler fput; do
        n=$(steps_for "$s" "$pr")
        I[$s:$pr]=$(awk -v a="$(icount 'stepping_loop_*' "$s" "$pr" "$n")" -v n="$n" 'BEGIN { printf "%.0f", a / (n - 1) }')
        if [[ $s == *_cb* ]]; then
            G[$s:$pr]=$(awk -v a="$(icount 'grad_cb_*' "$s" "$pr" "$n")" -v n="$n" 'BEGIN { printf "%.0f", a / (n - 1) }')
        fi
    done
done
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.3f", a / b }'; }
share() { if [ -n "${2:-}" ]; then awk -v g="$2" -v a="$1" 'BEGIN { printf "%.2f", g / a }'; else echo "-"; fi; }

{
    echo "<!-- emit-figures:begin (written by bench/run_emit.sh) -->"
    echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), shared with other jobs; $(date -u +%Y-%m-%d); gcc -O2."
    echo
    echo "#### Wall time (bench/emit_bench)"
    "$out/emit_bench" 1000000 2000 | sed 's/^### /##### /'
    echo
    echo "#### Instructions per step (bench/emit_icount under callgrind)"
    echo
    echo "Instructions of the stepping loop divided by the steps (the first step, with its"
    echo "start-up work, runs outside the loop), and the share of them executed inside the"
    echo "gradient callbacks (the \"cb\" rows call the gradients out of line; \"direct\" rows"
    echo "let the compiler inline them)."
    echo
    echo "| stepper | Kepler instr/step | Kepler grad share | FPUT n = 1000 instr/step | FPUT grad share |"
    echo "|---|--:|--:|--:|--:|"
    for s in $rows; do
        echo "| $s | ${I[$s:kepler]} | $(share "${I[$s:kepler]}" "${G[$s:kepler]:-}") | ${I[$s:fput]} | $(share "${I[$s:fput]}" "${G[$s:fput]:-}") |"
    done
    echo
    echo "| emitted / hand-written instructions | Kepler | FPUT n = 1000 |"
    echo "|---|--:|--:|"
    echo "| Verlet, callbacks (Kahan, the default) | $(ratio "${I[emit_sv_cb:kepler]}" "${I[hand_sv_cb:kepler]}") | $(ratio "${I[emit_sv_cb:fput]}" "${I[hand_sv_cb:fput]}") |"
    echo "| Verlet, direct | $(ratio "${I[emit_sv_direct:kepler]}" "${I[hand_sv_direct:kepler]}") | $(ratio "${I[emit_sv_direct:fput]}" "${I[hand_sv_direct:fput]}") |"
    echo "| Verlet, callbacks, no Kahan | $(ratio "${I[emit_sv_cb_nokahan:kepler]}" "${I[hand_sv_cb_nokahan:kepler]}") | $(ratio "${I[emit_sv_cb_nokahan:fput]}" "${I[hand_sv_cb_nokahan:fput]}") |"
    echo "| Gauss-2, callbacks | $(ratio "${I[emit_g2_cb:kepler]}" "${I[hand_g2_cb:kepler]}") | $(ratio "${I[emit_g2_cb:fput]}" "${I[hand_g2_cb:fput]}") |"
    echo "| Gauss-2, direct | $(ratio "${I[emit_g2_direct:kepler]}" "${I[hand_g2_direct:kepler]}") | $(ratio "${I[emit_g2_direct:fput]}" "${I[hand_g2_direct:fput]}") |"
    echo "<!-- emit-figures:end -->"
} >"$work/figures.md"

doc=$root/docs/benchmarks.md
python3 - "$doc" "$work/figures.md" <<'PY'
import re, sys
doc, fig = sys.argv[1], open(sys.argv[2]).read()
text = open(doc).read()
pat = re.compile(r"<!-- emit-figures:begin.*?<!-- emit-figures:end -->\n?", re.S)
if not pat.search(text):
    sys.exit("docs/benchmarks.md has no emit-figures block (inside the emit section)")
open(doc, "w").write(pat.sub(lambda m: fig, text))
PY
cat "$work/figures.md"
