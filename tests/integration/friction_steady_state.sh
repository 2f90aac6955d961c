#!/bin/sh
# Steady sliding on a mesh with RATE STATE friction (ageing and slip laws): a one-element
# block on a rigid base, its top driven at 1e-3, 1e-2, 1e-4 mm/s in three steps, sigma_n =
# 10 MPa by pressure. After 20 DC of slip in each step the contact friction (history shear /
# pressure every increment, and the 'mu' field of the results) equals mu_ss(V) = MU0 +
# (A - B) ln(V/V0) within 1e-6 and the slip rate equals V within 1e-6. Deck and checks:
# friction/steady_state.py (its doc string says why; the step-end increments and the force
# the loading system feels are checked by tests/pending/friction_steady_state_body.sh).
# By hand: FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/friction_steady_state.sh'
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy or h5py not available to $py"; exit 77; }
script=$tests/integration/friction/steady_state.py
mkdir -p friction_steady_state && cd friction_steady_state || exit 1
status=0
for law in AGEING SLIP; do
  job=steady_$(echo $law | tr 'A-Z' 'a-z')
  "$py" "$script" deck $job.inp --state-law $law || exit 1
  "$FCS3D" -q $job.inp || { echo "fcs3d failed on $job.inp"; exit 1; }
  "$py" "$script" check $job --state-law $law || status=1
done
exit $status
