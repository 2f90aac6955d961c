#!/bin/sh
# *ELASTIC + *PLASTIC under NLGEOM, CalculiX's multiplicative finite-strain plasticity (Simo
# 1988; doc/theory.md 2.8): one C3D8 in uniaxial stress (ISOTROPIC, KINEMATIC, COMBINED,
# stretched and compressed) and heated between fixed ends, against the law re-derived in
# tests/validate/calculix_finite_strain.py (1e-4; 5e-4 heated), the first yield event at the
# law's first yield (1e-3); a cube yielded in uniaxial strain and turned rigidly by 90
# degrees: the stress turns with it, PEEQ kept (1e-9).
# Details in plasticity/finite_strain.py. By hand:
#   FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/plasticity_finite_strain.sh'
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
mkdir -p plasticity_finite_strain || exit 1
cd "$tests/integration/plasticity" && "$py" finite_strain.py "$OLDPWD/plasticity_finite_strain"
