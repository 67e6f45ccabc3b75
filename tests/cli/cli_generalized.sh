#!/bin/bash
# cli_generalized.sh VIGEN SRC — splitting files with named flows: the
# generalized orders of the library's near-integrable methods equal the
# papers' tables (Laskar & Robutel 2001: SABA_n is O(eps h^2n + eps^2 h^2),
# and the eps^2 h^2 coefficient of SABA_n is their g_n, 1/12, (2 - sqrt 3)/24,
# (54 - 13 sqrt 15)/648; Blanes et al. 2013: (10,6,4); Wisdom-Holman (2,2)
# and, with the Wisdom-Holman-Touma corrector, (4,2)); a kernel processed by
# itself (C = K, so that C K C^-1 = K) keeps its orders, and a corrector
# that is not near the identity (C = the Kepler flow for 4h/21) spoils them
# (e^(x h ad A) (h eps B) has the term x h^2 eps [A,B]);
# naming the other flow the perturbation swaps the letters; a false claim
# fails with a message that gives the certified orders (exit 1); malformed
# files are refused with one line naming the file and the entry (exit 2).
set -u
VIGEN=$1
SRC=$2
T=$(mktemp -d /tmp/vigen-cli-generalized-XXXXXX)
trap 'rm -rf "$T"' EXIT
fail=0
bad() { echo "FAIL: $*"; fail=1; }
P=$SRC/tableaux/published

# name  generalized order (the papers')  classical order
while read -r name orders p; do
  [ -n "$name" ] || continue
  "$VIGEN" check "$P/$name.lua" --json > "$T/$name.json" 2> "$T/err"
  rc=$?
  [ $rc = 0 ] || bad "$name: exit $rc ($(head -2 "$T/err"))"
  python3 - "$T/$name.json" "$orders" "$p" <<'PY' || bad "$name: expected generalized order $orders, classical $p"
import json, sys
g = json.load(open(sys.argv[1]))["generalized_order"]
want = [int(x) for x in sys.argv[2].split(",")]
ok = g["orders"] == want and g["classical_order"] == int(sys.argv[3]) and g["claim_status"] == "holds"
ok = ok and all(s == "decided" for s in g["orders_status"]) and g["classical_status"] == "decided"
if not ok:
    print(json.dumps(g)[:400])
sys.exit(0 if ok else 1)
PY
done <<'EOF'
saba_1 2,2 2
saba_2 4,2 2
saba_3 6,2 2
saba_4 8,2 2
saba_10_6_4 10,6,4 4
wisdom_holman 2,2 2
wisdom_holman_corrected 4,2 2
EOF

# the eps^2 h^2 term of SABA_n: [[A,B],B] with Laskar & Robutel's g_n; the
# eps h^2 term of the Wisdom-Holman map: [A,[A,B]] with 1/12 (symmetric BCH)
python3 - "$T" <<'PY' || fail=1
import json, math, sys
t = sys.argv[1]
def term(name, eps):
    g = json.load(open("%s/%s.json" % (t, name)))["generalized_order"]
    for e in g["terms"]:
        if e["eps"] == eps:
            return {x["bracket"]: x["coefficient"] for x in e["terms"]}
want = {"saba_1": 1 / 12, "saba_2": (2 - math.sqrt(3)) / 24, "saba_3": (54 - 13 * math.sqrt(15)) / 648}
ok = True
for name, gn in want.items():
    got = term(name, 2)
    if list(got) != ["[[A,B],B]"] or abs(got["[[A,B],B]"] - gn) > 1e-15:
        print("FAIL: %s: eps^2 h^2 term %r, Laskar-Robutel g = %.17g" % (name, got, gn)); ok = False
got = term("wisdom_holman", 1)
if list(got) != ["[A,[A,B]]"] or abs(abs(got["[A,[A,B]]"]) - 1 / 12) > 1e-15:
    print("FAIL: wisdom_holman: eps h^2 term %r, expected +-1/12" % got); ok = False
sys.exit(0 if ok else 1)
PY

# the 40-digit decimals of (10,6,4): its orders hold to the data's precision
python3 -c "
import json, sys
g = json.load(open(sys.argv[1]))['generalized_order']
sys.exit(0 if g['rounded'] and g['within_data'] else 1)" "$T/saba_10_6_4.json" || bad "saba_10_6_4: not read as rounded data"

