#!/bin/sh
# Damaged checkpoints are refused: a bit flipped in the data of each dataset of job.rst.h5 in
# turn, a changed checksum or hash attribute, the file truncated (0, 2048 bytes, half, all but
# one byte): exit 2 and a message that names the damage (the dataset and "checksum mismatch",
# "overall checksum", "truncated or damaged") and offers the older generation job.rst.1.h5;
# the restart from the offered checkpoint completes with the complete run's outputs bit for
# bit; with no older generation there is no offer. Details in restart/corrupt.py. By hand:
#   FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/restart_corrupt.sh'
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy or h5py not available to $py"; exit 77; }
mkdir -p restart_corrupt || exit 1
cd "$tests/integration/restart" && "$py" corrupt.py "$OLDPWD/restart_corrupt"
