#!/bin/sh
# Restart after SIGKILL, bit for bit: the stick-slip problem (block pushed on a block,
# rate-weakening friction) run in one go, then killed with kill -9 at a random moment after a
# checkpoint exists, restarted from job.rst.h5, killed again, restarted to the end: every
# dataset and attribute of job.h5, job.dat and the history and event CSVs byte for byte, and
# the frames of job.xdmf, equal the one-go run's. Also a restart at a step boundary (the deck
# with step 1 only, then the whole deck from its end-of-step checkpoint). Details in
# restart/sigkill.py; the kill moments are seeded from $FCS3D_TEST_SEED (else the clock) and
# the seed is printed. By hand:
#   FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/restart_sigkill.sh'
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy or h5py not available to $py"; exit 77; }
mkdir -p restart_sigkill || exit 1
cd "$tests/integration/restart" && "$py" sigkill.py "$OLDPWD/restart_sigkill"
