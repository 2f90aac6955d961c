#!/bin/sh
# Convergence of the R-minimum stepper as its limits are tightened: simple shear to gamma = 1
# with *RMIN, MAX STRAIN INCREMENT = 1e-2, 3e-3, 1e-3 and MAX ROTATION INCREMENT = 2, 0.5,
# 0.1 degrees. Asserts that the error decreases monotonically, that the observed order is
# 1 +- 0.2, and that every increment line of every job.log names its limiting criterion.
# The table of doc/validation/nlgeom.md is this script's output. nlgeom/convergence.py.
# By hand: FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/nlgeom_convergence.sh'
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
mkdir -p nlgeom_convergence && cd nlgeom_convergence || exit 1
"$py" "$tests/integration/nlgeom/convergence.py" --markdown convergence.md
