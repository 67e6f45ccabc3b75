#!/bin/bash
# cli_emit.sh VIGEN SRC — `vigen emit` from the command line: files written,
# byte-identical reruns, sanitised names, refusal of too few digits (with
# advice) and --allow-inexact (one summary warning), specs generated on the
# fly, the warning for tableaux that are not symplectic or not consistent,
# usage, --dim, a template that breaks the slot contract, a slot no template
# declares, and a missing template.
set -u
VIGEN=$1
SRC=$2
T=$(mktemp -d /tmp/vigen-cli-emit-XXXXXX)
fail=0
check() { if ! eval "$1"; then echo "FAIL: $2"; fail=1; fi; }

"$VIGEN" emit "$SRC/tests/data/emit/gauss2.lua" --name g2 -o "$T" -q
check '[ $? -eq 0 ] && [ -f "$T/g2.h" ] && [ -f "$T/g2.c" ]' "emit writes NAME.h and NAME.c"
check 'gcc -std=c11 -Wall -Wextra -Wpedantic -Werror -I"$SRC/runtime/include" -I"$T" -c "$T/g2.c" -o "$T/g2.o"' "emitted code compiles warning-free"
mkdir -p "$T/again"
"$VIGEN" emit "$SRC/tests/data/emit/gauss2.lua" --name g2 -o "$T/again" -q
check 'cmp -s "$T/g2.c" "$T/again/g2.c" && cmp -s "$T/g2.h" "$T/again/g2.h"' "byte-identical output"
check '! grep -q "[0-9][0-9]:[0-9][0-9]:[0-9][0-9]" "$T/g2.c"' "no timestamp"
check 'grep -q "Tableau digest" "$T/g2.c" && grep -q "vigen emit gauss2.lua --name g2 --real double" "$T/g2.c"' "header names input, options"
check '[ -z "$(ls "$T" | grep "\.tmp")" ]' "no temporary files left"

# --dim N: recorded in the header, N in the header's NAME_DIM, strict-clean
# with gcc and clang; a dimension that is not a positive number is a usage
# error naming the option (exit 2, nothing written)
"$VIGEN" emit "$SRC/tests/data/emit/gauss2.lua" --name g2d --dim 3 -o "$T" -q
check '[ $? -eq 0 ] && grep -q "vigen emit gauss2.lua --name g2d --real double --dim 3" "$T/g2d.c" && grep -q "^#define G2D_DIM 3$" "$T/g2d.h"' "--dim recorded in the header and in NAME_DIM"
check 'for cc in gcc clang; do $cc -std=c11 -Wall -Wextra -Wpedantic -Werror -I"$SRC/runtime/include" -I"$T" -c "$T/g2d.c" -o "$T/g2d.o" || exit 1; done' "--dim: compiles warning-free with gcc and clang"
for bad in 0 -1 x 3x 100001; do
    "$VIGEN" emit "$SRC/tests/data/emit/gauss2.lua" --name g2bad --dim "$bad" -o "$T" -q 2>"$T/err.txt"
    check '[ $? -eq 2 ] && [ ! -f "$T/g2bad.c" ] && grep -q "\-\-dim takes a dimension from 1 to 100000, not .$bad." "$T/err.txt"' "--dim $bad: usage error naming the option"
done

"$VIGEN" emit "$SRC/tests/data/emit/gauss2.lua" --name '../x; int y' -o "$T" -q 2>/dev/null
check '[ -f "$T/m____x__int_y.c" ] && [ ! -e "$T/../x; int y.c" ]' "hostile --name sanitised"

