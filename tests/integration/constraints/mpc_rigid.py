"""*MPC PLANE / STRAIGHT and *RIGID BODY (issue 17) on a prism 2 x 1 x 1 of 4 x 2 x 2 C3D8.

    mpc_rigid.py deck JOB.inp CASE        CASE: plane, plane_offset, rigid
    mpc_rigid.py check JOB CASE

plane: the end face x = 2 is held plane by *MPC PLANE (defining nodes: three of its corners)
and the edge y = z = 0 straight by *MPC STRAIGHT; a force F = 10 in x at the face's
centre node, the face x = 0 on rollers (u_x = 0, plus the rigid-body modes held at two
nodes). The plane constraint acts like a frictionless rigid platen: the exact solution is the
uniform uniaxial stress s_xx = F / A with free lateral contraction (a linear displacement
field, which C3D8 represents exactly): every stress component within 1e-6 F/A of it (the
7-digit print), u_x of the whole end face F L / (E A) within 1e-6 relative.
plane_offset: PLANE only, F = 1 at an edge node of the face, off the centre: no closed form,
but the linearised plane condition (L3) must hold for every end-face node to round-off
(below 1e-6 of the largest displacement: print precision); the distance from the deformed
plane, second order in the displacements, is printed.
rigid: nu = 0; the end face nodes form a *RIGID BODY with reference node 1000 at the face
centre and rotation node 1001 (in no element); F = 10 in x on the reference node and a
prescribed rotation theta_z = 1e-3 on the rotation node. Checked: every end-face node moves
as u_ref + theta x (x - x_ref) to round-off (1e-6 of the largest displacement, print); RF at
the rotation node (the moment the body transmits, as CalculiX prints it) balances the moment
of the support reactions about the reference node (1e-6 relative, print), and RF at the
reference node, the applied force (the force the body transmits), equals F (1e-6).
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
THETA = 1e-3


def prism():
    return cc.Box(np.linspace(0, LENGTH, 5), np.linspace(0, 1, 3), np.linspace(0, 1, 3))


def at(box, x, y, z):
    nodes = box.nodes_where(lambda px, py, pz: abs(px - x) < 1e-9 and abs(py - y) < 1e-9 and
                            abs(pz - z) < 1e-9)
    assert len(nodes) == 1
    return nodes[0]


def make_deck(path, case):
    box = prism()
    nu = 0.0 if case == 'rigid' else 0.3
    end = box.face_nodes(0, 1)
    lines = ['*HEADING', 'Constraints %s (tests/integration/constraints/mpc_rigid.py)' % case]
    lines += box.mesh_cards('PRISM')
    lines += cc.nset_cards('ROLLER', box.face_nodes(0, 0))
    lines += cc.nset_cards('END', end)
    if case == 'rigid':
        lines += ['*NODE', '%d, %g, 0.5, 0.5' % (REF, LENGTH), '%d, %g, 0.5, 0.5' % (ROT, LENGTH)]
        lines += ['*RIGID BODY, NSET=END, REF NODE=%d, ROT NODE=%d' % (REF, ROT)]
        lines += cc.nset_cards('PIVOTS', [REF, ROT])
    else:
        corners = [at(box, LENGTH, 0, 0), at(box, LENGTH, 1, 0), at(box, LENGTH, 1, 1)]
        others = [n for n in end if n not in corners]
        lines += ['*MPC', 'PLANE, ' + ', '.join(str(n) for n in corners + others[:12])]
        if others[12:]:
            lines += [', '.join(str(n) for n in others[12:])]
        line = [at(box, x, 0, 0) for x in (0.0, LENGTH, 0.5, 1.0, 1.5)]
        if case == 'plane':
            lines += ['*MPC', 'STRAIGHT, ' + ', '.join(str(n) for n in line)]
    lines += cc.material_cards('MAT', 'PRISM', YOUNG, nu)
    lines += ['*STEP', '*STATIC', '1., 1.', '*BOUNDARY', 'ROLLER, 1, 1',
              '%d, 2, 3' % at(box, 0, 0, 0), '%d, 3, 3' % at(box, 0, 1, 0)]
    if case == 'rigid':
        lines += ['%d, 2, 2' % at(box, 0, 0, 1)]
        lines += ['%d, 3, 3, %.12g' % (ROT, THETA), '*CLOAD', '%d, 1, %.12g' % (REF, FORCE)]
    elif case == 'plane':
        lines += ['%d, 2, 2' % at(box, 0, 0, 1), '*CLOAD', '%d, 1, %.12g' % (at(box, LENGTH, 0.5, 0.5), FORCE)]
    else:
        lines += ['%d, 2, 2' % at(box, 0, 0, 1), '*CLOAD', '%d, 1, 1.' % at(box, LENGTH, 0.5, 0.0)]
    lines += ['*NODE PRINT, NSET=END', 'U', '*NODE PRINT, NSET=ROLLER', 'RF', '*EL PRINT, ELSET=PRISM', 'S']
    if case == 'rigid':
        lines += ['*NODE PRINT, NSET=PIVOTS', 'U, RF']
    lines += ['*END STEP']
    cc.write_deck(path, lines)


def table(blocks, title, set_name):
    rows = [b for b in blocks if b['title'].startswith(title) and (b['set'] or '').upper() == set_name]
    return {k[0]: v for k, v in rows[-1]['rows']}


def check(job, case):
    checker = cc.Checker()
    box = prism()
    blocks = cc.read_dat(job + '.dat')
    u = table(blocks, 'displacements', 'END')
    scale = max(np.abs(v).max() for v in u.values())
    if case == 'plane':
        stress = [b for b in blocks if b['title'].startswith('stresses')][-1]
        exact = np.array([FORCE / 1.0, 0, 0, 0, 0, 0])
        worst = max(np.abs(v - exact).max() for _, v in stress['rows'])
        checker.check(worst <= 1e-6 * FORCE, 'uniform s_xx = F/A, others 0, at every integration '
                      'point: largest error %.2e (tolerance 1e-6 F/A, print)' % worst)
        ux = np.array([v[0] for v in u.values()])
        checker.check(np.abs(ux - FORCE * LENGTH / YOUNG).max() <= 1e-6 * FORCE * LENGTH / YOUNG,
                      'end face u_x = F L / (E A) at all %d nodes (1e-6 relative)' % len(ux))
    elif case == 'plane_offset':
        ia, ib, ic = at(box, LENGTH, 0, 0), at(box, LENGTH, 1, 0), at(box, LENGTH, 1, 1)
        xa, xb, xc = (box.coordinates(n) for n in (ia, ib, ic))
        e1, e2 = xb - xa, xc - xa
        n0 = np.cross(e1, e2)
        linear, distance = 0.0, 0.0
        p = {n: box.coordinates(n) + u[n] for n in u}
        normal = np.cross(p[ib] - p[ia], p[ic] - p[ia])
        normal /= np.linalg.norm(normal)
        for n in u:
            r = box.coordinates(n) - xa
            f = (np.dot(n0, u[n] - u[ia]) + np.dot(np.cross(e2, r), u[ib] - u[ia]) +
                 np.dot(np.cross(r, e1), u[ic] - u[ia]))
            linear = max(linear, abs(f) / np.linalg.norm(n0))
            distance = max(distance, abs(np.dot(p[n] - p[ia], normal)))
        tilt = max(v[0] for v in u.values()) - min(v[0] for v in u.values())
        checker.check(tilt > 1e-2 * scale, 'the off-centre load tilts the end face (u_x varies by '
                      '%.3e)' % tilt)
        checker.check(linear <= 1e-6 * scale, 'the linearised plane condition (L3) holds at every '
                      'end-face node: largest residual %.2e (tolerance 1e-6 of the largest '
                      'displacement %.3e, print); distance from the deformed plane %.2e (second '
                      'order)' % (linear, scale, distance))
    else:
        pivots = table(blocks, 'displacements', 'PIVOTS')
        ref_u, theta = pivots[REF], pivots[ROT]
        checker.relative('rotation node theta_z = prescribed', theta[2], THETA, 1e-6)
        x_ref = np.array([LENGTH, 0.5, 0.5])
        worst = max(np.abs(u[n] - (ref_u + np.cross(theta, box.coordinates(n) - x_ref))).max()
                    for n in u)
        checker.check(worst <= 1e-6 * scale, 'end face moves rigidly (u_ref + theta x r): largest '
                      'deviation %.2e (tolerance 1e-6 of %.3e, print)' % (worst, scale))
        forces = table(blocks, 'forces', 'PIVOTS')
        checker.relative('RF at the reference node = F (transmitted force)', forces[REF][0], FORCE, 1e-6)
        roller = table(blocks, 'forces', 'ROLLER')
        moment = np.zeros(3)
        for n, f in roller.items():
            moment += np.cross(box.coordinates(n) - x_ref, f)
        checker.relative('RF moment_z at the rotation node + moment of the support reactions '
                         'about the reference node = 0', forces[ROT][2] + moment[2], 0.0, 1e-6,
                         scale=abs(forces[ROT][2]))
        checker.check(abs(forces[ROT][2]) > 0.0, 'the prescribed rotation needs a moment (%.4g)'
                      % forces[ROT][2])
    checker.finish()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    sub = parser.add_subparsers(dest='command', required=True)
    d = sub.add_parser('deck')
    d.add_argument('path')
    d.add_argument('case', choices=['plane', 'plane_offset', 'rigid'])
    c = sub.add_parser('check')
    c.add_argument('job')
    c.add_argument('case', choices=['plane', 'plane_offset', 'rigid'])
    args = parser.parse_args()
    if args.command == 'deck':
        make_deck(args.path, args.case)
    else:
        check(args.job, args.case)


if __name__ == '__main__':
    main()
