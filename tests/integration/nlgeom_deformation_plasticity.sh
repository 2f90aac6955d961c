#!/bin/sh
# *DEFORMATION PLASTICITY (Ramberg-Osgood, doc/theory.md 2.12) under NLGEOM: a 2 x 2 x 2 C3D8
# block with CalculiX's beampl constants stretched to 1.03 (about 1.2 sigma_0) and back to
# 1.01, lateral faces free; the reaction force and the lateral contraction against the closed
# form within 1e-6 at both step ends, the equilibrium iterations held to 1e-8 (the unloading follows the loading curve: a total law).
# Deck and checks: nlgeom/deformation_plasticity.py (its doc string gives the closed form).
# By hand: FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/nlgeom_deformation_plasticity.sh'
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
mkdir -p nlgeom_deformation_plasticity && cd nlgeom_deformation_plasticity || exit 1
"$py" "$tests/integration/nlgeom/deformation_plasticity.py"