"$VIGEN" emit "$SRC/tests/data/emit/gauss2_20digits.lua" --name q --real float128 -o "$T" -q 2>"$T/err.txt"
check '[ $? -eq 2 ] && grep -q "digits" "$T/err.txt" && [ ! -f "$T/q.c" ]' "too few digits for float128 refused"
# The default output of vigen generate (34 digits) as float128, and a
# 16-digit textbook tableau as double: refused, naming the file and the entry
# and saying what to do; --allow-inexact gives one summary warning.
"$VIGEN" generate "$SRC/tableaux/specs/gauss_legendre_s3.lua" -q -o "$T/g3_34.lua"
"$VIGEN" emit "$T/g3_34.lua" --name q --real float128 -o "$T" -q 2>"$T/err.txt"
check '[ $? -eq 2 ] && [ ! -f "$T/q.c" ]' "34 digits as float128: refused, exit 2 (the data are too short)"
check 'grep -q "^vigen emit: $T/g3_34.lua: c\[1\] = 0.112701665379258311482073460021760[0-9]* is not known well enough to round it correctly to 113 bits (float128)" "$T/err.txt"' "34 digits as float128: message names file and entry"
check 'grep -q "vigen generate SPEC --digits 60. (or more)" "$T/err.txt" && grep -q "emit the spec itself" "$T/err.txt" && grep -q "give the entry exactly" "$T/err.txt" && grep -q "pass --allow-inexact to round the decimals as written" "$T/err.txt"' "34 digits as float128: says what to do"
"$VIGEN" emit "$T/g3_34.lua" --name q --real float128 -o "$T" -q --allow-inexact 2>"$T/err.txt"
check '[ $? -eq 0 ] && [ -f "$T/q.c" ] && [ "$(wc -l < "$T/err.txt")" -eq 1 ]' "--allow-inexact: exactly one warning line"
check '! grep -q "correctly rounded" "$T/q.c" && grep -q "from the decimals as written" "$T/q.c"' "--allow-inexact: the header does not promise correct rounding"
check 'grep -q "g3_34.lua: --allow-inexact: rounded 24 entries to float128 (113 bits) from their decimals as written (c\[1\], c\[2\], c\[3\], A\[1\]\[1\], A\[1\]\[2\] and 19 more; and 25 coefficients computed from them).*only as good as these decimals" "$T/err.txt"' "--allow-inexact: the summary counts and names entries"
check '[ "$(grep -o "b\[1\]" "$T/err.txt" | wc -l)" -le 1 ] && ! grep -q "rounding the value as written" "$T/err.txt"' "--allow-inexact: no entry twice, no per-entry warnings"
check 'grep -q "vigen emit g3_34.lua --name q --real float128 --allow-inexact" "$T/q.c"' "--allow-inexact recorded in the header"
"$VIGEN" emit "$SRC/tests/data/published_printed/blanes_moan_s6_4.lua" --name bm -o "$T" -q 2>"$T/err.txt"
check '[ $? -eq 2 ] && grep -q "^vigen emit: .*blanes_moan_s6_4.lua: c\[1\] = 0.0792036964311957 is not known well enough to round it correctly to 53 bits (double): give the entry exactly .* or with 40 or more significant digits.*pass --allow-inexact" "$T/err.txt"' "16-digit tableau as double: refused with the same advice"
"$VIGEN" emit "$SRC/tests/data/published_printed/blanes_moan_s6_4.lua" --name bm -o "$T" -q --allow-inexact 2>"$T/err.txt"
check '[ $? -eq 0 ] && [ "$(grep -c "allow-inexact" "$T/err.txt")" -eq 1 ] && [ "$(grep -c "warning" "$T/err.txt")" -eq 1 ]' "16-digit tableau, --allow-inexact: one warning"

# A spec is generated on the fly (40 digits for double, 60 for float128):
# the same coefficients as the generated 50-digit tableau file, and the
# header says where the tableau came from.
for real in double float128; do
  digits=40; [ $real = float128 ] && digits=60
  mkdir -p "$T/spec_$real" "$T/gen_$real"
  "$VIGEN" emit "$SRC/tableaux/specs/gauss_legendre_s2.lua" --name gl2 --real $real -o "$T/spec_$real" 2>"$T/err.txt"
  check '[ $? -eq 0 ] && [ -f "$T/spec_$real/gl2.c" ] && [ -f "$T/spec_$real/gl2.h" ]' "spec as $real: emitted"
  check 'grep -q "wrote .*(tableau generated from the spec with $digits certified digits)" "$T/err.txt" && [ "$(wc -l < "$T/err.txt")" -eq 1 ]' "spec as $real: summary, no warning"
  check 'grep -q "Tableau generated from the spec gauss_legendre_s2.lua with $digits certified digits" "$T/spec_$real/gl2.c"' "spec as $real: header records spec and digits"
  "$VIGEN" emit "$SRC/tableaux/generated/gauss_legendre_s2.lua" --name gl2 --real $real -o "$T/gen_$real" -q
  grep -E "0x1(\.[0-9a-f]+)?p" "$T/spec_$real/gl2.c" > "$T/spec_$real/lits"
  grep -E "0x1(\.[0-9a-f]+)?p" "$T/gen_$real/gl2.c" > "$T/gen_$real/lits"
  check '[ -s "$T/spec_$real/lits" ] && cmp -s "$T/spec_$real/lits" "$T/gen_$real/lits"' "spec as $real: literals identical to the generated tableau's"
  check 'gcc -std=c11 -Wall -Wextra -Wpedantic -Werror -I"$SRC/runtime/include" -I"$T/spec_$real" -c "$T/spec_$real/gl2.c" -o "$T/spec_$real/gl2.o"' "spec as $real: compiles"
