#!/bin/sh
# *CONTACT PRINT in CalculiX's frame and sign (issue 16, item 5): two unit cubes pressed
# together and sheared while sticking, the master face normal along +x, -x, +y, -y, +z and -z
# in turn (tests/integration/contact/print_frame.py writes the six decks). ccx and fcs3d run
# each unchanged; the relative contact displacement and contact stress tables must agree
# within 1e-3 of each table's largest entry (measured: 5.8e-5 and 2.4e-4, from ccx's smoothed
# penalty with sigma_inf = 0.01 and its Newton tolerance). Before the frame was CalculiX's, the
# tangential columns differed by a rotation about the normal and the shear had the opposite
# sign (errors of order 1 to 2). Skips (exit 77) when ccx is not installed.
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
py=${PYTHON:-/usr/bin/python3}
command -v ccx >/dev/null 2>&1 || { echo "ccx (Debian package calculix-ccx) not installed"; exit 77; }
exec "$py" "$here/tests/integration/contact/print_frame.py" "$FCS3D"
