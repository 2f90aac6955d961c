"""Anisotropic elasticity (issue 17, item 4), for tests/integration/anisotropic_block.sh.

An orthotropic unit cube of 2 x 2 x 2 C3D8 elements, its material axes turned out of the
global ones by an *ORIENTATION, under uniaxial stress sigma along global x (a pressure -sigma on
the face x = 1). Supported so that every uniform strain is free: u_x = 0 on x = 0, u_y = u_z = 0
at the origin, u_z = 0 at (0, 1, 0) (the displacement u_x = e_xx x, u_y = g_xy x + e_yy y +
g_yz z, u_z = g_xz x + e_zz z meets them). The closed form: the stress is sigma e_x e_x
everywhere, in the material axes sigma_local = A^T sigma A; the strain there is
eps_local = S sigma_local with S the orthotropic compliance of the engineering constants
(S11 = 1/E1, S12 = -nu12/E1, ..., S44 = 1/G12), and in global axes eps = A eps_local A^T. The
uniform field is in the element's space, so the only error is the print precision of the .dat
file (7 significant digits): tolerance 1e-6 of the largest component.

The same material is given four ways, each of which must give the closed form:
  engineering  TYPE=ENGINEERING CONSTANTS with the orientation by two vectors a, b;
  rotation     the same, with the orientation as the global axes turned by a rotation line
               (local axis 3, angle) and then tilted: a, b are the turned axes;
  ortho        TYPE=ORTHO with D = S^-1 (D1111 ... D2323), orientation a, b;
  aniso        TYPE=ANISO with the 21 constants of the global stiffness T D T^T in CalculiX's
               order, no orientation.
*EL PRINT with GLOBAL=YES prints sigma e_x e_x; with GLOBAL=NO (the default) it prints
sigma_local followed by the orientation's name (elements with an orientation).
"""

import math
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import datfile  # noqa: E402

FCS3D = os.environ.get('FCS3D', 'fcs3d')
N = 2
SIGMA = 10.0
# E1, E2, E3, nu12, nu13, nu23, G12, G13, G23
ENGINEERING = [100.0e3, 20.0e3, 10.0e3, 0.3, 0.25, 0.4, 8.0e3, 6.0e3, 4.0e3]
A_VECTOR = np.array([1.0, 0.6, -0.3])
B_VECTOR = np.array([-0.2, 1.0, 0.5])
ANGLE = 30.0
TOL = 1e-6


def axes_of(a, b):
    """Columns e1, e2, e3 of a rectangular *ORIENTATION (ccx manual: e1 along a, e2 the part
    of b normal to it, e3 = e1 x e2)."""
    e1 = a / np.linalg.norm(a)
    e2 = b - (b @ e1) * e1
    e2 /= np.linalg.norm(e2)
    return np.column_stack([e1, e2, np.cross(e1, e2)])


def turned(axes, axis, angle):
    """The axes turned by `angle` degrees about their own axis `axis` (1..3), right-handed."""
    n = axes[:, axis - 1]
    t = math.radians(angle)
    k = np.array([[0.0, -n[2], n[1]], [n[2], 0.0, -n[0]], [-n[1], n[0], 0.0]])
    r = np.eye(3) + math.sin(t) * k + (1.0 - math.cos(t)) * (k @ k)
    return r @ axes


def compliance():
    e1, e2, e3, n12, n13, n23, g12, g13, g23 = ENGINEERING
    s = np.zeros((6, 6))
    s[:3, :3] = [[1 / e1, -n12 / e1, -n13 / e1], [-n12 / e1, 1 / e2, -n23 / e2],
                 [-n13 / e1, -n23 / e2, 1 / e3]]
    s[3, 3], s[4, 4], s[5, 5] = 1 / g12, 1 / g13, 1 / g23
    return s


def tensor(v, engineering):
    f = 0.5 if engineering else 1.0
    return np.array([[v[0], f * v[3], f * v[4]], [f * v[3], v[1], f * v[5]],
                     [f * v[4], f * v[5], v[2]]])


def voigt(t, engineering):
    f = 2.0 if engineering else 1.0
    return np.array([t[0, 0], t[1, 1], t[2, 2], f * t[0, 1], f * t[0, 2], f * t[1, 2]])


def global_strain(stress, axes):
    """Engineering strain in global axes of a global stress (the closed form)."""
    local = voigt(axes.T @ tensor(stress, False) @ axes, False)
    return voigt(axes @ tensor(compliance() @ local, True) @ axes.T, True)


def global_stiffness(axes):
    """The 6 x 6 global stiffness (engineering shear) of the material in `axes`."""
    s = np.column_stack([global_strain(np.eye(6)[j], axes) for j in range(6)])
    return np.linalg.inv(s)


def nid(i, j, k):
    return 1 + i + (N + 1) * (j + (N + 1) * k)


def mesh():
    lines = ['*NODE, NSET=NALL']
    for k in range(N + 1):
        for j in range(N + 1):
            for i in range(N + 1):
                lines.append('%d, %.12g, %.12g, %.12g' % (nid(i, j, k), i / N, j / N, k / N))
    lines.append('*ELEMENT, TYPE=C3D8, ELSET=EALL')
    e = 0
    loaded = []
    for k in range(N):
        for j in range(N):
            for i in range(N):
                e += 1
                lines.append('%d, %s' % (e, ', '.join(map(str, [
                    nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k),
                    nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1),
                    nid(i, j + 1, k + 1)]))))
                if i == N - 1:
                    loaded.append(e)
    x0 = [nid(0, j, k) for k in range(N + 1) for j in range(N + 1)]
    x1 = [nid(N, j, k) for k in range(N + 1) for j in range(N + 1)]
    lines += ['*NSET, NSET=X0', ', '.join(map(str, x0)), '*NSET, NSET=X1', ', '.join(map(str, x1)),
              '*ELSET, ELSET=EX1', ', '.join(map(str, loaded))]
    return lines


