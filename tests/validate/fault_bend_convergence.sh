#!/bin/sh
# Mesh convergence of the fault-bend run (issue 19, item 6; tests/validate/
# fault_bend_convergence.py): the deck of `make run` on three meshes refined from the .geo
# defaults h (h_fault and h_far divided by the factor, the layers through the thickness
# multiplied by it): h sqrt 2, h and h/sqrt 2, each to the deck's end time; first slip,
# nucleation duration, onsets and stress drops of the first three system-size events, with
# relative differences between consecutive meshes, into doc/validation/fault_bend_convergence.md
# and .csv. Exit 0 when every run completed and the table was written: whether the two finest
# agree within 5 % is in the table, not in the status. About 9.5 CPU-minutes (h/sqrt 2: 6.2);
# h/2 would take 20-30 (doc/validation/fault_bend.md, section 5.1): FAULT_BEND_FACTORS=1,1.414214,2.
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
command -v gmsh >/dev/null 2>&1 || { echo "gmsh not installed"; exit 77; }
"${PYTHON:-/usr/bin/python3}" "$root/tests/validate/fault_bend_convergence.py" --fcs3d "$FCS3D" \
  --work "$PWD/convergence" --out "$root/doc/validation" --jobs 2 \
  ${FAULT_BEND_FACTORS:+--factors "$FAULT_BEND_FACTORS"}
