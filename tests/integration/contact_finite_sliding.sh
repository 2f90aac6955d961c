#!/bin/sh
# Finite sliding (contact issue, test 5), coarse meshes: a slider pushed 3 along a base whose
# top has a 6-degree kink (NLGEOM): on the flat part each slave node crosses 3 master segments
# with T/N = mu within 2 % and no jump of T between outputs (every 0.02 of push) above
# 0.03 mu N (measured 0.013); across the kink T rises in steps (the loaded leading row of
# slave nodes reaching the slope and passing its master nodes), none above 0.2 mu N (half the
# change across the kink; measured 0.16), without spike or dip; on the slope RF_x matches the
# closed form within 2 % (measured 0.7 %). The fine meshes run in `make validate`
# (tests/validate/contact_finite_sliding.sh). contact/finite_sliding.py. About 3 s.
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
script=$tests/integration/contact/finite_sliding.py
mkdir -p contact_finite_sliding && cd contact_finite_sliding || exit 1
"$py" "$script" deck kink.inp --mesh coarse --angle 6 --push 3 --max-increment 0.005 || exit 1
"$FCS3D" -q kink.inp || { echo "fcs3d failed on kink.inp"; exit 1; }
"$py" "$script" check kink --angle 6 --push 3 --jump-bound 0.03 --kink-bound 0.2
