#!/bin/sh
# Rigid smooth strip footing on a weightless von Mises layer in plane strain against Prandtl's
# limit load (2 + pi) s_y / sqrt(3) (`make validate`): three meshes graded towards the footing
# edge (96, 384 and 1536 C3D8, B-bar), displacement control; the limit load must be within
# 5 % on the finest mesh. Details in tests/validate/plasticity_footing.py; table in
# doc/validation/plasticity.md.
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
work=${FCS3D_TEST_WORK:-/tmp}/plasticity_footing
mkdir -p "$work" || exit 1
"${PYTHON:-/usr/bin/python3}" "$here/tests/validate/plasticity_footing.py" --fcs3d "$FCS3D" \
  --work "$work" --meshes 12x8,24x16,48x32 --markdown "$work/plasticity_footing.md" --assert-limit 0.05
