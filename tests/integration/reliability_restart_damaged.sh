#!/bin/sh
# Restart next to damaged outputs (issue 15, item 9): job.dat emptied, job.h5 deleted, job.h5
# short of a frame. The restart continues with a warning naming the file and what is lost;
# no NUL padding; the new outputs hold exactly what the uninterrupted run wrote after the
# checkpoint. Details: reliability/restart_damaged.py. By hand:
#   FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/reliability_restart_damaged.sh'
set -u
here=$(cd "$(dirname "$0")" && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy or h5py not available to $py"; exit 77; }
mkdir -p restart_damaged || exit 1
cd "$here/reliability" && "$py" restart_damaged.py "$OLDPWD/restart_damaged"