done
"$VIGEN" emit "$SRC/tests/data/bad_specs/repeated_nodes.lua" --name z -o "$T" -q 2>"$T/err.txt"
check '[ $? -eq 2 ] && grep -q "^vigen emit: .*repeated_nodes.lua: nodes\[1\] and nodes\[2\] are equal" "$T/err.txt"' "a spec that describes no method: exit 2, named"

"$VIGEN" emit "$SRC/tests/data/emit/gauss2.lua" --name q --real long-double -o "$T" -q
check '[ $? -eq 0 ] && grep -q "0x1p-2L" "$T/q.c"' "long double literals"
"$VIGEN" emit "$SRC/tests/data/emit/gauss2.lua" --name q128 --real float128 -o "$T" -q
check '[ $? -eq 0 ] && gcc -std=c11 -Wall -Wextra -Wpedantic -Werror -I"$SRC/runtime/include" -I"$T" -c "$T/q128.c" -o "$T/q128.o"' "float128 stepper compiles"

# The audit: a tableau that certainly fails a row sum or a symplecticity
# condition is still emitted (exit 0) with a warning that -q does not silence;
# a symplectic one, even written with rounded decimals, gets none.
# The classical RK4 (Kutta 1901), one RK method for both parts: consistent,
# order 4, not symplectic (b_1 a_11 + b_1 a_11 - b_1^2 = -1/36).
"$VIGEN" emit "$SRC/tests/data/check/rk4.lua" --name rk4 -o "$T" -q 2>"$T/err.txt"
check '[ $? -eq 0 ] && [ -f "$T/rk4.c" ] && [ -f "$T/rk4.h" ]' "non-symplectic tableau still emitted, exit 0"
check 'grep -q "warning: .*rk4.lua: the tableau is not symplectic (10 of 10 conditions" "$T/err.txt"' "RK4: warns 'not symplectic' despite -q"
check 'grep -q "run .vigen check .*rk4.lua. for details" "$T/err.txt"' "RK4: points to vigen check"
# the same tableau saying symplectic = false: the user knows, no warning
sed 's/^return {/return { symplectic = false,/' "$SRC/tests/data/check/rk4.lua" >"$T/rk4_known.lua"
"$VIGEN" emit "$T/rk4_known.lua" --name rk4k -o "$T" -q 2>"$T/err.txt"
check '[ $? -eq 0 ] && ! grep -q "not symplectic" "$T/err.txt"' "RK4 claimed non-symplectic: no warning"
check '! grep -q "not consistent" "$T/err.txt"' "RK4: its row sums hold, no consistency warning"
check 'gcc -std=c11 -Wall -Wextra -Wpedantic -Werror -I"$SRC/runtime/include" -I"$T" -c "$T/rk4.c" -o "$T/rk4.o"' "RK4 stepper compiles"
# Leok-Zhang Ex. 5 (iii) as printed: a_33 misprinted, so row 3 of A does not
# sum to c_3 and the pair (3, 3) is not symplectic; one entry explains both.
"$VIGEN" emit "$SRC/tableaux/published/leok_zhang_ex5_iii.lua" --name ex5 -o "$T" 2>"$T/err.txt"
check '[ $? -eq 0 ] && [ -f "$T/ex5.c" ]' "inconsistent published tableau still emitted"
check 'grep -q "not consistent (1 of 7 conditions.*row 3 of A sums to" "$T/err.txt"' "Ex. 5 (iii): warns 'not consistent', names row 3 of A"
check 'grep -q "not symplectic (1 of 9 conditions.*pair (3, 3)" "$T/err.txt"' "Ex. 5 (iii): warns 'not symplectic', names pair (3, 3)"
check 'grep -q "A\[3\]\[3\]" "$T/err.txt"' "Ex. 5 (iii): names the misprinted entry"
check 'grep -q "wrote" "$T/err.txt"' "without -q the summary is printed too"
# sum b = 0.51 + 1/2: the ball of the rounded 0.51 excludes sum b = 1
"$VIGEN" emit "$SRC/tests/data/check/gauss2_b051.lua" --name b051 -o "$T" -q --allow-inexact 2>"$T/err.txt"
check '[ $? -eq 0 ] && grep -q "not consistent.*sum of b" "$T/err.txt"' "sum b != 1 on rounded data: warned"
# symplectic tableaux: exact, generated (50 digits) and rounded to 6 digits
# (the conditions hold only within the precision of the data: no alarm)
for f in tests/data/emit/gauss2.lua tableaux/generated/gauss_legendre_s3.lua tableaux/published/yoshida_4.lua; do
  "$VIGEN" emit "$SRC/$f" --name ok -o "$T" -q 2>"$T/err.txt"
  check '[ $? -eq 0 ] && [ ! -s "$T/err.txt" ]' "$f: symplectic, no warning"
