#!/bin/sh
# Too little memory (issue 15, item 4): a 16^3 cube under `ulimit -v` limits from 150 to 450 MB
# with UMFPACK and MUMPS; every run ends within 120 s (no hang in OpenBLAS's retry loop) with
# status 0, or 1 and "fcs3d: ... out of memory while ...", never a signal; job.h5 stays
# readable with its last good frame. Details: reliability/memory_limit.py. By hand:
#   FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/reliability_memory_limit.sh'
set -u
here=$(cd "$(dirname "$0")" && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy or h5py not available to $py"; exit 77; }
mkdir -p memory_limit || exit 1
cd "$here/reliability" && "$py" memory_limit.py "$OLDPWD/memory_limit" "$here/../bench"
