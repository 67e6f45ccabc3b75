#!/usr/bin/env bash
# cli_atomic.sh VIGEN SRCDIR — output is never lost or mixed, and the caps of
# the process end a command cleanly:
#   - vigen emit with the k-th write, fsync, close, rename or link failing
#     (tests/data/faults/failwrite.c, LD_PRELOAD), for k = 1, 2, ... until it
#     succeeds: each failure exits 3 with one line and leaves the old .h/.c
#     pair (both old, from the same tableau; both absent when there was none)
#     and no temporary file; the success leaves both new;
#   - the same for generate -o over an existing file;
#   - SIGTERM, SIGINT and SIGHUP while generate computes or writes leave no
#     temporary and no partial file, and the process ends by the signal;
#   - two generate -o onto the same file at once leave one complete file;
#   - --max-seconds and the memory cap of the arithmetic (--max-memory) end
#     the command with exit 3, one line naming the cap and the option, and no
#     file; a FLINT abort reached from a file is a message, not SIGABRT.
set -u
vigen=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }
cd "$work" || exit 1
emitdata=$src/tests/data/emit
slow=$src/tableaux/specs/exponential_lua.lua # a Lua basis: quadrature, seconds at 5000 digits

cc -shared -fPIC -o failwrite.so "$src/tests/data/faults/failwrite.c" -ldl || { echo "FAIL cannot compile the shim"; exit 1; }
shim=$work/failwrite.so
# a sanitizer build (libasan) accepts the shim loaded before its runtime
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}verify_asan_link_order=0"

digest() { sed -n 's/.*Tableau digest (FNV-1a 64 of the canonical text): \([0-9a-f]*\).*/\1/p' "$1"; }
temps() { ls -a "$1" | grep -c '\.tmp\.' ; }

# ---- emit: fault at each step ----------------------------------------------
# fault_loop DIR: emits gauss2 as m into DIR with the k-th call failing, for
# k = 1.. until success; OLD is the digest both files must keep ("" = absent)
fault_loop() {
  local dir=$1 old=$2 k rc kinds=""
  for k in $(seq 1 80); do
    rm -f log
    LD_PRELOAD=$shim FAULT_AT=$k FAULT_LOG=$work/log "$vigen" emit "$emitdata/gauss2.lua" --name m -q -o "$dir" \
      >/dev/null 2>err
    rc=$?
    [ $rc = 0 ] && break
    kinds="$kinds $(awk '$1 != "total" {print $2}' log)"
    [ $rc = 3 ] || fail "emit, fault $k ($(cat log)): exit status $rc, expected 3"
    [ "$(wc -l <err)" = 1 ] || { fail "emit, fault $k: not one line:"; cat err; }
    grep -q "cannot write $dir/m\.[hc]" err || { fail "emit, fault $k: the message does not name the file"; cat err; }
    if [ -z "$old" ]; then
      [ ! -e "$dir/m.h" ] && [ ! -e "$dir/m.c" ] || fail "emit, fault $k: a file was left where there was none"
    else
      [ "$(digest "$dir/m.h")" = "$old" ] && [ "$(digest "$dir/m.c")" = "$old" ] ||
        fail "emit, fault $k ($(cat log)): the pair is not the old one: h $(digest "$dir/m.h"), c $(digest "$dir/m.c")"
    fi
    [ "$(temps "$dir")" = 0 ] || fail "emit, fault $k: temporary files left: $(ls -a "$dir")"
  done
  [ $rc = 0 ] || { fail "emit never succeeded under fault injection"; return; }
  [ "$k" -ge 10 ] || fail "emit succeeded at fault $k: the shim is not injecting"
  local kind expected="write fsync close rename"
  [ -n "$old" ] && expected="$expected link"
  for kind in $expected; do
    echo "$kinds" | grep -qw $kind || fail "no failing $kind was tried (tried:$kinds)"
  done
  local new
  new=$(digest "$dir/m.h")
  [ -n "$new" ] && [ "$new" != "$old" ] && [ "$(digest "$dir/m.c")" = "$new" ] || fail "emit: after success the pair is not new"
  [ "$(temps "$dir")" = 0 ] || fail "emit: temporary files left after success: $(ls -a "$dir")"
}

mkdir pair fresh
"$vigen" emit "$emitdata/verlet.lua" --name m -q -o pair || fail "emit the old pair"
old=$(digest pair/m.h)
[ -n "$old" ] && [ "$(digest pair/m.c)" = "$old" ] || fail "the old pair has no common digest"
fault_loop pair "$old"
fault_loop fresh ""

# with EIO instead of ENOSPC, at the second rename (the .h already new)
"$vigen" emit "$emitdata/verlet.lua" --name m -q -o pair || fail "emit the old pair again"
n=$(LD_PRELOAD=$shim FAULT_LOG=$work/all "$vigen" emit "$emitdata/gauss2.lua" --name m -q -o scratch >/dev/null 2>&1;
    awk '$1 == "total" {print $2}' all)
rm -f log
LD_PRELOAD=$shim FAULT_AT=10 FAULT_ERRNO=EIO FAULT_LOG=$work/log "$vigen" emit "$emitdata/gauss2.lua" --name m -q -o pair 2>err
[ $? = 3 ] && grep -q "Input/output error" err || fail "emit with EIO: $(cat err)"
[ "$(digest pair/m.h)" = "$old" ] && [ "$(digest pair/m.c)" = "$old" ] || fail "emit with EIO: the pair is not the old one"
[ -n "$n" ] && [ "$n" -ge 10 ] || fail "the shim counted $n calls for one emit"

