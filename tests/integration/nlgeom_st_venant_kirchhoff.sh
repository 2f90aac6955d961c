#!/bin/sh
# *ELASTIC under NLGEOM is St Venant-Kirchhoff (CalculiX's law; doc/theory.md 2.10): closed forms
# of a uniaxial stretch to 1.3 (lateral faces free), simple shear to gamma = 0.5, a stretch then
# a quarter turn (the stress turns, the Green-Lagrange strain in reference axes does not), and
# a rotated orthotropic block (*ELASTIC, TYPE=ENGINEERING CONSTANTS with an *ORIENTATION: axes in
# the reference configuration): Cauchy stress, E (Green-Lagrange) and ENER (1/2 S:E) at every
# point, and the lateral contractions, within 1e-4. Decks and checks:
# nlgeom/st_venant_kirchhoff.py (its doc string gives the closed forms).
# By hand: FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/nlgeom_st_venant_kirchhoff.sh'
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
mkdir -p nlgeom_st_venant_kirchhoff && cd nlgeom_st_venant_kirchhoff || exit 1
"$py" "$tests/integration/nlgeom/st_venant_kirchhoff.py"
