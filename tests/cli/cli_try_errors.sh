#!/bin/bash
# cli_try_errors.sh VIGEN SRC — what `vigen try` says when something is
# wrong, with the exit statuses of include/vigen/status.def: an unknown
# problem, parameter or method, a bad option value, no compiler (CC=
# /nonexistent), a compiler that rejects the code, a step that fails; a
# run ended by SIGINT; and in every case nothing left in TMPDIR and no
# plot written.
set -u
VIGEN=$1
SRC=$2
T=$(mktemp -d /tmp/vigen-cli-try-errors-XXXXXX)
trap 'rm -rf "$T"' EXIT
export TMPDIR="$T/tmp"
mkdir -p "$TMPDIR"
fail=0
check() { if ! eval "$1"; then echo "FAIL: $2"; fail=1; fi; }
empty_tmp() { [ -z "$(ls -A "$TMPDIR")" ]; }

"$VIGEN" try gauss_2 --problem keplr --plot "$T/p1" 2> "$T/err"
rc=$?
check '[ $rc -eq 2 ] && grep -q "keplr" "$T/err" && [ "$(wc -l < "$T/err")" -le 2 ] && [ ! -e "$T/p1" ]' "unknown problem: exit 2, named ($(cat "$T/err"))"
"$VIGEN" try gauss_2 --problem kepler --param ecc=0.5 2> "$T/err"
rc=$?
check '[ $rc -eq 2 ] && grep -q "ecc" "$T/err"' "unknown parameter: exit 2, named ($(cat "$T/err"))"
"$VIGEN" try gauss_2 --problem kepler --param e=7 2> "$T/err"
rc=$?
check '[ $rc -eq 2 ] && grep -q "e" "$T/err"' "parameter out of range: exit 2"
"$VIGEN" try gauss2 --problem kepler 2> "$T/err"
rc=$?
check '[ $rc -eq 2 ] && grep -q "gauss2: no such file or published method; did you mean .gauss_2.?" "$T/err"' "unknown method: exit 2, with the nearest name ($(cat "$T/err"))"
"$VIGEN" try gauss_2 --problem kepler --h -1 2> "$T/err"
rc=$?
check '[ $rc -eq 2 ] && grep -q -- "--h takes a positive number" "$T/err"' "negative --h: exit 2"
"$VIGEN" try gauss_2 --problem kepler --h 0.1 --steps-per-period 10 2> "$T/err"
rc=$?
check '[ $rc -eq 2 ] && grep -q "not both" "$T/err"' "--h with --steps-per-period: exit 2"
"$VIGEN" try gauss_2 2> "$T/err"
rc=$?
check '[ $rc -eq 2 ] && grep -q "which problem" "$T/err"' "no --problem: exit 2"
"$VIGEN" try --problem kepler 2> "$T/err"
rc=$?
check '[ $rc -eq 2 ] && grep -q "which methods" "$T/err"' "no method: exit 2"
check 'empty_tmp' "nothing left in TMPDIR after usage errors"

CC=/nonexistent "$VIGEN" try gauss_2 --problem kepler --plot "$T/p2" > "$T/out" 2> "$T/err"
rc=$?
check '[ $rc -eq 3 ] && grep -q "gauss_2: cannot run the C compiler ./nonexistent." "$T/err" && [ ! -s "$T/out" ] && [ ! -e "$T/p2" ]' "no compiler: exit 3, names the method and the compiler ($(cat "$T/err"))"
check 'empty_tmp' "nothing left in TMPDIR without a compiler"

printf 'this is not C;\n' > "$T/broken.h"
CC="cc -include $T/broken.h" "$VIGEN" try stormer_verlet_velocity --problem kepler > "$T/out" 2> "$T/err"
rc=$?
check '[ $rc -eq 3 ] && grep -q "stormer_verlet_velocity: the C compiler .* failed" "$T/err" && grep -q "broken.h" "$T/err" && [ ! -s "$T/out" ]' "compile error: exit 3, names the method, shows the compiler's first lines ($(cat "$T/err"))"
check 'empty_tmp' "nothing left in TMPDIR after a compile error"

