#!/bin/sh
# The paper's statements over an ensemble of fault-bend runs that differ in round-off only
# (issue 19, item 7; tests/validate/fault_bend_ensemble.py): the deck of `make run` with MUMPS,
# UMFPACK and SKYLINE, 1 or 2 BLAS/OpenMP threads, factor reuse, and (with bin/fcs3d-mpi and
# mpirun) MUMPS on 2 MPI processes; the fraction of runs in which each statement holds and the
# spread of the first slip, nucleation and event onsets go to
# doc/validation/fault_bend_ensemble.md and .csv. Then the static-friction anchors (item 4:
# the deck's level against mu_s = MU0, times from the first slip) into
# doc/validation/fault_bend_anchors.md and .csv. Exit 0 when every run completed and the tables
# were written; the fractions are results, not checks. 9 + 3 runs of the default mesh: the
# reference deck took 2.1-4.8 CPU-minutes per serial run and 7.6 for MUMPS on 2 processes
# (doc/validation/fault_bend.md, section 5).
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
py=${PYTHON:-/usr/bin/python3}
command -v gmsh >/dev/null 2>&1 || { echo "gmsh not installed"; exit 77; }
status=0
"$py" "$root/tests/validate/fault_bend_ensemble.py" --fcs3d "$FCS3D" --work "$PWD/ensemble" \
  --out "$root/doc/validation" --jobs 2 || status=1
"$py" "$root/tests/validate/fault_bend_ensemble.py" --set anchors --fcs3d "$FCS3D" \
  --work "$PWD/anchors" --out "$root/doc/validation" --jobs 2 || status=1
exit $status
