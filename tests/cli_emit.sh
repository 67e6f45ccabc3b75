#!/bin/bash
# cli_emit.sh VIGEN SRC — `vigen emit` from the command line: files written,
# byte-identical reruns, sanitised names, refusal of too few digits, usage.
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

"$VIGEN" emit "$SRC/tests/data/emit/gauss2.lua" --name '../x; int y' -o "$T" -q 2>/dev/null
check '[ -f "$T/m____x__int_y.c" ] && [ ! -e "$T/../x; int y.c" ]' "hostile --name sanitised"

"$VIGEN" emit "$SRC/tests/data/emit/gauss2_20digits.lua" --name q --real float128 -o "$T" -q 2>"$T/err.txt"
check '[ $? -eq 1 ] && grep -q "digits" "$T/err.txt" && [ ! -f "$T/q.c" ]' "too few digits for float128 refused"
"$VIGEN" emit "$SRC/tests/data/emit/gauss2.lua" --name q --real long-double -o "$T" -q
check '[ $? -eq 0 ] && grep -q "0x1p-2L" "$T/q.c"' "long double literals"
"$VIGEN" emit "$SRC/tests/data/emit/gauss2.lua" --name q128 --real float128 -o "$T" -q
check '[ $? -eq 0 ] && gcc -std=c11 -Wall -Wextra -Wpedantic -Werror -I"$SRC/runtime/include" -I"$T" -c "$T/q128.c" -o "$T/q128.o"' "float128 stepper compiles"

"$VIGEN" emit "$SRC/tests/data/emit/gauss2.lua" -o "$T" 2>/dev/null
check '[ $? -eq 2 ]' "missing --name is a usage error"
"$VIGEN" emit --help >/dev/null
check '[ $? -eq 0 ]' "--help"
"$VIGEN" emit "$SRC/tests/data/emit/none.lua" --name z -o "$T" 2>/dev/null
check '[ $? -eq 2 ]' "unreadable input"

rm -rf "$T"
exit $fail
