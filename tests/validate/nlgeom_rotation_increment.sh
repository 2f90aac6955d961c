#!/bin/sh
# Rigid rotation of a pre-stressed block (tests/integration/nlgeom/rigid_rotation.py, one step)
# with rotation increments of 0.05, 0.1, 0.2, 0.5 degrees, and 0.25-degree increments between
# amplitude points 1 degree apart (ending on the chord): the stress offset during the rotation
# (the one-increment lag of the static-explicit predictor on the free dofs) grows as dtheta^2
# and matches its estimate; after a hold the rotation is exact to 1e-5 in every run. Prints
# the table of doc/validation/nlgeom.md. nlgeom/rotation_increment_study.py.
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
"$py" "$tests/integration/nlgeom/rotation_increment_study.py" --markdown rotation_increment.md
