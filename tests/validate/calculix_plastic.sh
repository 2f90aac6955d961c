#!/bin/sh
# fcs3d against CalculiX (`make validate`) on the *PLASTIC decks of tests/decks/plastic: a
# C3D8 cantilever bent into the plastic range and back with isotropic (small strain),
# kinematic and combined hardening (NLGEOM). Each deck runs unchanged in ccx and fcs3d; every
# table printed at the step ends (tip displacements and forces, stresses, PEEQ) must agree
# within 1e-2 of the table's largest value (tests/validate/calculix_plastic.py; the measured
# differences are in doc/validation/plasticity.md). Skips (exit 77) without ccx.
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
py=${PYTHON:-/usr/bin/python3}
command -v ccx >/dev/null 2>&1 || { echo "ccx (Debian package calculix-ccx) not installed"; exit 77; }
work=${FCS3D_TEST_WORK:-/tmp}/calculix_plastic
mkdir -p "$work" || exit 1
"$py" "$here/tests/validate/calculix_plastic.py" --fcs3d "$FCS3D" --work "$work" --tolerance 1e-2 \
  --markdown "$work/calculix_plastic.md" "$here"/tests/decks/plastic/*.inp
