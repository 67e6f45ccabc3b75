#!/bin/bash
# cli_library.sh VIGEN SRC — the method library: `vigen list` certifies the
# orders the literature gives (Gauss with s stages 2s, Lobatto IIIA-IIIB
# 2s - 2, Radau 2s - 1: Hairer & Wanner, Solving ODEs II, IV.5, and GNI
# VI.4; Stormer-Verlet 2; the splitting methods the order their papers
# state); names resolve in the current directory, then VIGEN_PATH, then the
# library (published before generated); an installed vigen (the build
# installed into a moved prefix) knows the installed library, and its
# vigen_add_stepper takes names; unknown names get a did-you-mean hint and
# exit 2.
set -u
VIGEN=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
SRC=$(cd "$2" && pwd)
BUILD=$(dirname "$VIGEN")
T=$(mktemp -d /tmp/vigen-cli-library-XXXXXX)
trap 'rm -rf "$T"' EXIT
fail=0
bad() { echo "FAIL: $*"; fail=1; }
cd "$T" || exit 1

"$VIGEN" list --json > list.json 2> err || bad "vigen list --json: exit $? ($(cat err))"
python3 - "$SRC" <<'PY' || fail=1
import json, os, sys
src = sys.argv[1]
ms = json.load(open("list.json"))["methods"]
ok = True
for part in ("published", "generated"):
    want = sorted(f[:-4] for f in os.listdir(os.path.join(src, "tableaux", part)) if f.endswith(".lua"))
    got = sorted(m["name"] for m in ms if m["directory"] == part)
    if want != got:
        print("FAIL: %s: listed %s, folder has %s" % (part, got, want)); ok = False
first = {}
for m in ms:
    if not m["shadowed"]:
        first.setdefault(m["name"], m)
def order(name):
    o = first[name]["orders"]["general"]
    return o["order"], o["at_least"]
expect = {"gauss_1": 2, "gauss_2": 4, "gauss_3": 6, "lobatto_iiia_iiib_2": 2, "lobatto_iiia_iiib_3": 4,
          "lobatto_iiia_iiib_4": 6, "stormer_verlet_velocity": 2, "stormer_verlet_position": 2,
          "symplectic_euler_p_first": 1, "yoshida_4": 4, "forest_ruth_4": 4, "suzuki_4": 4, "candy_rozmus_4": 4,
          "blanes_moan_s6_4": 4, "yoshida_6": 6, "blanes_moan_s10_6": 6, "ruth_3": 3, "mclachlan_atela_3": 3}
for s in range(1, 9):
    expect["gauss_legendre_s%d" % s] = 2 * s
for s in range(2, 5):
    expect["gauss_lobatto_s%d" % s] = 2 * s - 2
    expect["radau_right_s%d" % s] = 2 * s - 1
for name, p in sorted(expect.items()):
    got = order(name)
    if got != (p, False):
        print("FAIL: %s: order %s, the literature says %d" % (name, got, p)); ok = False
for s in (5, 6):      # beyond what the trees enumerated and the theorem decide: at least 8, at most 2s - 2
    got = order("gauss_lobatto_s%d" % s)
    if not (got[0] <= 2 * s - 2 and (got[1] or got[0] == 2 * s - 2)):
        print("FAIL: gauss_lobatto_s%d: %s" % (s, got)); ok = False
shadow = [m for m in ms if m["name"] == "leok_zhang_ex4"]
if [m["directory"] for m in shadow] != ["published", "generated"] or [m["shadowed"] for m in shadow] != [False, True]:
    print("FAIL: leok_zhang_ex4 in both parts: %r" % shadow); ok = False
sys.exit(0 if ok else 1)
PY

