#!/bin/bash
# cli_try.sh VIGEN SRC — `vigen try` on every problem of the collection: a
# symplectic method (Gauss s = 2) keeps the energy error bounded while the
# classical RK4 (not symplectic, tests/data/check/rk4.lua) lets it grow, read
# from the CSV beside the energy plot (the plot's own data); the summary's
# largest energy error is that of the CSV; the figures are well-formed SVG
# with one curve per method and PNG of the stated size; problem and
# parameter listing; and the temporary directory is gone afterwards.
set -u
VIGEN=$1
SRC=$2
T=$(mktemp -d /tmp/vigen-cli-try-XXXXXX)
trap 'rm -rf "$T"' EXIT
export TMPDIR="$T/tmp"
mkdir -p "$TMPDIR"
fail=0
check() { if ! eval "$1"; then echo "FAIL: $2"; fail=1; fi; }
RK4="$SRC/tests/data/check/rk4.lua"

# The plot data and the figures of one run, checked against each other and
# against the energy behaviour expected of each method.
cat > "$T/check_run.py" <<'PY'
import csv, json, struct, sys, xml.etree.ElementTree as ET
d, summary = sys.argv[1], json.load(open(sys.argv[2]))
errors = []
rows = list(csv.reader(open(d + "/energy.csv")))
head, data = rows[0], [r for r in rows[1:] if r]
methods = {m["name"]: m for m in summary["methods"]}
if head[1:] != ["gauss_2", "rk4"]:
    errors.append("energy.csv header %r" % head)
n = len(data)
if n < 50:
    errors.append("only %d energy samples" % n)
