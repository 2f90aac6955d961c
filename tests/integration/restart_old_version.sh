#!/bin/sh
# A checkpoint of an older format version is refused (exit 2) with a message naming both
# versions; the unchanged checkpoint is accepted. Details in integration/restart/old_version.py.
#   FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/restart_old_version.sh'
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy or h5py not available to $py"; exit 77; }
mkdir -p restart_old_version || exit 1
cd "$tests/integration/restart" && "$py" old_version.py "$OLDPWD/restart_old_version"
