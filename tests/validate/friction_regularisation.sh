#!/bin/sh
# The paper's law (RATE DEPENDENT, MU0=0.60, A=0.010, B=0.025, V0=0.001 mm/s) on a spring-slider
# under a constant load rate (1e-3 mm/s): stick-slip events for REGULARISATION=FLOOR and
# LINEAR, VC = 1e-6, 1e-5, 1e-4 mm/s, maximum increments 1 and 0.1 s. Checks the closed forms
# (static level, first event time, recurrence = stress drop / (k V_lp)) and that the stress drop
# is the one-increment root of the return mapping; prints the table of
# doc/validation/friction.md. friction/regularisation.py (about 20 s).
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
"$py" "$tests/integration/friction/regularisation.py" "$PWD/runs" --markdown regularisation.md
