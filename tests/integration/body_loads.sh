#!/bin/sh
# Body loads and the lithostatic pre-stress (issue 17): a column under *DLOAD GRAV (stress
# linear in depth, base reaction = weight, to round-off), the same column starting from
# *INITIAL CONDITIONS, TYPE=STRESS, GEOSTATIC with gravity held (stays put), and a rotating
# annular disk under CENTRIF against the plane-stress solution on three meshes (second-order
# convergence: error ratio >= 3, finest below 0.5 %). Decks, closed forms and tolerances:
# tests/tools/body_loads.py.
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
"$py" "$here/tests/tools/body_loads.py" "$PWD"
