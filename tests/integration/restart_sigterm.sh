#!/bin/sh
# SIGTERM and SIGINT during a run of the stick-slip problem (at a random moment once a
# checkpoint exists): exit status 3, the message on stderr and in job.log names the
# checkpoint job.rst.h5 and the increment it holds, and the restart from it completes with
# the one-go run's outputs bit for bit (job.h5, job.dat, CSVs, XDMF frames). Details in
# restart/sigterm.py; the moments are seeded from $FCS3D_TEST_SEED (else the clock). By hand:
#   FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/restart_sigterm.sh'
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy or h5py not available to $py"; exit 77; }
mkdir -p restart_sigterm || exit 1
cd "$tests/integration/restart" && "$py" sigterm.py "$OLDPWD/restart_sigterm"
