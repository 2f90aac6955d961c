#!/bin/sh
# Regression (failed at 1a72340, fixed since): the friction state (theta of the rate-and-state laws) is not in
# the results. The contact grids have status, gap, pressure, shear_magnitude, slip, slip_rate,
# mu and shear; the state is only in the checkpoints (/contact/scalars, row 7), so it survives
# a restart (tests/integration/friction_restart_state.sh) but cannot be plotted or checked.
#
# Checks (friction/results_state.py, its doc string): a field 'friction_state' (or 'theta',
# 'state') in the contact grid; THETA0 + t at rest (ageing law heals); DC/V at steady sliding
# within 1e-6; mu of the frame's slip_rate and state equal to the 'mu' field within 1e-9.
# Measured at 1a72340: no such field. With the patch: 0, 6.4e-9, 0.
#
# Patch: friction_state_in_results.patch (src/stepper/fcs_driver.f90, write_contact_fields:
# an eighth field 'friction_state' = cstate%friction_state; theta [time] for the
# rate-and-state laws, the accumulated slip for SLIP WEAKENING, 0 for laws without state).
# Run: FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/friction_state_in_results.sh'
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy or h5py not available to $py"; exit 77; }
"$py" "$tests/integration/friction/results_state.py" "$PWD/friction_state_in_results"
