#!/bin/sh
# Spring-slider stability with RATE STATE (ageing) friction: the block's loading spring
# k = 0.8 k_c gives repeated stick-slip events (event catalog) to the end of a 400 s run;
# k = 1.2 k_c settles to steady sliding (no event after 200 s, mu = mu_ss within 1e-5, the
# oscillation decaying per cycle like the quasi-static ODE's, with the scheme's extra
# damping), k_c = sigma_n (B - A)/DC. Deck and checks: friction/stability.py (its doc string
# describes what the static-explicit scheme does with the unbounded quasi-static event).
# By hand: FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/friction_stability.sh'
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
script=$tests/integration/friction/stability.py
mkdir -p friction_stability && cd friction_stability || exit 1
status=0
"$py" "$script" deck unstable.inp --ratio 0.8 || exit 1
"$py" "$script" deck stable.inp --ratio 1.2 || exit 1
"$FCS3D" -q unstable.inp || { echo "fcs3d failed on unstable.inp"; exit 1; }
"$FCS3D" -q stable.inp || { echo "fcs3d failed on stable.inp"; exit 1; }
"$py" "$script" check unstable --ratio 0.8 --expect unstable || status=1
"$py" "$script" check stable --ratio 1.2 --expect stable || status=1
exit $status
