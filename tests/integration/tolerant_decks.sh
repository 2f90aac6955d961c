#!/bin/sh
# Decks that CalculiX accepts and fcs3d reads as CalculiX does (issue 16, item 4: a reader as
# tolerant as CalculiX where CalculiX is tolerant, each tolerance still reported where a user
# should know). Every tests/decks/tolerant/*.inp must pass `fcs3d --check` (exit 0) and print
# each of its `** warning:` lines (the text, with the file:line it names, as a warning); a deck
# without such lines must print no warning at all. With ccx installed (Debian calculix-ccx),
# ccx must run every deck too (exit 0, no *ERROR in its output): CalculiX accepts them. What
# stays refused is in tests/decks/bad/. About 5 s.
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
work=${FCS3D_TEST_WORK:-$(mktemp -d)}/tolerant_decks
mkdir -p "$work" || exit 1
have_ccx=0
command -v ccx >/dev/null 2>&1 && have_ccx=1
fail=0; n=0
for deck in "$here"/tests/decks/tolerant/*.inp; do
  name=$(basename "$deck" .inp)
  n=$((n + 1))
  out=$(cd "$work" && "$FCS3D" --check -o "$work" "$deck" 2>&1); status=$?
  if [ "$status" -ne 0 ]; then
    echo "FAIL $name: fcs3d --check exit status $status, expected 0:"; printf '%s\n' "$out" | head -5
    fail=1; continue
  fi
  expected=$(sed -n 's/^\*\* *warning: *//p' "$deck")
  if [ -z "$expected" ]; then
    if printf '%s\n' "$out" | grep -q '^warning: '; then
      echo "FAIL $name: a warning, where none was expected:"; printf '%s\n' "$out" | grep '^warning: '
      fail=1
    fi
  else
    printf '%s\n' "$expected" | while IFS= read -r text; do
      printf '%s\n' "$out" | grep '^warning: ' | grep -qF -- "$text" || {
        echo "FAIL $name: missing warning: $text"; printf 'output was:\n%s\n' "$out"; exit 1; }
    done || fail=1
  fi
  if [ "$have_ccx" -eq 1 ]; then
    mkdir -p "$work/ccx_$name" && cp "$deck" "$work/ccx_$name/" || exit 1
    (cd "$work/ccx_$name" && OMP_NUM_THREADS=1 timeout 120 ccx -i "$name" > ccx.log 2>&1); status=$?
    if [ "$status" -ne 0 ] || grep -q '\*ERROR' "$work/ccx_$name/ccx.log"; then
      echo "FAIL $name: ccx does not accept it (exit status $status):"
      grep -A3 '\*ERROR' "$work/ccx_$name/ccx.log" | head -8
      fail=1
    fi
  fi
done
[ "$have_ccx" -eq 1 ] || echo "(ccx not installed: CalculiX's acceptance not checked)"
[ "$fail" -eq 0 ] || exit 1
echo "$n tolerant decks read with their warnings$( [ "$have_ccx" -eq 1 ] && echo ', and run by ccx')"
