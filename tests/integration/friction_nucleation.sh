#!/bin/sh
# A nucleation phase (issue 19): a granite strip on a fixed base, RATE STATE friction with
# Ruina's slip law and the fault-bend reference parameters (DC = 5e-4 mm here, nucleation
# length about 39 mm = 8 node spacings), RADIATION DAMPING=MATERIAL and the reference deck's
# *RMIN limits, pushed slowly at one end. The first node slips at 1.10 s; the slip front creeps
# along the strip and the first event over at least half of the 42 slave nodes starts 11.6-11.7 s
# later (36 nodes, peak slip rate about 1e3 mm/s, stress drop 1.04-1.06 MPa), with no
# increment carried out of equilibrium. Run with MAX SLIP INCREMENT = 0.1 and 0.05: first
# slip, onset and nucleation duration agree within 1 %, the stress drop within 5 % (measured:
# onset 12.825 s against 12.743 s, 0.64 %; nucleation 0.70 %; stress drop 1.7 %; with 0.2
# against 0.1 the onset differs by 1.6 %, so the difference roughly halves with xi, the
# first-order error of the stepping). Deck and checks: friction/nucleation.py. About 10 s.
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