# gnuplot missing, or failing on its second figure: no figure, no data, no
# directory is written (the figures are written when all are drawn)
GNUPLOT=/nonexistent "$VIGEN" try stormer_verlet_velocity --problem kepler --time 10 --plot "$T/p3" > /dev/null 2> "$T/err"
rc=$?
check '[ $rc -eq 3 ] && grep -q "cannot run gnuplot ./nonexistent." "$T/err" && grep -q "gnuplot-nox" "$T/err" && [ ! -e "$T/p3" ]' "no gnuplot: exit 3, nothing written ($(cat "$T/err"))"
cat > "$T/gnuplot-once" <<SH
#!/bin/sh
# draws the first figure, fails on the next
if [ -e "$T/drawn" ]; then echo "gnuplot: error: made to fail" >&2; exit 1; fi
touch "$T/drawn"
exec gnuplot "\$@"
SH
chmod +x "$T/gnuplot-once"
GNUPLOT="$T/gnuplot-once" "$VIGEN" try stormer_verlet_velocity --problem kepler --time 10 --plot "$T/p4" > /dev/null 2> "$T/err"
rc=$?
check '[ $rc -eq 3 ] && grep -q "gnuplot failed on orbit (status 1): gnuplot: error: made to fail" "$T/err" && [ ! -e "$T/p4" ]' "gnuplot failing on the second figure: exit 3, nothing written ($(cat "$T/err"))"
check 'empty_tmp' "nothing left in TMPDIR after gnuplot failures"

# an explicit method far beyond its stability bound: the state overflows
"$VIGEN" try stormer_verlet_velocity --problem harmonic-oscillator --param omega=1000 --h 1 --time 100000 > "$T/out" 2> "$T/err"
rc=$?
check '[ $rc -eq 2 ] && grep -q "stormer_verlet_velocity: step [0-9]* (t = .*) failed: " "$T/err" && grep -q "smaller step" "$T/err"' "failed step: exit 2, names the method, the step and what to do ($(cat "$T/err"))"
check 'empty_tmp' "nothing left in TMPDIR after a failed step"

# work-precision where every method fails at every step size: no figure can
# be drawn, and the message says what to change instead of gnuplot's error
# (FPUT with 64 particles at the default 100 steps per period: Gauss-2's
# stage iteration diverges and Yoshida's state overflows at every level)
"$VIGEN" try gauss_2 yoshida_4 --problem fput --param n=64 --work-precision --plot "$T/p5" > "$T/out" 2> "$T/err"
rc=$?
check '[ $rc -eq 2 ] && grep -q "no method completed any step size" "$T/err" && ! grep -q gnuplot "$T/err" && [ ! -e "$T/p5" ]' "work-precision with no completed level: exit 2, no figure ($(cat "$T/err"))"
check 'empty_tmp' "nothing left in TMPDIR after a work-precision run with no data"

# SIGTERM, and SIGINT (job control on: a background job of a script
# otherwise ignores it), while a driver runs: the child is ended, the
# directory removed, the command ends by the signal
set -m
for sig in TERM INT; do
  "$VIGEN" try gauss_2 --problem harmonic-oscillator --h 0.001 --time 1000000 > /dev/null 2> "$T/err" &
  pid=$!
  for i in $(seq 1 200); do
    ls "$TMPDIR"/vigen-try-*/m0_driver.out > /dev/null 2>&1 && break
    sleep 0.05
  done
  kill -$sig $pid
  wait $pid
  rc=$?
  want=$((128 + $(kill -l $sig)))
  check '[ $rc -eq $want ]' "SIG$sig: ended by the signal (status $rc, not $want)"
  check 'empty_tmp' "SIG$sig: nothing left in TMPDIR ($(ls -A "$TMPDIR"))"
  check '! pgrep -f "$TMPDIR" > /dev/null' "SIG$sig: no driver left running"
done
set +m
exit $fail
