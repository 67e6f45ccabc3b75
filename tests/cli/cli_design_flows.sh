#!/bin/bash
# cli_design_flows.sh VIGEN SRC — splittings of two named flows for
# H = A + eps B, designed from their generalized order: the symmetric
# three-step family of generalized order (6, 2) asks that the steps of B sit
# at the nodes of a quadrature exact to degree 5 with the B steps as weights,
# so its real solutions are Laskar and Robutel's SABA_3 (Gauss-Legendre:
# c1 = 1/2 - sqrt(15)/10, c2 = sqrt(15)/10, d1 = 5/18, d2 = 4/9) and the same
# nodes visited in the other order (c1 = 1/2 + sqrt(15)/10, c2 = -sqrt(15)/10),
# and no other; likewise SABA_2 for (4, 2) (c1 = 1/2 -+ sqrt(3)/6,
# c2 = +-sqrt(3)/3, d1 = 1/2).  Every digit is compared with the closed forms
# by mpmath; the files name the flows, the perturbation and the
# generalized_order the checker certifies (asked (3, 2), the two-step
# family claims the (4, 2) it reaches); the grade takes words of length up
# to r_j, so a non-symmetric SBAB splitting of (3, 2) is the Gauss-Radau
# rule (B at 0 and 2/3, weights 1/4 and 3/4).  Ill-posed fields are refused
# with one line and exit status 2.
set -u
VIGEN=$1
T=$(mktemp -d /tmp/vigen-cli-design-flows-XXXXXX)
trap 'rm -rf "$T"' EXIT
export TMPDIR="$T/tmp"
mkdir -p "$TMPDIR"
fail=0
bad() { echo "FAIL: $*"; fail=1; }

