#!/bin/sh
# Contact patch test over mesh ratios, refinements and penalties (contact issue, test 2;
# `make validate`): matching meshes exact to 1e-8, non-matching within the bounds of
# tests/integration/contact_patch_test.sh; rewrites doc/validation/contact_patch.md.
# contact/studies.py patch. About 30 s.
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy/h5py not available to $py"; exit 77; }
"$py" "$here/tests/integration/contact/studies.py" patch --work "$PWD/patch" \
  --markdown "$here/doc/validation/contact_patch.md"
