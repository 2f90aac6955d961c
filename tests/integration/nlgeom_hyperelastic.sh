#!/bin/sh
# *HYPERELASTIC (MOONEY-RIVLIN, OGDEN N=2 with ccx's default D_i) and *HYPERFOAM under NLGEOM
# (doc/theory.md 2.11): a 2 x 2 x 2 C3D8 block stretched to 1.5 with free lateral faces; the
# reaction force and the lateral contraction against the closed form of each energy within
# 1e-4; the Ogden job restarted from a checkpoint ends bit for bit as the one-go run. Decks
# and checks: nlgeom/hyperelastic.py (its doc string gives the closed forms).
# By hand: FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/nlgeom_hyperelastic.sh'
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
mkdir -p nlgeom_hyperelastic && cd nlgeom_hyperelastic || exit 1
"$py" "$tests/integration/nlgeom/hyperelastic.py"
