#!/bin/sh
# The rate-and-state friction state survives a restart: a block sliding with RATE STATE
# (ageing) friction is restarted from a checkpoint written in the middle of a velocity-step
# transient (theta between its two steady states), once in an empty directory and once over
# the outputs of the uninterrupted run; the final checkpoint (contact state incl. theta), the
# results frames and the history equal the uninterrupted run's bit for bit. Details in
# friction/restart_state.py.
# By hand: FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/friction_restart_state.sh'
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy or h5py not available to $py"; exit 77; }
"$py" "$tests/integration/friction/restart_state.py" "$PWD/friction_restart_state"
