#!/bin/sh
# Uniaxial stress with linear hardening (isotropic, kinematic, combined as CalculiX reads
# *PLASTIC and *CYCLIC HARDENING) against the closed form s = s_y + E H/(E + H)(eps - s_y/E):
# loading, elastic unloading (slope E, the unloading points switched to the elastic tangent),
# reverse yield at b - R (Bauschinger), every increment at full precision from job.h5 within
# 1e-10 of s_y; and NLGEOM to 10 % strain against the same curve in logarithmic strain (2e-3),
# kinematic and combined also stretched and compressed again (the back stress co-rotated).
# The isotropic case also with every other element kind (C3D4 ... C3D20R), to 1e-10.
# Details in plasticity/uniaxial.py. By hand:
#   FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/plasticity_uniaxial.sh'
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy or h5py not available to $py"; exit 77; }
mkdir -p plasticity_uniaxial || exit 1
cd "$tests/integration/plasticity" && "$py" uniaxial.py "$OLDPWD/plasticity_uniaxial"
