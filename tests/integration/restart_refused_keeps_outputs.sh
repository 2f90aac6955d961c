#!/bin/sh
# A refused
# restart (damaged checkpoint, changed model, changed step already begun) must exit 2 and
# leave job.dat, job.h5, job.xdmf and the history and event CSVs of the earlier run as they
# were. Bug: resume_outputs calls monitors%init, which writes new CSVs (headers only), before
# the checkpoint is read; read_checkpoint then rewrites them from the checkpoint's rows before
# the deck is checked. A damaged checkpoint leaves header-only CSVs, a changed deck CSVs cut
# back to the checkpoint. Fixed: the CSVs are written by monitors%write_files, called
# for a new run and after the checkpoint was accepted. Details in
# integration/restart/refused.py.
#   FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/restart_refused_keeps_outputs.sh'
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy or h5py not available to $py"; exit 77; }
mkdir -p restart_refused_keeps_outputs || exit 1
cd "$tests/integration/restart" && "$py" refused.py "$OLDPWD/restart_refused_keeps_outputs"
