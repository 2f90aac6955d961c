#!/bin/sh
# A restart of a deck with *EQUATION (issue 17) continues bit for bit: the tied blocks of
# constraints_equation_patch.sh (upper 4x4 on lower 2x2) in two steps of four increments;
# the deck with step 1 only, then the whole deck restarted from its end-of-step checkpoint,
# give the .dat of the run in one go byte for byte, and the same displacement and stress
# datasets in job.h5. The constraints are model data: the restart rebuilds them from the
# deck (whose model definition the checkpoint's hash pins down), nothing of them is saved.
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy or h5py not available to $py"; exit 77; }
script=$tests/integration/constraints/equation_patch_test.py
mkdir -p whole split || exit 1
"$py" "$script" deck whole/job.inp --upper 4 --lower 2 --steps 2 || exit 1
"$py" "$script" deck split/job.inp --upper 4 --lower 2 --steps 1 || exit 1
# Step 1 of the two-step deck must be the one-step deck's step (same loads, same increments).
sed -i 's/^1\., 1\.$/0.25, 1., , 0.25/' split/job.inp
(cd whole && "$FCS3D" -q job.inp) || { echo "the run in one go failed"; exit 1; }
(cd split && "$FCS3D" -q job.inp) || { echo "step 1 alone failed"; exit 1; }
"$py" "$script" deck split/job.inp --upper 4 --lower 2 --steps 2 || exit 1
(cd split && "$FCS3D" -q job.inp --restart job.rst.h5) || { echo "the restart failed"; exit 1; }
fail=0
if cmp -s whole/job.dat split/job.dat; then
  echo "ok   job.dat of the restarted run = the run in one go, byte for byte"
else
  echo "FAIL job.dat differs:"; diff whole/job.dat split/job.dat | head -10; fail=1
fi
"$py" - <<'PY' || fail=1
import sys
import h5py
import numpy as np

def arrays(path):
    out = {}
    def visit(name, item):
        if isinstance(item, h5py.Dataset) and item.dtype.kind == 'f' and \
                ('displacement' in name or 'stress' in name):
            out[name] = item[()]
    with h5py.File(path, 'r') as f:
        f.visititems(visit)
    return out

a, b = arrays('whole/job.h5'), arrays('split/job.h5')
ok = len(a) > 0 and a.keys() == b.keys() and all(np.array_equal(a[k], b[k]) for k in a)
print(('ok   ' if ok else 'FAIL ') + '%d displacement and stress datasets of job.h5 bit-identical' % len(a))
sys.exit(0 if ok else 1)
PY
exit $fail
