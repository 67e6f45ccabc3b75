#!/bin/bash
# cli_design_library.sh VIGEN SRC — the library's methods re-derived from
# their families (tests/data/design/library/): McLachlan and Atela's optimal
# second- and third-order methods are stationary points of the norm of the
# principal error, found and certified by `vigen design`, equal within half a
# unit of the 40th digit to their closed forms (1 - 1/sqrt 2; the root of
# 12x^4 - 24x^2 + 16x - 3, evaluated by mpmath here) and to the 18 digits
# McLachlan and Atela print, and the one among the stationary points with
# the smallest Lyndon norm (`vigen check`); the Blanes-Moan files hold the
# digits the design run finds (the exact member nearest the printed
# coefficients), and the printed decimals agree with them except the last
# digits docs/published.md lists as wrong; optimal_s6_4 holds the digits its
# design run proves; optimal_rkn6_4 holds the digits its design run finds
# (the search screened and seeded, so reproducible), of 6 forces per step
# with a Nystrom error constant, by the checker, below Blanes-Moan S6's;
# optimal_rkn7_6 is one of the roots its family's run
# proves, of order 6 for Nystrom H, with a smaller Nystrom error constant
# than Yoshida's sixth order of the same cost, and Yoshida's A is among the
# roots; Yoshida's printed w1, w2, w3 against the library's
# yoshida_6 likewise, and McLachlan's RKN method's 20 transcribed digits
# against its closed forms; the criterion fields are refused when
# ill-posed; every re-derived or new method of
# the library is shown in every format, emitted and run without
# --allow-inexact.
set -u
VIGEN=$1
SRC=$2
T=$(mktemp -d /tmp/vigen-cli-design-library-XXXXXX)
trap 'rm -rf "$T"' EXIT
export TMPDIR="$T/tmp"
mkdir -p "$TMPDIR"
fail=0
bad() { echo "FAIL: $*"; fail=1; }
D=$SRC/tests/data/design/library
P=$SRC/tableaux/published

