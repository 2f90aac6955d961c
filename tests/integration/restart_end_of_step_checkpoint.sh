#!/bin/sh
# A restart from the periodic checkpoint of the LAST increment of a step (FREQUENCY=1: it is
# written after that increment, before the end-of-step frame and the end-of-step checkpoint;
# the newest checkpoint when a kill falls while the end-of-step one is written) gives the
# one-go outputs: job.h5 bit for bit, job.dat, CSVs, XDMF frames; for step 1 (the deck with
# step 1 only, then the whole deck) and for the last step. Failed up to 418dfd4 (the restart
# kept the frames up to the checkpoint's increment, the end-of-step frame included, and wrote
# it again); fixed in 70d89cb (checkpoints record the number of frames). Details in
# restart/end_of_step.py. By hand:
#   FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/restart_end_of_step_checkpoint.sh'
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy or h5py not available to $py"; exit 77; }
mkdir -p restart_end_of_step_checkpoint || exit 1
cd "$tests/integration/restart" && "$py" end_of_step.py "$OLDPWD/restart_end_of_step_checkpoint"
