#!/bin/sh
# The test runner's own checks (issue 15, item 13):
#  - the location a bad deck's message must hold has a line number: "deck.inp:12: ..." is
#    one, "deck.inp: ..." (a file name alone) is not (tests/tools/has_location.sh, which
#    tests/run_tests.sh uses);
#  - results_xdmf.sh and results_xdmf_vtk.sh check files written by their own run of the unit
#    test: given a unit-test directory whose test_fcs_results fails and whose output directory
#    holds valid files of an earlier run, they must fail.
set -u
here=$(cd "$(dirname "$0")/.." && pwd)
fail=0
expect() { # description expected-status text
  printf '%s' "$3" | sh "$here/tools/has_location.sh"; got=$?
  if [ "$got" -ne "$2" ]; then echo "FAIL: $1: has_location.sh gave $got, expected $2"; fail=1
  else echo "ok: $1"; fi
}
expect 'file:line:' 0 'fcs3d: deck.inp:12: *STATIC: the period must be positive'
expect 'included file:line:' 0 'fcs3d: sub/part.inc:3: unknown keyword *NODEE'
expect 'file name without a line' 1 'fcs3d: deck.inp: the deck defines no step'
expect 'mesh file name without a line' 1 'fcs3d: deck.inp: *MESH: mesh.msh: no hexahedra'
expect 'no location at all' 1 'fcs3d: 1 error(s) in the input; nothing was run'

# A unit-test directory with stale but valid outputs and a unit test that fails.
stale=$(pwd)/stale_unit_dir
rm -rf "$stale" && mkdir -p "$stale" || exit 1
py=${PYTHON:-/usr/bin/python3}
if "$py" -c 'import h5py' 2>/dev/null && [ -n "${UNIT_DIR:-}" ] && [ -x "$UNIT_DIR/test_fcs_results" ]; then
  # The real unit test, run there, writes valid files into $stale/test_fcs_results_out.
  (cd "$stale" && cp "$UNIT_DIR/test_fcs_results" . && ./test_fcs_results > /dev/null 2>&1)
  [ -f "$stale/test_fcs_results_out/three_frames.xdmf" ] || {
    echo "FAIL: could not prepare the stale outputs"; exit 1; }
  printf '#!/bin/sh\necho "test_fcs_results: 0 passed, 1 failed"\nexit 1\n' > "$stale/test_fcs_results"
  chmod +x "$stale/test_fcs_results"
  for t in results_xdmf results_xdmf_vtk; do
    if (mkdir -p "$t.run" && cd "$t.run" && UNIT_DIR="$stale" sh "$here/integration/$t.sh" > out.txt 2>&1); then
      echo "FAIL: $t.sh passed on an earlier run's files although the unit test failed"; fail=1
    else
      echo "ok: $t.sh fails when the unit test fails, whatever earlier files are there"
    fi
  done
else
  echo "h5py or the unit test test_fcs_results not available: the results_xdmf checks are not run"
fi
exit $fail
