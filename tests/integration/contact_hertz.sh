#!/bin/sh
# Hertz line contact and Cattaneo-Mindlin partial slip, coarse mesh (contact issue, tests 3
# and 4): a cylinder on a block in plane strain, meshed by gmsh from
# tests/data/contact/hertz_cylinder.geo with 10 elements across the contact width (hc = 0.2,
# a = 1). Hertz (frictionless): peak nodal pressure and the fitted p0 and half-width a within
# 5 % of theory (measured +1.3 %, +0.9 %, -2.1 %). Cattaneo-Mindlin (mu = 0.3, tangential
# displacement of the cylinder's top, Q/(mu P) up to 0.88): the stick-zone half-width from the
# 'status' field within 10 % of a sqrt(1 - Q/(mu P)) plus half a node spacing (hc/2 = 0.1,
# the resolution of a node-based status: 11 % to 29 % of c here); measured errors -13 % to
# +4.7 %, at most 0.09 absolute (less than half an element). The fine meshes
# (5 % and 10 % strictly, convergence table) run in `make validate`
# (tests/validate/contact_hertz_convergence.sh). contact/hertz.py. About 10 s.
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy/h5py not available to $py"; exit 77; }
command -v gmsh >/dev/null 2>&1 || { echo "gmsh (Debian package gmsh) not installed"; exit 77; }
script=$tests/integration/contact/hertz.py
mkdir -p contact_hertz && cd contact_hertz || exit 1
fail=0
"$py" "$script" mesh hertz.msh --hc 0.2 || exit 1
"$py" "$script" deck hertz.inp --mesh hertz.msh --hc 0.2 || exit 1
"$FCS3D" -q hertz.inp || { echo "fcs3d failed on hertz.inp"; exit 1; }
"$py" "$script" check hertz --hc 0.2 --tolerance 0.05 || fail=1
"$py" "$script" deck cattaneo.inp --mesh hertz.msh --hc 0.2 --cattaneo || exit 1
"$FCS3D" -q cattaneo.inp || { echo "fcs3d failed on cattaneo.inp"; exit 1; }
"$py" "$script" check cattaneo --hc 0.2 --cattaneo --tolerance 0.05 --stick-tolerance 0.10 \
  --stick-resolution || fail=1
exit $fail
