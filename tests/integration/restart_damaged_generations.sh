#!/bin/sh
# When a checkpoint
# cannot be read, the message must offer the newest OLDER generation that can be read in full,
# and a checkpoint HDF5 cannot open must exit 2 like any damaged one. Bugs: the offer checks
# only a candidate's /meta (read_checkpoint_info), so a generation with damaged data is
# offered; the search starts at generation 0, so restarting from a damaged job.rst.1.h5 offers
# the newer job.rst.h5 as "older"; an HDF5 failure ("H5Dopen of /state/strain failed") exits 1.
# Fixed: candidates are read like a restart reads them (scratch copies), from the next
# older generation on; read_checkpoint's errors exit 2. Details in
# integration/restart/damaged_generations.py.
#   FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/restart_damaged_generations.sh'
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy or h5py not available to $py"; exit 77; }
mkdir -p restart_damaged_generations || exit 1
cd "$tests/integration/restart" && "$py" damaged_generations.py "$OLDPWD/restart_damaged_generations"
