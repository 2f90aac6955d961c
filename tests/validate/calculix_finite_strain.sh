#!/bin/sh
# CalculiX's NLGEOM *PLASTIC decks (beampiso, beampkin, beampik, beampt) in one element
# (`make validate`): one C3D8 in uniaxial stress at NLGEOM through ccx and fcs3d, against
# CalculiX's finite-strain plasticity re-derived for uniaxial stress (Simo 1988, ccx's
# incplas.f; it must reproduce ccx within 2e-5); fcs3d's *ELASTIC + *PLASTIC must reproduce ccx
# within 1e-4 (3e-4 heated) and its *HYPOELASTIC + *PLASTIC the rate form's closed form (the
# small-strain J2 law on the logarithmic strain, within 1e-4); prints how the back-stress
# transport and the flow rule split the differences between the two laws on the beam decks
# (doc/theory.md 2.8). Skips (exit 77) without ccx. About 20 s.
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
work=${FCS3D_TEST_WORK:-/tmp}/calculix_finite_strain
mkdir -p "$work" || exit 1
"$py" "$here/tests/validate/calculix_finite_strain.py" --work "$work"
