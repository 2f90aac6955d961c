#!/bin/sh
# *RMIN, MAX SLIP INCREMENT (issue 19, item 4: error-controlled stepping, the increment at most
# xi L / V_max; Lapusta et al. 2000): the steady-sliding block-slider of
# friction_steady_state.sh (RATE STATE, slip law, DC = L = 1e-3 mm, 1e-3, 1e-2, 1e-4 mm/s)
# with MAX SLIP INCREMENT = 0.1: no increment slips more than 1.01 xi L (measured 0.10002 L;
# 0.25 L without the option, the steps' maximum increment), the bound binds in the steady
# windows (median within 1 % of 0.1 L), and mu = mu_ss(V) within 1e-6 as without it.
# Deck and checks: friction/steady_state.py.
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy or h5py not available to $py"; exit 77; }
script=$tests/integration/friction/steady_state.py
mkdir -p friction_slip_increment && cd friction_slip_increment || exit 1
"$py" "$script" deck xi.inp --state-law SLIP --rmin "MAX SLIP INCREMENT=0.1" || exit 1
"$FCS3D" -q xi.inp || { echo "fcs3d failed on xi.inp"; exit 1; }
grep -q 'limit slip-increment' xi.log || { echo "no increment limited by slip-increment in xi.log"; exit 1; }
"$py" "$script" check xi --state-law SLIP --max-slip-increment 0.1
