#!/bin/sh
# A full disk during a run (issue 15, item 1): on small tmpfs file systems the run stops with
# exit status 1 and "the disk is full", job.h5 keeps every completed frame readable by h5py
# (bit for bit those of a run on a roomy disk), the XDMF, CSVs and .dat hold whole rows, the
# log records the failure, and after the disk is enlarged --restart ends with the roomy run's
# outputs. job.h5 linked to /dev/full too. Skipped where tmpfs cannot be mounted. Details:
# reliability/disk_full.py. By hand (as root):
#   FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/reliability_disk_full.sh'
set -u
here=$(cd "$(dirname "$0")" && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy or h5py not available to $py"; exit 77; }
mkdir -p disk_full || exit 1
cd "$here/reliability" && "$py" disk_full.py "$OLDPWD/disk_full"
