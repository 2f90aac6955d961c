#!/bin/sh
# Every element kind through the deck (issue 16): for C3D4, C3D6, C3D10, C3D15, C3D20, C3D20R
# and two mixed meshes (C3D8 + C3D6, C3D20 + C3D15), a distorted 4x4x4 grid of the box
# [0,2]x[0,1.5]x[0,1] cut into elements of the kind (tests/tools/kind_meshes.py) with the
# linear displacement field u = u0 + A x prescribed on its boundary must reproduce the constant
# strain and stress at every integration point and the field at every node to round-off (the
# patch test; tolerances in tests/tools/patch_test.py), with UMFPACK and SKYLINE, which must
# agree; and the XDMF must open in VTK's Xdmf reader (as ParaView) with every cell a positive
# 3D solid in VTK's node order (post/check_xdmf_vtk.py; skipped when VTK's reader is missing).
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
py=${PYTHON:-/usr/bin/python3}
tool="$here/tests/tools/patch_test.py"
fail=0
for kind in C3D4 C3D6 C3D10 C3D15 C3D20 C3D20R MIXED MIXED20; do
  job=kind_$kind
  "$py" "$tool" deck "$job.inp" --kind "$kind" || exit 1
  for solver in UMFPACK SKYLINE; do
    mkdir -p "$solver"
    echo "== $kind, $solver"
    "$FCS3D" -q --solver "$solver" -o "$solver" "$job.inp" || { echo "fcs3d failed"; fail=1; continue; }
    "$py" "$tool" check "$job.json" "$solver/$job.h5" "$solver/$job.dat" || fail=1
  done
  "$py" "$tool" agree "UMFPACK/$job.h5" "SKYLINE/$job.h5" || fail=1
  "$py" "$here/post/check_xdmf_vtk.py" "UMFPACK/$job.xdmf"; status=$?
  [ $status -eq 0 ] || [ $status -eq 77 ] || fail=1
done
exit $fail
