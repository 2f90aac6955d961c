#!/bin/sh
# *HISTORY with TIME POINTS= and FREQUENCY=0 samples exactly at those times, in every step,
# with no output request naming the list: the stepper lands on them (once a regression: it
# landed only on the time points of output requests). A two-step compression of a cube.
# By hand: FCS3D=$PWD/bin/fcs3d sh -c 'cd $(mktemp -d) && sh '$PWD'/tests/integration/history_time_points.sh'
set -u
cat > job.inp <<'DECK'
*NODE, NSET=NALL
1, 0, 0, 0
2, 1, 0, 0
3, 1, 1, 0
4, 0, 1, 0
5, 0, 0, 1
6, 1, 0, 1
7, 1, 1, 1
8, 0, 1, 1
*ELEMENT, TYPE=C3D8, ELSET=E
1, 1, 2, 3, 4, 5, 6, 7, 8
*NSET, NSET=BOT
1, 2, 3, 4
*NSET, NSET=TOP
5, 6, 7, 8
*MATERIAL, NAME=M
*ELASTIC
1000., 0.3
*SOLID SECTION, ELSET=E, MATERIAL=M
*BOUNDARY
BOT, 1, 3
*TIME POINTS, NAME=TP, TIME=TOTAL TIME
0.137, 0.5, 0.731, 1.25, 1.9
*HISTORY, NAME=H, FREQUENCY=0, TIME POINTS=TP
NSET, TOP, U
*STEP
*STATIC
1., 1.
*BOUNDARY
TOP, 3, 3, -0.01
*END STEP
*STEP
*STATIC
1., 1.
*BOUNDARY
TOP, 3, 3, -0.02
*END STEP
DECK
"$FCS3D" -q job.inp || { echo "fcs3d failed"; exit 1; }
"${PYTHON:-/usr/bin/python3}" - <<'PY'
import sys
rows = [l.split(',') for l in open('job_h.csv').read().split('\n')[1:] if l.strip()]
times = [float(r[0]) for r in rows]
wanted = [0.137, 0.5, 0.731, 1.25, 1.9]
missing = [t for t in wanted if not any(abs(s - t) <= 1e-12 for s in times)]
print('history sample times: %s' % ', '.join('%.12g' % t for t in times))
if missing:
    print('FAIL: no sample at %s' % missing)
    sys.exit(1)
# u_z of TOP is linear in time within each step: -0.01 t, then -0.01 - 0.01 (t - 1).
for t, r in zip(times, rows):
    expected = -0.01 * t if t <= 1 else -0.01 - 0.01 * (t - 1)
    if t in wanted and abs(float(r[3]) - expected) > 1e-9:
        print('FAIL: u_z(%g) = %s, expected %g' % (t, r[3], expected))
        sys.exit(1)
print('ok   samples at every time point, u_z linear in time')
PY
