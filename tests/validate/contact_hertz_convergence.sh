#!/bin/sh
# Hertz line contact and Cattaneo-Mindlin partial slip on three meshes (contact issue, tests 3
# and 4; `make validate`): the cylinder of tests/integration/contact_hertz.sh with
# hc = 0.2, 0.1, 0.05 (5, 10, 20 elements per contact half-width a = 1). Requires on the
# finest mesh the peak pressure, the fitted p0 and the fitted half-width within 5 % of Hertz
# and every stick-zone half-width (Q/(mu P) from 0.19 to 0.88) within 10 % of
# a sqrt(1 - Q/(mu P)). Rewrites doc/validation/contact_hertz.md (the convergence table) and
# doc/validation/contact_hertz.png. contact/studies.py hertz. About 5 minutes.
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py, matplotlib' 2>/dev/null || { echo "numpy/h5py/matplotlib missing"; exit 77; }
command -v gmsh >/dev/null 2>&1 || { echo "gmsh (Debian package gmsh) not installed"; exit 77; }
FCS3D_TEST_DATA=${FCS3D_TEST_DATA:-$here/tests/data} "$py" \
  "$here/tests/integration/contact/studies.py" hertz --work "$PWD/hertz" \
  --meshes 0.2,0.1,0.05 --markdown "$here/doc/validation/contact_hertz.md" \
  --png "$here/doc/validation/contact_hertz.png"
