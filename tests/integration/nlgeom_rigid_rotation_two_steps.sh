#!/bin/sh
# The rigid-rotation test of the issue in its two-step form: step 1 pre-stretches the block (and
# holds), step 2 rotates it by 90 degrees about z through per-node tabular *AMPLITUDEs (points
# every 0.1 degree) and holds; stresses from *EL PRINT at the end of each step and at 30, 45,
# 60, 90 degrees; s_xx and s_yy swap and the Mises stress is unchanged within 0.5 %, the
# rotation itself exact to 1e-5. Same checks as nlgeom_rigid_rotation.sh (one-step form).
# (Pending until 458ddac: fcs3d fbf1617 never ran step 2, state%step_time not being reset.)
# By hand: FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/nlgeom_rigid_rotation_two_steps.sh'
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
script=$tests/integration/nlgeom/rigid_rotation.py
mkdir -p nlgeom_rigid_rotation_two_steps && cd nlgeom_rigid_rotation_two_steps || exit 1
"$py" "$script" deck rotation.inp --steps 2 --spacing 0.1 || exit 1
"$FCS3D" -q rotation.inp || { echo "fcs3d failed"; exit 1; }
"$py" "$script" check rotation --steps 2 --spacing 0.1 --tolerance 0.005
