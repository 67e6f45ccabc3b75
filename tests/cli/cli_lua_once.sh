#!/usr/bin/env bash
# cli_lua_once.sh VIGEN SRCDIR — a spec or tableau file runs exactly once per
# command: a file that prints a marker (print writes to stderr) shows it once
# for generate, show, check, check --against and emit.
set -u
vigen=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

cat >"$work/spec.lua" <<'LUA'
print("MARK-SPEC")
return { name = "once_spec", nodes = gauss_legendre(2), basis = "lagrange" }
LUA
# a tableau file: the 1-stage Gauss method (implicit midpoint), exact entries
cat >"$work/tableau.lua" <<'LUA'
print("MARK-TABLEAU")
return { name = "once_tableau", s = 1, c = { "1/2" }, A = { { "1/2" } }, b = { "1" } }
LUA

# once LABEL MARKER COUNT COMMAND...: run the command, expect MARKER COUNT times on stderr
once() {
  local label=$1 marker=$2 want=$3
  shift 3
  (cd "$work" && "$@") >"$work/stdout" 2>"$work/stderr"
  local got
  got=$(grep -c -- "$marker" "$work/stderr")
  if [ "$got" != "$want" ]; then
    echo "FAIL $label: $marker printed $got times, expected $want"; cat "$work/stderr"; failures=$((failures + 1))
  fi
}

once "generate spec"          MARK-SPEC    1 "$vigen" generate spec.lua -o out.lua
once "show spec"              MARK-SPEC    1 "$vigen" show spec.lua
once "show tableau"           MARK-TABLEAU 1 "$vigen" show tableau.lua
once "check spec"             MARK-SPEC    1 "$vigen" check spec.lua
once "check tableau"          MARK-TABLEAU 1 "$vigen" check tableau.lua
once "check --against (spec)" MARK-SPEC    1 "$vigen" check spec.lua --against tableau.lua
once "check --against (tableau)" MARK-TABLEAU 1 "$vigen" check spec.lua --against tableau.lua
once "check tableau --against spec" MARK-SPEC 1 "$vigen" check tableau.lua --against spec.lua

once "emit spec"    MARK-SPEC    1 "$vigen" emit spec.lua --name once_spec -o "$work/emit_spec" -q
once "emit tableau" MARK-TABLEAU 1 "$vigen" emit tableau.lua --name once_tableau -o "$work/emit_tableau" -q

[ "$failures" = 0 ] && echo ok
exit $((failures > 0))
