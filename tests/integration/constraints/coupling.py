"""*COUPLING with *KINEMATIC and *DISTRIBUTING (issue 17) on a prism 2 x 1 x 1 of C3D8 (4 x 2 x 2,
graded across so that the nodal areas of the end face differ).

    coupling.py deck JOB.inp CASE        CASE: kinematic, kinematic_nlgeom, distributing
    coupling.py check JOB CASE

The face x = 0 is on rollers (u_x = 0, the rigid-body modes held at three nodes), the end face
x = 2 is the coupled element-face surface, E = 1000.

kinematic: nu = 0; reference node 1000 at the end face's centre, *KINEMATIC 1, 3; fcs3d
generates the rotation node 1001 (the next node number, as CalculiX); F = 10 in x on the
reference node, theta_z = 1e-3 prescribed as CalculiX's degree of freedom 6 of the reference
node (held by the rotation node). Checked: every end-face node
moves as u_ref + theta x (x - x_ref) (the face stays rigid) to 1e-6 of the largest
displacement (7-digit print); RF at the reference node (the force the face transmits) = F and
= the sum of RF over the end-face nodes (their internal forces, the face's internal force),
1e-6 relative; RF at the rotation node balances the moment of the support reactions about the
reference node (1e-6 of the sum of the moments' magnitudes: 7-digit print).
kinematic_nlgeom: as kinematic with NLGEOM and theta_z = 0.2 (prescribed on node 1001): the end face moves with the finite
rotation x = x_ref + u_ref + C(theta) (X - X_ref) (Rodrigues) to 1e-6 of the largest
displacement.
distributing: nu = 0.3; reference node 1000 at (2.5, 0.5, 0.5), off the body, *DISTRIBUTING
1, 3; F = 10 in x on the reference node. The force is spread in proportion to the nodal
areas, which are the consistent nodal forces of the uniform traction F/A: the exact
solution is the uniform stress s_xx = F/A (patch test, C3D8 exact): every stress component
within 1e-6 F/A (print), u_x of the end face F L / (E A) (1e-6); and u of the reference
node = the area-weighted mean of the end face's displacements (weights computed here from
the face grid, trapezoidal: 1e-6 of the largest displacement).
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'contact'))
import contact_common as cc  # noqa: E402

YOUNG = 1000.0
FORCE = 10.0
LENGTH = 2.0
REF, ROT = 1000, 1001
YS = [0.0, 0.3, 1.0]
ZS = [0.0, 0.6, 1.0]
THETA = {'kinematic': 1e-3, 'kinematic_nlgeom': 0.2}
CASES = ['kinematic', 'kinematic_nlgeom', 'distributing']


def prism():
    return cc.Box(np.linspace(0, LENGTH, 5), YS, ZS)


def at(box, x, y, z):
    nodes = box.nodes_where(lambda px, py, pz: abs(px - x) < 1e-9 and abs(py - y) < 1e-9 and
                            abs(pz - z) < 1e-9)
    assert len(nodes) == 1
    return nodes[0]


def make_deck(path, case):
    box = prism()
    kinematic = case.startswith('kinematic')
    nu = 0.0 if kinematic else 0.3
    lines = ['*HEADING', 'Coupling %s (tests/integration/constraints/coupling.py)' % case]
    lines += box.mesh_cards('PRISM')
    lines += cc.nset_cards('ROLLER', box.face_nodes(0, 0))
    lines += cc.nset_cards('END', box.face_nodes(0, 1))
    lines += cc.face_surface_cards('ENDS', box, 0, 1)
    ref_x = LENGTH if kinematic else LENGTH + 0.5
    lines += ['*NODE', '%d, %g, 0.5, 0.5' % (REF, ref_x)]
    lines += ['*COUPLING, REF NODE=%d, SURFACE=ENDS, CONSTRAINT NAME=C1' % REF]
    lines += ['*KINEMATIC', '1, 3'] if kinematic else ['*DISTRIBUTING', '1, 3']
    lines += cc.material_cards('MAT', 'PRISM', YOUNG, nu)
    lines += ['*STEP, NLGEOM' if case == 'kinematic_nlgeom' else '*STEP', '*STATIC',
              '0.25, 1.' if case == 'kinematic_nlgeom' else '1., 1.',
              '*BOUNDARY', 'ROLLER, 1, 1', '%d, 2, 3' % at(box, 0, 0, 0), '%d, 3, 3' % at(box, 0, 1, 0),
              '%d, 2, 2' % at(box, 0, 0, 1)]
    if case == 'kinematic':
        # CalculiX's way: degree of freedom 6 of the reference node is its rotation about z.
        lines += ['%d, 6, 6, %.12g' % (REF, THETA[case])]
    elif kinematic:
        lines += ['%d, 3, 3, %.12g' % (ROT, THETA[case])]
    lines += ['*CLOAD', '%d, 1, %.12g' % (REF, FORCE)]
    lines += ['*NODE PRINT, NSET=END', 'U, RF', '*NODE PRINT, NSET=ROLLER', 'RF',
              '*EL PRINT, ELSET=PRISM', 'S']
    lines += cc.nset_cards('PIVOTS', [REF, ROT] if kinematic else [REF])
    lines += ['*NODE PRINT, NSET=PIVOTS', 'U, RF', '*END STEP']
    # The node set PIVOTS must come before the step: move it up.
    step = lines.index('*STEP, NLGEOM' if case == 'kinematic_nlgeom' else '*STEP')
    pivots = lines.index('*NSET, NSET=PIVOTS')
    lines = lines[:step] + lines[pivots:pivots + 2] + lines[step:pivots] + lines[pivots + 2:]
    cc.write_deck(path, lines)


def table(blocks, title, set_name):
    rows = [b for b in blocks if b['title'].startswith(title) and (b['set'] or '').upper() == set_name]
    return {k[0]: v for k, v in rows[-1]['rows']}


def rodrigues(w):
    t = np.linalg.norm(w)
    k = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
    if t == 0:
        return np.eye(3)
    return np.eye(3) + np.sin(t) / t * k + (1 - np.cos(t)) / t**2 * k @ k


def nodal_areas(box):
    """Trapezoidal nodal areas of the end face (bilinear faces on a rectangular grid)."""
    def weights(c):
        w = np.zeros(len(c))
        for i in range(len(c) - 1):
            w[i] += 0.5 * (c[i + 1] - c[i])
            w[i + 1] += 0.5 * (c[i + 1] - c[i])
        return w
    wy, wz = weights(YS), weights(ZS)
    return {at(box, LENGTH, y, z): wy[j] * wz[k] for j, y in enumerate(YS) for k, z in enumerate(ZS)}


def check(job, case):
    checker = cc.Checker()
    box = prism()
    blocks = cc.read_dat(job + '.dat')
    u = table(blocks, 'displacements', 'END')
    pivots = table(blocks, 'displacements', 'PIVOTS')
    forces = table(blocks, 'forces', 'PIVOTS')
    scale = max(np.abs(v).max() for v in u.values())
    if case.startswith('kinematic'):
        ref_u, theta = pivots[REF], pivots[ROT]
        checker.relative('rotation node theta_z = prescribed', theta[2], THETA[case], 1e-6)
        x_ref = np.array([LENGTH, 0.5, 0.5])
        if case == 'kinematic':
            motion = {n: ref_u + np.cross(theta, box.coordinates(n) - x_ref) for n in u}
        else:
            c = rodrigues(theta)
            motion = {n: ref_u + c @ (box.coordinates(n) - x_ref) - (box.coordinates(n) - x_ref)
                      for n in u}
        worst = max(np.abs(u[n] - motion[n]).max() for n in u)
        checker.check(worst <= 1e-6 * scale, 'end face moves rigidly with the reference and '
                      'rotation nodes: largest deviation %.2e (tolerance 1e-6 of %.3e, print)'
                      % (worst, scale))
        if case == 'kinematic':
            checker.relative('RF at the reference node = F (transmitted force)', forces[REF][0],
                             FORCE, 1e-6)
            face = sum(v for v in table(blocks, 'forces', 'END').values())
            checker.relative('RF at the reference node = sum of the end-face internal forces',
                             forces[REF][0], face[0], 1e-6)
            roller = table(blocks, 'forces', 'ROLLER')
            moment, size = np.zeros(3), 0.0
            for n, f in roller.items():
                moment += np.cross(box.coordinates(n) - x_ref, f)
                size += abs(np.cross(box.coordinates(n) - x_ref, f)[2])
            # Each printed reaction has 7 digits: the tolerance is 1e-6 of the sum of the
            # magnitudes of the moments that cancel.
            checker.relative('RF moment_z at the rotation node + moment of the support reactions '
                             'about the reference node = 0', forces[ROT][2] + moment[2], 0.0, 1e-6,
                             scale=size + abs(forces[ROT][2]))
            checker.check(abs(forces[ROT][2]) > 0.0, 'the prescribed rotation needs a moment '
                          '(%.4g)' % forces[ROT][2])
    else:
        area = 1.0
        stress = [b for b in blocks if b['title'].startswith('stresses')][-1]
        exact = np.array([FORCE / area, 0, 0, 0, 0, 0])
        worst = max(np.abs(v - exact).max() for _, v in stress['rows'])
        checker.check(worst <= 1e-6 * FORCE, 'uniform s_xx = F/A, others 0, at every integration '
                      'point: largest error %.2e (tolerance 1e-6 F/A, print)' % worst)
        ux = np.array([v[0] for v in u.values()])
        expected = FORCE * LENGTH / (YOUNG * area)
        checker.check(np.abs(ux - expected).max() <= 1e-6 * expected,
                      'end face u_x = F L / (E A) at all %d nodes (1e-6 relative)' % len(ux))
        weights = nodal_areas(box)
        mean = sum(weights[n] * u[n] for n in u) / sum(weights.values())
        gap = np.abs(pivots[REF] - mean).max()
        checker.check(gap <= 1e-6 * scale, 'u of the reference node = area-weighted mean of the '
                      'end face: largest difference %.2e (tolerance 1e-6 of %.3e)' % (gap, scale))
        lateral = max(abs(v[1]) for v in u.values())
        checker.check(lateral > 1e-3 * scale, 'the lateral contraction moves the face nodes '
                      'apart (|u_y| up to %.3e), so the weights matter' % lateral)
    checker.finish()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    sub = parser.add_subparsers(dest='command', required=True)
    d = sub.add_parser('deck')
    d.add_argument('path')
    d.add_argument('case', choices=CASES)
    c = sub.add_parser('check')
    c.add_argument('job')
    c.add_argument('case', choices=CASES)
    args = parser.parse_args()
    if args.command == 'deck':
        make_deck(args.path, args.case)
    else:
        check(args.job, args.case)


if __name__ == '__main__':
    main()
