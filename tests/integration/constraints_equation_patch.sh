#!/bin/sh
# *EQUATION patch test (issue 17): two blocks with non-matching meshes tied by linear
# equations (each upper interface node = bilinear interpolation of the lower face) carry a
# uniform stress to round-off: s_xx = -q, s_zz = -p at every integration point within 1e-6 q
# (7-digit print), the base reaction and the corner displacement of Hooke's law within 1e-6.
# Upper 4x4 on lower 2x2 (a refinement: the test holds with traction across the interface)
# with UMFPACK, SKYLINE, MUMPS and, if built, MUMPS on 2 MPI ranks; upper 3x3 on 2x2 and 2x2
# on 3x3 with traction along the interface only (why: constraints/equation_patch_test.py).
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
script=$tests/integration/constraints/equation_patch_test.py
fail=0
"$py" "$script" deck nested.inp --upper 4 --lower 2 || exit 1
for solver in UMFPACK SKYLINE MUMPS; do
  mkdir -p "$solver"
  echo "== upper 4x4 on lower 2x2, $solver"
  "$FCS3D" -q --solver "$solver" -o "$solver" nested.inp || { echo "fcs3d failed"; fail=1; continue; }
  "$py" "$script" check "$solver/nested" || fail=1
done
mpi_bin=${FCS3D_MPI:-}
if [ -n "$mpi_bin" ] && [ -x "$mpi_bin" ] && command -v mpirun >/dev/null 2>&1; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
  mkdir -p mpi && cp nested.inp mpi/nested.inp
  echo "== upper 4x4 on lower 2x2, MUMPS on 2 MPI ranks"
  (cd mpi && timeout 300 mpirun --oversubscribe -np 2 "$mpi_bin" -q --solver MUMPS nested.inp) || \
    { echo "fcs3d-mpi failed"; fail=1; }
  "$py" "$script" check mpi/nested || fail=1
else
  echo "(no MPI build or mpirun: the 2-rank run is skipped)"
fi
for case in "3 2" "2 3"; do
  set -- $case
  job=lateral_$1_on_$2
  echo "== upper $1x$1 on lower $2x$2, traction along the interface only"
  "$py" "$script" deck "$job.inp" --upper "$1" --lower "$2" --pressure 0 || exit 1
  "$FCS3D" -q "$job.inp" || { echo "fcs3d failed on $job.inp"; fail=1; continue; }
  "$py" "$script" check "$job" --pressure 0 || fail=1
done
exit $fail
