#!/bin/sh
# A two-step deck (the classic
# two-material bar; step 2 replaces the load with *CLOAD, OP=NEW) through CalculiX and fcs3d,
# job.dat compared as in tests/integration/calculix_compare.sh (once failed: fcs3d skipped
# every step after the first). Run from a scratch directory:
#   FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/two_steps.sh'
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
command -v ccx >/dev/null 2>&1 || { echo "ccx not installed"; exit 77; }
cp "$here/tests/data/classic/two_steps.inp" "$here/tests/decks/classic/include_sets_mesh.inc" . || exit 1
OMP_NUM_THREADS=1 ccx two_steps > two_steps.ccx.log 2>&1 || { tail -5 two_steps.ccx.log; exit 1; }
mkdir -p fcs3d
"$FCS3D" -q -o fcs3d two_steps.inp || exit 1
grep -q 'end of step 2 .* at time 2 ' fcs3d/two_steps.log || {
  echo "fcs3d did not reach time 2 at the end of step 2:"; grep 'step' fcs3d/two_steps.log; exit 1; }
"${PYTHON:-/usr/bin/python3}" "$here/tests/tools/compare_dat.py" two_steps.dat fcs3d/two_steps.dat