def numbers(values, per_line=8):
    text = ['%.15g' % v for v in values]
    return [', '.join(text[i:i + per_line]) + (',' if i + per_line < len(text) else '')
            for i in range(0, len(text), per_line)]


def deck(case, axes):
    lines = mesh()
    orientation = True
    if case == 'engineering':
        lines += ['*ORIENTATION, NAME=AXES', numbers(list(A_VECTOR) + list(B_VECTOR))[0]]
        material = ['*ELASTIC, TYPE=ENGINEERING CONSTANTS'] + numbers(ENGINEERING)
    elif case == 'rotation':
        # The axes of a, b, turned by ANGLE about their local axis 3 (the second line).
        base = axes_of(A_VECTOR, B_VECTOR)
        lines += ['*ORIENTATION, NAME=AXES', numbers(list(base[:, 0]) + list(base[:, 1]))[0],
                  '3, %g' % ANGLE]
        material = ['*ELASTIC, TYPE=ENGINEERING CONSTANTS'] + numbers(ENGINEERING)
    elif case == 'ortho':
        d = np.linalg.inv(compliance())
        lines += ['*ORIENTATION, NAME=AXES', numbers(list(A_VECTOR) + list(B_VECTOR))[0]]
        material = ['*ELASTIC, TYPE=ORTHO'] + numbers(
            [d[0, 0], d[0, 1], d[1, 1], d[0, 2], d[1, 2], d[2, 2], d[3, 3], d[4, 4], d[5, 5]])
    else:
        c = global_stiffness(axes)
        upper = [c[i, j] for j in range(6) for i in range(j + 1)]
        material = ['*ELASTIC, TYPE=ANISO'] + numbers(upper)
        orientation = False
    lines += ['*MATERIAL, NAME=ROCK'] + material
    lines.append('*SOLID SECTION, ELSET=EALL, MATERIAL=ROCK' + (', ORIENTATION=AXES'
                                                                 if orientation else ''))
    lines += ['*BOUNDARY', 'X0, 1, 1', '%d, 2, 3' % nid(0, 0, 0), '%d, 3, 3' % nid(0, N, 0),
              '*STEP', '*STATIC', '*DLOAD', 'EX1, P4, %g' % -SIGMA,
              '*NODE PRINT, NSET=X1', 'U', '*EL PRINT, ELSET=EALL, GLOBAL=YES', 'S, E',
              '*EL PRINT, ELSET=EALL', 'S', '*END STEP']
    return '\n'.join(lines) + '\n'


def run(directory, text):
    os.makedirs(directory, exist_ok=True)
    with open(os.path.join(directory, 'block.inp'), 'w') as f:
        f.write(text)
    p = subprocess.run([FCS3D, '-q', 'block.inp'], cwd=directory, capture_output=True,
                       text=True, timeout=600)
    if p.returncode != 0:
        print('fcs3d exit %d: %s %s' % (p.returncode, p.stdout, p.stderr))
        return None, None
    with open(os.path.join(directory, 'block.dat')) as f:
        text = f.read()
    return datfile.read_blocks(os.path.join(directory, 'block.dat')), text


def report(what, error, failures):
    ok = error <= TOL
    print('%-72s %.1e  %s' % (what, error, 'ok' if ok else 'FAIL'))
    return failures + (not ok)


def check(case, work, failures):
    axes = axes_of(A_VECTOR, B_VECTOR)
    if case == 'rotation':
        axes = turned(axes, 3, ANGLE)
    blocks, text = run(os.path.join(work, case), deck(case, axes))
    if blocks is None:
        return failures + 1
    stress = np.array([SIGMA, 0, 0, 0, 0, 0])
    strain = global_strain(stress, axes)
    tensor_strain = voigt(tensor(strain, True), False)
    scale = abs(strain).max()
    u = [b for b in blocks if b.kind == 'displacements'][-1].values()
    s_global, s_local = [b.values() for b in blocks if b.kind == 'stresses']
    e_global = [b for b in blocks if b.kind == 'strains'][-1].values()
    failures = report('%s: |E - closed form| / |E| at every point' % case,
                      abs(e_global - tensor_strain).max() / scale, failures)
    failures = report('%s: |u_x(x = 1) - e_xx| / |E|' % case,
                      abs(u[:, 0] - strain[0]).max() / scale, failures)
    failures = report('%s: GLOBAL=YES |S - sigma e_x e_x| / sigma' % case,
                      abs(s_global - stress).max() / SIGMA, failures)
    if case != 'aniso':
        local = voigt(axes.T @ tensor(stress, False) @ axes, False)
        failures = report('%s: GLOBAL=NO |S - A^T sigma A| / sigma' % case,
                          abs(s_local - local).max() / SIGMA, failures)
        named = sum(1 for line in text.splitlines() if line.rstrip().endswith(' AXES'))
        failures = report('%s: GLOBAL=NO rows end with the orientation name (8 x 8 rows)' % case,
                          0.0 if named == N**3 * 8 else 1.0, failures)
    else:
        failures = report('aniso: GLOBAL=NO without orientation prints global S',
                          abs(s_local - stress).max() / SIGMA, failures)
    return failures


def main():
    work = sys.argv[1] if len(sys.argv) > 1 else '.'
    failures = 0
    for case in ['engineering', 'rotation', 'ortho', 'aniso']:
        failures = check(case, work, failures)
    print('%d failure(s)' % failures)
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
