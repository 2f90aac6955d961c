#!/bin/sh
# Anisotropic elasticity (issue 17): an orthotropic cube in turned material axes
# (*ORIENTATION, also with a rotation line) under uniaxial stress, its material given as
# ENGINEERING CONSTANTS, ORTHO and (in global axes) ANISO: the strain is the compliance's,
# turned (closed form), and *EL PRINT prints S in global (GLOBAL=YES) or local (default) axes.
# Deck and tolerances: tests/tools/anisotropic_block.py.
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
"$py" "$here/tests/tools/anisotropic_block.py" "$PWD"
