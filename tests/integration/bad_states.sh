#!/bin/sh
# Bad states during a run (NaN, singular matrix with each solver, excessive penetration, an
# increment below the minimum, an inverted element): each stops with exit status 1 and a
# message naming the step, increment, time, entity and likely cause, and the last good
# increment is complete and readable in job.h5, with a checkpoint. Details and decks:
# robustness/bad_states.py. By hand:
#   FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/bad_states.sh'
set -u
here=$(cd "$(dirname "$0")" && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy or h5py not available to $py"; exit 77; }
mkdir -p bad_states || exit 1
"$py" "$here/robustness/bad_states.py" "$PWD/bad_states"
