#!/bin/sh
# Radiation damping (issue 19, item 3; quasi-dynamic approximation, Rice 1993): the block-slider
# with RATE STATE friction (slip law) and RADIATION DAMPING = 5 MPa s/mm, then = MATERIAL (eta
# from the two materials' shear impedances, with *DENSITY), driven at 1e-3, 1e-2, 1e-1 mm/s:
# after 20 DC of slip in each step the contact's shear over its pressure equals
# mu_ss(V) + eta V / sigma_n within 1e-6 (measured 7e-11; without the damping the error would
# be eta V / sigma_n, up to 5e-2) and the echo states the pair's eta. Deck and checks:
# friction/radiation_damping.py.
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
script=$tests/integration/friction/radiation_damping.py
mkdir -p friction_radiation_damping && cd friction_radiation_damping || exit 1
status=0
for damping in 5 MATERIAL; do
  job=damping_$(echo $damping | tr 'A-Z' 'a-z')
  "$py" "$script" deck $job.inp --damping $damping || exit 1
  "$FCS3D" -q $job.inp || { echo "fcs3d failed on $job.inp"; exit 1; }
  "$py" "$script" check $job --damping $damping || status=1
done
exit $status
