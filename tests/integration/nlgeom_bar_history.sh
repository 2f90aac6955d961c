#!/bin/sh
# Loading histories against the closed form R(t) = E A u(t) / L, in ONE step: a bar driven by a
# non-monotonic tabular *AMPLITUDE and a bar driven by *BOUNDARY, TYPE=VELOCITY with a tabular
# amplitude (the displacement is its exact integral); reactions (*NODE PRINT, TOTALS=ONLY) and
# displacements at *TIME POINTS within 1e-6 (linear) and, with NLGEOM and strains < 2.5e-6,
# within 1e-5; the .dat header times are the requested ones. nlgeom/bar_history.py.
# The multi-step form of the issue is nlgeom_bar_history_steps.sh.
# By hand: FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/nlgeom_bar_history.sh'
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy' 2>/dev/null || { echo "numpy not available to $py"; exit 77; }
script=$tests/integration/nlgeom/bar_history.py
mkdir -p nlgeom_bar_history && cd nlgeom_bar_history || exit 1
"$py" "$script" deck bar.inp --steps 1 || exit 1
"$FCS3D" -q bar.inp || { echo "fcs3d failed on bar.inp"; exit 1; }
"$py" "$script" check bar --steps 1 || exit 1
"$py" "$script" deck bar_nlgeom.inp --steps 1 --nlgeom --scale 1e-5 || exit 1
"$FCS3D" -q bar_nlgeom.inp || { echo "fcs3d failed on bar_nlgeom.inp"; exit 1; }
"$py" "$script" check bar_nlgeom --steps 1 --nlgeom --scale 1e-5