# a name is the library's file
"$VIGEN" show gauss_3 --format json > by_name.json 2> err || bad "show gauss_3: $(cat err)"
"$VIGEN" show "$SRC/tableaux/published/gauss_3.lua" --format json > by_path.json
cmp -s by_name.json by_path.json || bad "show gauss_3 differs from the published file"
"$VIGEN" show generated/leok_zhang_ex4 > gen.txt 2> err || bad "show generated/leok_zhang_ex4: $(cat err)"
grep -q "certified digits" gen.txt || bad "generated/leok_zhang_ex4 is not the generated file: $(head -3 gen.txt)"
# the current directory first, then VIGEN_PATH, then the library
mkdir -p mine here
sed 's/name = "gauss_1"/name = "mine_gauss_1"/' "$SRC/tableaux/published/gauss_1.lua" > mine/gauss_2.lua
cp "$SRC/tableaux/published/yoshida_4.lua" mine/my_method.lua
VIGEN_PATH="$T/nowhere:$T/mine" "$VIGEN" show gauss_2 > v.txt 2>&1 || bad "VIGEN_PATH: $(cat v.txt)"
grep -q "^mine_gauss_1: 1 stage" v.txt || bad "VIGEN_PATH does not come before the library: $(head -1 v.txt)"
VIGEN_PATH="$T/mine" "$VIGEN" check my_method > c.txt 2>&1 || bad "check my_method from VIGEN_PATH: $(tail -2 c.txt)"
sed 's/name = "stormer_verlet_velocity"/name = "here_verlet"/' "$SRC/tableaux/published/stormer_verlet_velocity.lua" > here/gauss_2.lua
(cd here && VIGEN_PATH="$T/mine" "$VIGEN" show gauss_2.lua) > h.txt 2>&1
grep -q "^here_verlet: 2 stages" h.txt || bad "the current directory does not come first: $(head -1 h.txt)"
# unknown names: a hint, exit 2, nothing on standard output
"$VIGEN" check gaus_2 > out 2> err
rc=$?
[ $rc = 2 ] && [ ! -s out ] && grep -q "did you mean 'gauss_2'" err && grep -q "vigen list" err \
  || bad "unknown name: exit $rc, $(cat err)"
"$VIGEN" compare gauss_2 yoshida_4 > cmp.txt 2>&1 || bad "compare by names: $(cat cmp.txt)"

# an installed vigen, its prefix moved, lists and resolves the installed library
if [ -f "$BUILD/CMakeCache.txt" ] && cmake --install "$BUILD" --prefix "$T/prefix" > install.log 2>&1; then
  mv "$T/prefix" "$T/moved"
  "$T/moved/bin/vigen" list > inst.txt 2>&1 || bad "installed list: $(tail -3 inst.txt)"
  n=$(grep -cE " (published|generated) " inst.txt)
  want=$(( $(ls "$SRC"/tableaux/published/*.lua | wc -l) + $(ls "$SRC"/tableaux/generated/*.lua | wc -l) ))
  [ "$n" = "$want" ] || bad "installed list has $n methods, the library $want"
  "$T/moved/bin/vigen" show gauss_legendre_s3 > inst_show.txt 2>&1 || bad "installed show by name: $(cat inst_show.txt)"
  grep -q "moved/.*tableaux/generated/" <("$T/moved/bin/vigen" list --json) || bad "installed list does not read the installed files"
  # vigen_add_stepper takes a method name in place of a file
  mkdir -p "$T/proj"
  cat > "$T/proj/CMakeLists.txt" <<'CM'
cmake_minimum_required(VERSION 3.16)
project(by_name C)
find_package(vigen REQUIRED)
vigen_add_stepper(TARGET g2 TABLEAU gauss_2 NAME g2)
vigen_add_stepper(TARGET g3 TABLEAU generated/gauss_legendre_s3 NAME g3)
add_executable(by_name main.c)
target_link_libraries(by_name PRIVATE g2 g3)
CM
  cat > "$T/proj/main.c" <<'C'
#include <stdio.h>
#include "g2.h"
#include "g3.h"
int main(void) { printf("%d %d %zu\n", G2_ORDER, G3_ORDER, g2_dim()); return 0; }
C
  if cmake -S "$T/proj" -B "$T/proj/build" -DCMAKE_PREFIX_PATH="$T/moved" > proj.log 2>&1 &&
     cmake --build "$T/proj/build" >> proj.log 2>&1; then
    # Gauss s = 2 and s = 3: orders 4 and 6 (Hairer, Lubich & Wanner, GNI II.1.3)
    [ "$("$T/proj/build/by_name")" = "4 6 0" ] || bad "vigen_add_stepper by name: $("$T/proj/build/by_name")"
  else
    bad "vigen_add_stepper with method names: $(tail -8 proj.log)"
  fi
else
  bad "cmake --install failed: $(tail -5 install.log)"
fi

[ $fail = 0 ] && echo "cli_library: ok"
exit $fail
