#!/bin/sh
# The two readings of the friction law's velocity in the fault-bend model (issue 19, item 4;
# tests/validate/fault_bend_readings.py): the paper's law (fault_bend_paper_law.inp) with
# VELOCITY=SLIP (the slip rate, fcs3d's default) and VELOCITY=RELATIVE (the total relative
# tangential velocity, the literal eq. 3 of Xing, Mora & Makinouchi 2003), each with the
# floor anchor (VC = 1e-6 mm/s) and the mu_s = 0.60 anchor (VC = V0), plus the reference deck
# read with VELOCITY=RELATIVE: first slip, first system-size event, event times from the first
# slip, stress drops, and whether the release of D-E comes the paper's 64 s after the first
# slip, into doc/validation/fault_bend_readings.md and .csv. Exit 0 when every run completed
# and the table was written; the verdicts are results, not checks. 5 runs of the default mesh,
# 0.5-3 CPU-minutes each.
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
py=${PYTHON:-/usr/bin/python3}
command -v gmsh >/dev/null 2>&1 || { echo "gmsh not installed"; exit 77; }
"$py" "$root/tests/validate/fault_bend_readings.py" --fcs3d "$FCS3D" --work "$PWD/readings" \
  --out "$root/doc/validation" --with-reference