done
"$VIGEN" emit "$SRC/tests/data/check/gauss2_6digits.lua" --name ok -o "$T" -q --allow-inexact 2>"$T/err.txt"
check '[ $? -eq 0 ] && ! grep -q "not symplectic\|not consistent" "$T/err.txt"' "6-digit Gauss-2: no false alarm"
"$VIGEN" emit --help | grep -q "certainly fails"
check '[ $? -eq 0 ]' "--help describes the audit"
"$VIGEN" emit --help > "$T/help.txt"
check 'grep -q -- "-q, --quiet" "$T/help.txt" && grep -q -- "--allow-inexact  an entry given" "$T/help.txt" && grep -q "rounded as written" "$T/help.txt" && grep -q "spec file" "$T/help.txt"' "--help: -q, --allow-inexact, specs"

"$VIGEN" emit "$SRC/tests/data/emit/gauss2.lua" -o "$T" 2>"$T/err.txt"
check '[ $? -eq 2 ] && grep -q "^vigen emit: --name is required" "$T/err.txt" && [ "$(wc -l < "$T/err.txt")" -le 2 ]' "missing --name is a usage error"
"$VIGEN" emit "$SRC/tests/data/emit/gauss2.lua" --name x --frobnicate 2>"$T/err.txt"
check '[ $? -eq 2 ] && grep -q "^vigen emit: unknown option .--frobnicate." "$T/err.txt"' "unknown option: vigen emit prefix"
"$VIGEN" emit "$SRC/tests/data/emit/gauss2.lua" --name x --real half 2>"$T/err.txt"
check '[ $? -eq 2 ] && grep -q "^vigen emit: --real takes" "$T/err.txt"' "bad --real: vigen emit prefix"
"$VIGEN" emit --help >/dev/null
check '[ $? -eq 0 ]' "--help"
"$VIGEN" emit "$SRC/tests/data/emit/none.lua" --name z -o "$T" 2>/dev/null
check '[ $? -eq 2 ]' "unreadable input"

# a claim beyond the 2s bound of an s-stage method is warned about
printf 'return { name = "g2", s = 2, order = 6, c = { "1/2 - sqrt(3)/6", "1/2 + sqrt(3)/6" },\n  A = { { "1/4", "1/4 - sqrt(3)/6" }, { "1/4 + sqrt(3)/6", "1/4" } }, b = { "1/2", "1/2" } }\n' >"$T/g2_order6.lua"
"$VIGEN" emit "$T/g2_order6.lua" --name g6 -o "$T" -q 2>"$T/err.txt"
check '[ $? -eq 0 ] && grep -q "claims order 6, but a 2-stage method has order at most 4" "$T/err.txt"' "impossible order claim warned"
sed 's/order = 6/order = 3/' "$T/g2_order6.lua" >"$T/g2_order3.lua"
"$VIGEN" emit "$T/g2_order3.lua" --name g3c -o "$T" -q 2>"$T/err.txt"
check '[ $? -eq 0 ] && grep -q "claims order 3, which is false (the order conditions hold up to order 4)" "$T/err.txt"' "false order claim warned"
sed 's/order = 6/order = 4/' "$T/g2_order6.lua" >"$T/g2_order4.lua"
"$VIGEN" emit "$T/g2_order4.lua" --name g4c -o "$T" -q 2>"$T/err.txt"
check '[ $? -eq 0 ] && [ ! -s "$T/err.txt" ]' "true order claim: no warning"

