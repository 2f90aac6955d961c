#!/bin/sh
# Mesh and run the gmsh example without make: copies block.inp and block.geo into a work
# directory, meshes block.geo there with gmsh (MSH 4.1) and runs fcs3d on block.inp.
# Usage: sh input/examples/run_block.sh [work directory (default ./block_run)]
# The fcs3d binary is $FCS3D, else bin/fcs3d of this checkout, else fcs3d on the PATH.
set -eu
examples=$(cd "$(dirname "$0")" && pwd)
work=${1:-block_run}
fcs3d=${FCS3D:-$examples/../../bin/fcs3d}
[ -x "$fcs3d" ] || fcs3d=fcs3d
command -v gmsh >/dev/null 2>&1 || { echo "gmsh is not installed (Debian package gmsh)" >&2; exit 1; }
mkdir -p "$work"
cp "$examples/block.inp" "$examples/block.geo" "$work/"
cd "$work"
gmsh -3 -format msh41 block.geo -o block.msh > gmsh.log 2>&1 || { cat gmsh.log >&2; exit 1; }
"$fcs3d" block.inp
echo "results in $(pwd): block.h5, block.xdmf (open in ParaView), block.dat, block.log"
