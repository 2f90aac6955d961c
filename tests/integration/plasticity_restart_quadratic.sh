#!/bin/sh
# Restart with plastic state in quadratic elements, bit for bit: plasticity_restart.sh's bar
# bent into the plastic range and back (NLGEOM, combined hardening), meshed with C3D20R
# (8 points per element), killed with kill -9 at a random moment after a checkpoint exists
# and restarted from it: job.h5, job.dat, the frames of job.xdmf and the final checkpoint's
# state equal the one-go run's. Details in plasticity/restart_plastic.py (KIND argument).
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy or h5py not available to $py"; exit 77; }
mkdir -p plasticity_restart_quadratic || exit 1
cd "$tests/integration/plasticity" && "$py" restart_plastic.py "$OLDPWD/plasticity_restart_quadratic" C3D20R
