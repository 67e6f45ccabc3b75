#!/bin/bash
# cli_help.sh VIGEN SRCDIR — the command line itself: `vigen help`,
# `vigen help COMMAND` (the same text as `vigen COMMAND --help`), --version,
# did-you-mean for commands and options, errors of at most two lines with no
# help dump, and the one exit-status map (0 success, 1 a verdict of check,
# 2 bad input or usage, 3 a resource or system failure) for every command.
vigen=$1
src=$2
work=$(mktemp -d)
trap 'chmod -R u+rwx "$work"; rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }
pub=$src/tableaux/published
bad=$src/tests/data/bad_tableaux

# status WANT CMD...: runs vigen CMD, keeps stdout and stderr, checks the status
status() {
  local want=$1; shift
  "$vigen" "$@" >"$work/out" 2>"$work/err"
  local got=$?
  [ "$got" = "$want" ] || { fail "vigen $*: exit status $got, expected $want"; head -3 "$work/err"; }
}
# short_error WHAT: stderr holds at most two lines and no help text
short_error() {
  local n
  n=$(wc -l <"$work/err")
  [ "$n" -ge 1 ] && [ "$n" -le 2 ] || { fail "$1: $n lines on stderr, expected 1 or 2"; cat "$work/err"; }
  ! grep -q -e "^usage:" -e "^options:" -e "^commands:" "$work/err" || fail "$1: help printed with the error"
  [ ! -s "$work/out" ] || fail "$1: output on stdout"
}
has() { grep -q -- "$2" "$work/$1" || { fail "expected '$2' in $1"; cat "$work/$1" | head -5; }; }

# vigen help: every command, the global options, the exit statuses
status 0 help
for c in generate show check emit help version; do
  grep -q "^  $c " "$work/out" || fail "vigen help does not list $c"
done
has out "--max-memory MIB"
has out "--max-instructions N"
for e in 0 1 2 3; do grep -q "^  $e  " "$work/out" || fail "vigen help does not explain exit status $e"; done
has out "^  3  a resource or system failure"
status 0 --help
cmp -s "$work/out" <("$vigen" help) || fail "vigen --help differs from vigen help"

# vigen help check and vigen check --help: the same text
status 0 help check
cp "$work/out" "$work/help_check"
has help_check "^usage: vigen check FILE \[--against FILE2\] \[--max-order P\] \[--json\] \[--prec BITS\]$"
has help_check "^  --against FILE2  compare every entry with FILE2"
status 0 check --help
cmp -s "$work/out" "$work/help_check" || fail "vigen check --help differs from vigen help check"
status 0 check -h
cmp -s "$work/out" "$work/help_check" || fail "vigen check -h differs from vigen help check"
for c in generate show emit help version; do
  status 0 help "$c"
  cp "$work/out" "$work/help_$c"
  status 0 "$c" --help
  cmp -s "$work/out" "$work/help_$c" || fail "vigen $c --help differs from vigen help $c"
done

# --version and vigen version
status 0 --version
grep -qE "^vigen [0-9]+\.[0-9]+\.[0-9]+$" "$work/out" || fail "--version: $(cat "$work/out")"
cp "$work/out" "$work/version"
status 0 version
cmp -s "$work/out" "$work/version" || fail "vigen version differs from vigen --version"

