#!/bin/sh
# Drucker-Prager triaxial compression at confining pressures 0, 10, 20 against the closed-form
# axial stress sigma_c(eps_bar) + p_c (1 + 2 tan(beta)/3)/(1 - tan(beta)/3), associated and
# non-associated (dilatancy tan(psi)/(1 - tan(psi)/3)), every increment within 1e-10; the
# unsymmetric non-associated tangent solved by UMFPACK, SKYLINE and MUMPS alike. Details in
# plasticity/triaxial.py. By hand:
#   FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/plasticity_drucker_prager.sh'
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy or h5py not available to $py"; exit 77; }
mkdir -p plasticity_drucker_prager || exit 1
cd "$tests/integration/plasticity" && "$py" triaxial.py "$OLDPWD/plasticity_drucker_prager"
