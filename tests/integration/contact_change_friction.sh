#!/bin/sh
# *CHANGE FRICTION between steps (CalculiX's friction2 deck uses it): a cube pressed onto a
# cube and pushed sideways with mu 0.3, then changed to 0.1 and to 0.5; at the end of each step
# every slave node slips with shear / pressure = mu, and a run resumed from a checkpoint within
# the last step ends identically. tests/integration/contact/change_friction.py has the details
# and the tolerances. About 3 s.
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
exec "${PYTHON:-/usr/bin/python3}" "$here/tests/integration/contact/change_friction.py" "$FCS3D"
