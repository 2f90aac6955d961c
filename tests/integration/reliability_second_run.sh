#!/bin/sh
# Two runs of one job in one directory (issue 15, item 3): while a run holds job.lock, a second
# run or --check of the same job is refused with exit status 2 naming the running process, and
# the first run's outputs stay bit for bit those of a run alone; a lock left by a killed run
# or written by hand for a process that is gone is taken over with a note in job.log.
# Details: reliability/second_run.py. By hand:
#   FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/reliability_second_run.sh'
set -u
here=$(cd "$(dirname "$0")" && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy or h5py not available to $py"; exit 77; }
mkdir -p second_run || exit 1
cd "$here/reliability" && "$py" second_run.py "$OLDPWD/second_run"
