#!/bin/sh
# A nucleation phase (issue 19): a granite strip on a fixed base, RATE STATE friction with
# Ruina's slip law and the fault-bend reference parameters (DC = 5e-4 mm, nucleation length
# about 39 mm = 8 node spacings), RADIATION DAMPING=MATERIAL, pushed slowly at one end. The
# first node slips at 1.10 s; the slip front creeps along the strip and the first event over
# at least half of the 42 slave nodes starts 11.6-11.8 s later (36 nodes, peak slip rate about
# 1e3 mm/s, stress drop 1.06 MPa), with no increment carried out of equilibrium. Run with
# MAX SLIP INCREMENT = 0.1 and 0.05: first slip, onset and nucleation duration agree within
# 1 %, the stress drop within 5 % (measured: onset 12.818 s against 12.738 s, 0.6 %;
# nucleation 0.7 %; stress drop 0.3 %). Deck and checks: friction/nucleation.py.
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
script=$tests/integration/friction/nucleation.py
mkdir -p friction_nucleation && cd friction_nucleation || exit 1
for xi in 0.1 0.05; do
  job=xi_$xi
  "$py" "$script" deck $job.inp --xi $xi || exit 1
  "$FCS3D" -q $job.inp || { echo "fcs3d failed on $job.inp"; exit 1; }
done
"$py" "$script" check xi_0.1 --compare xi_0.05
