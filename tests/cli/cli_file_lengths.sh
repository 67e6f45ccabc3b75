#!/bin/bash
# cli_file_lengths.sh VIGEN SRC — no template and no test source is over 800
# lines: a file that long holds several concerns, and is split by concern
# (templates with @include FILE@, docs/templates.md; tests into one file per
# concern, shared helpers in a header).  Covered: every file under templates/
# and tests/, except tests/data/ (inputs and expected outputs: a golden
# emitted stepper is as long as the emitter's output).
#
# LONG lists the files still over the limit, each a known debt; a file named
# there that is no longer over the limit fails too, so the list only shrinks.
set -u
SRC=$2
MAX=800
LONG=""
fail=0
cd "$SRC" || { echo "FAIL: cannot enter $SRC"; exit 1; }
files=$(find templates tests -path tests/data -prune -o -type f -print | sort)
[ -n "$files" ] || { echo "FAIL: no file under templates/ or tests/"; exit 1; }
n=0
for f in $files; do
  n=$((n + 1))
  lines=$(wc -l <"$f")
  known=0
  for k in $LONG; do [ "$f" = "$k" ] && known=1; done
  if [ "$lines" -gt $MAX ] && [ $known -eq 0 ]; then
    echo "FAIL: $f has $lines lines (at most $MAX: split it by concern)"
    fail=1
  elif [ "$lines" -le $MAX ] && [ $known -eq 1 ]; then
    echo "FAIL: $f has $lines lines, no longer over $MAX: remove it from LONG in $0"
    fail=1
  fi
done
for k in $LONG; do [ -f "$k" ] || { echo "FAIL: LONG names $k, which does not exist: remove it"; fail=1; }; done
[ $fail -eq 0 ] && echo "cli_file_lengths: $n files under templates/ and tests/, none over $MAX lines but those LONG names"
exit $fail
