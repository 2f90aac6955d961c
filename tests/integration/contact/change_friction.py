#!/usr/bin/python3
"""*CHANGE FRICTION between steps (tests/integration/contact_change_friction.sh).

A unit cube pressed by 10 MPa (*DLOAD P2) onto a fixed cube and pushed sideways by its top
face in three steps: mu = 0.3 (model definition), then *CHANGE FRICTION to 0.1 (lower: the
stored friction force is brought back onto the new cone and the nodes keep slipping), then to
0.5 (higher: the nodes stick, load up and slip again on the new cone). At the end of each
pushing step every slave node slips, so its shear over its pressure in *CONTACT PRINT (CSTR)
is that step's mu; required within 2e-6 (measured at most 7.7e-7: the printed 7 digits of
shear and pressure, 1e-7 each, and the explicit update of the cone with the normal force). Also checked: a run resumed (--restart) from a checkpoint within
the mu = 0.5 step (*RESTART, WRITE, FREQUENCY=1, GENERATIONS=3 keeps the last three; the
oldest of them is within the step) prints the same last table to 1e-9 relative: the changes
are applied again on resuming, without altering the state.

Usage: change_friction.py FCS3D   (run in a scratch directory)
"""

import os
import subprocess
import sys

import numpy as np

STEPS = [('push mu 0.3', None), ('push mu 0.1', 0.1), ('push mu 0.5', 0.5)]
MU0 = 0.3


def deck():
    lines = ['*NODE, NSET=NALL']
    corners = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
    lines += ['%d, %g, %g, %g' % (i + 1, *c) for i, c in enumerate(corners)]
    lines += ['%d, %g, %g, %g' % (i + 11, c[0], c[1], c[2] + 1) for i, c in enumerate(corners)]
    lines += ['*ELEMENT, TYPE=C3D8, ELSET=EALL', '1, 1, 2, 3, 4, 5, 6, 7, 8',
              '2, 11, 12, 13, 14, 15, 16, 17, 18', '*ELSET, ELSET=LOWER', '1',
              '*ELSET, ELSET=UPPER', '2', '*NSET, NSET=BOTTOM', '1, 2, 3, 4',
              '*NSET, NSET=TOP', '15, 16, 17, 18',
              '*SURFACE, NAME=MASTER', 'LOWER, S2', '*SURFACE, NAME=SLAVE', 'UPPER, S1',
              '*MATERIAL, NAME=EL', '*ELASTIC', '210000., 0.3',
              '*SOLID SECTION, ELSET=EALL, MATERIAL=EL',
              '*SURFACE INTERACTION, NAME=SI1', '*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR',
              '1.e6', '*FRICTION', '%g, 1.e5' % MU0,
              '*CONTACT PAIR, INTERACTION=SI1, TYPE=NODE TO SURFACE', 'SLAVE, MASTER',
              '*BOUNDARY', 'BOTTOM, 1, 3', 'TOP, 2, 2',
              '*RESTART, WRITE, FREQUENCY=1, GENERATIONS=3']
    lines += ['*STEP, NAME=PRESS', '*STATIC', '0.5, 1.', '*BOUNDARY', 'TOP, 1, 1, 0.',
              '*DLOAD', '2, P2, 10.', '*END STEP']
    push = 0.0
    for name, mu in STEPS:
        push += 1e-3
        lines += ['*STEP, NAME=%s' % name.replace(' ', '_').replace('.', ''), '*STATIC',
                  '0.1, 1.']
        if mu is not None:
            lines += ['*CHANGE FRICTION, INTERACTION=SI1', '*FRICTION', '%g' % mu]
        lines += ['*BOUNDARY', 'TOP, 1, 1, %g' % push, '*CONTACT PRINT', 'CSTR', '*END STEP']
    return '\n'.join(line for line in lines if line) + '\n'


def stress_tables(path):
    """[(time, {node: (p, t1, t2)})] of the contact stress tables."""
    tables, current = [], None
    with open(path) as f:
        for line in f:
            if line.startswith(' contact stress'):
                current = {}
                tables.append((float(line.split()[-1]), current))
                continue
            fields = line.split()
            if current is not None and len(fields) == 4:
                current[int(fields[0])] = np.array([float(v) for v in fields[1:]])
            elif current and not fields:
                current = None
    return tables


def run(fcs3d, directory, text, extra=()):
    os.makedirs(directory, exist_ok=True)
    with open(os.path.join(directory, 'slide.inp'), 'w') as f:
        f.write(text)
    return subprocess.run([fcs3d, '-q', *extra, 'slide.inp'], cwd=directory,
                          capture_output=True, text=True)


def main():
    fcs3d = sys.argv[1]
    failures = 0
    result = run(fcs3d, 'straight', deck())
    if result.returncode != 0:
        print('FAIL fcs3d exit %d: %s' % (result.returncode, result.stderr[-400:]))
        sys.exit(1)
    tables = stress_tables('straight/slide.dat')
    if len(tables) != len(STEPS):
        print('FAIL %d contact stress tables, expected %d' % (len(tables), len(STEPS)))
        sys.exit(1)
    for (name, mu), (time, table) in zip(STEPS, tables):
        mu = MU0 if mu is None else mu
        ratios = np.array([np.hypot(v[1], v[2]) / v[0] for v in table.values()])
        error = np.abs(ratios / mu - 1).max()
        ok = len(table) == 4 and error <= 2e-6
        failures += not ok
        print('%s %s (t = %g): %d slave nodes, shear / pressure %s, |ratio / mu - 1| max %.1e '
              '(tolerance 2e-6)' % ('ok  ' if ok else 'FAIL', name, time, len(table),
                                    np.array2string(ratios, precision=7), error))
    # Resume from the oldest checkpoint kept, within the last step.
    os.makedirs('resumed', exist_ok=True)
    with open('straight/slide.rst.2.h5', 'rb') as source, open('resumed/old.rst.h5', 'wb') as f:
        f.write(source.read())
    resumed = run(fcs3d, 'resumed', deck(), ['--restart', 'old.rst.h5'])
    if resumed.returncode != 0:
        print('FAIL restart: exit %d: %s' % (resumed.returncode, resumed.stderr[-400:]))
        failures += 1
    else:
        last = stress_tables('resumed/slide.dat')[-1][1]
        reference = tables[-1][1]
        a = np.array([reference[n] for n in sorted(reference)])
        b = np.array([last[n] for n in sorted(reference)])
        error = np.abs(b - a).max() / np.abs(a).max()
        start = [line for line in open('resumed/slide.log') if 'restart' in line.lower()][:1]
        ok = sorted(last) == sorted(reference) and error <= 1e-9
        failures += not ok
        print('%s resumed (%s): last table differs by %.1e (tolerance 1e-9)'
              % ('ok  ' if ok else 'FAIL', start[0].strip() if start else '?', error))
    sys.exit(1 if failures else 0)


if __name__ == '__main__':
    main()
