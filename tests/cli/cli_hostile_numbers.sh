#!/usr/bin/env bash
# cli_hostile_numbers.sh VIGEN SRCDIR — numbers and sizes from hostile files and
# options: absurd decimal exponents, 100,000 nodes, literals and options that
# ask for huge precision, a zero with a tiny radius.  Each ends quickly (under
# `timeout`) with a clean status (2: input out of range, 3: a cap reached; 0
# where the input is fine), one line naming the file or option and what to do,
# no core dump and no output file.
set -u
vigen=$1
src=$2
specs=$src/tests/data/bad_specs
tabs=$src/tests/data/bad_tableaux
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
limit=60
lines=1   # lines of a failure's message (a usage error adds "see 'vigen help ...'")

fail() { echo "FAIL $*"; failures=$((failures + 1)); }

# two tableau files that are not bad for every command (tests/data/bad_tableaux
# must be refused by show, check and emit alike): written here
cat >"$work/hostile_num_zero_format.lua" <<'LUA'
-- An entry equal to 0 whose ball is tiny (radius ~2^-4000000000): formatting
-- it as "0eK" used to raise K one by one at ever higher precision and run out
-- of memory.  vigen writes it as 0e-34 (certified) at once.
return { name = "hostile_num_zero_format", s = 1, c = { "1/2" }, A = { { "sin(pi) * 2^-4000000000" } },
         b = { "1" }, ct = { "1/2" }, At = { { "1/2" } } }
LUA
cat >"$work/hostile_num_power.lua" <<'LUA'
-- A literal whose digits imply a precision of 33 million bits: the check used
-- to run there for minutes with gigabytes.  vigen stops at the precision cap
-- (exit 3, --max-prec).
return { name = "hostile_num_power", s = 1, c = { "1/2" }, A = { { "1/2 + 3^-100000000" } },
         b = { "1" }, ct = { "1/2" }, At = { { "1/2" } } }
LUA

cat >"$work/hostile_num_huge_weight.lua" <<'LUA'
-- A basis function t^(10^19): the weight b[1] is about 10^(5 10^17), beyond
-- every decimal vigen writes.  The refinement loop used to double the
-- precision up to its cap (10 s in the fuzz harness) before giving up with a
-- message about ties; vigen now says at once that no decimal can carry it.
return { name = "hostile_num_huge_weight", nodes = gauss_legendre(3),
         basis = { "-t", "t^10134836310148149702", "155555555555555555555555555555555" } }
LUA

cat >"$work/hostile_num_monomial.lua" <<'LUA'
-- A basis function t^101349702 (found by the spec fuzz harness): its integrals
-- are below 2^-10^7, so quadrature to an absolute tolerance lost them and the
-- refinement loop doubled the precision up to its cap (10 s) before giving up
-- with a message about ties.  Its integral is now the closed form
-- c^(k+1)/(k+1) and the refinement is cheap; the method's ct still cancels
-- terms of about 10^(5 10^6), which no precision under the cap certifies.
return { name = "hostile_num_monomial", nodes = gauss_legendre(3),
         basis = { "-t", "t^101349702", "15555.5555555555555555555555555555555555555" } }
LUA

