#!/bin/sh
# A deck with five independent errors (tests/decks/bad/multiple_errors.inp) must report all
# five at once, each with its own file:line:, end with the count line "5 error(s) in the
# input" and exit with status 2 (STYLE.md, "Errors": the parser collects errors and reports
# them together). The bad-deck runner checks one expect line only; this checks the rest.
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
deck="$here/tests/decks/bad/multiple_errors.inp"
out=$("$FCS3D" --check -o . "$deck" 2>&1); status=$?
fail=0
[ "$status" -eq 2 ] || { echo "exit status $status, expected 2"; fail=1; }
for expected in \
  'multiple_errors.inp:12: *NODE: coordinate z must be a number, not "2z"' \
  "multiple_errors.inp:21: *ELASTIC: Poisson's ratio must lie in (-1, 0.5)" \
  'multiple_errors.inp:26: *BOUNDARY: degrees of freedom must satisfy' \
  'multiple_errors.inp:29: *NODE PRINT: unknown parameter "FREQ"' \
  'multiple_errors.inp:31: unknown keyword *DSLOADS (did you mean *DSLOAD?)' \
  '5 error(s) in the input; nothing was run'; do
  printf '%s\n' "$out" | grep -qF -- "$expected" || { echo "missing: $expected"; fail=1; }
done
[ -e multiple_errors.echo ] && { echo "an echo was written for a deck with errors"; fail=1; }
[ "$fail" -eq 0 ] || { printf 'output was:\n%s\n' "$out"; exit 1; }
echo "all 5 errors reported with their lines, exit status 2"
