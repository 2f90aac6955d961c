#!/bin/sh
# Nonlinear *RIGID BODY, *MPC STRAIGHT / PLANE / MEANROT under NLGEOM (issue 17; doc/theory.md
# 6.2.3) on a prism of C3D8 (constraints/nonlinear_mpc.py states the invariants and
# tolerances): rigid90, a rigid end face turned by 90 degrees, keeps its shape and follows
# Rodrigues' rotation to 1e-10; line_plane, turned by 60 degrees with loads against a
# STRAIGHT and a PLANE MPC: collinear and coplanar to 1e-10; meanrot, a MEANROT of 0.3 rad:
# the mean rotation of its nodes is 0.3 to 1e-10; meanrot_linear, without NLGEOM, the
# linearised mean rotation is the prescribed one.
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy or h5py not available to $py"; exit 77; }
script=$tests/integration/constraints/nonlinear_mpc.py
fail=0
for case in rigid90 line_plane meanrot meanrot_linear; do
  echo "== $case"
  "$py" "$script" deck "$case.inp" "$case" || exit 1
  "$FCS3D" -q "$case.inp" 2>&1 | grep -v '^warning\|^    |' ; [ -f "$case.h5" ] || { echo "fcs3d failed on $case.inp"; fail=1; continue; }
  "$py" "$script" check "$case" "$case" || fail=1
done
exit $fail
