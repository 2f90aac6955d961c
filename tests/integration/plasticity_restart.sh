#!/bin/sh
# Restart with plastic state, bit for bit: a bar bent into the plastic range and back (NLGEOM,
# combined hardening: PEEQ, plastic strain and back stress in the checkpoint) run in one go,
# then killed with kill -9 at a random moment after a checkpoint exists and restarted from
# it: job.h5, job.dat, the frames of job.xdmf and the final checkpoint's state equal the
# one-go run's. The kill moment is seeded from $FCS3D_TEST_SEED (else the clock; printed).
# Also: job.xdmf lists PEEQ, PE and ALPHA, which ParaView's Xdmf reader (VTK) reads back equal
# to the HDF5 data (skipped without python3-paraview).
# Details in plasticity/restart_plastic.py. By hand:
#   FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/plasticity_restart.sh'
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy or h5py not available to $py"; exit 77; }
mkdir -p plasticity_restart || exit 1
cd "$tests/integration/plasticity" && "$py" restart_plastic.py "$OLDPWD/plasticity_restart"