design() {   # name stages generalized flows claim [symmetric [first]]
  cat > "$T/$1.lua" <<LUA
return { name = "$1", design = "splitting", stages = $2, symmetric = ${6:-true}, ${7:-}
         flows = $4, perturbation = "interaction",
         generalized_order = $3, solutions = "all" }
LUA
  mkdir "$T/$1"
  "$VIGEN" design "$T/$1.lua" -o "$T/$1" > "$T/$1.out" 2> "$T/$1.err" || bad "$1: exit $? ($(cat "$T/$1.err"))"
  for g in "$T/$1"/*.lua; do
    "$VIGEN" check "$g" > "${g%.lua}.check" 2>&1 || bad "$g: check fails"
    grep -q "claim generalized_order = $5: holds" "${g%.lua}.check" || bad "$g: generalized order claim not certified"
  done
}
design saba3 3 "{6, 2}" '{ "kepler", "interaction" }' "{6, 2}"
design saba2 2 "{4, 2}" '{ "kepler", "interaction" }' "{4, 2}"
# the perturbation may be listed first: the same methods, the flows as listed
design saba3r 3 "{6, 2}" '{ "interaction", "kepler" }' "{6, 2}"
# asked (3, 2), the two-step symmetric family goes beyond: it claims (4, 2)
design g32 2 "{3, 2}" '{ "kepler", "interaction" }' "{4, 2}"
# the grade counts the length up to r_j: (3, 2) asks [A B] and [A A B], so
# B steps at 0 and 2/3 with weights 1/4, 3/4 (the Gauss-Radau rule) and
# drifts 0, 2/3, 1/3, which the checker certifies of generalized order (3, 2)
design radau 2 "{3, 2}" '{ "kepler", "interaction" }' "{3, 2}" false 'first = "kick",'
grep -q '{ "kepler", "0.6666666666666666666666666666666666666667" }' "$T/radau/radau_1.lua" &&
  grep -q '{ "interaction", "0.2500000000000000000000000000000000000000" }' "$T/radau/radau_1.lua" &&
  grep -q '{ "interaction", "0.7500000000000000000000000000000000000000" }' "$T/radau/radau_1.lua" &&
  grep -q '{ "kepler", "0.3333333333333333333333333333333333333333" }' "$T/radau/radau_1.lua" &&
  [ ! -e "$T/radau/radau_2.lua" ] || bad "radau: not the Gauss-Radau splitting alone"

python3 - "$T" <<'PY' || fail=1
import glob, re, sys
from mpmath import mp, mpf, sqrt
mp.dps = 60
T = sys.argv[1]
bad = []

def within_half_ulp(text, exact):
    digits = len(text.split(".")[1]) if "." in text else 0
    return abs(mpf(text) - exact) <= mpf(10) ** (-digits) / 2

def family(name, kepler, interaction, flows):
    files = sorted(glob.glob(f"{T}/{name}/*.lua"))
    want = [(kepler(s), interaction) for s in (-1, 1)]
    if len(files) != 2:
        bad.append(f"{name}: {len(files)} solutions, not 2")
        return
    found = set()
    for f in files:
        text = open(f).read()
        if 'flows = { %s }' % flows not in text or 'perturbation = "interaction"' not in text:
            bad.append(f"{f}: flows or perturbation not named")
        steps = re.findall(r'\{ "(kepler|interaction)", "([-0-9.]+)" \}', text)
        a = [v for k, v in steps if k == "kepler"]
        b = [v for k, v in steps if k == "interaction"]
        for s, (ka, kb) in enumerate(want):
            if len(a) == len(ka) and len(b) == len(kb) and all(within_half_ulp(x, e) for x, e in zip(a, ka)) \
               and all(within_half_ulp(x, e) for x, e in zip(b, kb)) and all(len(x) > 40 for x in a + b if x != "0.5"):
                found.add(s)
    if found != {0, 1}:
        bad.append(f"{name}: the closed forms found {sorted(found)} of [0, 1] (SABA and its reversed nodes)")

# SABA_3: c1 = 1/2 - sqrt(15)/10, c2 = sqrt(15)/10; reversed: signs of sqrt(15) flipped
r15 = sqrt(15) / 10
family("saba3", lambda s: [mpf(1) / 2 + s * r15, -s * r15, -s * r15, mpf(1) / 2 + s * r15],
       [mpf(5) / 18, mpf(4) / 9, mpf(5) / 18], '"kepler", "interaction"')
family("saba3r", lambda s: [mpf(1) / 2 + s * r15, -s * r15, -s * r15, mpf(1) / 2 + s * r15],
       [mpf(5) / 18, mpf(4) / 9, mpf(5) / 18], '"interaction", "kepler"')
r3 = sqrt(3) / 6
family("saba2", lambda s: [mpf(1) / 2 + s * r3, -2 * s * r3, mpf(1) / 2 + s * r3],
       [mpf(1) / 2, mpf(1) / 2], '"kepler", "interaction"')
for b in bad: print("FAIL:", b)
sys.exit(1 if bad else 0)
PY

# ill-posed fields: one line, exit status 2
refuse() {   # label, fields, expected text
  printf 'return { name = "x", design = "splitting", stages = 3, symmetric = true, solutions = "all", %s }\n' "$2" > "$T/$1.lua"
  "$VIGEN" design "$T/$1.lua" -o "$T" > "$T/$1.out" 2> "$T/$1.err"
  rc=$?
  [ "$rc" = 2 ] || bad "$1: exit $rc, not 2"
  [ "$(wc -l < "$T/$1.err")" = 1 ] || bad "$1: not one line: $(cat "$T/$1.err")"
  grep -q -- "$3" "$T/$1.err" || bad "$1: message $(cat "$T/$1.err") lacks '$3'"
}
refuse stranger 'flows = { "kepler", "interaction" }, perturbation = "drag", generalized_order = {6, 2}' \
  "perturbation: 'drag' is not one of the flows"
refuse zero 'flows = { "kepler", "interaction" }, perturbation = "interaction", generalized_order = {6, 0}' \
  "generalized_order: must be a list"
refuse notlist 'flows = { "kepler", "interaction" }, perturbation = "interaction", generalized_order = 6' \
  "generalized_order: must be a list"
refuse text 'flows = { "kepler", "interaction" }, perturbation = "interaction", generalized_order = { "6" }' \
  "generalized_order: must be a list"
refuse three 'flows = { "kepler", "interaction", "drag" }, perturbation = "interaction", generalized_order = {6, 2}' \
  "flows: must be a list of two different flow names"
refuse same 'flows = { "kepler", "kepler" }, perturbation = "kepler", generalized_order = {6, 2}' \
  "flows: must be a list of two different flow names"
refuse noflows 'order = 2, generalized_order = {6, 2}' "generalized_order: needs flows"
refuse nopert 'flows = { "kepler", "interaction" }, generalized_order = {6, 2}' "perturbation: missing"
refuse minimize 'flows = { "kepler", "interaction" }, perturbation = "interaction", generalized_order = {6, 2}, solutions = nil, minimize = "error_constant"' \
  'flows: a splitting of named flows asks solutions = "all"'
refuse noorder 'flows = { "kepler", "interaction" }, perturbation = "interaction"' "order: missing"
exit $fail
