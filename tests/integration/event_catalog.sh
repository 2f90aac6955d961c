#!/bin/sh
# The slip-event catalog (*EVENT CATALOG) against the slip-rate history of the same run
# (*HISTORY, FREQUENCY=1, CONTACT, <pair>: column <PAIR>_RATE_MAX) on the stick-slip problem:
# an event per up-crossing of the threshold, onset = start of the first increment above it,
# end = start of the first increment after it below it, peak slip rate = the largest
# RATE_MAX in between; job_events.csv equals /events/catalog/values of job.h5; one log line
# per event; MIN SLIP drops exactly the events whose largest slip is below it. The rule is
# stated in restart/event_catalog.py. By hand:
#   FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/event_catalog.sh'
set -u
tests=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-/usr/bin/python3}
"$py" -c 'import numpy, h5py' 2>/dev/null || { echo "numpy or h5py not available to $py"; exit 77; }
mkdir -p event_catalog || exit 1
cd "$tests/integration/restart" && "$py" event_catalog.py "$OLDPWD/event_catalog"
