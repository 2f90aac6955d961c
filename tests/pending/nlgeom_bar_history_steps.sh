#!/bin/sh
# PENDING (not run by `make test`): multi-step loading of a bar against R(t) = E A u(t) / L:
# step 1 a non-monotonic tabular *AMPLITUDE on the end displacement, step 2
# *BOUNDARY, TYPE=VELOCITY, step 3 TYPE=VELOCITY with an amplitude in total time; reactions
# (TOTALS=ONLY) and displacements at *TIME POINTS (step time in steps 1-2, total time in step
# 3) within 1e-6 (linear) and 1e-5 (NLGEOM, strains < 2.5e-6); the .dat times are the requested
# ones. tests/integration/nlgeom_bar_history.sh is the single-step form, in the suite.
# Fails at fbf1617: every step after the first is skipped or cut short (state%step_time is not
# reset at the start of a step; step 2, period 2, runs only from step time 1 to 2 and prints at
# the wrong times, step 3 not at all), and the run exits 0. Passes with `state%step_time = 0`
# after each step in run_steps. Move it to tests/integration/ when that is fixed.
# By hand: FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/pending/nlgeom_bar_history_steps.sh'
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
script=$tests/integration/nlgeom/bar_history.py
mkdir -p nlgeom_bar_history_steps && cd nlgeom_bar_history_steps || exit 1
"$py" "$script" deck bar.inp --steps 3 || exit 1
"$FCS3D" -q bar.inp || { echo "fcs3d failed on bar.inp"; exit 1; }
"$py" "$script" check bar --steps 3 || exit 1
"$py" "$script" deck bar_nlgeom.inp --steps 3 --nlgeom --scale 1e-5 || exit 1
"$FCS3D" -q bar_nlgeom.inp || { echo "fcs3d failed on bar_nlgeom.inp"; exit 1; }
"$py" "$script" check bar_nlgeom --steps 3 --nlgeom --scale 1e-5
