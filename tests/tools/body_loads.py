"""Body loads (*DLOAD GRAV, CENTRIF) and the lithostatic pre-stress (issue 17, items 1 and 3),
for tests/integration/body_loads.sh.

1. A column 1 x 1 x H (H = 3) of 2 x 2 x 6 C3D8, on rollers on its four sides and its base,
   under gravity g along -z (GRAV, ramped over the step): uniaxial strain. The consistent
   nodal loads make the nodal displacements of this one-dimensional problem exact, so the
   strain of each element (constant in it) is the mean of the exact one, and its stress the
   exact stress at its mid-height:  szz = -rho g (H - z_c), sxx = syy = nu / (1 - nu) szz;
   the reaction of the base is the weight rho g H. Tolerance: round-off (1e-9), and 1e-6 for
   stresses read back from the .dat file (7 significant digits).
2. The same column starting from the lithostatic stress *INITIAL CONDITIONS, TYPE=STRESS,
   GEOSTATIC (szz = 0 at z = H, -rho g H at z = 0, k = nu / (1 - nu)) with gravity held from
   the start (an amplitude at 1): the stress solves the equilibrium equations and the
   boundary conditions exactly, and 2 x 2 x 2 Gauss points integrate its internal forces
   exactly (B^T sigma is at most quadratic per direction), so the column stays put:
   |u| below 1e-9 of the displacement gravity alone gives, the stress unchanged.
3. A rotating annular disk (inner radius a = 0.25, outer b = 1, thickness 0.05), a quarter
   meshed in polar rings (n_r x n_theta x 1 C3D8; rollers on the symmetry planes and on the
   base z = 0), under CENTRIF about the z axis: the plane-stress solution (Timoshenko &
   Goodier, section 32):
     u_r(r) = r / E (s_t - nu s_r),
     s_r = (3 + nu)/8 rho w^2 (a^2 + b^2 - a^2 b^2 / r^2 - r^2),
     s_t = (3 + nu)/8 rho w^2 (a^2 + b^2 + a^2 b^2 / r^2 - (1 + 3 nu)/(3 + nu) r^2).
   The error of u_r at the inner and outer rims is measured on three meshes (each halving
   h): the straight-sided elements miss the circle by O(h^2) and the trilinear field is
   second-order accurate, so each error must shrink by a factor of at least 3 (4 in the
   limit) and the finest stay below 0.5 %.
"""

import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import datfile  # noqa: E402

FCS3D = os.environ.get('FCS3D', 'fcs3d')
E, NU, RHO, G = 1.0e9, 0.25, 2000.0, 10.0
H, NX, NZ = 3.0, 2, 6
TOL = 1e-9
# Values read back from the .dat file carry its 7 significant digits: 1e-6 relative.
PRINTED = 1e-6


def write_run(directory, job, lines):
    os.makedirs(directory, exist_ok=True)
    with open(os.path.join(directory, job + '.inp'), 'w') as f:
        f.write('\n'.join(lines) + '\n')
    p = subprocess.run([FCS3D, '-q', job + '.inp'], cwd=directory, capture_output=True,
                       text=True, timeout=600)
    if p.returncode != 0:
        print('%s: fcs3d exit %d: %s' % (job, p.returncode, p.stderr))
        return None
    return datfile.read_blocks(os.path.join(directory, job + '.dat'))


def brick_lines(coords, n1, n2, n3):
    """Nodes and C3D8 of a structured block; coords(i, j, k) gives the node position."""
    def nid(i, j, k):
        return 1 + i + (n1 + 1) * (j + (n2 + 1) * k)
    lines = ['*NODE, NSET=NALL']
    for k in range(n3 + 1):
        for j in range(n2 + 1):
            for i in range(n1 + 1):
                lines.append('%d, %.15g, %.15g, %.15g' % ((nid(i, j, k),) + coords(i, j, k)))
    lines.append('*ELEMENT, TYPE=C3D8, ELSET=EALL')
    e = 0
    for k in range(n3):
        for j in range(n2):
            for i in range(n1):
                e += 1
                n = [nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k),
                     nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1),
                     nid(i, j + 1, k + 1)]
                lines.append('%d, %s' % (e, ', '.join(map(str, n))))
    return lines, nid


