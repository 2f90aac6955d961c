#!/bin/sh
# Seeded fuzz test of the deck reader: 6 good decks x 60 mutations (truncation, swapped fields,
# garbage numbers, huge ids, missing includes, include cycles, non-ASCII bytes, empty files,
# deleted/repeated lines, mangled parameters, a long line), each through `fcs3d --check`: no
# crash, no hang, exit 0 or 2, a file:line: message with every refusal, and a refusal for the
# mutations that cannot give a valid deck. Details: robustness/deck_fuzz.py. The seed is
# $FCS3D_TEST_SEED, else fixed (20261121), and printed. By hand:
#   FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/deck_fuzz.sh'
set -u
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p deck_fuzz || exit 1
"${PYTHON:-/usr/bin/python3}" "$here/robustness/deck_fuzz.py" "$PWD/deck_fuzz"
