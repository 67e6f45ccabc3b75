#!/usr/bin/env bash
# cli_sandbox_caps.sh VIGEN SRCDIR — the sandbox's caps cannot be escaped: each
# hostile spec (tests/data/bad_specs/hostile_lua_*.lua: error handlers that
# loop, pcall that swallows a cap, library functions that loop in C over a
# count the file chooses) ends within seconds with exit status 3, one line
# naming the cap and the option that raises it, and no output file.
set -u
vigen=$1
src=$2
bad=$src/tests/data/bad_specs
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

# expect NAME CAP OPTION: generate bad_specs/hostile_lua_NAME.lua
expect() {
  local name=hostile_lua_$1 cap=$2 option=$3
  local out=$work/$name.out.lua start end
  start=$(date +%s)
  timeout 20 "$vigen" generate "$bad/$name.lua" -o "$out" >"$work/stdout" 2>"$work/stderr"
  local got=$?
  end=$(date +%s)
  if [ "$got" != 3 ]; then
    echo "FAIL $name: exit status $got, expected 3 (124: still running after 20 s)"; head -c 2000 "$work/stderr"
    failures=$((failures + 1)); rm -f "$out"; return
  fi
  if [ $((end - start)) -gt 10 ]; then
    echo "FAIL $name: took $((end - start)) s"; failures=$((failures + 1))
  fi
  if [ -e "$out" ] || [ -n "$(ls "$work" | grep -v -e '^stdout$' -e '^stderr$')" ]; then
    echo "FAIL $name: output left behind: $(ls "$work")"; failures=$((failures + 1))
  fi
  if [ "$(wc -l <"$work/stderr")" != 1 ]; then
    echo "FAIL $name: expected one line of message"; cat "$work/stderr"; failures=$((failures + 1))
  fi
  for phrase in "$name.lua" "$cap" "$option"; do
    if ! grep -q -- "$phrase" "$work/stderr"; then
      echo "FAIL $name: message lacks '$phrase'"; cat "$work/stderr"; failures=$((failures + 1))
    fi
  done
  rm -f "$work"/*.lua
}

instructions="Lua instructions"
memory="of memory"

# error handlers and pcall
expect xpcall_loop_handler   "$instructions" --max-instructions
expect xpcall_handler_errors "$instructions" --max-instructions
expect pcall_swallow         "$instructions" --max-instructions
expect nested_pcall          "$instructions" --max-instructions
expect error_table_tostring  "$instructions" --max-instructions
expect pcall_memory          "$memory"       --max-memory
expect xpcall_memory         "$memory"       --max-memory
# library functions that loop in C over a count the file chooses
expect table_move            "$instructions" --max-instructions
expect table_sort_len        "$instructions" --max-instructions
expect table_concat          "$instructions" --max-instructions
expect table_unpack          "$instructions" --max-instructions
expect table_insert          "$instructions" --max-instructions
expect table_remove          "$instructions" --max-instructions
expect string_byte           "$instructions" --max-instructions
expect select_count          "$instructions" --max-instructions
expect tonumber_long         "$instructions" --max-instructions
# work the VM does in one instruction, seen through what it allocates
expect string_concat         "$instructions" --max-instructions

if [ $failures -gt 0 ]; then echo "$failures failure(s)"; exit 1; fi
echo ok
