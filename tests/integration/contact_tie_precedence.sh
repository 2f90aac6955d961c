#!/bin/sh
# A slave surface sharing nodes with a tie (the end of a fault segment next to a tied
# segment): the tie holds the shared nodes and the contact pair leaves them out, with a note
# in the log (tests/integration/contact/tie_precedence.py: model and checks).
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy/h5py not available to $py"; exit 77; }
script=$tests/integration/contact/tie_precedence.py
mkdir -p contact_tie_precedence && cd contact_tie_precedence || exit 1
"$py" "$script" deck tie.inp || exit 1
"$FCS3D" -q tie.inp || { echo "fcs3d failed on tie.inp"; tail -5 tie.log; exit 1; }
"$py" "$script" check tie
