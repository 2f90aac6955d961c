#!/bin/sh
# Read the XDMF files written by the unit test test_fcs_results with VTK's vtkXdmfReader (as
# ParaView does) and compare with the HDF5 data: post/check_xdmf_vtk.py. The unit test is run
# here, from a copy in this test's scratch directory (it writes next to its executable), so
# that an earlier run's files are never the ones checked. Exit 77 (skip) when VTK's Xdmf2
# reader is not installed (Debian package python3-paraview) or UNIT_DIR is not set.
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
[ -n "${UNIT_DIR:-}" ] || { echo "UNIT_DIR not set"; exit 77; }
[ -x "$UNIT_DIR/test_fcs_results" ] || { echo "missing $UNIT_DIR/test_fcs_results"; exit 1; }
work=$(pwd)/results_xdmf_vtk
rm -rf "$work" && mkdir -p "$work" || exit 1
cp "$UNIT_DIR/test_fcs_results" "$work/" || exit 1
(cd "$work" && ./test_fcs_results > test_fcs_results.log 2>&1) || {
  tail -20 "$work/test_fcs_results.log"; echo "test_fcs_results failed"; exit 1; }
out="$work/test_fcs_results_out"
[ -f "$out/three_frames.xdmf" ] || { echo "missing $out/three_frames.xdmf"; exit 1; }
"${PYTHON:-/usr/bin/python3}" "$here/post/check_xdmf_vtk.py" "$out/three_frames.xdmf" \
  "$out/volume_only.xdmf" "$out/append.xdmf"
