#!/usr/bin/python3
"""Six decks of two unit cubes in sticking contact, one per direction of the master normal;
ccx and fcs3d run each; their *CONTACT PRINT tables (CDIS, CSTR) must agree within 1e-3 of the
table's largest entry (tests/integration/contact_print_frame.sh says why).

Usage: print_frame.py FCS3D   (run in a scratch directory)
"""

import os
import subprocess
import sys

import numpy as np

TOLERANCE = 1e-3
CORNERS = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0],
                    [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]], float)
# C3D8 faces (CalculiX numbering) by outward normal, and their nodes.
FACE_OF = {'+x': 4, '-x': 6, '+y': 5, '-y': 3, '+z': 2, '-z': 1}
OPPOSITE = {'+x': '-x', '-x': '+x', '+y': '-y', '-y': '+y', '+z': '-z', '-z': '+z'}
FACE_NODES = {1: [4, 3, 2, 1], 2: [5, 6, 7, 8], 3: [1, 2, 6, 5], 4: [2, 3, 7, 6],
              5: [3, 4, 8, 7], 6: [4, 1, 5, 8]}


def deck(direction):
    """The lower cube fixed; the upper one, beyond the lower cube's face `direction`, has its
    far face pushed 2e-5 into contact and moved 1e-5 and 3e-5 along the two other axes."""
    axis = 'xyz'.index(direction[1])
    sign = 1.0 if direction[0] == '+' else -1.0
    upper = CORNERS.copy()
    upper[:, axis] += sign
    far = [10 + n for n in FACE_NODES[FACE_OF[direction]]]
    move = np.zeros(3)
    move[axis] = -2e-5 * sign
    others = [k for k in range(3) if k != axis]
    move[others[0]], move[others[1]] = 1e-5, 3e-5
    lines = ['*NODE, NSET=NALL']
    lines += ['%d, %g, %g, %g' % (i + 1, *CORNERS[i]) for i in range(8)]
    lines += ['%d, %g, %g, %g' % (i + 11, *upper[i]) for i in range(8)]
    lines += ['*ELEMENT, TYPE=C3D8, ELSET=EALL', '1, 1, 2, 3, 4, 5, 6, 7, 8',
              '2, 11, 12, 13, 14, 15, 16, 17, 18', '*ELSET, ELSET=LOWER', '1',
              '*ELSET, ELSET=UPPER', '2', '*NSET, NSET=FIXED', '1, 2, 3, 4, 5, 6, 7, 8',
              '*NSET, NSET=DRIVEN', ', '.join(map(str, far)),
              '*SURFACE, NAME=MASTER', 'LOWER, S%d' % FACE_OF[direction],
              '*SURFACE, NAME=SLAVE', 'UPPER, S%d' % FACE_OF[OPPOSITE[direction]],
              '*MATERIAL, NAME=EL', '*ELASTIC', '210000., 0.3',
              '*SOLID SECTION, ELSET=EALL, MATERIAL=EL',
              '*SURFACE INTERACTION, NAME=SI1', '*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR',
              '1.e7, 0.01', '*FRICTION', '0.5, 1.e5',
              '*CONTACT PAIR, INTERACTION=SI1, TYPE=NODE TO SURFACE', 'SLAVE, MASTER',
              '*BOUNDARY', 'FIXED, 1, 3', '*STEP', '*STATIC', '0.25, 1.', '*BOUNDARY']
    lines += ['DRIVEN, %d, %d, %.6g' % (k + 1, k + 1, move[k]) for k in range(3)]
    lines += ['*CONTACT PRINT', 'CDIS, CSTR', '*END STEP']
    return '\n'.join(lines) + '\n'


def last_tables(path):
    """{'relative contact displacement': {node: row}, 'contact stress': {...}}, last of each."""
    tables, current = {}, None
    with open(path) as f:
        for line in f:
            if 'for all contact elements' in line:
                current = line.split('(')[0].strip()
                tables[current] = {}
                continue
            fields = line.split()
            if current and len(fields) == 4:
                tables[current][int(fields[0])] = np.array([float(v) for v in fields[1:]])
            elif current and tables[current] and not fields:
                current = None
    return tables


def main():
    fcs3d = sys.argv[1]
    failures = 0
    for direction in FACE_OF:
        job = 'frame_' + direction.replace('+', 'p').replace('-', 'm')
        os.makedirs(job + '/fcs3d', exist_ok=True)
        with open(os.path.join(job, job + '.inp'), 'w') as f:
            f.write(deck(direction))
        env = dict(os.environ, OMP_NUM_THREADS='1')
        ccx = subprocess.run(['ccx', '-i', job], cwd=job, env=env, capture_output=True, text=True)
        ours = subprocess.run([fcs3d, '-q', '-o', 'fcs3d', job + '.inp'], cwd=job,
                              capture_output=True, text=True)
        if ccx.returncode != 0 or ours.returncode != 0:
            print('FAIL %s: ccx exit %d, fcs3d exit %d %s' % (direction, ccx.returncode,
                                                             ours.returncode, ours.stderr[-300:]))
            failures += 1
            continue
        reference = last_tables(os.path.join(job, job + '.dat'))
        other = last_tables(os.path.join(job, 'fcs3d', job + '.dat'))
        for title in ('relative contact displacement', 'contact stress'):
            ref, oth = reference.get(title, {}), other.get(title, {})
            if not ref or sorted(ref) != sorted(oth):
                print('FAIL %s %s: nodes %s (ccx) vs %s (fcs3d)' % (direction, title, sorted(ref),
                                                                    sorted(oth)))
                failures += 1
                continue
            a = np.array([ref[n] for n in sorted(ref)])
            b = np.array([oth[n] for n in sorted(ref)])
            error = np.abs(b - a).max() / np.abs(a).max()
            ok = error <= TOLERANCE
            failures += not ok
            print('%s master normal %s, %s: error %.2e (tolerance %g)'
                  % ('ok  ' if ok else 'FAIL', direction, title, error, TOLERANCE))
    sys.exit(1 if failures else 0)


if __name__ == '__main__':
    main()
