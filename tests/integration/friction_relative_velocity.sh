#!/bin/sh
# *FRICTION, VELOCITY=RELATIVE (the literal reading of eq. 3 of Xing, Mora & Makinouchi 2003:
# the law's V is the total relative tangential velocity, elastic stick part included) on a
# granite block sheared between two granite blocks under the paper's law
# mu = 0.60 - 0.015 ln(V/0.001), floor below VC = 1e-9 mm/s, E_t = 10 MPa/mm, p = 10 MPa
# (tests/integration/friction/relative_velocity.py has the model and the closed forms).
# Checks: the onset of sliding at t_s = mu_ss(v) p / (E_t v) (the stick part sets the static
# level mu_ss(v), finite without the floor) at v = 0.01 and 0.001 mm/s, against
# mu_ss(VC) p / (E_t v) with VELOCITY=SLIP (the floor's level, 43 % later), within 2.5 %; with
# RELATIVE the friction never exceeds mu_ss(v) and at 0.01 mm/s slides at mu_ss(v) (1e-3) with
# no stress drop; with SLIP it peaks at the floor level and drops by more than 0.1.
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
script=$tests/integration/friction/relative_velocity.py
mkdir -p friction_relative_velocity && cd friction_relative_velocity || exit 1
status=0
run() {
  job=$1; shift
  "$py" "$script" deck $job.inp "$@" || exit 1
  "$FCS3D" -q $job.inp || { echo "fcs3d failed on $job.inp"; exit 1; }
}
run relative_fast --velocity RELATIVE --rate 0.01 --end 100
"$py" "$script" check relative_fast --velocity RELATIVE --rate 0.01 --steady || status=1
run slip_fast --velocity SLIP --rate 0.01 --end 100
"$py" "$script" check slip_fast --velocity SLIP --rate 0.01 || status=1
run relative_slow --velocity RELATIVE --rate 0.001 --end 700
"$py" "$script" check relative_slow --velocity RELATIVE --rate 0.001 || status=1
exit $status
