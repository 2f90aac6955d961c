#!/bin/sh
# Write errors of every output file (issue 15, item 2): each of job.dat, job.log, the
# temporary files of the echo, XDMF, CSVs and checkpoint, and the lock file in turn links to
# /dev/full; the run exits with status 1, says the disk is full, names the file, and records it
# in job.log. Details: reliability/write_errors.py. By hand:
#   FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/reliability_write_errors.sh'
set -u
here=$(cd "$(dirname "$0")" && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy or h5py not available to $py"; exit 77; }
[ -c /dev/full ] || { echo "no /dev/full on this system"; exit 77; }
mkdir -p write_errors || exit 1
cd "$here/reliability" && "$py" write_errors.py "$OLDPWD/write_errors"
