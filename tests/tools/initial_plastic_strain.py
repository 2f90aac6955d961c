"""Initial plastic strain of a von Mises material (issue 18), for
tests/integration/initial_plastic_strain.sh.

A unit cube of 3 x 3 x 3 C3D8 elements (E = 210000, nu = 0.3, *PLASTIC 800 at 0 to 1600 at
0.1: isotropic hardening H = 8000) on rollers on the planes x = 0, y = 0, z = 0 and held at
u_x = 0 on x = 1 starts from the deviatoric plastic strain eps_0 = (e, -e/2, -e/2, 0, 0, 0),
e = 3e-3, given point by point (*INITIAL CONDITIONS, TYPE=PLASTIC STRAIN, as CalculiX). As in
CalculiX the plastic strain is a strain the material does not resist and it does not harden
(PEEQ starts at 0), so the closed forms (small strain, uniform state) are

  step 1 (held):  s_xx = -E e, s_yy = s_zz = 0, u_y = (nu - 1/2) e y (same for z), PEEQ = 0;
  step 2 (x = 1 pulled to u_x = d = 0.01): elastic from -E e until s_xx = s_y = 800 at
      eps_xx = (s_y + E e) / E, then s_xx = s_y + E H / (E + H) (d - (s_y + E e) / E),
      PEEQ = (s_xx - s_y) / H, u_y = (-e/2 - PEEQ/2 - nu s_xx / E) y.

Had the initial plastic strain hardened the material (PEEQ = e at the start), step 2 would
yield at 824 instead of 800. Tolerance: 2e-6 of the largest value of each quantity, the
print precision of the .dat tables (7 significant digits); the solution itself is exact to
round-off (linear hardening, proportional loading, the yield event lands on the surface).
"""

import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import datfile  # noqa: E402
from initial_state import mesh, nid, N  # noqa: E402

FCS3D = os.environ.get('FCS3D', 'fcs3d')
E, NU, SY, H = 210000.0, 0.3, 800.0, 8000.0
STRAIN, PULL = 3e-3, 0.01
TOL = 2e-6


def deck():
    lines, centres = mesh()
    x1 = [nid(N, j, k) for k in range(N + 1) for j in range(N + 1)]
    lines.append('*NSET, NSET=X1')
    for c in range(0, len(x1), 8):
        lines.append(', '.join(map(str, x1[c:c + 8])))
    lines += ['*MATERIAL, NAME=STEEL', '*ELASTIC', '%g, %g' % (E, NU),
              '*PLASTIC', '%g, 0.' % SY, '%g, 0.1' % (SY + 0.1 * H),
              '*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL',
              '*INITIAL CONDITIONS, TYPE=PLASTIC STRAIN']
    for e in sorted(centres):
        for q in range(1, 9):
            lines.append('%d, %d, %g, %g, %g, 0., 0., 0.' % (e, q, STRAIN, -STRAIN / 2, -STRAIN / 2))
    lines += ['*BOUNDARY', 'X0, 1, 1', 'Y0, 2, 2', 'Z0, 3, 3']
    for value in (0.0, PULL):
        lines += ['*STEP', '*STATIC', '*BOUNDARY', 'X1, 1, 1, %g' % value,
                  '*NODE PRINT, NSET=NALL', 'U', '*EL PRINT, ELSET=EALL', 'S, PEEQ', '*END STEP']
    return '\n'.join(lines) + '\n'


def expected(step):
    """s_xx, PEEQ and the lateral strain u_y / y at the end of step 1 or 2 (closed forms)."""
    if step == 1:
        s = -E * STRAIN
        peeq = 0.0
    else:
        yield_strain = (SY + E * STRAIN) / E
        s = SY + E * H / (E + H) * (PULL - yield_strain)
        peeq = (s - SY) / H
    return s, peeq, -STRAIN / 2 - peeq / 2 - NU * s / E


def coordinates():
    """Reference coordinates of every node, from the deck's *NODE lines."""
    xyz = {}
    for k in range(N + 1):
        for j in range(N + 1):
            for i in range(N + 1):
                xyz[nid(i, j, k)] = (i / N, j / N, k / N)
    return xyz


def main():
    work = sys.argv[1] if len(sys.argv) > 1 else '.'
    os.makedirs(work, exist_ok=True)
    with open(os.path.join(work, 'cube.inp'), 'w') as f:
        f.write(deck())
    p = subprocess.run([FCS3D, '-q', 'cube.inp'], cwd=work, capture_output=True, text=True,
                       timeout=600)
    if p.returncode != 0:
        print('fcs3d exit %d: %s' % (p.returncode, p.stderr))
        return 1
    blocks = datfile.read_blocks(os.path.join(work, 'cube.dat'))
    xyz = coordinates()
    failures = 0
    for step in (1, 2):
        s_xx, peeq, lateral = expected(step)
        at = [b for b in blocks if abs(b.time - step) < 1e-9]
        stress = [b for b in at if b.kind == 'stresses'][0].values()
        plastic = [b for b in at if b.kind == 'equivalent'][0].values()
        u = [b for b in at if b.kind == 'displacements'][0]
        want = [s_xx, 0.0, 0.0, 0.0, 0.0, 0.0]
        errors = {
            'stress: largest |s - closed form| / |s_xx|':
                max(abs(row[c] - want[c]) for row in stress for c in range(6)) / abs(s_xx),
            'PEEQ: largest |PEEQ - closed form| / max(PEEQ, e)':
                max(abs(row[0] - peeq) for row in plastic) / max(peeq, STRAIN),
            'u: largest |u - closed form| / |u_y(1)|':
                max(max(abs(u.rows[key][0] - (PULL if step == 2 else 0.0) * xyz[key[0]][0]),
                        abs(u.rows[key][1] - lateral * xyz[key[0]][1]),
                        abs(u.rows[key][2] - lateral * xyz[key[0]][2])) for key in u.order)
                / abs(lateral),
        }
        print('step %d: closed form s_xx %.6g, PEEQ %.6g, lateral strain %.6g' % (step, s_xx, peeq,
                                                                                  lateral))
        for what, error in errors.items():
            ok = error <= TOL
            failures += not ok
            print('  %-62s %.1e  %s' % (what, error, 'ok' if ok else 'FAIL'))
    print('%d failure(s)' % failures)
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
