#!/bin/sh
# Initial stress (issue 17): a cube of 3 x 3 x 3 C3D8 starting from a uniform stress given
# per integration point (*INITIAL CONDITIONS, TYPE=STRESS, as CalculiX), balanced by face
# pressures held through the step, stays put: u = 0 and the stress unchanged to round-off.
# Deck and tolerances: tests/tools/initial_state.py.
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
"$py" "$here/tests/tools/initial_state.py" "$PWD"
