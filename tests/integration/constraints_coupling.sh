#!/bin/sh
# *COUPLING with *KINEMATIC and *DISTRIBUTING (issue 17) on a graded prism of C3D8
# (constraints/coupling.py states the closed forms and tolerances): kinematic: the end face
# pulled and turned through the reference node (and the generated rotation node) stays
# rigid to round-off, RF at the reference node = F = the face's internal force, RF at the
# rotation node balances the supports' moment; kinematic_nlgeom: the face follows the
# finite rotation; distributing: a force on the reference node is the uniform traction F/A
# (patch test: s_xx = F/A everywhere) and the reference node moves as the area-weighted mean
# of the face, with UMFPACK, SKYLINE and MUMPS.
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
script=$tests/integration/constraints/coupling.py
fail=0
for case in kinematic kinematic_nlgeom; do
  echo "== $case"
  "$py" "$script" deck "$case.inp" "$case" || exit 1
  "$FCS3D" -q "$case.inp" || { echo "fcs3d failed on $case.inp"; fail=1; continue; }
  "$py" "$script" check "$case" "$case" || fail=1
done
"$py" "$script" deck distributing.inp distributing || exit 1
for solver in UMFPACK SKYLINE MUMPS; do
  mkdir -p "$solver"
  echo "== distributing, $solver"
  "$FCS3D" -q --solver "$solver" -o "$solver" distributing.inp || { echo "fcs3d failed"; fail=1; continue; }
  "$py" "$script" check "$solver/distributing" distributing || fail=1
done
exit $fail
