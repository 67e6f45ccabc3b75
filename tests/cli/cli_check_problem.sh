#!/bin/bash
# cli_check_problem.sh VIGEN SRC — an emitted stepper compiled with
# -DVIGEN_CHECK_PROBLEM checks its problem at the first step
# (vigen/diagnostics.h): the harmonic oscillator H = (q^2 + p^2)/2 with a sign
# error in dH/dq fails every step with VIGEN_EGRADIENT and one sentence on
# standard error naming dH/dq; the correct gradient steps as without the
# flag, bit for bit; so does the mechanical form; without the flag the wrong
# gradient is not noticed.
set -u
VIGEN=$1
SRC=$(cd "$2" && pwd)
BUILD=$(cd "$(dirname "$VIGEN")" && pwd)
T=$(mktemp -d /tmp/vigen-cli-check-problem-XXXXXX)
trap 'rm -rf "$T"' EXIT
fail=0
bad() { echo "FAIL: $*"; fail=1; }
RT=$BUILD/runtime/libvigen_runtime.a
[ -f "$RT" ] || { echo "FAIL: no $RT"; exit 1; }

"$VIGEN" emit gauss_2 --name g2 -o "$T" -q || { echo "FAIL: emit"; exit 1; }
cat > "$T/main.c" <<'C'
#include <stdio.h>
#include <string.h>
#include "g2.h"
static int sign = 1;
static void dHdq(double t, const double *q, const double *p, double *o, void *c) { (void)t; (void)p; (void)c; o[0] = sign * q[0]; }
static void dHdp(double t, const double *q, const double *p, double *o, void *c) { (void)t; (void)q; (void)c; o[0] = p[0]; }
static double H(double t, const double *q, const double *p, void *c) { (void)t; (void)c; return (q[0] * q[0] + p[0] * p[0]) / 2; }
static void force(double t, const double *q, double *f, void *c) { (void)t; (void)c; f[0] = -sign * q[0]; }
static double V(double t, const double *q, void *c) { (void)t; (void)c; return q[0] * q[0] / 2; }
int main(int argc, char **argv)
{
    sign = argc > 1 && strcmp(argv[1], "wrong") == 0 ? -1 : 1;
    int mech = argc > 2;
    vigen_hamiltonian sys = { 1, dHdq, dHdp, H, NULL, 1, NULL };
    vigen_mechanical ms = { 1, force, V, NULL, NULL };
    g2_workspace *w = mech ? g2_alloc_mechanical(&ms, NULL) : g2_alloc(&sys, NULL);
    double t = 0, q = 1, p = 0;
    int st = 0;
    for (int k = 0; k < 3; k++) st |= g2_step(w, &t, &q, &p, 0.1) << (4 * k);
    printf("%x %a %a\n", (unsigned)st, q, p);
    g2_free(w);
    return 0;
}
C
# a sanitized build's runtime needs the sanitizers' runtime at link time
san=
grep -q "^VIGEN_SANITIZE:BOOL=ON" "$BUILD/CMakeCache.txt" 2>/dev/null && san="-fsanitize=address,undefined"
cc_() { gcc -std=c11 -O2 -Wall -Wextra -Werror $san -I"$T" -I"$SRC/runtime/include" "$@" "$T/main.c" "$T/g2.c" "$RT" -lgsl -lgslcblas -lm -o "$T/prog" 2> "$T/cc.log" || { bad "compile $*: $(head -5 "$T/cc.log")"; return 1; }; }
cc_ -DVIGEN_CHECK_PROBLEM && {
  "$T/prog" wrong > "$T/out" 2> "$T/err"
  # VIGEN_EGRADIENT in each of the three steps, state unchanged
  want=$(printf '%x%x%x' 9 9 9)
  read -r st q p < "$T/out"
  [ "$st" = "$want" ] && [ "$q" = "0x1p+0" ] && [ "$p" = "0x0p+0" ] || bad "wrong gradient: status $st, q $q, p $p (want $want, unchanged state)"
  [ "$(wc -l < "$T/err")" = 1 ] && grep -q "dH/dq" "$T/err" || bad "wrong gradient: stderr $(cat "$T/err")"
  "$T/prog" wrong mech > "$T/out" 2> "$T/err"
  read -r st q p < "$T/out"
  [ "$st" = "$want" ] || bad "wrong force (mechanical): status $st"
  "$T/prog" right > "$T/checked" 2> "$T/err"
  [ ! -s "$T/err" ] || bad "correct gradient flagged: $(cat "$T/err")"
  "$T/prog" right mech > "$T/checked_mech" 2>&1
}
cc_ && {
  "$T/prog" right > "$T/plain" 2>&1
  "$T/prog" right mech > "$T/plain_mech" 2>&1
  cmp -s "$T/checked" "$T/plain" || bad "the checked stepper steps differently: $(cat "$T/checked") vs $(cat "$T/plain")"
  cmp -s "$T/checked_mech" "$T/plain_mech" || bad "mechanical: $(cat "$T/checked_mech") vs $(cat "$T/plain_mech")"
  "$T/prog" wrong > "$T/out" 2> "$T/err"
  read -r st q p < "$T/out"
  [ "$st" = 0 ] || bad "without the flag the wrong gradient should go unnoticed (status $st)"
}
[ $fail = 0 ] && echo "cli_check_problem: ok"
exit $fail
