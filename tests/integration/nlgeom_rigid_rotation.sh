#!/bin/sh
# Rigid rotation of a pre-stressed hexahedron by 90 degrees about z in 900 increments (every
# node's x, y prescribed by its own tabular *AMPLITUDE, points every 0.1 degree), in ONE step
# (pre-stretch, hold, rotate, hold): the stress rotates with the body (s_xx and s_yy swap) and
# the Mises stress is unchanged, within the issue's 0.5 %; the rotation itself is exact to 1e-5.
# Deck and checks: nlgeom/rigid_rotation.py (its doc string explains the chord and the lag).
# The two-step form of the issue is nlgeom_rigid_rotation_two_steps.sh.
# By hand: FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/nlgeom_rigid_rotation.sh'
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
script=$tests/integration/nlgeom/rigid_rotation.py
mkdir -p nlgeom_rigid_rotation && cd nlgeom_rigid_rotation || exit 1
"$py" "$script" deck rotation.inp --steps 1 --spacing 0.1 || exit 1
"$FCS3D" -q rotation.inp || { echo "fcs3d failed"; exit 1; }
"$py" "$script" check rotation --steps 1 --spacing 0.1 --tolerance 0.005
