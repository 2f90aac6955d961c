#!/bin/sh
# A frictionless contact pair must not cost increments for stick/slip events: the contact
# patch test with matching meshes (tests/integration/contact/patch_test.py --mu 0, linear, one
# load step) is exact in one increment, and the frictionless Hertz problem needs no increment
# limited by 'stick->slip'.
#
# Bug: the matching patch test takes 12529 increments (3 minutes) instead of 1, nearly all of
# them floored (r = 1e-5 of the step) and limited by 'stick->slip'; the frictionless Hertz
# cylinder of contact_hertz.sh (hc = 0.2) takes 20 increments, 9 of them 'stick->slip' events
# at the floor.
# Diagnosis: a node closes (initial_state, update_open) in CONTACT_STICK, also when mu = 0.
# The Coulomb cone of a frictionless node has no interior, so the R-minimum search finds its
# stick->slip event at r = 0 (an increment of the minimum size); update_closed then sets it to
# slip, but contact_update returns CONTACT_STICK again whenever the trial friction is zero
# (|f_tr| <= mu f_n with both sides 0: a node without tangential motion, as in the patch test,
# or the symmetry node of the Hertz problem), and the cycle repeats every increment.
# Fix (the patch): close frictionless nodes as CONTACT_SLIP, and keep a frictionless node that
# the return mapping calls stick in slip (closing_status). With it: 1 increment for the patch
# test (same pressures, to 1e-13), 11 instead of 20 for Hertz (same p0 and a), no stick->slip
# event in either.
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy/h5py not available to $py"; exit 77; }
mkdir -p contact_frictionless_closing && cd contact_frictionless_closing || exit 1
script=$tests/integration/contact/patch_test.py
"$py" "$script" deck patch.inp --slave 4 --master 4 --mu 0 || exit 1
# At most 100 increments, so that the failing run stops at once.
sed 's/^\*STEP$/*STEP, INC=100/' patch.inp > patch_capped.inp
fail=0
"$FCS3D" -q patch_capped.inp || { echo "fcs3d failed (more than 100 increments?)"; fail=1; }
n=$(grep -c '^inc ' patch_capped.log)
echo "matching frictionless patch test: $n increment(s) (expected 1)"
[ "$n" -eq 1 ] || fail=1
if [ "$fail" -eq 0 ]; then
  "$py" "$script" check patch_capped --slave 4 --master 4 || fail=1
fi
if command -v gmsh >/dev/null 2>&1; then
  hertz=$tests/integration/contact/hertz.py
  "$py" "$hertz" mesh hertz.msh --hc 0.2 || exit 1
  "$py" "$hertz" deck hertz.inp --mesh hertz.msh --hc 0.2 || exit 1
  "$FCS3D" -q hertz.inp || { echo "fcs3d failed on hertz.inp"; exit 1; }
  events=$(grep '^inc ' hertz.log | grep -c 'limit stick->slip')
  echo "frictionless Hertz: $(grep -c '^inc ' hertz.log) increments, $events limited by stick->slip (expected 0)"
  [ "$events" -eq 0 ] || fail=1
fi
exit $fail
