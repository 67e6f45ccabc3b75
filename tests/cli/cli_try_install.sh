#!/bin/bash
# cli_try_install.sh VIGEN SRC — `vigen try` from an installed vigen: this
# build installed into a temporary prefix, the prefix moved, and the
# installed vigen (outside the build tree, so using the installed runtime,
# problem library, headers and published tableaux) runs Gauss s = 2 by name
# on the harmonic oscillator; its global error after 10 time units at h =
# 0.1 is t h^4 / 720 (the error constant of the (2,2) Pade approximant of
# exp, Hairer-Wanner, Solving ODEs II, IV.3) within 5 %.  With the installed
# library files renamed, the message names what is missing (exit 3).
set -u
VIGEN=$1
SRC=$(cd "$2" && pwd)
BUILD=$(cd "$(dirname "$VIGEN")" && pwd)
T=$(mktemp -d /tmp/vigen-cli-try-install-XXXXXX)
trap 'rm -rf "$T"' EXIT
export TMPDIR="$T/tmp"
mkdir -p "$TMPDIR"
fail=0
check() { if ! eval "$1"; then echo "FAIL: $2"; fail=1; fi; }
die() { echo "FAIL: $1"; [ -f "$T/log" ] && tail -30 "$T/log"; exit 1; }

[ -f "$BUILD/CMakeCache.txt" ] || die "no CMakeCache.txt next to $VIGEN"
cmake --install "$BUILD" --prefix "$T/prefix" > "$T/log" 2>&1 || die "cmake --install"
mv "$T/prefix" "$T/moved"
cd "$T"
"$T/moved/bin/vigen" try gauss_2 --problem harmonic-oscillator --h 0.1 --time 10 --json > "$T/out.json" 2> "$T/err"
rc=$?
check '[ $rc -eq 0 ]' "installed vigen try: exit $rc ($(cat "$T/err"))"
check 'python3 -c "
import json, sys
m = json.load(open(sys.argv[1]))[\"methods\"][0]
want = 10 * 0.1**4 / 720
sys.exit(0 if abs(m[\"global_error\"] / want - 1) < 0.05 else 1)" "$T/out.json"' "installed: Gauss s = 2 global error t h^4/720 ($(cat "$T/out.json"))"
"$T/moved/bin/vigen" try --list-methods > "$T/methods"
check '[ "$(grep -c "^[^ ]*$" "$T/methods")" -eq "$(ls "$SRC"/tableaux/published/*.lua | wc -l)" ] && grep -q "^hp-midpoint " "$T/methods"' "installed: the published tableaux and the built-in Lagrangian integrators are known by name"
# the built-in Lagrangian integrators compile against the installed runtime:
# on the harmonic oscillator (q = 1, p = 0, omega = 1) hp-trapezoidal is
# velocity Verlet, which keeps p^2/2 + (1 - h^2/4) q^2/2 exactly, so H moves
# between H(0) = 1/2 (q = 1) and H(0) - h^2/8 (q = 0): the largest relative
# energy error is h^2/4 (reached within 10 % by the samples)
"$T/moved/bin/vigen" try hp-trapezoidal --problem harmonic-oscillator --h 0.1 --time 10 --json > "$T/lag.json" 2> "$T/err"
rc=$?
check '[ $rc -eq 0 ] && python3 -c "
import json, sys
m = json.load(open(sys.argv[1]))[\"methods\"][0]
e, want = m[\"energy_error_max\"], 0.1**2 / 4
sys.exit(0 if 0.9 * want < e <= want * (1 + 1e-9) else 1)" "$T/lag.json"' "installed: hp-trapezoidal (velocity Verlet) on the oscillator: largest energy error h^2/4 ($rc, $(cat "$T/err"), $(cat "$T/lag.json"))"

lib=$(ls "$T"/moved/lib*/libvigen_problems.a "$T"/moved/lib/*/libvigen_problems.a 2>/dev/null | head -1)
mv "$lib" "$lib.away"
"$T/moved/bin/vigen" try gauss_2 --problem harmonic-oscillator > /dev/null 2> "$T/err"
rc=$?
check '[ $rc -eq 3 ] && grep -q "libvigen_problems.a is missing" "$T/err" && grep -q "reinstall" "$T/err"' "incomplete installation: exit 3, names the file ($(cat "$T/err"))"
check '[ -z "$(ls -A "$TMPDIR")" ]' "nothing left in TMPDIR"
exit $fail
