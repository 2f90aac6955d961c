#!/bin/sh
# Cantilever convergence table (`make validate`): the meshes of tests/integration/cantilever.sh
# and two finer ones (80x8x8, 160x16x16: about 30 s), FORMULATION=FULL and BBAR, against
# Timoshenko beam theory (tests/tools/cantilever.py). Rewrites doc/validation/cantilever.md
# with the table and the command, and requires |error| <= 2% with BBAR on the finest mesh and
# an error that shrinks with every refinement.
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
cd "$here" || exit 1
work=${FCS3D_TEST_WORK:-/tmp}/cantilever
mkdir -p "$work" || exit 1
"${PYTHON:-/usr/bin/python3}" tests/tools/cantilever.py --fcs3d "$FCS3D" --work "$work" \
  --meshes 10x1x1,20x2x2,40x4x4,80x8x8,160x16x16 --formulations FULL,BBAR --solvers UMFPACK \
  --markdown doc/validation/cantilever.md --assert-error 0.02 --assert-converging
