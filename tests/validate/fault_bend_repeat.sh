#!/bin/sh
# Reproducibility of the fault-bend model: the default deck (MUMPS), stopped at 236 s, just
# after the onset of the first large slip event of the reference run (issue 19: 235.15 s; the
# event's thousands of short increments amplify any round-off difference), run twice at the
# same time must give identical increment logs and bit-identical results files' datasets. It
# failed before fcs3d gave MUMPS its own METIS ordering (MUMPS chose SCOTCH, whose ordering
# changed from run to run: the two runs parted at increment 54 and ended with 115 and 142
# increments). A few minutes of two cores.
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
py=${PYTHON:-/usr/bin/python3}
command -v gmsh >/dev/null 2>&1 || { echo "gmsh not installed"; exit 77; }
mkdir -p mesh a b || exit 1
cp "$root/input/fault_bend/fault_bend.geo" mesh/ || exit 1
(cd mesh && gmsh -3 -format msh41 fault_bend.geo -o fault_bend.msh > gmsh.log 2>&1) || {
  echo "gmsh failed:"; tail -5 mesh/gmsh.log; exit 1; }
for d in a b; do
  cp mesh/fault_bend.msh "$d/" || exit 1
  sed 's/^1\., 390\., \(.*\)$/1., 226., \1/' "$root/input/fault_bend/fault_bend.inp" > "$d/fault_bend.inp"
  grep -q '^1\., 226\., ' "$d/fault_bend.inp" || {
    echo "the stage-2 *STATIC line of fault_bend.inp does not start with '1., 390.,' any more"; exit 1; }
done
(cd a && "$FCS3D" -q fault_bend.inp > run.out 2>&1) & pa=$!
(cd b && "$FCS3D" -q fault_bend.inp > run.out 2>&1) & pb=$!
wait $pa || { echo "run a failed:"; tail -5 a/run.out; exit 1; }
wait $pb || { echo "run b failed:"; tail -5 b/run.out; exit 1; }
grep '^inc ' a/fault_bend.log > a/increments.txt
grep '^inc ' b/fault_bend.log > b/increments.txt
echo "run a: $(wc -l < a/increments.txt) increments, run b: $(wc -l < b/increments.txt)"
if ! cmp -s a/increments.txt b/increments.txt; then
  echo "FAIL the increment logs differ, first at:"
  diff a/increments.txt b/increments.txt | head -4
  exit 1
fi
"$py" - <<'PY'
import sys
import h5py
import numpy as np


def datasets(path):
    f = h5py.File(path, 'r')
    out = {}
    f.visit(lambda n: out.__setitem__(n, f[n][()]) if isinstance(f[n], h5py.Dataset) else None)
    return out


a, b = datasets('a/fault_bend.h5'), datasets('b/fault_bend.h5')
if set(a) != set(b):
    print('FAIL the results files hold different datasets')
    sys.exit(1)
differ = [n for n in a if not np.array_equal(a[n], b[n])]
print('%d datasets, %d differ%s' % (len(a), len(differ), (': ' + ', '.join(differ[:5])) if differ else ''))
sys.exit(1 if differ else 0)
PY
