#!/bin/sh
# Uniaxial compression of a hypoelastic unit cube (2x2x2 hexahedra, symmetry conditions) to
# 20 % engineering strain (NLGEOM): s_zz = E ln(0.8) within 1 %, lateral stresses ~ 0, lateral
# stretch (l/l0)^-nu, top reaction = s_zz x current area (from the printed displacements), at
# 5, 10, 15, 20 %. Deck and checks: nlgeom/uniaxial_compression.py.
# By hand: FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/nlgeom_uniaxial_compression.sh'
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
script=$tests/integration/nlgeom/uniaxial_compression.py
mkdir -p nlgeom_uniaxial_compression && cd nlgeom_uniaxial_compression || exit 1
"$py" "$script" deck compression.inp || exit 1
"$FCS3D" -q compression.inp || { echo "fcs3d failed"; exit 1; }
"$py" "$script" check compression --tolerance 0.01
