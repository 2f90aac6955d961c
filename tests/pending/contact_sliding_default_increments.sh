#!/bin/sh
# PENDING (fails at 798158c; no fix proposed yet, see doc/validation/contact.md).
# The block-sliding test of tests/integration/contact_block_sliding.sh (variant partial: T/N
# must not exceed mu by more than 1 %) with the default increments instead of a cap of 0.01 of
# the step: T/N overshoots to 0.3173 (+5.8 %) at the onset of gross slip and comes back to
# 0.2980 only at the end of the push; with a cap of 0.05 the overshoot is the same, 0.02 gives
# +2.0 %, 0.01 and 0.005 give none.
# Diagnosis: once every node slips, nothing limits the increment but the strain limit, and
# the slider barely strains: increments reach 0.2 of the step (0.02 of slide, 200 times the
# stick slip mu p / E_t = 1e-4). Within such an increment the friction direction of the
# nodes that slipped radially under the pressure of step 1 turns by up to 90 degrees to -x;
# the linear predictor (slip tangent with the perpendicular stiffness mu f_n E_t / |f_tr|)
# cannot follow the rotation, the return mapping caps the forces, and the out-of-balance
# force (0.16-0.20, against internal forces of 4.5) is carried over several increments, the
# elastic shear of the slider first overshooting.
# Tried in src/contact/fcs_contact_system.f90 (not proposed): an R-minimum limit on the
# rotation of the trial friction direction of slipping nodes (2 degrees: overshoot gone, 327
# increments instead of 46; 5 degrees: still +3.7 %) makes the finite-sliding tests several
# times slower (chatter of nodes near the cone), so it needs more thought; the remedy today
# is a maximum increment on *STATIC.
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
script=$tests/integration/contact/block_sliding.py
mkdir -p contact_sliding_default_increments && cd contact_sliding_default_increments || exit 1
"$py" "$script" deck partial.inp --variant partial || exit 1
"$FCS3D" -q partial.inp || { echo "fcs3d failed on partial.inp"; exit 1; }
"$py" "$script" check partial --variant partial --tolerance 0.01
