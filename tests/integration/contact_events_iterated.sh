#!/bin/sh
# *RMIN, CONTACT EVENTS=NORMAL | CLOSING and --contact-events (contact changes left to the
# equilibrium iterations: onsets of slip and segment hand-overs; with CLOSING openings too)
# against the R-minimum events of every contact change (ALL, the default) on the contact
# benchmark's block on a block at N = 8 (non-matching interface, Coulomb mu = 0.3, NLGEOM,
# default increments *STATIC 1., 1.; contact/contact_events.py says what is checked and why):
#  - every run ends in gross slip with T/(mu N) - 1 within 0.5 %;
#  - NORMAL's and CLOSING's T at 20 sample times of the push within 1 % of mu N of ALL's;
#  - each takes fewer increments than ALL, none limited by an event it leaves to the iterations;
#  - the deck parameter and the command line option give identical .dat and history files;
#  - CLOSING restarted from its end-of-step-1 checkpoint repeats its .dat and history byte
#    for byte;
#  - --contact-events with another value is a command-line error (exit 2).
# About 50 s.
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
script=$tests/integration/contact/contact_events.py
mkdir -p contact_events_iterated && cd contact_events_iterated || exit 1
fail=0
"$py" "$script" deck 8 all.inp || exit 1
cp all.inp normal.inp && cp all.inp closing.inp || exit 1
"$py" "$script" deck 8 deck.inp --in-deck NORMAL || exit 1
"$FCS3D" -q all.inp || { echo "fcs3d failed on all.inp"; exit 1; }
"$FCS3D" -q --contact-events normal normal.inp || { echo "fcs3d failed on normal.inp"; exit 1; }
"$FCS3D" -q --contact-events CLOSING closing.inp || { echo "fcs3d failed on closing.inp"; exit 1; }
"$FCS3D" -q deck.inp || { echo "fcs3d failed on deck.inp"; exit 1; }
"$py" "$script" check all normal --mode NORMAL || fail=1
"$py" "$script" check all closing --mode CLOSING || fail=1
for f in .dat _h.csv; do
  if cmp -s "normal$f" "deck$f"; then
    echo "PASS  --contact-events NORMAL and *RMIN, CONTACT EVENTS=NORMAL: identical $f files"
  else
    echo "FAIL  --contact-events NORMAL and *RMIN, CONTACT EVENTS=NORMAL: the $f files differ"; fail=1
  fi
done
# A restart of the CLOSING run from its end-of-step-1 checkpoint (the older generation), with
# the same option (also taken from the checkpoint when not given:
# restart_command_line_options.sh), continues bit for bit.
cp closing.dat closing_once.dat && cp closing_h.csv closing_once_h.csv || exit 1
if "$FCS3D" -q --contact-events CLOSING --restart closing.rst.1.h5 closing.inp &&
   cmp -s closing.dat closing_once.dat && cmp -s closing_h.csv closing_once_h.csv; then
  echo "PASS  CLOSING restarted from the step-1 checkpoint: identical .dat and history"
else
  echo "FAIL  CLOSING restarted from the step-1 checkpoint: not the run in one go"; fail=1
fi
out=$("$FCS3D" --check --contact-events some all.inp 2>&1); status=$?
if [ "$status" -eq 2 ] && printf '%s' "$out" | grep -qF -- '--contact-events some: expected ALL, NORMAL or CLOSING'; then
  echo "PASS  --contact-events some refused (exit 2)"
else
  echo "FAIL  --contact-events some: exit status $status, output: $out"; fail=1
fi
exit $fail