# did you mean: commands and options, one line and the pointer to help
status 2 chek "$pub/gauss_2.lua"
short_error "mistyped command"
has err "^vigen: unknown command 'chek'; did you mean 'check'?$"
has err "^see 'vigen help'$"
status 2 help chek
short_error "vigen help of a mistyped command"
has err "did you mean 'check'?"
# after `vigen help X` the pointer is `vigen help` (not the help of help)
status 2 help nosuch
short_error "vigen help of an unknown name"
has err "^see 'vigen help'$"
# a unique prefix of a command is taken for an abbreviation
status 2 gen "$src/tableaux/specs/gauss_legendre_s1.lua"
short_error "an abbreviated command"
has err "^vigen: unknown command 'gen'; did you mean 'generate'?$"
status 2 check "$pub/gauss_2.lua" --agianst "$pub/gauss_2.lua"
short_error "mistyped option"
has err "^vigen check: unknown option '--agianst'; did you mean '--against'?$"
has err "^see 'vigen help check'$"
status 2 show "$pub/gauss_2.lua" --fromat=json
short_error "mistyped option with a value"
has err "did you mean '--format'?"
# a one-letter option gets no guess, except a change of case
status 2 show "$pub/gauss_2.lua" -x
short_error "unknown short option"
has err "^vigen show: unknown option '-x'$"
status 2 generate "$src/tableaux/specs/gauss_legendre_s1.lua" -Q
short_error "short option in the wrong case"
has err "^vigen generate: unknown option '-Q'; did you mean '-q'?$"
# an option of other commands is named as such
status 2 check "$pub/gauss_2.lua" -o x
short_error "option of other commands"
has err "^vigen check: -o is an option of generate, emit and design, not of check$"
has err "^see 'vigen help check'$"
status 2 --json check "$pub/gauss_2.lua"
short_error "a command's option before the command"
has err "^vigen: --json is an option of check: put it after the command$"
status 2 frobnicate
short_error "unknown command"
! grep -q "did you mean" "$work/err" || fail "a far name got a did-you-mean hint"

# usage errors: one line and the pointer to help
status 2
short_error "no command"
status 2 check
short_error "check without a file"
has err "^vigen check: which file? give a tableau or spec file, e.g. tableaux/published/gauss_2.lua$"
has err "^see 'vigen help check'$"
status 2 generate
short_error "generate without a spec"
status 2 generate "$pub/gauss_2.lua"
short_error "generate of a tableau file"
has err "gauss_2.lua is a tableau file, not a spec"
status 2 emit "$pub/gauss_2.lua"
short_error "emit without --name"
has err "^vigen emit: --name is required"
status 2 check "$pub/gauss_2.lua" --against
short_error "a value missing"
has err "^vigen check: --against needs a value"
status 2 check "$pub/gauss_2.lua" --json=yes
short_error "a value given to a flag"
status 2 check "$pub/gauss_2.lua" "$pub/gauss_3.lua"
short_error "two files"
status 2 show "$pub/gauss_2.lua" --digits many
short_error "a number that is not one"
has err "^vigen show: --digits takes a whole number from 1 to 100000, not 'many'$"
status 2 show "$pub/gauss_2.lua" --max-memory 0
short_error "a global option out of range"

# both forms of a value option, and global options anywhere on the line
status 0 show "$pub/gauss_2.lua" --format json
cp "$work/out" "$work/json1"
status 0 show "$pub/gauss_2.lua" --format=json
cmp -s "$work/out" "$work/json1" || fail "--format=json differs from --format json"
status 0 --max-memory 512 show --max-instructions=1000000 "$pub/gauss_2.lua" --format json
cmp -s "$work/out" "$work/json1" || fail "global options change the output"

# a missing file and an unreadable file: named, one line, exit 2
for c in show check; do
  status 2 $c "$work/missing.lua"
  short_error "$c of a missing file"
  has err "^vigen $c: $work/missing.lua: cannot open: No such file or directory; check the path$"
done
status 2 emit "$work/missing.lua" --name m -o "$work"
short_error "emit of a missing file"
# a directory cannot be read as a file, whoever runs the test (root too)
for c in show check; do
  status 2 $c "$work"
  short_error "$c of a directory"
  [ "$(wc -l <"$work/err")" = 1 ] || fail "$c of a directory: not one line"
  has err "^vigen $c: $work: .*; give a file, not a directory$"
