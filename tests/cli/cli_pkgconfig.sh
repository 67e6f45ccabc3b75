#!/bin/bash
# cli_pkgconfig.sh VIGEN SRC — building without CMake: install this build of
# vigen into a temporary prefix, emit a stepper with the installed vigen, and
# compile it with a program using the problem collection by
#   cc main.c gauss2.c $(pkg-config --cflags --libs vigen)
# with PKG_CONFIG_PATH pointing into the prefix.  The program integrates the
# Kepler problem (e = 0.6) over 10 periods with the 2-stage Gauss method at
# h = 2 pi / 400; checked against independent truths: the energy error is
# small (order 4, 400 steps per period: below 1e-6), the angular momentum is
# conserved to round-off (a quadratic invariant, conserved by Gauss methods),
# and the final position is within 1e-3 of the solution of Kepler's equation
# (the phase error of an order-4 method grows linearly in time).  Then the prefix
# is moved and the build repeated (the .pc file finds its prefix from its own
# place).
set -u
VIGEN=$1
SRC=$(cd "$2" && pwd)
BUILD=$(cd "$(dirname "$VIGEN")" && pwd)
T=$(mktemp -d /tmp/vigen-cli-pkgconfig-XXXXXX)
trap 'rm -rf "$T"' EXIT
fail=0
check() { if ! eval "$1"; then echo "FAIL: $2"; fail=1; fi; }
die() { echo "FAIL: $1"; [ -f "$T/log" ] && tail -30 "$T/log"; exit 1; }

command -v pkg-config >/dev/null || die "pkg-config is not installed"
[ -f "$BUILD/CMakeCache.txt" ] || die "no CMakeCache.txt next to $VIGEN"
cmake --install "$BUILD" --prefix "$T/prefix" >"$T/log" 2>&1 || die "cmake --install"
pc=$(ls "$T"/prefix/lib*/pkgconfig/vigen.pc "$T"/prefix/lib/*/pkgconfig/vigen.pc 2>/dev/null | head -1)
[ -n "$pc" ] || die "vigen.pc is not installed under lib*/pkgconfig"
for f in include/vigen/problems.h include/vigen/lagrangian.h include/vigen/runtime.h; do
    check '[ -f "$T/prefix/$f" ]' "installed $f"
done
check '! grep -q -e "$BUILD" -e "$SRC" "$pc"' "vigen.pc names neither the build nor the source tree"
export PKG_CONFIG_PATH=$(dirname "$pc")
version=$("$VIGEN" --version | awk '{ print $2 }')
check '[ "$(pkg-config --modversion vigen)" = "$version" ]' "pkg-config --modversion vigen = $version"
libs=$(pkg-config --libs vigen)
for l in -lvigen_problems -lvigen_runtime -lgsl -lm; do
    check 'echo " $libs " | grep -q -- " $l "' "pkg-config --libs vigen has $l ($libs)"
done

"$T/prefix/bin/vigen" emit "$SRC/tableaux/published/gauss_2.lua" --name gauss2 -o "$T/app" -q \
    >"$T/log" 2>&1 || die "installed vigen emit"
cat >"$T/app/main.c" <<'C'
#include <math.h>
#include <stdio.h>
#include <vigen/problems.h>
#include "gauss2.h"

int main(void)
{
    vigen_problem *pb;
    char why[200];
    if (vigen_problem_create(&pb, "kepler", "e=0.6", why, sizeof why) != VIGEN_SUCCESS) {
        fprintf(stderr, "%s\n", why);
        return 1;
    }
    double t, q[2], p[2], qr[2], pr[2];
    vigen_problem_initial(pb, &t, q, p);
    double E0 = vigen_problem_energy(pb, t, q, p), L0 = vigen_problem_invariant(pb, 0, t, q, p);
    double h = vigen_problem_period(pb) / 400, dE = 0, dL = 0;
    gauss2_workspace *w = gauss2_alloc(vigen_problem_hamiltonian(pb), NULL);
    for (int n = 0; n < 4000; n++) {
        if (w == NULL || gauss2_step(w, &t, q, p, h) != VIGEN_SUCCESS) return 1;
        dE = fmax(dE, fabs(vigen_problem_energy(pb, t, q, p) - E0));
        dL = fmax(dL, fabs(vigen_problem_invariant(pb, 0, t, q, p) - L0));
    }
    vigen_problem_reference(pb, t, qr, pr);
    printf("energy %.3e angular-momentum %.3e position %.3e\n", dE, dL, hypot(q[0] - qr[0], q[1] - qr[1]));
    gauss2_free(w);
    vigen_problem_free(pb);
    return 0;
}
C
build() {
    (cd "$T/app" && cc -std=c11 -o app main.c gauss2.c $(pkg-config --cflags --libs vigen)) >"$T/log" 2>&1
}
build || die "cc main.c gauss2.c \$(pkg-config --cflags --libs vigen)"
out=$("$T/app/app") || die "the program built with pkg-config failed"
read -r _ dE _ dL _ dx <<<"$out"
check 'awk -v x="$dE" "BEGIN { exit !(x < 1e-6) }"' "energy error $dE < 1e-6"
check 'awk -v x="$dL" "BEGIN { exit !(x < 1e-13) }"' "angular momentum error $dL is round-off"
check 'awk -v x="$dx" "BEGIN { exit !(x < 1e-3) }"' "distance to Kepler's equation's solution $dx < 1e-3"

# a moved prefix still works
mv "$T/prefix" "$T/moved"
export PKG_CONFIG_PATH=${PKG_CONFIG_PATH/$T\/prefix/$T/moved}
rm -f "$T/app/app"
build || die "build against the moved prefix"
check '[ -x "$T/app/app" ]' "built against the moved prefix"

[ $fail -eq 0 ] && echo "ok: pkg-config build (energy $dE, angular momentum $dL, position $dx)"
exit $fail