def nset(name, members):
    out = ['*NSET, NSET=' + name]
    for c in range(0, len(members), 8):
        out.append(', '.join(map(str, members[c:c + 8])))
    return out


def column_deck(geostatic):
    lines, nid = brick_lines(lambda i, j, k: (i / NX, j / NX, H * k / NZ), NX, NX, NZ)
    every = [(i, j, k) for k in range(NZ + 1) for j in range(NX + 1) for i in range(NX + 1)]
    lines += nset('XS', [nid(*p) for p in every if p[0] in (0, NX)])
    lines += nset('YS', [nid(*p) for p in every if p[1] in (0, NX)])
    lines += nset('BASE', [nid(*p) for p in every if p[2] == 0])
    lines += ['*MATERIAL, NAME=ROCK', '*ELASTIC', '%g, %g' % (E, NU), '*DENSITY', '%g' % RHO,
              '*SOLID SECTION, ELSET=EALL, MATERIAL=ROCK']
    k0 = NU / (1 - NU)
    if geostatic:
        lines += ['*INITIAL CONDITIONS, TYPE=STRESS, GEOSTATIC',
                  'EALL, 0., %g, %g, 0., %.15g, %.15g' % (H, -RHO * G * H, k0, k0)]
    lines += ['*BOUNDARY', 'XS, 1, 1', 'YS, 2, 2', 'BASE, 3, 3',
              '*AMPLITUDE, NAME=HOLD', '0., 1., 1., 1.',
              '*STEP', '*STATIC', '0.5, 1.',
              '*DLOAD' + (', AMPLITUDE=HOLD' if geostatic else ''), 'EALL, GRAV, %g, 0., 0., -1.' % G,
              '*NODE PRINT, NSET=NALL', 'U', '*NODE PRINT, NSET=BASE, TOTALS=ONLY', 'RF',
              '*EL PRINT, ELSET=EALL', 'S', '*END STEP']
    return lines


def element_centre_z(e):
    layer = (e - 1) // (NX * NX)
    return H * (layer + 0.5) / NZ


def check_columns(work):
    failures = 0
    weight = RHO * G * H
    blocks = write_run(os.path.join(work, 'column'), 'column', column_deck(False))
    if blocks is None:
        return 1
    stress = [b for b in blocks if b.kind == 'stresses'][-1]
    worst = 0.0
    for (e, q), row in stress.rows.items():
        szz = -RHO * G * (H - element_centre_z(e))
        expected = (NU / (1 - NU) * szz, NU / (1 - NU) * szz, szz, 0.0, 0.0, 0.0)
        worst = max(worst, max(abs(a - b) for a, b in zip(row, expected)) / weight)
    failures += report('column: largest |sigma - sigma(z_c)| / (rho g H) (printed digits)',
                       worst, PRINTED)
    rf = [b for b in blocks if b.kind == 'total'][-1].values()[0]
    failures += report('column: base reaction %.6e against the weight %.6e, rel. error'
                       % (rf[2], weight), abs(rf[2] - weight) / weight)
    u_gravity = max(abs(v[2]) for v in [b for b in blocks if b.kind == 'displacements'][-1]
                    .rows.values())

    blocks = write_run(os.path.join(work, 'geostatic'), 'column', column_deck(True))
    if blocks is None:
        return failures + 1
    u = max(abs(v).max() for v in [b for b in blocks if b.kind == 'displacements'][-1]
            .rows.values())
    failures += report('geostatic + gravity: largest |u| / (u_z of gravity alone)', u / u_gravity)
    stress = [b for b in blocks if b.kind == 'stresses'][-1]
    worst = 0.0
    offset = 0.5 * H / NZ / math.sqrt(3.0)
    for (e, q), row in stress.rows.items():
        # CalculiX's 2x2x2 order: points 1-4 at the lower zeta, 5-8 at the upper.
        z = element_centre_z(e) + (offset if q > 4 else -offset)
        szz = -RHO * G * (H - z)
        expected = (NU / (1 - NU) * szz, NU / (1 - NU) * szz, szz, 0.0, 0.0, 0.0)
        worst = max(worst, max(abs(a - b) for a, b in zip(row, expected)) / weight)
    failures += report('geostatic + gravity: largest |sigma - sigma(z)| / (rho g H) (printed)',
                       worst, PRINTED)
    return failures


