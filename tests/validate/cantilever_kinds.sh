#!/bin/sh
# Cantilever convergence table with C3D20R, C3D10 and C3D8I (`make validate`): the meshes of
# tests/integration/cantilever_kinds.sh and two finer ones (40x4x4, 80x8x8), against
# Timoshenko beam theory (tests/tools/cantilever_kinds.py). Rewrites
# doc/validation/cantilever_kinds.md with the table and the command, and requires an error
# that shrinks with every refinement and |error| <= 1% on the finest mesh for each kind.
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
cd "$here" || exit 1
work=${FCS3D_TEST_WORK:-/tmp}/cantilever_kinds
mkdir -p "$work" || exit 1
"${PYTHON:-/usr/bin/python3}" tests/tools/cantilever_kinds.py --fcs3d "$FCS3D" --work "$work" \
  --kinds C3D20R,C3D10,C3D8I --meshes 10x2x2,20x2x2,40x4x4,80x8x8 \
  --markdown doc/validation/cantilever_kinds.md --assert-converging \
  --assert-error C3D20R:80x8x8:0.01 --assert-error C3D10:80x8x8:0.01 --assert-error C3D8I:80x8x8:0.01