# processed by itself saba_3 keeps (6,2); by a Kepler step of 4h/21 it has
# order 1 (eps h); the perturbation named swaps A and B
sed -e 's/^  splitting = {/  corrector = { { "kepler", c1 }, { "interaction", d1 }, { "kepler", c2 }, { "interaction", d2 }, { "kepler", c2 }, { "interaction", d1 }, { "kepler", c1 } },\n&/' "$P/saba_3.lua" > "$T/self.lua"
"$VIGEN" check "$T/self.lua" > "$T/out" 2>&1 || bad "saba_3 processed by itself: exit $? ($(tail -3 "$T/out"))"
grep -q "generalized order (6,2)" "$T/out" && grep -q "the step C K C^-1" "$T/out" || bad "saba_3 processed by itself: $(grep -A1 '^generalized' "$T/out")"
sed -e 's/generalized_order = {6, 2},//' -e 's/^  splitting = {/  corrector = { { "kepler", "1\/3" }, { "kepler", "-1\/7" } },\n&/' "$P/saba_3.lua" > "$T/shift.lua"
"$VIGEN" check "$T/shift.lua" > "$T/out" 2>&1
grep -q "generalized order (1,2): error O(eps h^1 + eps^2 h^2); classical order 1" "$T/out" || bad "saba_3 shifted by a Kepler step: $(grep -A1 '^generalized' "$T/out")"
sed -e 's/perturbation = "interaction"/perturbation = "kepler"/' -e 's/generalized_order = {4, 2},//' "$P/saba_2.lua" > "$T/swap.lua"
"$VIGEN" check "$T/swap.lua" > "$T/out" 2>&1 || bad "saba_2 with eps on kepler: exit $?"
grep -q "^generalized   H = interaction + eps kepler (A = interaction, B = kepler)" "$T/out" || bad "perturbation not swapped: $(grep '^generalized' "$T/out")"
grep -q "Lie basis .*A kepler, B interaction" "$T/out" || bad "the Lie basis does not name its letters: $(grep 'Lie basis' "$T/out")"

# a false claim: exit 1, the message gives the certified orders
sed -e 's/generalized_order = {4, 2}/generalized_order = {6, 2}/' "$P/saba_2.lua" > "$T/wrong.lua"
"$VIGEN" check "$T/wrong.lua" > "$T/out" 2>&1
rc=$?
[ $rc = 1 ] || bad "false claim: exit $rc"
grep -q "claim generalized_order = (6,2) is false: the generalized order for H = kepler + eps interaction is (4,2)" "$T/out" \
  || bad "false claim message: $(grep -i 'generalized_order' "$T/out")"
# a shorter list claims that the terms beyond are dominated: {4, 2} and {4, 2, 2} hold, {4} does not
sed -e 's/generalized_order = {4, 2}/generalized_order = {4, 2, 2}/' "$P/saba_2.lua" > "$T/long.lua"
"$VIGEN" check "$T/long.lua" > /dev/null 2>&1 || bad "claim {4, 2, 2}: exit $?"
sed -e 's/generalized_order = {4, 2}/generalized_order = {4}/' "$P/saba_2.lua" > "$T/short.lua"
"$VIGEN" check "$T/short.lua" > /dev/null 2>&1
[ $? = 1 ] || bad "claim {4} (eps^2 h^2 is there) does not fail"

# malformed files: exit 2, one line naming the file and the entry
. "$(dirname "$0")/refuse.bash"
K='{ "kepler", "1/2" }, { "interaction", "1" }, { "kepler", "1/2" }'
echo "return { name = 'u', flows = { 'kepler', 'interaction' }, splitting = { { 'kepler', '1/2' }, { 'interactoin', '1' }, { 'kepler', '1/2' } } }" > "$T/unknown.lua"
refuse unknown.lua 'splitting[2][1] "interactoin" is not a flow of this file ("kepler", "interaction")'
echo "return { name = 'd', flows = { 'kepler', 'kepler' }, splitting = { $K } }" > "$T/dup.lua"
refuse dup.lua 'flows[2] "kepler" repeats flows[1]'
echo "return { name = 'o', flows = { 'kepler' }, splitting = { { 'kepler', '1' }, { 'kepler', '1' } } }" > "$T/one.lua"
refuse one.lua "'flows' must be a plain list of 2 to"
echo "return { name = 's', flows = { 'kepler', 'interaction' }, splitting = { $K }, corrector = { { 'kepler', '1', '2' } } }" > "$T/shape.lua"
refuse shape.lua 'corrector[1] must be {FLOW, coef} with FLOW one of "kepler", "interaction"'
echo "return { name = 'e', flows = { 'kepler', 'interaction' }, splitting = { $K }, corrector = {} }" > "$T/empty.lua"
refuse empty.lua "'corrector' must be a plain list of 1 to"
echo "return { name = 'p', flows = { 'kepler', 'interaction' }, perturbation = 'moon', splitting = { $K } }" > "$T/pert.lua"
refuse pert.lua "'perturbation' must name one of the flows"
echo "return { name = 't', flows = { 'a', 'b', 'c' }, splitting = { { 'a', '1' }, { 'b', '1' }, { 'c', '1' } } }" > "$T/three.lua"
refuse three.lua "not decided for more than two flows"
echo "return { name = 'k', generalized_order = { 2, 2 }, splitting = { { 'kick', '1/2' }, { 'drift', '1' }, { 'kick', '1/2' } } }" > "$T/kd.lua"
refuse kd.lua "'generalized_order' (a claim) must be a plain list"
echo "return { name = 'k', perturbation = 'kick', splitting = { { 'kick', '1/2' }, { 'drift', '1' }, { 'kick', '1/2' } } }" > "$T/kdp.lua"
refuse kdp.lua "'perturbation' names one of the 'flows'"

exit $fail
