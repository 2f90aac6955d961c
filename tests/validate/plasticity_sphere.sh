#!/bin/sh
# Thick-walled sphere (a = 1, b = 2) under internal pressure, elastic-perfectly plastic von
# Mises, against Hill's closed form (`make validate`): three cube-sphere meshes of the octant
# (48, 384 and 3072 C3D8, B-bar), the pressure-expansion curve and the limit pressure
# 2 s_y ln(b/a); the limit pressure must be within 2 % on the finest mesh. About 3 minutes.
# Details in tests/validate/plasticity_sphere.py; table in doc/validation/plasticity.md.
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
work=${FCS3D_TEST_WORK:-/tmp}/plasticity_sphere
mkdir -p "$work" || exit 1
"${PYTHON:-/usr/bin/python3}" "$here/tests/validate/plasticity_sphere.py" --fcs3d "$FCS3D" \
  --work "$work" --meshes 2x4,4x8,8x16 --markdown "$work/plasticity_sphere.md" --assert-limit 0.02