# A template that breaks the slot contract: exit 3, one line naming the
# template file, the line and the slot; nothing written.
mkdir -p "$T/tpl/prk"
cp "$SRC"/templates/prk/*.in "$T/tpl/prk/"
sed 's|^#include <float.h>$|#include <float.h> /* @ORDRE@ */|' "$SRC/templates/prk/stepper.c.in" >"$T/tpl/prk/stepper.c.in"
line=$(grep -n "@ORDRE@" "$T/tpl/prk/stepper.c.in" | cut -d: -f1)
VIGEN_TEMPLATE_DIR="$T/tpl" "$VIGEN" emit "$SRC/tests/data/emit/gauss2.lua" --name bad -o "$T" 2>"$T/err.txt"
check '[ $? -eq 3 ] && [ ! -f "$T/bad.c" ] && [ "$(wc -l < "$T/err.txt")" -eq 1 ] && grep -q "^vigen emit: template $T/tpl/prk/stepper.c.in:$line: slot ORDRE is used but not declared" "$T/err.txt"' "template breaking the slot contract: refused, file, line and slot named (not the input)"
# A slot the builder supplies that neither template declares any more.
sed -e '1s/ ORDER / /' -e 's/_ORDER @ORDER@$/_ORDER -1/' "$SRC/templates/prk/stepper.h.in" >"$T/tpl/prk/stepper.h.in"
sed -e '1,/\*\//s/ ORDER / /' -e 's/@STAGES@, @ORDER@,/@STAGES@, -1,/' "$SRC/templates/prk/stepper.c.in" >"$T/tpl/prk/stepper.c.in"
VIGEN_TEMPLATE_DIR="$T/tpl" "$VIGEN" emit "$SRC/tests/data/emit/gauss2.lua" --name bad -o "$T" 2>"$T/err.txt"
check '[ $? -eq 3 ] && [ ! -f "$T/bad.c" ] && [ "$(wc -l < "$T/err.txt")" -eq 1 ] && grep -q "^vigen emit: variant prk: its slot builder supplies slot ORDER, but no template of the variant declares it" "$T/err.txt"' "a supplied slot no template declares: refused, slot and variant named"
# A missing template is a broken installation: exit 3, the path and what to
# do, not blamed on the input; so is a missing file that stepper.c.in
# includes.
cp "$SRC/templates/prk/stepper.h.in" "$SRC/templates/prk/stepper.c.in" "$T/tpl/prk/"
rm "$T/tpl/prk/state.c.in"
VIGEN_TEMPLATE_DIR="$T/tpl" "$VIGEN" emit "$SRC/tests/data/emit/gauss2.lua" --name bad -o "$T" 2>"$T/err.txt"
check '[ $? -eq 3 ] && [ ! -f "$T/bad.c" ] && [ "$(wc -l < "$T/err.txt")" -eq 1 ] && grep -q "^vigen emit: template $T/tpl/prk/state.c.in: cannot open: .*reinstall vigen, or set VIGEN_TEMPLATE_DIR" "$T/err.txt"' "missing included template: exit 3, path and remedy"
rm "$T/tpl/prk/stepper.c.in"
VIGEN_TEMPLATE_DIR="$T/tpl" "$VIGEN" emit "$SRC/tests/data/emit/gauss2.lua" --name bad -o "$T" 2>"$T/err.txt"
check '[ $? -eq 3 ] && [ ! -f "$T/bad.c" ] && [ "$(wc -l < "$T/err.txt")" -eq 1 ] && grep -q "^vigen emit: template $T/tpl/prk/stepper.c.in: cannot open: .*reinstall vigen, or set VIGEN_TEMPLATE_DIR" "$T/err.txt"' "missing template: exit 3, path and remedy, no input prefix"

rm -rf "$T"
exit $fail