# run LABEL STATUS COMMAND-ARGS... -- PHRASE...: runs vigen with the arguments
# in an empty directory $work/out (the output directory of -o), expecting the
# exit status, the phrases in the standard error (status != 0) or output
# (status 0), a one-line message and nothing left in $work/out when it fails.
run() {
  local label=$1 status=$2
  shift 2
  local args=()
  while [ $# -gt 0 ] && [ "$1" != "--" ]; do args+=("$1"); shift; done
  [ $# -gt 0 ] && shift
  rm -rf "$work/out"; mkdir "$work/out"
  (cd "$work/out" && ulimit -c 0 && timeout "$limit" "$vigen" "${args[@]}") >"$work/stdout" 2>"$work/stderr"
  local got=$?
  if [ "$got" = 124 ]; then fail "$label: still running after ${limit}s"; return; fi
  if [ "$got" -ge 128 ]; then fail "$label: killed by signal $((got - 128))"; cat "$work/stderr"; return; fi
  if [ "$got" != "$status" ]; then
    fail "$label: exit status $got, expected $status"; head -c 2000 "$work/stderr"; return
  fi
  local text=$work/stdout
  if [ "$status" != 0 ]; then
    text=$work/stderr
    [ "$(wc -l <"$work/stderr")" = "$lines" ] || { fail "$label: the message is not $lines line(s)"; cat "$work/stderr"; }
    [ -z "$(ls -A "$work/out")" ] || fail "$label: output left behind: $(ls -A "$work/out")"
    grep -q -- "^vigen" "$work/stderr" || { fail "$label: the message does not start with vigen"; cat "$work/stderr"; }
  fi
  for phrase in "$@"; do
    grep -qF -- "$phrase" "$text" || { fail "$label: lacks '$phrase'"; head -c 2000 "$text"; }
  done
}

# a decimal exponent beyond every machine integer (FLINT aborted)
run exponent-node 2 generate "$specs/hostile_num_exponent.lua" -o out.lua -- \
  "hostile_num_exponent.lua" "nodes[2]" "exponent out of range" "at most 100000000"
run exponent-emit 2 emit "$specs/hostile_num_exponent.lua" --name hostile -o . -- \
  "hostile_num_exponent.lua" "nodes[2]" "exponent out of range"
run exponent-entry 2 check "$tabs/hostile_num_exponent.lua" -- \
  "hostile_num_exponent.lua" "c[1]" "exponent out of range"
# a weight of magnitude 10^(5 10^17): refused at the first precision
run huge-weight 2 generate "$work/hostile_num_huge_weight.lua" --digits 8 -o out.lua -- \
  "b[1]" "beyond the decimals vigen writes and reads"
# a monomial of degree 10^8 in the basis: refused within seconds, not at 10 s
limit=5 run monomial 3 generate "$work/hostile_num_monomial.lua" --digits 8 -o out.lua -- \
  "ct[1]" "is not certified to 8 digits" "the cap"
# a non-integer power t^111783.5 (found by the spec fuzz harness: quadrature
# lost its integrals, 14 s of refinement); its closed-form integral makes it
# a quick, if useless, method
cat >"$work/hostile_num_real_power.lua" <<'LUA'
return { name = "hostile_num_real_power", nodes = gauss_legendre(2), basis = { "-t", "t^111783.5" } }
LUA
limit=5 run real-power 0 generate "$work/hostile_num_real_power.lua" -q -o - -- "hostile_num_real_power"
# a product of powers of t, t^62652 * (-t) (found by the spec fuzz harness:
# not a power as written, so quadrature at rising precision up to the cap,
# 10 s): a product of powers of one linear base has the closed form of the
# combined power, and the ill-conditioned method is refused at once
cat >"$work/hostile_num_power_product.lua" <<'LUA'
return { name = "hostile_num_power_product", nodes = gauss_legendre(3), basis = { "---0-t", "t^62652*---t", "55" } }
LUA
limit=5 run power-product 3 generate "$work/hostile_num_power_product.lua" -q -o out.lua -- "is not certified" "the cap"
# a basis function of super-exponential range, -(5.3e-45)^((3.3e-38)^(-t))
# (found by the spec fuzz harness): its integrals need ever more precision,
# about 24 s of bounded work up to the precision cap; the wall-clock cap ends
# it when asked, with its message, exit 3 and no output file
cat >"$work/hostile_num_super_exponential.lua" <<'LUA'
return { name = "hostile_num_super_exponential", nodes = gauss_legendre(3),
         basis = { "2--0-t", "-53336626031e-55^ --------------333333333333626031e-55^ -----------------t", "5" } }
LUA
limit=5 run super-exponential 3 generate "$work/hostile_num_super_exponential.lua" --max-seconds 2 -q -o out.lua -- \
  "the time cap of 2 s was reached" "--max-seconds"
[ -e "$work/out/out.lua" ] && fail "super-exponential: an output file was left"
# 100,000 nodes (FLINT aborted allocating the matrices)
run many-nodes 2 generate "$specs/hostile_num_many_nodes.lua" -o out.lua -- \
  "hostile_num_many_nodes.lua" "nodes has 100000 entries" "at most 256"
# a literal implying 33 million bits (minutes and gigabytes)
run literal-precision 3 check "$work/hostile_num_power.lua" -- \
  "hostile_num_power.lua" "above the cap of 524288 bits" "--max-prec"
# exponents of 2^(2^62) and 2^-(2^62) in one entry (a signed overflow in the
# magnitude span of the expression evaluator, found by UBSan)
cat >"$work/hostile_num_span.lua" <<'LUA'
return { name = "hostile_num_span", s = 1, c = { "1/2" }, b = { "1" }, ct = { "1/2" }, At = { { "1/2" } },
         A = { { "1/2 + 2^-(2^61) * 2^-(2^61) - 2^(2^61) * 2^(2^61)" } } }
LUA
run magnitude-span 3 check "$work/hostile_num_span.lua" -- "hostile_num_span.lua" "--max-prec"
# --prec 1000000 (minutes)
run option-prec 3 check "$src/tableaux/published/gauss_2.lua" --prec 1000000 -- \
  "--prec asks for 1000000 bits" "--max-prec"
# --digits 100000 with quadrature (hours)
run quadrature-digits 3 generate "$specs/hostile_num_quadrature.lua" --digits 100000 -o out.lua -- \
  "hostile_num_quadrature.lua" "basis[2]" "quadrature" "--max-prec"
# a cap set low is honoured by generate, with the option in the message
run max-prec-generate 3 --max-prec 1000 generate "$src/tableaux/specs/gauss_legendre_s2.lua" --digits 2000 \
  -o out.lua -- "gauss_legendre_s2.lua" "above the cap of 1000 bits" "--max-prec"
run max-prec-check 3 check --max-prec 100 "$src/tableaux/published/gauss_2.lua" -- "--max-prec"
lines=2 run max-prec-usage 2 check --max-prec x "$src/tableaux/published/gauss_2.lua" -- "--max-prec" "vigen help"
# show honours the cap too (its refinement doubles the precision)
run max-prec-show 3 --max-prec 200 show "$src/tableaux/published/gauss_3.lua" --digits 300 -- "--max-prec"
# a tableau file declaring more stages than any method may have (minutes and
# gigabytes for 2000 stages)
python3 - "$work/hostile_num_stages.lua" <<'PY'
import sys
s = 300
z = ", ".join(['"0"'] * s)
with open(sys.argv[1], "w") as f:
    f.write('return { name = "stages", s = %d, c = { %s }, b = { %s }, A = { %s } }\n'
            % (s, z, z, ", ".join(["{ %s }" % z] * s)))
PY
run many-stages 2 check "$work/hostile_num_stages.lua" -- "hostile_num_stages.lua" "from 1 to 256"
# a zero of radius 2^-4000000000 (formatting it ran out of memory)
run zero-format 0 show "$work/hostile_num_zero_format.lua" -- "0e-34"
# what is cheap stays valid: 100000 digits of a polynomial basis
run digits-100000 0 generate "$src/tableaux/specs/gauss_legendre_s2.lua" --digits 100000 -o out.lua -q --
[ -s "$work/out/out.lua" ] || fail "digits-100000: no tableau written"

[ "$failures" = 0 ] && echo "cli_hostile_numbers: all passed"
exit $((failures > 0))
