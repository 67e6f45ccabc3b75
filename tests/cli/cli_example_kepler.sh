#!/bin/bash
# cli_example_kepler.sh VIGEN SRC — the user's path end to end: install this
# build of vigen into a temporary prefix (cmake --install of the build
# directory holding VIGEN), configure examples/kepler against it with
# find_package(vigen) + vigen_add_stepper, build, run, and check the physics:
# angular momentum conserved to round-off by both symplectic steppers, energy
# error small and bounded (no drift over 2000 periods), and shrinking like
# h^4 (Gauss-2) and h^2 (Verlet) when h is halved.  Also: the installed vigen
# renders its installed templates and emits the same bytes as the build tree's,
# and a changed tableau is re-emitted by the build.
set -u
VIGEN=$1
SRC=$2
BUILD=$(cd "$(dirname "$VIGEN")" && pwd)
T=$(mktemp -d /tmp/vigen-cli-kepler-XXXXXX)
trap 'rm -rf "$T"' EXIT
unset VIGEN_TEMPLATE_DIR
fail=0
check() { if ! eval "$1"; then echo "FAIL: $2"; fail=1; fi; }
die() { echo "FAIL: $1"; [ -f "$T/log" ] && tail -30 "$T/log"; exit 1; }

[ -f "$BUILD/CMakeCache.txt" ] || die "no CMakeCache.txt next to $VIGEN"
cmake --install "$BUILD" --prefix "$T/prefix" >"$T/log" 2>&1 || die "cmake --install"
for f in bin/vigen include/vigen/runtime.h share/vigen/templates/prk/stepper.c.in \
         lib/cmake/vigen/vigenConfig.cmake lib/cmake/vigen/VigenStepper.cmake; do
    check '[ -f "$T/prefix/$f" ]' "installed $f"
done

# the example as a user has it: its own directory, built against the prefix
cp -r "$SRC/examples/kepler" "$T/src"
cmake -S "$T/src" -B "$T/build" -DCMAKE_PREFIX_PATH="$T/prefix" -DCMAKE_BUILD_TYPE=Release \
    >"$T/log" 2>&1 || die "configure examples/kepler against the installed vigen"
cmake --build "$T/build" -j2 >"$T/log" 2>&1 || die "build examples/kepler"
check 'grep -q "$T/prefix/bin/vigen emit" "$T/build/CMakeFiles/kepler_gauss2.dir/build.make"' \
    "the stepper is emitted by the installed vigen"

# installed emission = build-tree emission, byte for byte
"$VIGEN" emit "$T/src/gauss2.lua" --name gauss2 -o "$T" -q
check 'cmp -s "$T/gauss2.c" "$T/build/vigen/kepler_gauss2/gauss2.c"' "installed vigen emits the same gauss2.c"

# the installed vigen reads the installed templates
mkdir -p "$T/mark"
echo '/* installed template */' >>"$T/prefix/share/vigen/templates/prk/stepper.h.in"
"$T/prefix/bin/vigen" emit "$T/src/gauss2.lua" --name g -o "$T/mark" -q
check 'tail -1 "$T/mark/g.h" | grep -q "installed template"' "installed vigen uses share/vigen/templates"

# a changed tableau is emitted again
sleep 1
touch "$T/src/gauss2.lua"
cmake --build "$T/build" >"$T/log" 2>&1 || die "rebuild"
check 'grep -q "vigen emit gauss2.lua" "$T/log"' "touching gauss2.lua re-runs vigen emit"

# physics: 2000 periods at h = T/100 and T/200
"$T/build/kepler" 2000 100 >"$T/run100.txt" || die "kepler 2000 100"
"$T/build/kepler" 2000 200 >"$T/run200.txt" || die "kepler 2000 200"
# rows "NAME  a..b  dH  dL", one per tenth of the run
col() { awk -v n="$1" -v c="$2" '$1 == n && $2 ~ /\.\./ { print $c }' "$3"; }
maxof() { sort -g | tail -1; }
for m in gauss2 verlet; do
    check '[ "$(col $m 3 "$T/run200.txt" | wc -l)" -eq 10 ]' "$m: ten rows"
    Lmax=$(col $m 4 "$T/run200.txt" | maxof)
    check 'awk -v x="$Lmax" "BEGIN { exit !(x < 1e-12) }"' "$m: |L/L0 - 1| = $Lmax is round-off (< 1e-12)"
    first=$(col $m 3 "$T/run200.txt" | head -1)
    last=$(col $m 3 "$T/run200.txt" | tail -1)
    Hmax=$(col $m 3 "$T/run200.txt" | maxof)
    check 'awk -v a="$first" -v m="$Hmax" "BEGIN { exit !(a > 0 && m <= 1.5 * a) }"' \
        "$m: energy error bounded (max $Hmax, first tenth $first)"
    coarse=$(col $m 3 "$T/run100.txt" | maxof)
    eval "H_$m=\$Hmax; R_$m=\$(awk -v a=\"\$coarse\" -v b=\"\$Hmax\" 'BEGIN { print a / b }')"
done
# order 4: halving h divides the energy error by 2^4; order 2: by 2^2
check 'awk -v r="$R_gauss2" "BEGIN { exit !(r > 11 && r < 23) }"' "gauss2: error ratio h vs h/2 = $R_gauss2, about 16"
check 'awk -v r="$R_verlet" "BEGIN { exit !(r > 3 && r < 5.5) }"' "verlet: error ratio h vs h/2 = $R_verlet, about 4"
# small: an order-4 method at 200 steps per period on this orbit
check 'awk -v x="$H_gauss2" "BEGIN { exit !(x < 1e-5) }"' "gauss2: energy error $H_gauss2 < 1e-5"
check 'grep -q "^verlet .* 2.00 gradient evaluations per step" "$T/run200.txt"' "verlet: explicit, 2 gradients per step"

[ $fail -eq 0 ] && echo "ok: kepler example (gauss2 dH $H_gauss2, ratio $R_gauss2; verlet dH $H_verlet, ratio $R_verlet)"
exit $fail
