#!/bin/bash
# cli_try_paths.sh VIGEN SRC — `vigen try` runs every method of `vigen list`
# on the fastest path the problem allows: a mechanical problem through the
# stepper's Nystrom form, whose force evaluations per step are the counts
# `vigen list` states for the method (its "evals" column: Yoshida's triple
# jump 3, Blanes-Moan S6 6 and S10 10, first same as last), and the library's
# methods published with 16-digit decimals (Blanes-Moan) taken with those
# digits and a warning saying so, the sixth-order one more accurate than the
# fourth-order one at the same step; the same decimals in a file of the
# user's refused unless --allow-inexact; a problem that is not mechanical
# (charged-particle) on the general path; splittings of named flows
# (Wisdom-Holman) on the problems' own Kepler flows.
set -u
VIGEN=$1
SRC=$2
T=$(mktemp -d /tmp/vigen-cli-try-paths-XXXXXX)
trap 'rm -rf "$T"' EXIT
export TMPDIR="$T/tmp"
mkdir -p "$TMPDIR"
fail=0
check() { if ! eval "$1"; then echo "FAIL: $2"; fail=1; fi; }

"$VIGEN" list --json > "$T/list.json" 2> "$T/list.err" || { echo "FAIL: vigen list"; fail=1; }
"$VIGEN" try blanes_moan_s6_4 blanes_moan_s10_6 yoshida_4 --problem kepler --time 20 --json > "$T/k.json" 2> "$T/k.err"
rc=$?
check '[ $rc -eq 0 ]' "try blanes_moan_s6_4 blanes_moan_s10_6 yoshida_4: exit $rc ($(cat "$T/k.err"))"
# the library's Blanes-Moan methods hold 40 certified digits: no warning
check '! grep -q "blanes_moan_s6_4: a method of the library" "$T/k.err"' "a warning for blanes_moan_s6_4 (40 digits)"
check '! grep -q "blanes_moan_s10_6: a method of the library" "$T/k.err"' "a warning for blanes_moan_s10_6 (40 digits)"
check '! grep -q "yoshida_4: a method of the library" "$T/k.err"' "a warning for yoshida_4, whose coefficients are exact"
python3 - "$T/k.json" "$T/list.json" <<'PY' || fail=1
import json, sys
run = {m["name"]: m for m in json.load(open(sys.argv[1]))["methods"]}
lib = json.load(open(sys.argv[2]))
lib = {m["name"]: m for m in (lib["methods"] if isinstance(lib, dict) else lib)}
bad = []
for name, m in run.items():
    steps = m["steps"]
    evals = lib[name]["evaluations_per_step"]
    # with first same as last, the first force of the run is one more
    if m["path"] != "mechanical": bad.append("%s: path %s" % (name, m["path"]))
    if not (evals <= m["grad_evals_per_step"] <= evals + 1.0 / steps + 1e-9):
        bad.append("%s: %r forces per step, vigen list says %r" % (name, m["grad_evals_per_step"], evals))
    if m["failed"] is not None: bad.append("%s failed: %s" % (name, m["failed"]))
if not run["blanes_moan_s10_6"]["global_error"] < run["blanes_moan_s6_4"]["global_error"] / 10:
    bad.append("S10 (order 6) not more accurate than S6 (order 4): %r %r"
               % (run["blanes_moan_s10_6"]["global_error"], run["blanes_moan_s6_4"]["global_error"]))
for b in bad: print("FAIL:", b)
sys.exit(1 if bad else 0)
PY

# the printed 16-digit decimals in the user's own file: refused, unless --allow-inexact
cp "$SRC/tests/data/published_printed/blanes_moan_s6_4.lua" "$T/mine.lua"
"$VIGEN" try "$T/mine.lua" --problem kepler --time 5 > "$T/m.out" 2> "$T/m.err"
rc=$?
check '[ $rc -eq 2 ] && grep -q -- "--allow-inexact" "$T/m.err"' "a user's 16-digit file not refused (exit $rc)"
"$VIGEN" try "$T/mine.lua" --problem kepler --time 5 --allow-inexact > "$T/m.out" 2> "$T/m.err"
rc=$?
check '[ $rc -eq 0 ] && grep -q "rounded .* entries to double" "$T/m.err"' "--allow-inexact: exit $rc ($(cat "$T/m.err"))"

# text output: one line says the mechanical path
"$VIGEN" try yoshida_4 --problem outer-solar-system --time 20000 > "$T/o.out" 2> "$T/o.err"
rc=$?
check '[ $rc -eq 0 ] && grep -q "^yoshida_4: mechanical problem, stepped in Nystrom form" "$T/o.out"' \
  "outer-solar-system: no mechanical path line (exit $rc)"
check 'awk "/^yoshida_4 /{ exit !(\$(NF-1) < 3.01) }" "$T/o.out"' "outer-solar-system: yoshida_4 above 3 forces per step"

