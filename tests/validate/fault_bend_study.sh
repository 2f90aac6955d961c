#!/bin/sh
# The fault-bend study (doc/validation/fault_bend_paper_law.md, section 8): the paper's-law deck
# (input/fault_bend/fault_bend_paper_law.inp, the default before issue 19, on its non-matching
# fault mesh, lower_fault_factor 1.25) and one-change variants (mesh, E_n, E_t, R-minimum limits, minimum increment, VC, LINEAR, flat fault,
# matching nodes), each meshed with gmsh and run to 400 s; the table goes to
# doc/validation/fault_bend_study.md and .csv. Checks: every run completes, the default first
# slip is within 25 % of the paper's 228.7 s, the two meshes agree within 10 %.
# Long: about an hour of CPU on 2 cores (the fine mesh dominates); FAULT_BEND_STUDY_ONLY=a,b
# runs a subset.
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
command -v gmsh >/dev/null 2>&1 || { echo "gmsh not installed"; exit 77; }
"${PYTHON:-/usr/bin/python3}" "$root/tests/validate/fault_bend_study.py" --fcs3d "$FCS3D" \
  --work "$PWD/study" --out "$root/doc/validation" --jobs 2 \
  ${FAULT_BEND_STUDY_ONLY:+--only "$FAULT_BEND_STUDY_ONLY"}
