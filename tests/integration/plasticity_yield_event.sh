#!/bin/sh
# The R-minimum yield event and the plastic strain limit, in load-controlled uniaxial stress:
# with the events the elastic-plastic transition lands on the yield surface (Mises = s_y
# within 1e-10, no plastic strain taken) and every increment matches the closed form within
# 1e-10; PEEQ grows by at most MAX PLASTIC STRAIN INCREMENT per increment; with a large fixed
# increment the floored event lets the elastic predictor overshoot by 12.5 % of s_y and the
# displacement and out-of-balance force show it. Details in plasticity/yield_event.py. By hand:
#   FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/plasticity_yield_event.sh'
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy or h5py not available to $py"; exit 77; }
mkdir -p plasticity_yield_event || exit 1
cd "$tests/integration/plasticity" && "$py" yield_event.py "$OLDPWD/plasticity_yield_event"
