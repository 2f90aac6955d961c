#!/bin/sh
# A deck means what it says (issue 15, items 7, 8, 10, 11): tabs and byte-order marks accepted,
# *INCLUDE of a FIFO or a directory and non-file decks refused as such, empty --restart and -o
# refused, checkpoint and gmsh messages that name the real problem, input errors in job.log.
# Details: reliability/input_checks.py. By hand:
#   FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/reliability_input_checks.sh'
set -u
here=$(cd "$(dirname "$0")" && pwd)
py=${PYTHON:-/usr/bin/python3}
mkdir -p input_checks || exit 1
cd "$here/reliability" && "$py" input_checks.py "$OLDPWD/input_checks"
