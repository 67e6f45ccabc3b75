#!/usr/bin/env bash
# cli_generate_errors.sh VIGEN SRCDIR — every bad-input path of `vigen generate`:
# a clear message naming the file (and the entry or line), a non-zero exit
# status, and no output file (not even a stray temporary one).
set -u
vigen=$1
src=$2
bad=$src/tests/data/bad_specs
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

# expect NAME STATUS PHRASE...: generate bad_specs/NAME.lua and check
expect() {
  local name=$1 status=$2
  shift 2
  local out=$work/$name.lua
  "$vigen" generate "$bad/$name.lua" -o "$out" >"$work/stdout" 2>"$work/stderr"
  local got=$?
  if [ "$got" != "$status" ]; then
    echo "FAIL $name: exit status $got, expected $status"; cat "$work/stderr"; failures=$((failures + 1)); return
  fi
  if [ "$status" != 0 ] && [ -n "$(ls "$work" | grep -v -e '^stdout$' -e '^stderr$')" ]; then
    echo "FAIL $name: output left behind: $(ls "$work")"; failures=$((failures + 1))
  fi
  if ! grep -q "$name.lua" "$work/stderr"; then
    echo "FAIL $name: the message does not name the file"; cat "$work/stderr"; failures=$((failures + 1))
  fi
  for phrase in "$@"; do
    if ! grep -qi -- "$phrase" "$work/stderr"; then
      echo "FAIL $name: message lacks '$phrase'"; cat "$work/stderr"; failures=$((failures + 1))
    fi
  done
  rm -f "$work"/*.lua
}

expect false_order         2 "claims order 5" "has order 4" "b\[b,b,b,b\]"
expect bad_order_claim     2 "'order' (a claim"
expect singular_m          2 "singular" "psi_2" "sin(pi\*t)"
expect zero_weight         2 "b_2 = 0" "divides by b_i"
expect count_mismatch      2 "basis has 2 functions but nodes has 1"
expect repeated_nodes      2 "nodes\[1\] and nodes\[2\] are equal"
expect repeated_irrational 3 "nodes\[1\] and nodes\[2\] cannot be told apart"
expect complex_value       2 "basis\[2\]"
expect not_finite          2 "basis\[2\]"
expect unknown_family      2 "gauss_legndre" "gauss_legendre"
expect syntax_error        2 "syntax_error.lua:4"
expect runtime_error       2 "runtime_error.lua:2" "fails on purpose"
expect float_node          2 "nodes\[2\]" "1/3"
expect float_in_function   2 "exact(\"1/3\")"
expect float_short         2 "exact(\"0.5\")"
expect endless_loop        3 "instructions"
expect memory_bomb         3 "memory"
expect escape_io           2 "escape_io.lua:1"
expect escape_os           2 "escape_os.lua:1"
expect chebyshev8          2 "complex"
expect log_singular        2 "singularity"
expect branch_point        2 "branch point"
expect rep_hang            3 "memory"
expect bad_expression      2 "cosh" "column"
[ -e /tmp/vigen-escape ] && { echo "FAIL: a spec escaped the sandbox"; failures=$((failures + 1)); }

# warnings: the tableau is written, the warning names the problem
expect no_constants        0 "sum of b" "not consistent"
expect node_outside        0 "outside \[0, 1\]"
expect row_sum_defect      0 "row 1 of A sums to" "not in the span"

# usage errors
"$vigen" generate >/dev/null 2>&1; [ $? = 2 ] || { echo "FAIL: no spec should be a usage error"; failures=$((failures + 1)); }
"$vigen" generate "$bad/../../../tableaux/specs/leok_zhang_ex4.lua" --digits 0 >/dev/null 2>&1
[ $? = 2 ] || { echo "FAIL: --digits 0 should be a usage error"; failures=$((failures + 1)); }
"$vigen" generate "$work/missing.lua" >/dev/null 2>"$work/stderr"
[ $? = 2 ] && grep -q "missing.lua" "$work/stderr" || { echo "FAIL: a missing file should be named, exit 2"; failures=$((failures + 1)); }

# the sandbox caps can be set on the command line
"$vigen" generate "$bad/endless_loop.lua" --max-instructions 12345 -o "$work/capped.lua" 2>"$work/stderr"
[ $? = 3 ] && grep -q "more than 12345 Lua instructions" "$work/stderr" && [ ! -e "$work/capped.lua" ] ||
  { echo "FAIL: --max-instructions 12345 should be the cap"; cat "$work/stderr"; failures=$((failures + 1)); }
"$vigen" generate "$bad/slow_basis.lua" --max-instructions 100000 -o "$work/slow.lua" 2>"$work/stderr"
[ $? = 3 ] && grep -q "2000000 instructions in all" "$work/stderr" && [ ! -e "$work/slow.lua" ] ||
  { echo "FAIL: the total instruction budget should stop slow_basis"; cat "$work/stderr"; failures=$((failures + 1)); }
"$vigen" --max-memory 1024 generate "$src/tableaux/specs/exponential_lua.lua" -q -o "$work/ok.lua" 2>"$work/stderr" ||
  { echo "FAIL: --max-memory 1024 should be accepted"; cat "$work/stderr"; failures=$((failures + 1)); }
"$vigen" generate "$src/tableaux/specs/exponential_lua.lua" --max-memory -3 >/dev/null 2>&1
[ $? = 2 ] || { echo "FAIL: --max-memory -3 should be a usage error"; failures=$((failures + 1)); }
rm -f "$work"/*.lua

if [ $failures -gt 0 ]; then echo "$failures failure(s)"; exit 1; fi
echo ok
