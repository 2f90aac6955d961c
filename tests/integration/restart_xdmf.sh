#!/bin/sh
# The XDMF after a restart: the stick-slip problem run to its end, then restarted from an
# early checkpoint (increment 20) so that most frames are deleted and written again.
# post/check_xdmf.py accepts job.xdmf with the one-go run's number of frames, frame times
# strictly increase and no (step, increment) has two frames, frames and job.h5 equal the
# one-go run's; post/check_xdmf_vtk.py reads it when VTK's Xdmf reader is installed
# (python3-paraview; otherwise that part is skipped). Details in restart/xdmf.py. By hand:
#   FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/restart_xdmf.sh'
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy or h5py not available to $py"; exit 77; }
mkdir -p restart_xdmf || exit 1
cd "$tests/integration/restart" && "$py" xdmf.py "$OLDPWD/restart_xdmf"
