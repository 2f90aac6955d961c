#!/bin/sh
# The contact step on plain decks (issue 21): blocks of ordinary proportions, several
# elements, non-matching meshes, default increments and penalties, against closed forms
# (tests/integration/contact/plain_decks.py: models, closed forms, tolerances). Every case
# also checks that the out-of-balance force left by every increment is below the equilibrium
# tolerance (1e-3). Within 0.5 %: frictionless sliding (T = 0), Coulomb with default and capped
# increments (T/N = mu, never above, F_n = N), a slider sliding off the edge of bases of its own
# footprint (1x1, 2x2, 4x4 elements), and a rate-and-state velocity step (RF_x / N = 0.600 then
# 0.6115); the Coulomb case again with penalties 1e4 .. 1e7 and slip-weakening and the ageing
# and slip rate-and-state laws. Within 2 % at every increment: finite sliding over a segmented
# base (2 mm, NLGEOM), across a 5.6-degree kink (closed forms on each plane, rigid-block bounds
# while crossing) and across the joint of two base blocks (one pair over both, two pairs).
# Ties on non-matching meshes pass the patch test (uniform stress within 1e-3: tension across
# and along the tie, shear). A cube under follower pressure on all six faces, turned rigidly
# through 90 degrees, keeps sigma = -p I and zero reactions within 1e-3 (the Jaumann rate and
# the follower load rotate together). The frictional pair of the Coulomb case, turned rigidly
# through 90 degrees with its base's bottom, keeps F_n = N, F_t = 0, the bottom's reaction
# turned with the pair (1e-3 of N) and no state change. About 1.5 min.
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
script=$tests/integration/contact/plain_decks.py
mkdir -p contact_plain_decks && cd contact_plain_decks || exit 1
fail=0
"$py" "$script" run frictionless coulomb capped edge1 edge2 edge4 ratestate --tolerance 0.005 || fail=1
"$py" "$script" run long kink joint1 joint2 --tolerance 0.02 || fail=1
"$py" "$script" tie --tolerance 1e-3 || fail=1
"$py" "$script" rotation --tolerance 1e-3 || fail=1
"$py" "$script" turn --tolerance 1e-3 || fail=1
for law in COULOMB "SLIP WEAKENING" "RATE STATE AGEING" "RATE STATE SLIP"; do
  for penalty in 1e4 1e5 1e6 1e7; do
    "$py" "$script" run coulomb --penalty "$penalty" --law "$law" --tolerance 0.005 || fail=1
  done
done
exit $fail
