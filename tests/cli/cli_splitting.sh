#!/bin/bash
# cli_splitting.sh VIGEN SRC — splitting and composition files: the
# published splitting and composition methods written as published (kicks
# and drifts, or steps of a base method; printed decimals and the papers'
# formulas for the dependent coefficients, tests/data/published_printed/ for
# the methods the library holds re-derived) give, entry by entry, the PRK
# tableaux transcribed by hand before (tests/data/published_prk/); Yoshida's triple jump written as a
# composition of velocity Verlet with steps (x1, 1 - 2 x1, x1) h is the same
# method as its splitting; the emitted stepper of a splitting file on the
# harmonic oscillator q'' = -q reproduces the splitting applied directly
# (kick and drift maps multiplied out in Python, no vigen code) with 3 force
# and 3 velocity evaluations per step (4 kicks, the last force reused);
# malformed files are refused with a message naming the entry.
set -u
VIGEN=$1
SRC=$2
T=$(mktemp -d /tmp/vigen-cli-splitting-XXXXXX)
trap 'rm -rf "$T"' EXIT
export TMPDIR="$T/tmp"
mkdir -p "$TMPDIR"
fail=0
bad() { echo "FAIL: $*"; fail=1; }
P=$SRC/tableaux/published

for f in "$SRC"/tests/data/published_prk/*.lua; do
  name=$(basename "$f" .lua)
  # a method the library now holds re-derived (40 certified digits) is
  # compared as printed (tests/data/published_printed/)
  file=$P/$name.lua
  [ -f "$SRC/tests/data/published_printed/$name.lua" ] && file=$SRC/tests/data/published_printed/$name.lua
  grep -q "^  splitting = \|^  composition = " "$file" || bad "$name: not written as a splitting or composition"
  "$VIGEN" check "$file" --against "$f" > "$T/out" 2>&1
  rc=$?
  [ $rc = 0 ] && grep -q "^against       0 entries differ" "$T/out" || { bad "$name: splitting and PRK transcription differ (exit $rc)"; grep -E "against|problems|differ" "$T/out" | head -5; }
done

cat > "$T/yoshida_comp.lua" <<'LUA'
local x1 = "(1/(2 - 2^(1/3)))"
return { name = "yoshida_comp", order = 4, symplectic = true,
         composition = { base = "stormer_verlet_velocity", gamma = { x1, "1 - 2*" .. x1, x1 } } }
LUA
"$VIGEN" check "$T/yoshida_comp.lua" --against "$P/yoshida_4.lua" > "$T/out" 2>&1
rc=$?
[ $rc = 0 ] && grep -q "^against       0 entries differ" "$T/out" && grep -q "3 force and 3 velocity evaluations per step" "$T/out" \
  || { bad "composition of Verlet is not Yoshida's splitting (exit $rc)"; tail -5 "$T/out"; }
# a base beside the composition file, by file name
cp "$P/stormer_verlet_position.lua" "$T/base.lua"
cat > "$T/comp_local.lua" <<'LUA'
return { name = "comp_local", composition = { base = "base.lua", gamma = { "1/2", "1/2" } } }
LUA
"$VIGEN" check "$T/comp_local.lua" > "$T/out" 2>&1 || { bad "composition with a local base"; tail -3 "$T/out"; }

# the emitted splitting on q'' = -q against the splitting applied directly
"$VIGEN" try yoshida_4 --problem harmonic-oscillator --h 0.1 --time 10 --json > "$T/try.json" 2> "$T/err" || bad "try yoshida_4: $(cat "$T/err")"
python3 - "$T/try.json" <<'PY' || fail=1
import json, math, sys
m = json.load(open(sys.argv[1]))["methods"][0]
x1 = 1 / (2 - 2 ** (1 / 3))
steps = [("kick", x1 / 2), ("drift", x1), ("kick", 0.5 - x1 / 2), ("drift", 1 - 2 * x1),
         ("kick", 0.5 - x1 / 2), ("drift", x1), ("kick", x1 / 2)]
h, q, p = 0.1, 1.0, 0.0
for n in range(100):
    for kind, c in steps:
        if kind == "kick": p -= c * h * q      # V = q^2/2
        else: q += c * h * p                   # T = p^2/2
err = math.hypot(q - math.cos(10.0), p + math.sin(10.0))
ok = abs(m["global_error"] - err) <= 1e-9 * err and m["grad_evals_per_step"] <= 6.02
print("global error %.12g (direct %.12g), %.2f gradients per step" % (m["global_error"], err, m["grad_evals_per_step"]))
sys.exit(0 if ok else 1)
PY

# malformed files: the entry named, exit 2
cat > "$T/bad_kind.lua" <<'LUA'
return { name = "bad", splitting = { {"kick", "1/2"}, {"drift", "1"}, {"kik", "1/2"} } }
LUA
cat > "$T/bad_sum.lua" <<'LUA'
return { name = "bad", splitting = { {"kick", "1/2"}, {"drift", "1"}, {"kick", "1/3"} } }
LUA
cat > "$T/bad_float.lua" <<'LUA'
return { name = "bad", splitting = { {"kick", 0.5}, {"drift", "1"}, {"kick", "1/2"} } }
LUA
cat > "$T/bad_self.lua" <<'LUA'
return { name = "bad", composition = { base = "bad_self.lua", gamma = { "1" } } }
LUA
for case in "bad_kind splitting[3]" "bad_sum add up to" "bad_float splitting[1][2]" "bad_self nested more than"; do
  set -- $case
  "$VIGEN" check "$T/$1.lua" > "$T/out" 2> "$T/err"
  rc=$?
  [ $rc = 2 ] && [ ! -s "$T/out" ] && grep -qF "$2" "$T/err" && [ "$(wc -l < "$T/err")" -le 2 ] \
    || bad "$1: exit $rc, $(head -c 300 "$T/err")"
done

[ $fail = 0 ] && echo "cli_splitting: ok"
exit $fail
