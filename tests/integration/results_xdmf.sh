#!/bin/sh
# Check the XDMF/HDF5 pairs written by the unit test test_fcs_results with post/check_xdmf.py
# (structure, references, shapes and sizes). Needs the unit tests to have run first
# (tests/run_tests.sh runs them before the integration tests). Exit 77 (skip) without UNIT_DIR.
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
[ -n "${UNIT_DIR:-}" ] || { echo "UNIT_DIR not set"; exit 77; }
out="$UNIT_DIR/test_fcs_results_out"
for pair in three_frames:3 volume_only:2 append:4; do
  name=${pair%%:*}; frames=${pair#*:}
  [ -f "$out/$name.xdmf" ] || { echo "missing $out/$name.xdmf (did test_fcs_results run?)"; exit 1; }
  "${PYTHON:-/usr/bin/python3}" "$here/post/check_xdmf.py" --frames "$frames" "$out/$name.xdmf" || exit 1
done