done
if [ "$(id -u)" != 0 ]; then
  cp "$pub/gauss_2.lua" "$work/locked.lua"
  chmod 000 "$work/locked.lua"
  status 2 check "$work/locked.lua"
  short_error "check of an unreadable file"
  has err "locked.lua"
fi

# the exit-status map: 0 success, 1 a verdict
status 0 check "$pub/gauss_2.lua"
status 1 check "$src/tests/data/check/rk4_claimed_symplectic.lua"
has out "FAILED"
status 1 check "$src/tests/data/check/rk4_claimed_symplectic.lua" --json
# 2: the same bad entry through show, check and emit
for f in "$bad"/*.lua; do
  for c in show check emit; do
    if [ $c = emit ]; then status 2 emit "$f" --name bad -o "$work/emit"; else status 2 $c "$f"; fi
    grep -q "$(basename "$f")" "$work/err" || fail "$c $(basename "$f"): the file is not named"
    [ "$(wc -l <"$work/err")" -le 2 ] || fail "$c $(basename "$f"): more than two lines"
  done
done
[ ! -e "$work/emit" ] || fail "emit wrote a stepper for a bad tableau"
# 2: a spec that describes no method (singular M), through every command
for c in generate show check; do status 2 $c "$src/tests/data/bad_specs/singular_m.lua"; done
status 2 emit "$src/tests/data/bad_specs/singular_m.lua" --name s -o "$work"
# 3: standard output cannot be written, a cap reached
for c in "show $pub/gauss_2.lua" "check $pub/gauss_2.lua" "check $pub/gauss_2.lua --json" help "--version"; do
  $vigen $c >/dev/full 2>"$work/err"
  st=$?
  [ $st = 3 ] || fail "vigen $c >/dev/full: exit status $st, expected 3"
  [ "$(wc -l <"$work/err")" = 1 ] && grep -q "standard output" "$work/err" || { fail "vigen $c >/dev/full: message"; cat "$work/err"; }
done
"$vigen" generate "$src/tableaux/specs/gauss_legendre_s1.lua" -q >/dev/full 2>"$work/err"
[ $? = 3 ] || fail "generate >/dev/full: expected exit status 3"
[ "$(wc -l <"$work/err")" = 1 ] || { fail "generate >/dev/full: one line expected"; cat "$work/err"; }
status 3 --max-instructions 1000 generate "$src/tests/data/bad_specs/endless_loop.lua"
short_error "instruction cap"
has err "1000"

# every help text fits 80 columns (counted in characters: UTF-8 continuation
# bytes are dropped before counting)
for h in "help generate" "help show" "help check" "help emit" "help help" "help version" help "help spec"; do
  long=$("$vigen" $h | LC_ALL=C sed 's/[\x80-\xbf]//g' | LC_ALL=C awk 'length > 80')
  [ -z "$long" ] || fail "vigen $h: lines over 80 columns: $long"
done
# wrapped exit-status lines start under the words, at column 5
"$vigen" help | grep -q "^     [a-z]" || fail "vigen help: no wrapped exit-status line at column 5"
! "$vigen" help | grep -q "^      [a-z]" || fail "vigen help: an exit-status line indented past the words"
"$vigen" help check | grep -q "the exit statuses are explained in 'vigen help'" \
  || fail "vigen help check: the pointer to the exit statuses"

# vigen help spec: the vocabulary of method files, written from the tables
status 0 help spec
for w in "gauss_legendre(s)" "chebyshev_t(s)" "sqrt(x)" "galerkin" "tableau"; do has out "$w"; done
grep -q "help spec" <("$vigen" help) || fail "vigen help does not list the topic spec"
status 0 help checks
for w in consistency symplecticity orders claims against; do grep -q "^  $w " "$work/out" || fail "vigen help checks lacks $w"; done
status 2 help spce
short_error "vigen help spce"
has err "did you mean 'spec'"

[ $failures -gt 0 ] && { echo "$failures failure(s)"; exit 1; }
exit 0
