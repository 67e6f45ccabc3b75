#!/usr/bin/env bash
# cli_check.sh VIGEN SRCDIR — `vigen check` from the command line: exit
# status (0 consistent and claims hold, 1 something fails, 2 unreadable input
# or usage), the JSON object, the typo diagnosis, --against, --max-order.
set -u
vigen=$1
src=$2
data=$src/tests/data/check
pub=$src/tableaux/published
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

fail() { echo "FAIL $*"; failures=$((failures + 1)); }

# run STATUS ARGS...: runs vigen check ARGS, expects STATUS
run() {
  local status=$1
  shift
  "$vigen" check "$@" >"$work/stdout" 2>"$work/stderr"
  local got=$?
  if [ "$got" != "$status" ]; then
    fail "vigen check $*: exit status $got, expected $status"
    cat "$work/stdout" "$work/stderr"
  fi
}

# json EXPR: a Python expression on d (the JSON object of the last run) must be true
json() {
  if ! python3 -c "import json,sys; d=json.load(open(sys.argv[1])); sys.exit(0 if ($1) else 1)" "$work/stdout"; then
    fail "JSON check ($1) on: $(head -c 2000 "$work/stdout")"
  fi
}

grep_out() {
  if ! grep -q -- "$1" "$work/stdout"; then fail "output lacks '$1'"; cat "$work/stdout"; fi
}

# published methods of known order
run 0 "$pub/gauss_3.lua" --json
json "d['order'] == 6 and d['symplectic'] is True and d['consistent'] is True and d['problems'] == []"
run 0 "$pub/lobatto_iiia_iiib_3.lua" --json
json "d['order'] == 4 and d['order_separable'] == 4 and d['symplectic'] is True"
run 0 "$data/rk4.lua" --json
json "d['order'] == 4 and d['symplectic'] is False and d['order_A'] == 4"

# a 40-digit Gauss-3 and a copy with a 1e-30 perturbation of A[2][3]
run 0 "$data/gauss3_40.lua" --against "$pub/gauss_3.lua"
grep_out "0 entries differ"
run 1 "$data/gauss3_40_perturbed.lua" --json
json "any(p['kind'] == 'rowsum' and p['matrix'] == 'A' and p['row'] == 2 and p['col'] == 3 and p.get('diagnosed') for p in d['problems'])"
json "any(p['kind'] == 'symplectic' and p['matrix'] == 'A' and p['row'] == 2 and p['col'] == 3 for p in d['problems'])"
json "any(p['kind'] == 'claim' and p.get('claim') == 'order' for p in d['problems'])"
json "d['consistent'] is False and d['symplectic'] is False and 'order_separable' in d"
run 1 "$data/gauss3_40_perturbed.lua"
grep_out "A\[2\]\[3\] = "
grep_out "both ask for"
run 1 "$data/gauss3_40_perturbed.lua" --against "$data/gauss3_40.lua" --json
json "[(p['matrix'], p['row'], p['col']) for p in d['problems'] if p['kind'] == 'against'] == [('A', 2, 3)]"

# claims
run 1 "$data/rk4_claimed_symplectic.lua" --json
json "d['claims']['symplectic']['holds'] is False and d['claims']['order']['holds'] is True"

# undecided: 6 digits cannot certify anything to 2^-30
run 1 "$data/gauss2_6digits.lua" --json
json "d['consistent'] is None and d['order_status'] == 'undecided'"
run 1 "$data/gauss2_6digits.lua"
grep_out "undecided at this precision"

# --max-order 10 works
run 0 "$pub/gauss_3.lua" --max-order 10 --json
json "d['max_order'] == 10 and d['order'] == 6"

# unreadable input and usage errors: status 2
run 2 "$data/syntax_error.lua"
run 2 "$work/does_not_exist.lua"
run 2
run 2 "$pub/gauss_3.lua" --max-order 0
run 2 "$pub/gauss_3.lua" --max-order 99
run 2 "$pub/gauss_3.lua" --bogus
run 2 "$pub/gauss_3.lua" --against "$work/does_not_exist.lua"

if [ "$failures" -gt 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo ok
