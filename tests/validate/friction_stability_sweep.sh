#!/bin/sh
# Spring-slider stability study with RATE STATE (ageing) friction: outcome against k / k_c =
# 0.8 ... 1.2, the scheme's damping against the quasi-static ODE for three maximum increments,
# and the size of quasi-static events against the minimum increment; prints the tables of
# doc/validation/friction.md and checks the +-20 % outcome. friction/stability_sweep.py
# (about 25 s).
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
"$py" "$tests/integration/friction/stability_sweep.py" "$PWD/runs" --markdown stability.md