# not mechanical: the general path, no such line
"$VIGEN" try gauss_1 --problem charged-particle --time 1 --json > "$T/c.json" 2> "$T/c.err"
rc=$?
check '[ $rc -eq 0 ] && grep -q "\"path\": \"general\"" "$T/c.json"' "charged-particle: not the general path (exit $rc)"

# splittings of named flows on the problems' own exact flows: Wisdom-Holman
# on kepler (the Kepler flow is the whole problem, the interaction zero:
# exact to round-off at 10 steps per period, e = 0.6), and on the outer
# solar system, whose energy error O(eps h^2) (generalized order (2, 2))
# falls by 4 per halving of h, the corrected kernel's far below it
"$VIGEN" try wisdom_holman --problem kepler --steps-per-period 10 --time 200 --json > "$T/wk.json" 2> "$T/wk.err"
rc=$?
check '[ $rc -eq 0 ]' "wisdom_holman on kepler: exit $rc ($(cat "$T/wk.err"))"
for h in 100 50; do
  "$VIGEN" try wisdom_holman wisdom_holman_corrected --problem outer-solar-system --h $h --time 200000 --json \
    > "$T/wo$h.json" 2> "$T/wo$h.err" || { echo "FAIL: wisdom_holman on outer-solar-system, h = $h: $(cat "$T/wo$h.err")"; fail=1; }
done
python3 - "$T/wk.json" "$T/wo100.json" "$T/wo50.json" <<'PY' || fail=1
import json, sys
k = json.load(open(sys.argv[1]))["methods"][0]
o100 = {m["name"]: m for m in json.load(open(sys.argv[2]))["methods"]}
o50 = {m["name"]: m for m in json.load(open(sys.argv[3]))["methods"]}
bad = []
if k["path"] != "split": bad.append("kepler: path %r" % k["path"])
if not k["global_error"] < 1e-11: bad.append("kepler: Wisdom-Holman not exact: error %r" % k["global_error"])
# interaction h/2, kepler h, interaction h/2: 3 flow calls per step
if abs(k["grad_evals_per_step"] - 3) > 1e-12: bad.append("kepler: %r flow calls per step" % k["grad_evals_per_step"])
r = o100["wisdom_holman"]["energy_error_max"] / o50["wisdom_holman"]["energy_error_max"]
if not 3.5 < r < 4.5: bad.append("outer solar system: energy error ratio %r per halving, not 4" % r)
for o in (o100, o50):
    if not o["wisdom_holman_corrected"]["energy_error_max"] < o["wisdom_holman"]["energy_error_max"] / 100:
        bad.append("the corrector does not reduce the energy error: %r %r" % (
            o["wisdom_holman_corrected"]["energy_error_max"], o["wisdom_holman"]["energy_error_max"]))
    if o["wisdom_holman"]["path"] != "split": bad.append("outer solar system: path %r" % o["wisdom_holman"]["path"])
for b in bad: print("FAIL:", b)
sys.exit(1 if bad else 0)
PY
# a processed method over many steps: between two samples the driver takes
# the steps in one NAME_advance call, so the corrector C and its inverse
# (22 flow calls each for the order-11 corrector) run once per stretch and
# the kernel's last drift is merged with the next step's first: about 2
# flow calls per step after the first 2000 steps (taken one at a time for
# the orbit plot), against 45 per NAME_step
"$VIGEN" try wisdom_holman_corrected_11 --problem outer-solar-system --h 100 --time 10000000 --json \
    > "$T/wc.json" 2> "$T/wc.err" || { echo "FAIL: wisdom_holman_corrected_11: $(cat "$T/wc.err")"; fail=1; }
python3 - "$T/wc.json" <<'PY' || fail=1
import json, sys
m = json.load(open(sys.argv[1]))["methods"][0]
bad = []
if not m["grad_evals_per_step"] < 5: bad.append("%r flow calls per step: not stepped by NAME_advance" % m["grad_evals_per_step"])
# generalized order (12,2): the eps^2 h^2 floor, 8e-10 at 100 days (WHFast + corr. 11 likewise)
if not m["energy_error_max"] < 2e-9: bad.append("energy error %r" % m["energy_error_max"])
for b in bad: print("FAIL: wisdom_holman_corrected_11:", b)
sys.exit(1 if bad else 0)
PY
# a problem without a Kepler splitting: one line that says so, exit 2
"$VIGEN" try wisdom_holman --problem pendulum --time 5 > "$T/wp.out" 2> "$T/wp.err"
rc=$?
check '[ $rc -eq 2 ] && grep -q "has no Kepler splitting" "$T/wp.err"' "wisdom_holman on pendulum: exit $rc ($(cat "$T/wp.err"))"

[ $fail = 0 ] && echo "cli_try_paths: ok"
exit $fail
