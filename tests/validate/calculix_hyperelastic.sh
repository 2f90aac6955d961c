#!/bin/sh
# Every *HYPERELASTIC form and *HYPERFOAM against CalculiX 2.20 (`make validate`): a 2 x 2 x 2
# C3D8 block stretched to 1.4 under NLGEOM through ccx and fcs3d, reaction force and nodal
# displacements within 1e-4 (doc/theory.md 2.11; details in calculix_hyperelastic.py). Skips
# (exit 77) without ccx. About 10 s.
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
work=${FCS3D_TEST_WORK:-/tmp}/calculix_hyperelastic
mkdir -p "$work" || exit 1
"$py" "$here/tests/validate/calculix_hyperelastic.py" --work "$work"
