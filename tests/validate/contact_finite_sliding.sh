#!/bin/sh
# Finite sliding over a 6-degree kink, fine meshes (contact issue, test 5; `make validate`):
# tests/integration/contact/finite_sliding.py with the slider 5 x 2 x 2 (spacing 0.2) on the
# base 24 x 2 x 2 (spacing 0.25): 5 master segments on the flat part, the kink, the slope.
# Same checks and bounds as tests/integration/contact_finite_sliding.sh; writes
# doc/validation/contact_finite_sliding.{png,csv}. About 1 to 3 minutes (several thousand
# increments: stick/slip chatter, see doc/validation/contact.md).
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, matplotlib' 2>/dev/null || { echo "numpy/matplotlib not available"; exit 77; }
script=$here/tests/integration/contact/finite_sliding.py
"$py" "$script" deck kink.inp --mesh fine --angle 6 --push 3 --max-increment 0.002 || exit 1
"$FCS3D" -q kink.inp || { echo "fcs3d failed on kink.inp"; exit 1; }
"$py" "$script" check kink --angle 6 --push 3 --jump-bound 0.03 --kink-bound 0.2 \
  --png "$here/doc/validation/contact_finite_sliding.png" \
  --csv "$here/doc/validation/contact_finite_sliding.csv"