def report(what, error, tolerance=TOL):
    ok = error <= tolerance
    print('%-78s %.2e  %s' % (what, error, 'ok' if ok else 'FAIL'))
    return 0 if ok else 1


A, B, T, OMEGA2 = 0.25, 1.0, 0.05, 1.0e4


def disk_u(r):
    c = (3 + NU) / 8 * RHO * OMEGA2
    s_r = c * (A * A + B * B - A * A * B * B / (r * r) - r * r)
    s_t = c * (A * A + B * B + A * A * B * B / (r * r) - (1 + 3 * NU) / (3 + NU) * r * r)
    return r / E * (s_t - NU * s_r)


def disk_deck(n_r, n_t):
    def coords(i, j, k):
        r = A + (B - A) * i / n_r
        t = 0.5 * math.pi * j / n_t
        return (r * math.cos(t), r * math.sin(t), T * k)
    lines, nid = brick_lines(coords, n_r, n_t, 1)
    every = [(i, j, k) for k in range(2) for j in range(n_t + 1) for i in range(n_r + 1)]
    lines += nset('Y0', [nid(*p) for p in every if p[1] == 0])
    lines += nset('X0', [nid(*p) for p in every if p[1] == n_t])
    lines += nset('BASE', [nid(*p) for p in every if p[2] == 0])
    lines += nset('INNER', [nid(*p) for p in every if p[0] == 0])
    lines += nset('OUTER', [nid(*p) for p in every if p[0] == n_r])
    lines += ['*MATERIAL, NAME=STEEL', '*ELASTIC', '%g, %g' % (E, NU), '*DENSITY', '%g' % RHO,
              '*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL',
              '*BOUNDARY', 'Y0, 2, 2', 'X0, 1, 1', 'BASE, 3, 3',
              '*STEP', '*STATIC',
              '*DLOAD', 'EALL, CENTRIF, %g, 0., 0., 0., 0., 0., 1.' % OMEGA2,
              '*NODE PRINT, NSET=INNER', 'U', '*NODE PRINT, NSET=OUTER', 'U', '*END STEP']
    return lines


def check_disk(work):
    failures = 0
    errors = []
    print('rotating disk, u_r at the rims against the plane-stress solution:')
    print('  n_r x n_theta   u_r(a) rel. error   u_r(b) rel. error')
    for n_r, n_t in [(4, 6), (8, 12), (16, 24)]:
        blocks = write_run(os.path.join(work, 'disk_%d' % n_r), 'disk', disk_deck(n_r, n_t))
        if blocks is None:
            return 1
        displacement = [b for b in blocks if b.kind == 'displacements']
        rims = []
        for block, radius in [(displacement[-2], A), (displacement[-1], B)]:
            # The nodes on the x axis (theta = 0): u_r = u_x.
            u_r = [v[0] for v in block.rows.values() if abs(v[1]) < 1e-30]
            rims.append(abs(sum(u_r) / len(u_r) - disk_u(radius)) / abs(disk_u(radius)))
        errors.append(rims)
        print('  %3d x %3d       %.3e           %.3e' % (n_r, n_t, rims[0], rims[1]))
    for side, name in [(0, 'inner'), (1, 'outer')]:
        for k in range(2):
            ratio = errors[k][side] / max(errors[k + 1][side], 1e-300)
            ok = ratio >= 3.0
            print('%-78s %.2f  %s' % ('disk: %s rim, error ratio from mesh %d to %d (>= 3)' % (
                name, k + 1, k + 2), ratio, 'ok' if ok else 'FAIL'))
            failures += not ok
        failures += report('disk: %s rim, finest error (<= 5e-3)' % name, errors[2][side], 5e-3)
    return failures


def main():
    work = sys.argv[1] if len(sys.argv) > 1 else '.'
    failures = check_columns(work) + check_disk(work)
    print('%d failure(s)' % failures)
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
