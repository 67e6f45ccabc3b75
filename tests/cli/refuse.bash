# refuse.bash — sourced by the cli tests of malformed input files:
# refuse FILE TEXT runs `$VIGEN check $T/FILE` and expects exit 2 and one
# line on stderr that names FILE and contains TEXT (else it calls bad).
refuse() {
  "$VIGEN" check "$T/$1" > "$T/out" 2> "$T/err"
  local rc=$?
  [ $rc = 2 ] || bad "$1: exit $rc, expected 2"
  [ "$(wc -l < "$T/err")" = 1 ] || bad "$1: not one line: $(cat "$T/err")"
  grep -qF "$1" "$T/err" && grep -qF "$2" "$T/err" || bad "$1: message '$(cat "$T/err")' lacks '$2'"
}
