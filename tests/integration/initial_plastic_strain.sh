#!/bin/sh
# Initial plastic strain (issue 18): a cube of 3 x 3 x 3 C3D8 of a von Mises material starting
# from a deviatoric plastic strain given per integration point (*INITIAL CONDITIONS,
# TYPE=PLASTIC STRAIN, as CalculiX), held and then pulled into the plastic range: stresses,
# PEEQ and displacements against the closed forms (the initial plastic strain is a strain the
# material does not resist and does not harden it). Deck and tolerances:
# tests/tools/initial_plastic_strain.py. The elastic case (an eigenstrain varying from point
# to point) is compared with ccx in calculix_compare.sh (tests/decks/classic/initial_plastic_strain.inp).
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
"$py" "$here/tests/tools/initial_plastic_strain.py" "$PWD"
