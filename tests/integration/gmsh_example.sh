#!/bin/sh
# gmsh end to end (foundation issue): input/examples/run_block.sh meshes
# input/examples/block.geo with `gmsh -3 -format msh41` into this scratch directory and runs
# input/examples/block.inp (*MESH, FILE=block.msh; physical groups BLOCK, FIXED, LOADED).
# Checks: exit status 0; block.h5 read back with h5py (tests/tools/check_gmsh_example.py:
# /mesh and the last frame's fields with the expected shapes, plus physics checks); and
# post/check_xdmf.py accepts block.xdmf with its 2 frames. Skips (77) only without gmsh.
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
py=${PYTHON:-/usr/bin/python3}
command -v gmsh >/dev/null 2>&1 || { echo "gmsh not installed"; exit 77; }
FCS3D="$FCS3D" sh "$here/input/examples/run_block.sh" block_run > run.log 2>&1 || {
  echo "run_block.sh failed (status $?):"; tail -20 run.log; exit 1; }
cd block_run || exit 1
[ -s block.msh ] && [ -s block.h5 ] && [ -s block.xdmf ] || { echo "missing block.msh/h5/xdmf"; exit 1; }
"$py" "$here/tests/tools/check_gmsh_example.py" block.h5 block.dat || exit 1
"$py" "$here/post/check_xdmf.py" --frames 2 block.xdmf
