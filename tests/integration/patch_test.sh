#!/bin/sh
# Patch test (foundation issue): a distorted 4x4x4 hex8 mesh with the linear displacement
# field u = u0 + A x prescribed on all boundary nodes (no NLGEOM) must reproduce the constant
# strain and stress C:eps at every integration point to round-off (relative 1e-10), and the
# field itself at the interior nodes, with FORMULATION=FULL and BBAR and with each linear
# solver (UMFPACK, SKYLINE, MUMPS); and the solvers must agree to 1e-10 relative on the
# displacements and stresses. Deck generator, checks and the justification of the
# tolerances: tests/tools/patch_test.py.
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
py=${PYTHON:-/usr/bin/python3}
tool="$here/tests/tools/patch_test.py"
fail=0
for formulation in FULL BBAR; do
  job=patch_$formulation
  "$py" "$tool" deck "$job.inp" --formulation "$formulation" || exit 1
  for solver in UMFPACK SKYLINE MUMPS; do
    mkdir -p "$solver"
    echo "== $formulation, $solver"
    "$FCS3D" -q --solver "$solver" -o "$solver" "$job.inp" || { echo "fcs3d failed"; fail=1; continue; }
    "$py" "$tool" check "$job.json" "$solver/$job.h5" "$solver/$job.dat" || fail=1
  done
  "$py" "$tool" agree "UMFPACK/$job.h5" "SKYLINE/$job.h5" || fail=1
  "$py" "$tool" agree "UMFPACK/$job.h5" "MUMPS/$job.h5" || fail=1
done
exit $fail
