#!/bin/sh
# Restarts with a changed deck (stick-slip problem): a changed material constant or node
# (model section) is refused with exit 2 and "the model definition ... differs"; a changed
# step already begun is refused ("step N of the deck differs"), as is a deck with fewer steps
# than the checkpoint ran; an added step 3 runs, gives the 3-step one-go run's outputs bit for
# bit and leaves what steps 1-2 wrote unchanged; step 2 may be changed under a checkpoint
# taken before it began. Details in restart/deck_changes.py. By hand:
#   FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/restart_deck_changes.sh'
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy or h5py not available to $py"; exit 77; }
mkdir -p restart_deck_changes || exit 1
cd "$tests/integration/restart" && "$py" deck_changes.py "$OLDPWD/restart_deck_changes"
