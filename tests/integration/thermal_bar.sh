#!/bin/sh
# Thermal strain (issue 17, item 3): a bar of 8 x 2 x 2 C3D8 heated uniformly, free (strain
# alpha dT, no stress) and clamped (sigma_xx = -E alpha dT, reaction -E alpha dT A); with
# *EXPANSION and *ELASTIC tables over temperature over two steps (the second through an
# amplitude), sigma_xx = -E(T) (alpha(T) (T - Z) - alpha(T0) (T0 - Z)) as CalculiX; NT in
# *NODE PRINT; a restart in the middle of step 2 gives the one-go outputs bit for bit.
# Homogeneous fields: round-off tolerance (1e-9 of E alpha dT). Deck generator, checks and
# the reasoning: tests/tools/thermal.py.
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy or h5py not available to $py"; exit 77; }
"$py" "$here/tests/tools/thermal.py" "$PWD"
