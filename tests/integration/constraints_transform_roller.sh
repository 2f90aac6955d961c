#!/bin/sh
# *TRANSFORM (issue 17): a block inclined at 30 degrees on a roller given in local axes
# (*BOUNDARY local dof 1 on the transformed face), under a pressure on the opposite face:
# the uniaxial stress -p n n^T at every integration point (1e-6 p, print), the roller nodes'
# U and RF printed in local axes (rows marked L, as ccx 2.20 prints them; its numbers are the
# same to the printed digits), their normal displacement 0, their lateral expansion and the
# local reaction p A (constraints/transform_roller.py).
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
script=$tests/integration/constraints/transform_roller.py
"$py" "$script" deck roller.inp || exit 1
"$FCS3D" -q roller.inp || { echo "fcs3d failed on roller.inp"; exit 1; }
"$py" "$script" check roller
