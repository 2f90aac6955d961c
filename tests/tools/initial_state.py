"""Initial stress (issue 17, item 3), for tests/integration/initial_stress.sh.

A unit cube of 3 x 3 x 3 C3D8 elements on rollers on the planes x = 0, y = 0, z = 0 starts
from the uniform stress sigma0 = (-10, -20, -30, 0, 0, 0) given point by point
(*INITIAL CONDITIONS, TYPE=STRESS: element, integration point, six components, as CalculiX),
with the pressures that balance it on the faces x = 1, y = 1, z = 1 held through the step
(an amplitude constant at 1). In equilibrium from the start, it stays put: every displacement
vanishes and the stress stays sigma0 (tolerance: round-off, 1e-9 of |sigma0| in stress and
1e-9 of |sigma0| / E in displacement: the only force is the round-off of the balance of a
uniform stress by exact face pressures on an undistorted mesh).

The GEOSTATIC form (a lithostatic pre-stress) is tested with gravity in tests/tools/body_loads.py.
"""

import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import datfile  # noqa: E402

FCS3D = os.environ.get('FCS3D', 'fcs3d')
N = 3
E, NU = 10000.0, 0.25
SIGMA0 = (-10.0, -20.0, -30.0, 0.0, 0.0, 0.0)
TOL = 1e-9


def nid(i, j, k):
    return 1 + i + (N + 1) * (j + (N + 1) * k)


def mesh():
    lines = ['*NODE, NSET=NALL']
    for k in range(N + 1):
        for j in range(N + 1):
            for i in range(N + 1):
                lines.append('%d, %.12g, %.12g, %.12g' % (nid(i, j, k), i / N, j / N, k / N))
    lines.append('*ELEMENT, TYPE=C3D8, ELSET=EALL')
    centres = {}
    e = 0
    for k in range(N):
        for j in range(N):
            for i in range(N):
                e += 1
                n = [nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k),
                     nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1),
                     nid(i, j + 1, k + 1)]
                lines.append('%d, %s' % (e, ', '.join(map(str, n))))
                centres[e] = ((i + 0.5) / N, (j + 0.5) / N, (k + 0.5) / N)
    for name, axis in [('X0', 0), ('Y0', 1), ('Z0', 2)]:
        members = [nid(i, j, k) for k in range(N + 1) for j in range(N + 1)
                   for i in range(N + 1) if (i, j, k)[axis] == 0]
        lines.append('*NSET, NSET=' + name)
        for c in range(0, len(members), 8):
            lines.append(', '.join(map(str, members[c:c + 8])))
    for name, axis in [('EX1', 0), ('EY1', 1), ('EZ1', 2)]:
        members = [e for e, c in centres.items() if c[axis] > 1 - 1 / N]
        lines.append('*ELSET, ELSET=' + name)
        lines.append(', '.join(map(str, members)))
    return lines, centres


def deck():
    lines, centres = mesh()
    lines += ['*MATERIAL, NAME=ROCK', '*ELASTIC', '%g, %g' % (E, NU),
              '*SOLID SECTION, ELSET=EALL, MATERIAL=ROCK']
    lines.append('*INITIAL CONDITIONS, TYPE=STRESS')
    for e in sorted(centres):
        for q in range(1, 9):
            lines.append('%d, %d, %s' % (e, q, ', '.join('%g' % v for v in SIGMA0)))
    lines += ['*BOUNDARY', 'X0, 1, 1', 'Y0, 2, 2', 'Z0, 3, 3',
              '*AMPLITUDE, NAME=HOLD', '0., 1., 1., 1.',
              '*STEP', '*STATIC', '0.5, 1.']
    # C3D8 faces as CalculiX numbers them: S2 z = 1 (nodes 5 8 7 6), S4 x = 1 (2 3 7 6),
    # S5 y = 1 (3 4 8 7).
    lines += ['*DLOAD, AMPLITUDE=HOLD', 'EX1, P4, %g' % -SIGMA0[0], 'EY1, P5, %g' % -SIGMA0[1],
              'EZ1, P2, %g' % -SIGMA0[2]]
    lines += ['*NODE PRINT, NSET=NALL', 'U', '*EL PRINT, ELSET=EALL', 'S', '*END STEP']
    return '\n'.join(lines) + '\n', centres


def run(directory, text):
    os.makedirs(directory, exist_ok=True)
    with open(os.path.join(directory, 'cube.inp'), 'w') as f:
        f.write(text)
    p = subprocess.run([FCS3D, '-q', 'cube.inp'], cwd=directory, capture_output=True, text=True,
                       timeout=600)
    if p.returncode != 0:
        print('fcs3d exit %d: %s' % (p.returncode, p.stderr))
        return None
    return datfile.read_blocks(os.path.join(directory, 'cube.dat'))


def report(what, error, failures):
    ok = error <= TOL
    print('%-70s %.1e  %s' % (what, error, 'ok' if ok else 'FAIL'))
    return failures + (not ok)


def main():
    work = sys.argv[1] if len(sys.argv) > 1 else '.'
    failures = 0
    text, _ = deck()
    blocks = run(os.path.join(work, 'uniform'), text)
    if blocks is None:
        return 1
    scale = max(abs(v) for v in SIGMA0)
    u = [b for b in blocks if b.kind == 'displacements'][-1].values()
    s = [b for b in blocks if b.kind == 'stresses'][-1].values()
    failures = report('uniform: largest |u| / (|sigma0| / E) (= 0)', abs(u).max() / (scale / E),
                      failures)
    failures = report('uniform: largest |sigma - sigma0| / |sigma0| (= 0)',
                      max(abs(row - SIGMA0).max() for row in s) / scale, failures)

    print('%d failure(s)' % failures)
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
