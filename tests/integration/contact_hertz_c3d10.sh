#!/bin/sh
# Hertz line contact with C3D10 (issue 16): the cylinder on a block of contact_hertz.sh
# (hc = 0.2, 5 elements per contact half-width a = 1), every hexahedron of gmsh's mesh split
# into six 10-node tetrahedra (smallest-vertex rule, conforming), the mid-side nodes of the
# cylinder's arc on the circle; 6-node triangular slave and master faces, frictionless,
# default increments. Peak nodal pressure, fitted p0 and fitted half-width within 5 % of
# Hertz (measured -0.7 %, -0.4 %, -0.8 %) and the contact edge bracketed. The three-mesh
# study runs in `make validate` (tests/validate/contact_hertz_c3d10.sh).
# contact/hertz_tet.py. About 25 s of CPU.
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy/h5py not available to $py"; exit 77; }
command -v gmsh >/dev/null 2>&1 || { echo "gmsh (Debian package gmsh) not installed"; exit 77; }
contact=$tests/integration/contact
mkdir -p contact_hertz_c3d10 && cd contact_hertz_c3d10 || exit 1
"$py" "$contact/hertz.py" mesh hertz.msh --hc 0.2 || exit 1
"$py" "$contact/hertz_tet.py" deck hertz_c3d10.inp --mesh hertz.msh --hc 0.2 || exit 1
"$FCS3D" -q hertz_c3d10.inp || { echo "fcs3d failed on hertz_c3d10.inp"; exit 1; }
"$py" "$contact/hertz_tet.py" check hertz_c3d10 --hc 0.2 --tolerance 0.05