curves = 0
for j, name in enumerate(head[1:], start=1):
    e = [abs(float(r[j])) for r in data if r[j] != ""]
    if max(e) > 0:
        curves += 1
    # the summary is computed from the same samples
    if abs(max(e) - methods[name]["energy_error_max"]) > 1e-12 * max(e):
        errors.append("%s: summary max %g, CSV max %g" % (name, methods[name]["energy_error_max"], max(e)))
    k = max(1, len(e) // 5)
    first, last = max(e[1:k + 1]), max(e[-k:])
    if name == "gauss_2":
        # bounded: the error of the second half at most 1.5 times that of
        # the first (it oscillates; it may rise while the motion moves into
        # other parts of phase space, as the FPUT chain's modes exchange
        # energy, and then stays), or at round-off
        h1, h2 = max(e[1:len(e) // 2]), max(e[len(e) // 2:])
        if not (h2 <= 1.5 * h1 or max(e) < 1e-11):
            errors.append("gauss_2: energy error grows: first half %g, second half %g" % (h1, h2))
    else:
        # RK4 drifts (linearly: 5 times at the end what it is at a fifth)
        if not last >= 3 * first:
            errors.append("rk4: energy error does not grow: first fifth %g, last fifth %g" % (first, last))
for stem, want in (("energy", curves), ("orbit", 2)):
    try:
        root = ET.parse(d + "/" + stem + ".svg").getroot()
    except ET.ParseError as ex:
        errors.append("%s.svg is not well-formed: %s" % (stem, ex))
        continue
    ids = [g.get("id") for g in root.iter() if (g.get("id") or "").startswith("gnuplot_plot_")]
    if len(ids) != want:
        errors.append("%s.svg has %d curves, not %d" % (stem, len(ids), want))
    png = open(d + "/" + stem + ".png", "rb").read()
    if png[:8] != b"\x89PNG\r\n\x1a\n" or png[12:16] != b"IHDR":
        errors.append("%s.png is not a PNG" % stem)
    elif struct.unpack(">II", png[16:24]) != (800, 560) or len(png) < 2000:
        errors.append("%s.png: size %r, %d bytes" % (stem, struct.unpack(">II", png[16:24]), len(png)))
    orows = list(csv.reader(open(d + "/orbit.csv")))
    if len(orows) < 10 or len(orows[0]) != 4:
        errors.append("orbit.csv: %d rows, header %r" % (len(orows), orows[0]))
print("\n".join(errors))
sys.exit(1 if errors else 0)
PY

"$VIGEN" try --list-problems > "$T/problems.txt"
check '[ $? -eq 0 ] && grep -q "^kepler " "$T/problems.txt" && grep -q "^  --param e=" "$T/problems.txt"' "--list-problems lists kepler and its eccentricity"
"$VIGEN" try --list-methods > "$T/methods.txt"
check '[ $? -eq 0 ] && [ "$(grep -c "^[^ ]*$" "$T/methods.txt")" -eq "$(ls "$SRC"/tableaux/published/*.lua | wc -l)" ] && grep -qx gauss_2 "$T/methods.txt"' "--list-methods lists tableaux/published"

for p in $(grep -v '^ ' "$T/problems.txt" | cut -d' ' -f1); do
  "$VIGEN" try gauss_2 "$RK4" --problem "$p" --json --plot "$T/plot-$p" > "$T/$p.json" 2> "$T/$p.err"
  rc=$?
  check '[ $rc -eq 0 ]' "$p: exit status $rc ($(head -c 300 "$T/$p.err"))"
  [ $rc -eq 0 ] || continue
  if ! python3 "$T/check_run.py" "$T/plot-$p" "$T/$p.json" > "$T/$p.check"; then
    echo "FAIL: $p: $(cat "$T/$p.check")"
    fail=1
  fi
  check 'grep -q "wrote $T/plot-$p/energy" "$T/$p.err"' "$p: says where the plots are"
done

# the text summary: one row per method with the measures named in its head
"$VIGEN" try gauss_2 stormer_verlet_velocity --problem harmonic-oscillator --time 20 > "$T/sum.txt"
check '[ $? -eq 0 ] && grep -q "max|dE|" "$T/sum.txt" && grep -q "^gauss_2 " "$T/sum.txt" && grep -q "^stormer_verlet_velocity " "$T/sum.txt"' "text summary"
# Stormer-Verlet on a mechanical problem (Nystrom form): one new force per
# step (first same as last), and the line that says so
check 'awk "/^stormer_verlet_velocity /{exit !(\$(NF-1) == 1.00)}" "$T/sum.txt"' "Stormer-Verlet: 1 force per step"
check 'grep -q "^stormer_verlet_velocity: mechanical problem" "$T/sum.txt"' "Stormer-Verlet: the mechanical path not said"

# a spec file is generated on the fly: the Galerkin method of Lagrange
# polynomials at 2 Gauss nodes is the Gauss method (Leok-Zhang, Theorem 3;
# Hairer-Lubich-Wanner VI.6), so it moves exactly as the published gauss_2
# up to the rounding of its coefficients
"$VIGEN" try "$SRC/tableaux/specs/gauss_legendre_s2.lua" gauss_2 --problem kepler --time 50 --json > "$T/spec.json" 2> "$T/spec.err"
rc=$?
check '[ $rc -eq 0 ] && python3 -c "
import json, sys
a, b = json.load(open(sys.argv[1]))[\"methods\"]
sys.exit(0 if a[\"name\"] == \"gauss_legendre_s2\" and abs(a[\"global_error\"] - b[\"global_error\"]) < 1e-9 * b[\"global_error\"] + 1e-13 else 1)" "$T/spec.json"' "spec generated on the fly = the published Gauss method ($(cat "$T/spec.err" "$T/spec.json"))"

# work-precision: the error falls by 2^p per halving of the step (p = 4 for
# Gauss s = 2, 2 for Stormer-Verlet: their orders) while the gradient
# evaluations grow (Verlet: double exactly, one of each gradient per step;
# Gauss: less than double, as its sweeps per step fall with h, the start
# nearer the fixed point); two curves in each figure
"$VIGEN" try gauss_2 stormer_verlet_velocity --problem harmonic-oscillator --work-precision --levels 3 --json --plot "$T/wp" > "$T/wp.json" 2> "$T/wp.err"
rc=$?
check '[ $rc -eq 0 ]' "work-precision: exit $rc ($(cat "$T/wp.err"))"
check 'python3 -c "
import json, sys
o = json.load(open(sys.argv[1]))
ok = not o[\"error_is_energy\"]
for m, p in zip(o[\"methods\"], (4, 2)):
    pts = m[\"points\"]
    ok = ok and len(pts) == 3
    for a, b in zip(pts, pts[1:]):
        ok = ok and abs(a[\"error\"] / b[\"error\"] / 2**p - 1) < 0.15 and b[\"evals\"] > a[\"evals\"]
    if m[\"name\"] == \"stormer_verlet_velocity\":
        # one force per step, and one more at the start (first same as last)
        ok = ok and all(b[\"evals\"] - 1 == 2 * (a[\"evals\"] - 1) for a, b in zip(pts, pts[1:]))
sys.exit(0 if ok else 1)" "$T/wp.json"' "work-precision: errors fall as h^p, costs grow ($(cat "$T/wp.json"))"
for f in work_precision_evals work_precision_seconds; do
  check 'python3 -c "import xml.etree.ElementTree as E,sys; r=E.parse(sys.argv[1]).getroot(); sys.exit(0 if len([g for g in r.iter() if (g.get(\"id\") or \"\").startswith(\"gnuplot_plot_\")]) == 2 else 1)" "$T/wp/$f.svg" && [ "$(head -c 4 "$T/wp/$f.png" | tail -c 3)" = PNG ] && [ "$(wc -l < "$T/wp/$f.csv")" -eq 7 ]' "$f: SVG with 2 curves, PNG, CSV of 6 points"
done

# the progress line: on a terminal (script(1) gives one) for a run of more
# than a second (3 * 10^7 steps: about 3 s on a 2-core machine), erased at
# the end; never in a pipe or file
if command -v script > /dev/null; then
  script -qec "'$VIGEN' try gauss_2 --problem harmonic-oscillator --h 0.001 --time 30000" "$T/tty.log" > /dev/null 2>&1
  check 'grep -q "vigen try: gauss_2: .*([0-9]* s)" "$T/tty.log" && grep -q $'"'"'\r\e\[K'"'"' "$T/tty.log"' "progress line on a terminal"
fi
"$VIGEN" try gauss_2 --problem harmonic-oscillator --h 0.001 --time 5000 > /dev/null 2> "$T/pipe.err"
check '[ ! -s "$T/pipe.err" ]' "no progress line when standard error is a file"

check '[ -z "$(ls -A "$TMPDIR")" ]' "nothing left in TMPDIR"
exit $fail
