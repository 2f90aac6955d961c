#!/bin/sh
# Block on a block under a normal load, pushed sideways (contact issue, test 1): T/N = mu within
# 1 % in gross slip, no overshoot, T(u) non-decreasing before (NLGEOM, non-matching meshes);
# and with a soft stick slope E_t the stick slope equals E_t A within 1 % (independent
# estimate with the blocks' shear compliance: 1e-4) and gross slip starts where the most
# loaded node's stick spring reaches the cone. Model, closed forms, tolerances:
# contact/block_sliding.py. The partial variant runs twice, with the push capped at 0.01 of the
# step per increment and with the default increments (the gross-slip phase then takes two or
# three increments; before the equilibrium iterations of the static-explicit step it
# overshot mu by 5.8 %); the soft one with a cap of 0.02. About 10 s.
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
script=$tests/integration/contact/block_sliding.py
mkdir -p contact_block_sliding && cd contact_block_sliding || exit 1
fail=0
"$py" "$script" deck partial.inp --variant partial --max-increment 0.01 || exit 1
"$FCS3D" -q partial.inp || { echo "fcs3d failed on partial.inp"; exit 1; }
"$py" "$script" check partial --variant partial --tolerance 0.01 || fail=1
"$py" "$script" deck default.inp --variant partial || exit 1
"$FCS3D" -q default.inp || { echo "fcs3d failed on default.inp"; exit 1; }
"$py" "$script" check default --variant partial --tolerance 0.01 --min-slip-outputs 2 || fail=1
"$py" "$script" deck soft.inp --variant soft --max-increment 0.02 || exit 1
"$FCS3D" -q soft.inp || { echo "fcs3d failed on soft.inp"; exit 1; }
"$py" "$script" check soft --variant soft --tolerance 0.01 || fail=1
exit $fail
