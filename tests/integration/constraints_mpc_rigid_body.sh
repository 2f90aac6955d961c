#!/bin/sh
# *MPC PLANE / STRAIGHT and *RIGID BODY (issue 17), linearised in the initial configuration,
# on a prism of C3D8 (constraints/mpc_rigid.py states the closed forms and tolerances):
# plane: a plane end face under a centred force is a frictionless platen, the stress is the
# uniform s_xx = F/A (1e-6, print), the edge kept straight by STRAIGHT stays so;
# plane_offset: an off-centre force tilts the plane face, which keeps the linearised plane
# condition to round-off; rigid: the end face follows the reference node and the rotation
# node exactly, RF at the reference node is the force the body transmits and RF at the
# rotation node the moment balancing the supports' (as CalculiX prints them).
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
script=$tests/integration/constraints/mpc_rigid.py
fail=0
for case in plane plane_offset rigid; do
  echo "== $case"
  "$py" "$script" deck "$case.inp" "$case" || exit 1
  "$FCS3D" -q "$case.inp" || { echo "fcs3d failed on $case.inp"; fail=1; continue; }
  "$py" "$script" check "$case" "$case" || fail=1
done
exit $fail