# ---- generate -o: fault at each step ---------------------------------------
spec=$src/tableaux/specs/gauss_legendre_s2.lua
echo "old" >g.lua
for k in $(seq 1 40); do
  LD_PRELOAD=$shim FAULT_AT=$k "$vigen" generate "$spec" -q -o g.lua 2>err
  rc=$?
  [ $rc = 0 ] && break
  [ $rc = 3 ] && [ "$(wc -l <err)" = 1 ] || { fail "generate, fault $k: status $rc"; cat err; }
  [ "$(cat g.lua)" = old ] || fail "generate, fault $k: g.lua changed"
  [ "$(temps .)" = 0 ] || fail "generate, fault $k: temporary files left: $(ls)"
done
[ $rc = 0 ] && grep -q 'name = "gauss_legendre_s2"' g.lua || fail "generate never succeeded under fault injection"

# ---- signals ---------------------------------------------------------------
# while computing (the slow spec), and while writing (each write slowed by the
# shim, the signal sent once the temporary file exists)
for sig in TERM INT HUP; do
  for phase in compute write; do
    rm -rf sig && mkdir sig
    set -m # background jobs get SIGINT as they would from a terminal
    if [ $phase = compute ]; then
      "$vigen" generate "$slow" --digits 5000 -q -o sig/out.lua 2>sig.err &
      pid=$!
      sleep 1
    else
      LD_PRELOAD=$shim FAULT_SLEEP_MS=4000 "$vigen" generate "$spec" -q -o sig/out.lua 2>sig.err &
      pid=$!
      for i in $(seq 1 100); do [ "$(temps sig)" != 0 ] && break; sleep 0.05; done
      [ "$(temps sig)" != 0 ] || fail "SIG$sig: the temporary file never appeared"
    fi
    kill -$sig $pid
    wait $pid 2>/dev/null
    rc=$?
    set +m
    [ $rc != 0 ] || fail "SIG$sig while $phase: exit status 0"
    [ -z "$(ls -A sig)" ] || fail "SIG$sig while $phase: left $(ls -a sig)"
    grep -q "interrupted (SIG$sig)" sig.err || { fail "SIG$sig while $phase: no message"; cat sig.err; }
  done
done

# ---- two writers of one file -----------------------------------------------
"$vigen" generate "$src/tableaux/specs/gauss_legendre_s3.lua" --digits 3000 -q -o ref3.lua
"$vigen" generate "$src/tableaux/specs/radau_right_s3.lua" --digits 3000 -q -o refr.lua
mkdir race
for i in $(seq 1 12); do
  "$vigen" generate "$src/tableaux/specs/gauss_legendre_s3.lua" --digits 3000 -q -o race/same.lua &
  "$vigen" generate "$src/tableaux/specs/radau_right_s3.lua" --digits 3000 -q -o race/same.lua &
  wait
  cmp -s race/same.lua ref3.lua || cmp -s race/same.lua refr.lua || fail "two writers, round $i: a mixed or partial file"
  [ "$(ls -A race)" = same.lua ] || fail "two writers, round $i: left $(ls -a race)"
done

# ---- caps ------------------------------------------------------------------
start=$(date +%s)
"$vigen" generate "$slow" --digits 5000 --max-seconds 1 -q -o capped.lua 2>err
rc=$?
[ $rc = 3 ] || fail "--max-seconds 1: exit status $rc, expected 3"
grep -qx "vigen generate: the time cap of 1 s was reached; raise it with --max-seconds" err ||
  { fail "--max-seconds 1: message"; cat err; }
[ $(($(date +%s) - start)) -le 5 ] || fail "--max-seconds 1 took $(($(date +%s) - start)) s"
[ ! -e capped.lua ] && [ "$(temps .)" = 0 ] || fail "--max-seconds 1 left a file: $(ls)"
"$vigen" generate "$spec" --max-seconds 0 2>err
[ $? = 2 ] && grep -q -- "--max-seconds" err || fail "--max-seconds 0 is not refused"

"$vigen" generate "$src/tableaux/specs/trig_gauss5.lua" --digits 100000 --max-memory 1 -q -o capped.lua 2>err
rc=$?
[ $rc = 3 ] || fail "the arithmetic's memory cap: exit status $rc, expected 3"
[ "$(wc -l <err)" = 1 ] && grep -q "memory cap of the arithmetic (4 MiB.*raise it with --max-memory" err ||
  { fail "the arithmetic's memory cap: message"; cat err; }
[ ! -e capped.lua ] && [ "$(temps .)" = 0 ] || fail "the memory cap left a file: $(ls)"

# a decimal exponent beyond FLINT's range: a message, never SIGABRT
printf 'return { name = "x", s = 1, c = {"1e99999999999999999999"}, A = {{"1/2"}}, b = {"1"} }\n' >huge.lua
"$vigen" show huge.lua >out.txt 2>err
rc=$?
[ $rc = 2 ] || [ $rc = 3 ] || fail "show of a huge exponent: exit status $rc"
[ "$(wc -l <err)" = 1 ] || { fail "show of a huge exponent: not one line"; cat err; }

[ $failures -gt 0 ] && { echo "$failures failure(s)"; exit 1; }
echo ok
