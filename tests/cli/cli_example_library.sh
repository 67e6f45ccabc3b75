#!/bin/bash
# cli_example_library.sh VIGEN SRC — libvigen used from a C program
# (examples/library/method_report.c), in the build tree and installed:
# certified orders and symplecticity of textbook methods (Gauss s = 2 has
# order 2s = 4 and is symplectic; RK4 has order 4 and is not symplectic;
# Lobatto IIIA-IIIB s = 3 has order 2s - 2 = 4 and is symplectic: Hairer,
# Lubich & Wanner, Geometric Numerical Integration, II.1 and VI.4), the exit
# status map for a bad file, and the emitted stepper byte-identical to
# `vigen emit` (the command and the program call the same library).  The
# installed package is used from a moved prefix.
set -u
VIGEN=$1
SRC=$2
BUILD=$(cd "$(dirname "$VIGEN")" && pwd)
T=$(mktemp -d /tmp/vigen-cli-library-XXXXXX)
trap 'rm -rf "$T"' EXIT
unset VIGEN_TEMPLATE_DIR
fail=0
check() { if ! eval "$1"; then echo "FAIL: $2"; fail=1; fi; }
die() { echo "FAIL: $1"; [ -f "$T/log" ] && tail -30 "$T/log"; exit 1; }

run_checks() { # PROGRAM LABEL
  local prog=$1 label=$2 out
  out=$("$prog" "$SRC/tableaux/published/gauss_2.lua" "$T/$label") ; local rc=$?
  check '[ $rc -eq 0 ] && [ "$out" = "gauss_2: 2 stages; order 4 (any H), 4 (separable H); symplectic yes" ]' "$label: Gauss s = 2 ($out)"
  out=$("$prog" "$SRC/tests/data/check/rk4.lua")
  check '[ "$out" = "rk4: 4 stages; order 4 (any H), 4 (separable H); symplectic no" ]' "$label: RK4 ($out)"
  out=$("$prog" "$SRC/tableaux/published/lobatto_iiia_iiib_3.lua")
  check 'echo "$out" | grep -q "3 stages; order 4 (any H), 4 (separable H); symplectic yes$"' "$label: Lobatto IIIA-IIIB 3 ($out)"
  "$prog" "$SRC/tests/data/bad_tableaux/bad_expression.lua" >/dev/null 2>"$T/err.txt"; rc=$?
  check '[ $rc -eq 2 ] && [ "$(wc -l < "$T/err.txt")" -eq 1 ] && grep -q "bad_expression.lua" "$T/err.txt"' "$label: a bad entry exits 2 with one line naming the file"
  "$VIGEN" emit "$SRC/tableaux/published/gauss_2.lua" --name gauss_2 -o "$T/$label-cli" -q
  check 'cmp -s "$T/$label/gauss_2.c" "$T/$label-cli/gauss_2.c" && cmp -s "$T/$label/gauss_2.h" "$T/$label-cli/gauss_2.h"' "$label: the program emits what vigen emit does"
}

mkdir -p "$T/build-tree"
[ -x "$BUILD/examples/library/method_report" ] || die "examples/library was not built in $BUILD"
run_checks "$BUILD/examples/library/method_report" build-tree

# installed, and the prefix moved: the package finds its library, headers,
# dependencies and templates relative to itself
cmake --install "$BUILD" --prefix "$T/prefix0" >"$T/log" 2>&1 || die "cmake --install"
for f in lib/libvigen.a include/vigen/vigen.h include/vigen/status.def lib/cmake/vigen/FindArb.cmake; do
  check '[ -f "$T/prefix0/$f" ]' "installed $f"
done
# the installed headers are the public ones (include/vigen/ and the runtime's),
# none of the support library's
for h in "$SRC"/src/support/*.h; do
  check '[ ! -e "$T/prefix0/include/vigen/$(basename "$h")" ] && [ ! -e "$T/prefix0/include/support" ]' \
    "$(basename "$h") of the support library not installed"
done
for h in "$SRC"/include/vigen/*.h; do
  check '[ -f "$T/prefix0/include/vigen/$(basename "$h")" ]' "public header $(basename "$h") installed"
done
mv "$T/prefix0" "$T/prefix"
cp -r "$SRC/examples/library" "$T/src"
cmake -S "$T/src" -B "$T/build" -DCMAKE_PREFIX_PATH="$T/prefix" -DCMAKE_BUILD_TYPE=Release \
  >"$T/log" 2>&1 || die "configure examples/library against the installed vigen"
cmake --build "$T/build" >"$T/log" 2>&1 || die "build examples/library against the installed vigen"
mkdir -p "$T/installed"
run_checks "$T/build/method_report" installed

[ $fail -eq 0 ] && echo "cli_example_library: all checks passed"
exit $fail
