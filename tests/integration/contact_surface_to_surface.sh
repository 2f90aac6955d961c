#!/bin/sh
# Surface-to-surface contact (*CONTACT PAIR, TYPE=SURFACE TO SURFACE; doc/theory.md 4.10,
# doc/validation/contact.md): the contact patch test on non-matching interfaces (C3D8 slave
# finer and coarser than the master, C3D20 and C3D20R): s_zz = -p at every integration point
# to 1e-6 (print), the pressure p at every slave point to 1e-8 (round-off); Coulomb sliding
# T/(mu N) within 0.5 %; a frictionless push with no shear traction anywhere.
# contact/surface_to_surface.py. About 25 s.
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy/h5py not available to $py"; exit 77; }
script=$tests/integration/contact/surface_to_surface.py
mkdir -p contact_surface_to_surface && cd contact_surface_to_surface || exit 1
fail=0
for case in "patch C3D8 5 3" "patch C3D8 3 5" "patch C3D20 5 3" "patch C3D20R 4 3" \
            "slide C3D8 5 3" "free C3D8 5 3"; do
  set -- $case
  job=$1_$2_$3_on_$4
  "$py" "$script" deck "$job.inp" --case "$1" --kind "$2" --slave "$3" --master "$4" || exit 1
  "$FCS3D" -q "$job.inp" || { echo "fcs3d failed on $job.inp"; fail=1; continue; }
  "$py" "$script" check "$job" --case "$1" --kind "$2" --slave "$3" --master "$4" || fail=1
done
exit $fail
