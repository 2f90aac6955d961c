#!/bin/sh
# Velocity step 1e-3 -> 1e-2 mm/s of a block sliding with RATE STATE friction (ageing and slip
# laws): the contact friction against an independent RK4 integration of the spring-slider ODE
# with the block's loading stiffness, within 1 % of mu over the whole record; direct effect
# (peak) against the ODE's and A ln 10; new steady state (A - B) ln 10 within 1e-4 relative.
# Deck and checks: friction/velocity_step.py.
# By hand: FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/friction_velocity_step.sh'
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
script=$tests/integration/friction/velocity_step.py
mkdir -p friction_velocity_step && cd friction_velocity_step || exit 1
status=0
for law in AGEING SLIP; do
  job=step_$(echo $law | tr 'A-Z' 'a-z')
  "$py" "$script" deck $job.inp --state-law $law || exit 1
  "$FCS3D" -q $job.inp || { echo "fcs3d failed on $job.inp"; exit 1; }
  "$py" "$script" check $job --state-law $law || status=1
done
exit $status
