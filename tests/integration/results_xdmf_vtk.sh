#!/bin/sh
# Read the XDMF files written by the unit test test_fcs_results with VTK's vtkXdmfReader (as
# ParaView does) and compare with the HDF5 data: post/check_xdmf_vtk.py. Exit 77 (skip) when
# VTK's Xdmf2 reader is not installed (Debian package python3-paraview) or UNIT_DIR is not set.
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
[ -n "${UNIT_DIR:-}" ] || { echo "UNIT_DIR not set"; exit 77; }
out="$UNIT_DIR/test_fcs_results_out"
[ -f "$out/three_frames.xdmf" ] || { echo "missing $out/three_frames.xdmf"; exit 1; }
"${PYTHON:-/usr/bin/python3}" "$here/post/check_xdmf_vtk.py" "$out/three_frames.xdmf" \
  "$out/volume_only.xdmf" "$out/append.xdmf"
