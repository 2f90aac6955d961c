#!/bin/sh
# CalculiX comparison of the block-sliding problem (contact issue, test 7; `make validate`):
# the deck of tests/integration/contact_block_sliding.sh (variant partial: pressure, then a
# push; *CONTACT PAIR, TYPE=NODE TO SURFACE; *SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR;
# *FRICTION mu, stick slope), with NLGEOM and without, run unchanged by CalculiX (Debian's
# calculix-ccx, installed by the Makefile's package list) and by fcs3d. Requires the pushed
# nodes' force histories to agree within 0.5 % of mu N in gross slip and 3 % (2 % without
# NLGEOM) over the whole push; both histories on one plot. Rewrites
# doc/validation/contact_vs_calculix.{png,csv,md}. contact/studies.py calculix. About 1 min.
# Skips (exit 77) only when ccx is not installed.
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
py=${PYTHON:-/usr/bin/python3}
command -v ccx >/dev/null 2>&1 || { echo "ccx (Debian package calculix-ccx) not installed"; exit 77; }
"$py" -c 'import numpy, matplotlib' 2>/dev/null || { echo "numpy/matplotlib not available"; exit 77; }
"$py" "$here/tests/integration/contact/studies.py" calculix --work "$PWD/calculix" \
  --markdown "$here/doc/validation/contact_vs_calculix.md" \
  --png "$here/doc/validation/contact_vs_calculix.png" \
  --csv "$here/doc/validation/contact_vs_calculix.csv"