for f in mclachlan_atela_2 mclachlan_atela_3 blanes_moan_s6_4 blanes_moan_s10_6 optimal_s6_4 optimal_rkn7_6 optimal_rkn6_4; do
  mkdir "$T/$f"
  "$VIGEN" design "$D/$f.lua" -o "$T/$f" > "$T/$f.out" 2> "$T/$f.err" || { bad "$f: exit $? ($(cat "$T/$f.err"))"; continue; }
  for g in "$T/$f"/*.lua; do "$VIGEN" check "$g" --json > "${g%.lua}.json" 2>/dev/null || bad "$g: check fails"; done
done
for f in yoshida_6 blanes_moan_s6_4; do
  "$VIGEN" check "$P/$f.lua" --json > "$T/$f.json" 2>/dev/null || bad "$f: check fails"
done

python3 - "$T" "$P" <<'PY' || fail=1
import glob, json, re, sys
from mpmath import mp, mpf, sqrt, findroot
mp.dps = 60
T, P = sys.argv[1], sys.argv[2]
bad = []

def steps(path):
    """the substeps (kind, decimal text) of a splitting file, in order"""
    return re.findall(r'\{ "(drift|kick)", "([-0-9.]+)" \}', open(path).read())

def within_half_ulp(text, exact):
    """the exact value lies within half a unit of the last digit of text"""
    digits = len(text.split(".")[1]) if "." in text else 0
    return abs(mpf(text) - exact) <= mpf(10) ** (-digits) / 2

def rounds_to(value, printed):
    """printed is value rounded to the printed number of decimals"""
    digits = len(printed.split(".")[1])
    return abs(mpf(printed) - value) <= mpf(10) ** (-digits) / 2

def lyndon_norm(path):
    return json.load(open(path[:-4] + ".json"))["lie_error"]["norm"]

# McLachlan-Atela 2: kick 1 - 1/sqrt 2, drift 1/sqrt 2, kick 1/sqrt 2, drift 1 - 1/sqrt 2
r = 1 / sqrt(2)
ma2 = [mpf(0), 1 - r, r, r, 1 - r]
files = sorted(glob.glob(T + "/mclachlan_atela_2/*.lua"))
hit = [f for f in files if all(within_half_ulp(t, x) for (_, t), x in zip(steps(f), ma2))]
if len(hit) != 1: bad.append("MA2: %d files equal the closed form" % len(hit))
elif lyndon_norm(hit[0]) != min(lyndon_norm(f) for f in files): bad.append("MA2: not the smallest norm")

# McLachlan-Atela 3: a1 the root near 0.92 of 12x^4 - 24x^2 + 16x - 3,
# a2 = 1/(4 a1) - a1/2, a3 = 1 - a1 - a2; kicks (a3, a2, a1), drifts (a1, a2, a3)
a1 = findroot(lambda x: 12 * x**4 - 24 * x**2 + 16 * x - 3, mpf("0.92"))
a2 = 1 / (4 * a1) - a1 / 2
a3 = 1 - a1 - a2
ma3 = [mpf(0), a3, a1, a2, a2, a1, a3]
files = sorted(glob.glob(T + "/mclachlan_atela_3/*.lua"))
hit = [f for f in files if all(within_half_ulp(t, x) for (_, t), x in zip(steps(f), ma3))]
if len(hit) != 1: bad.append("MA3: %d files equal the closed form" % len(hit))
else:
    if lyndon_norm(hit[0]) != min(lyndon_norm(f) for f in files): bad.append("MA3: not the smallest norm")
    got = [mpf(t) for _, t in steps(hit[0])]
    for name, printed, v in (("a1", "0.919661523017399857", got[2]), ("a2", "-0.187991618799159782", got[3]),
                             ("a3", "0.268330095781759925", got[1])):
        if not rounds_to(v, printed): bad.append("MA3: printed %s = %s is not the rounding of %s" % (name, printed, v))

# Blanes-Moan: the library file holds the design's digits; the printed
# decimals are their roundings except the digits docs/published.md lists
printed = {
    "blanes_moan_s6_4": (["a1", "b1", "a2", "b2", "a3", "b3", "a4"],
                         {"a1": "0.0792036964311957", "a2": "0.353172906049774", "a3": "-0.0420650803577195",
                          "b1": "0.209515106613362", "b2": "-0.143851773179818"}, set()),
    "blanes_moan_s10_6": (["a1", "b1", "a2", "b2", "a3", "b3", "a4", "b4", "a5", "b5", "a6"],
                          {"a1": "0.0502627644003922", "a2": "0.413514300428344", "a3": "0.0450798897943977",
                           "a4": "-0.188054853819569", "a5": "0.541960678450780", "b1": "0.148816447901042",
                           "b2": "-0.132385865767784", "b3": "0.067307604692185", "b4": "0.432666402578175"},
                          {"a1", "a2", "a3", "b1", "b3", "b4"}),
}
for name, (order, pr, wrong) in printed.items():
    design = steps(glob.glob(T + "/" + name + "/*_1.lua")[0])
    text = open(P + "/" + name + ".lua").read()
    stored = re.findall(r'"(-?0\.[0-9]{38,})"', text)
    d = [t for _, t in design]
    if sorted(set(d)) != sorted(set(stored)): bad.append("%s: the library's digits are not the design's" % name)
    value = dict(zip(order, (mpf(t) for t in d)))
    found = {k for k, p in pr.items() if not rounds_to(value[k], p)}
    if found != wrong: bad.append("%s: printed digits wrong: %s, docs say %s" % (name, sorted(found), sorted(wrong)))

# the new six-kick splitting: the library holds the digits the design proves
design = [t for _, t in steps(glob.glob(T + "/optimal_s6_4/*_1.lua")[0])]
stored = re.findall(r'"(-?[01]\.[0-9]{38,})"', open(P + "/optimal_s6_4.lua").read())
if sorted(set(design)) != sorted(set(stored)): bad.append("optimal_s6_4: the library's digits are not the design's")

# the seven-kick RKN splitting of order 4 that starts with a kick (6 forces
# per step): the library holds the digits its design run finds, and the
# checker gives it a smaller Nystrom error constant than Blanes-Moan S6 of
# the same cost (by a factor of at least 5; the optimiser is not consulted)
f = glob.glob(T + "/optimal_rkn6_4/*_1.lua")[0]
design = [t for _, t in steps(f)]
stored = re.findall(r'"(-?0\.[0-9]{38,})"', open(P + "/optimal_rkn6_4.lua").read())
if sorted(set(design)) != sorted(set(stored)): bad.append("optimal_rkn6_4: the library's digits are not the design's")
if [k for k, _ in steps(f)][0] != "kick" or len(steps(f)) != 13: bad.append("optimal_rkn6_4: not 7 kicks starting with one")
n = json.load(open(f[:-4] + ".json"))
s6 = json.load(open(T + "/blanes_moan_s6_4.json"))
if n["evaluations_per_step"] != 6 or s6["evaluations_per_step"] != 6:
    bad.append("optimal_rkn6_4: %s forces per step against S6's %s" % (n["evaluations_per_step"], s6["evaluations_per_step"]))
ny, sy = n["error_constants"]["nystrom"], s6["error_constants"]["nystrom"]
if ny["order"] != 4 or not ny["value"] < sy["value"] / 5:
    bad.append("optimal_rkn6_4: Nystrom order %s constant %s against blanes_moan_s6_4's %s" % (ny["order"], ny["value"], sy["value"]))

# the seven-kick RKN splitting: one of the proved roots of its family, digit
# for digit; of order 6 for Nystrom H, with a smaller Nystrom constant than
# yoshida_6 (7 forces too), which as a splitting is a root of the same family
def values(path):
    text = open(path).read()
    local = dict(re.findall(r'local (\w+) = "([-0-9.]+)"', text))
    return [local.get(t, t) for t in re.findall(r'\{ "(?:drift|kick)", "?([-\w.]+)"? \}', text)]
def nystrom(path):
    return json.load(open(path[:-4] + ".json"))["error_constants"]["nystrom"]
roots = sorted(glob.glob(T + "/optimal_rkn7_6/*.lua"))
lib = values(P + "/optimal_rkn7_6.lua")
hit = [f for f in roots if [t for _, t in steps(f)] == lib]
if len(hit) != 1: bad.append("optimal_rkn7_6: %d roots of the design equal the library's file" % len(hit))
else:
    n, y = nystrom(hit[0]), json.load(open(T + "/yoshida_6.json"))["error_constants"]["nystrom"]
    if n["order"] != 6 or not n["value"] < y["value"] / 30:
        bad.append("optimal_rkn7_6: Nystrom order %s constant %s against yoshida_6's %s" % (n["order"], n["value"], y["value"]))
# Yoshida's A (w3 w2 w1 w0 w1 w2 w3 of position Verlet) as a splitting:
# its third kick is w1
w1 = mpf(re.search(r'local w1 = "([-0-9.]+)"', open(P + "/yoshida_6.lua").read()).group(1))
if not any(steps(f)[5][0] == "kick" and abs(mpf(steps(f)[5][1]) - w1) < mpf(10) ** -35 for f in roots):
    bad.append("optimal_rkn7_6: Yoshida's A is not among the roots")

# Yoshida (1990) Table 1, solution A, against the library's 50 digits
text = open(P + "/yoshida_6.lua").read()
w = {k: mpf(re.search(r'local %s = "([-0-9.]+)"' % k, text).group(1)) for k in ("w1", "w2", "w3")}
found = {k for k, p in (("w1", "-1.17767998417887"), ("w2", "0.235573213359357"), ("w3", "0.784513610477560"))
         if not rounds_to(w[k], p)}
if found != {"w2", "w3"}: bad.append("yoshida_6: printed digits wrong: %s, docs say w2, w3" % sorted(found))

# McLachlan (1995) as transcribed with 20 digits against the library's closed forms
a1 = (1095 * sqrt(722025967665) - 229483763) / 1729961856
a2 = (315354233 - 1081 * sqrt(722025967665)) / 2100667968
text = open(P + "/mclachlan_rkn_4.lua").read()
if "722025967665" not in text: bad.append("mclachlan_rkn_4: not the closed form")
for name, printed, v in (("a1", "0.40518861839525227722", a1), ("a2", "-0.28714404081652408900", a2)):
    if not rounds_to(v, printed): bad.append("mclachlan_rkn_4: printed %s = %s is not the rounding of %s" % (name, printed, v))

for b in bad: print("FAIL:", b)
sys.exit(1 if bad else 0)
PY

# the criterion fields refused when ill-posed: exit 2, one line naming the field
refuse() {
  printf '%s\n' "$2" > "$T/bad.lua"
  "$VIGEN" design "$T/bad.lua" -o "$T" > "$T/bad.out" 2> "$T/bad.err"
  rc=$?
  { [ $rc = 2 ] && grep -q "$1" "$T/bad.err" && [ "$(wc -l < "$T/bad.err")" = 1 ]; } ||
    bad "refusal '$1': exit $rc, $(cat "$T/bad.err")"
}
refuse "nearest: 2 values for the 7 unknowns" \
  'return { name = "b", design = "splitting", stages = 6, order = 4, symmetric = true, nearest = { "0.1", "0.2" } }'
refuse "nearest: entry 2, .0.2x., is not a decimal" \
  'return { name = "b", design = "splitting", stages = 2, order = 2, nearest = { "0.1", "0.2x", "0", "0", "0" } }'
refuse "first: only a splitting has a first substep" \
  'return { name = "b", design = "composition", base = "stormer_verlet_position", stages = 5, order = 4, symmetric = true, stationary = "error_norm", first = "kick" }'
refuse "stationary: must be \"error_norm\"" \
  'return { name = "b", design = "splitting", stages = 2, order = 2, stationary = "smallest" }'
refuse "leave no unknown free" \
  'return { name = "b", design = "composition", base = "stormer_verlet_velocity", stages = 3, order = 4, symmetric = true, stationary = "error_norm" }'
refuse "give one of them" \
  'return { name = "b", design = "splitting", stages = 2, order = 2, stationary = "error_norm", solutions = "all" }'
refuse "equal: entry 1 must be a pair of two different unknowns" \
  'return { name = "b", design = "composition", base = "stormer_verlet_position", stages = 5, order = 4, symmetric = true, solutions = "all", equal = { { "gamma1", "gamma1" } } }'
refuse "screen: only a minimize design screens points" \
  'return { name = "b", design = "splitting", stages = 3, order = 4, symmetric = true, solutions = "all", screen = 10 }'
refuse "screen: must be a whole number" \
  'return { name = "b", design = "rkn", stages = 7, order = 4, symmetric = true, minimize = "error_constant", screen = -1 }'
[ -z "$(ls "$T"/b_*.lua 2>/dev/null)" ] || bad "a refused design wrote files"

# show (every format), emit and try without --allow-inexact
methods="yoshida_4 yoshida_6 suzuki_4 forest_ruth_4 candy_rozmus_4 ruth_3 mclachlan_atela_2 mclachlan_atela_3
         blanes_moan_s6_4 blanes_moan_s10_6 mclachlan_rkn_4 optimal_s5_4 optimal_s6_4 optimal_rkn7_6 optimal_rkn6_4"
for m in $methods; do
  for fmt in text latex json lua; do
    "$VIGEN" show "$P/$m.lua" --format $fmt > "$T/show" 2> "$T/show.err" || bad "show $m --format $fmt: $(cat "$T/show.err")"
  done
  "$VIGEN" emit "$P/$m.lua" --name s -o "$T" -q 2> "$T/emit.err" || bad "emit $m: $(cat "$T/emit.err")"
done
# shellcheck disable=SC2086
"$VIGEN" try $methods --problem kepler --time 1 > "$T/try" 2> "$T/try.err" || bad "try: exit $? ($(cat "$T/try.err"))"
grep -q "inexact\|too short" "$T/try.err" && bad "try warns of inexact decimals: $(cat "$T/try.err")"

exit $fail
