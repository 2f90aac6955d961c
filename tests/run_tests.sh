#!/bin/sh
# The fcs3d test suite (run by `make test`):
#   1. unit tests: every program in $UNIT_DIR (built from tests/unit/test_*.f90);
#   2. bad decks: every tests/decks/bad/*.inp must fail with exit status 2 and a message
#      containing the text of its `** expect:` line and a file:line: location (with a line
#      number: "deck.inp:12: ");
#   3. integration tests: every tests/integration/*.sh (exit 0 pass, 77 skip, else fail).
# Prints one line per test and ends with "N passed, N failed".
# Environment: FCS3D (the binary), UNIT_DIR, PYTHON (/usr/bin/python3).
set -u
here=$(cd "$(dirname "$0")" && pwd)
: "${FCS3D:?FCS3D must name the fcs3d binary}"
: "${UNIT_DIR:?UNIT_DIR must name the unit test directory}"
: "${PYTHON:=/usr/bin/python3}"
export FCS3D PYTHON
work=$(mktemp -d "${TMPDIR:-/tmp}/fcs3d-tests.XXXXXX")
export FCS3D_TEST_WORK="$work"
export FCS3D_TEST_DATA="$here/data"
passed=0; failed=0; skipped=0; failures=""
record() { # name status(0 pass, 77 skip, other fail) [detail]
  if [ "$2" -eq 0 ]; then passed=$((passed + 1)); printf 'PASS %s\n' "$1"
  elif [ "$2" -eq 77 ]; then skipped=$((skipped + 1)); printf 'SKIP %s\n' "$1"
  else failed=$((failed + 1)); failures="$failures $1"; printf 'FAIL %s\n' "$1"
    [ -n "${3:-}" ] && printf '%s\n' "$3" | sed 's/^/     /'
  fi
}

echo "== unit tests"
for t in "$UNIT_DIR"/test_*; do
  [ -f "$t" ] && [ -x "$t" ] || continue
  name=$(basename "$t")
  out=$(cd "$work" && timeout 600 "$t" 2>&1); status=$?
  record "unit/$name" "$status" "$(printf '%s\n' "$out" | grep -E 'FAIL|Error|error' | head -20)"
done

echo "== bad decks"
for deck in "$here"/decks/bad/*.inp; do
  [ -f "$deck" ] || continue
  name=$(basename "$deck" .inp)
  expect=$(sed -n 's/^\*\* *expect: *//p' "$deck" | head -1)
  out=$(cd "$work" && timeout 60 "$FCS3D" --check -o "$work" "$deck" 2>&1); status=$?
  if [ "$status" -ne 2 ]; then
    record "deck/$name" 1 "exit status $status, expected 2; output: $(printf '%s' "$out" | head -5)"
  elif [ -z "$expect" ]; then
    record "deck/$name" 1 "the deck has no '** expect:' line"
  elif ! printf '%s' "$out" | grep -qF -- "$expect"; then
    record "deck/$name" 1 "message lacks \"$expect\"; got: $(printf '%s' "$out" | head -5)"
  elif ! printf '%s' "$out" | sh "$here/tools/has_location.sh"; then
    record "deck/$name" 1 "no file:line: location (a line number) in: $(printf '%s' "$out" | head -3)"
  else
    record "deck/$name" 0
  fi
done

echo "== integration tests"
for t in "$here"/integration/*.sh; do
  [ -f "$t" ] || continue
  name=$(basename "$t" .sh)
  out=$(cd "$work" && timeout 1200 sh "$t" 2>&1); status=$?
  record "integration/$name" "$status" "$(printf '%s\n' "$out" | tail -15)"
done

rm -rf "$work"
echo
[ -n "$failures" ] && echo "failed:$failures"
if [ "$skipped" -gt 0 ]; then
  echo "$passed passed, $failed failed ($skipped skipped)"
else
  echo "$passed passed, $failed failed"
fi
[ "$failed" -eq 0 ]
