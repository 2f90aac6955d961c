#!/bin/sh
# Check the XDMF/HDF5 pairs written by the unit test test_fcs_results with post/check_xdmf.py
# (structure, references, shapes and sizes). The unit test is run here, from a copy in this
# test's scratch directory (it writes next to its executable), so that only files written by
# this run are checked, never those of an earlier run. Exit 77 (skip) without UNIT_DIR.
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
[ -n "${UNIT_DIR:-}" ] || { echo "UNIT_DIR not set"; exit 77; }
[ -x "$UNIT_DIR/test_fcs_results" ] || { echo "missing $UNIT_DIR/test_fcs_results"; exit 1; }
work=$(pwd)/results_xdmf
rm -rf "$work" && mkdir -p "$work" || exit 1
cp "$UNIT_DIR/test_fcs_results" "$work/" || exit 1
(cd "$work" && ./test_fcs_results > test_fcs_results.log 2>&1) || {
  tail -20 "$work/test_fcs_results.log"; echo "test_fcs_results failed"; exit 1; }
out="$work/test_fcs_results_out"
for pair in three_frames:3 volume_only:2 append:4; do
  name=${pair%%:*}; frames=${pair#*:}
  [ -f "$out/$name.xdmf" ] || { echo "missing $out/$name.xdmf (test_fcs_results wrote no $name)"; exit 1; }
  "${PYTHON:-/usr/bin/python3}" "$here/post/check_xdmf.py" --frames "$frames" "$out/$name.xdmf" || exit 1
done
