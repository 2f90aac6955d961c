"""Nonlinear *RIGID BODY, *MPC STRAIGHT / PLANE / MEANROT under NLGEOM (issue 17) on a prism
2 x 1 x 1 of 4 x 2 x 2 C3D8 (E = 1000, nu = 0.3); doc/theory.md 6.2.3.

    nonlinear_mpc.py deck JOB.inp CASE      CASE: rigid90, line_plane, meanrot, meanrot_linear
    nonlinear_mpc.py check JOB CASE

rigid90: the end face x = 2 is a *RIGID BODY (reference node at its centre, held; rotation
node turned by 90 degrees about z); nothing else holds the prism, a cantilever on the turned
end face, with a small force 0.1 in z at its far end (a force scale for the equilibrium
tolerance). Invariants: every end-face node is at x_ref + C(w) (X - X_ref) (Rodrigues) and
all distances between them are kept, to 1e-10 of the length (the constraint is imposed to
round-off); the far end lies at (0, -2) from the reference node in x, y (1e-3 L) and is bent
by about F L^3 / (3 E I) in z. The linearised rigid body (u = theta x r) would miss the
positions by (1 - cos 90) r = r and the distances by 41 %.
line_plane: as rigid90 but turned by 60 degrees about x, with *MPC STRAIGHT on the edge
y = z = 0 (its end nodes define the line; the one at x = 2 is in the rigid body: a cascade
of nonlinear constraints) and *MPC PLANE on the face z = 1 (defined by two nodes of the rigid
end and one at x = 0); forces at the line's middle node (y) and in the face's middle (z)
deform the prism against the constraints. Checked: the line's nodes are collinear and the
face's nodes coplanar to 1e-10 of the length, the end face rigid to 1e-10, and the loads did
deform the prism (the midpoints move off the rigid motion by more than 1e-4).
meanrot: the face x = 0 clamped, *MPC MEANROT on the 8 nodes of the face x = 2 off its
centre (which lies on the axis) about the x axis, turned by 0.3 rad: the mean of
asin(a . (p x q) / (|p| |q|)) over the members is 0.3 to 1e-10 (from the .h5 results, full
precision).
meanrot_linear: the same without NLGEOM, angle 1e-3: the linearised mean rotation
(1/N) sum (a x p) . (u - u_mean) / |p|^2 is 1e-3 to 1e-9 (a linear solve: round-off).
"""
import argparse
import os
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'contact'))
import contact_common as cc  # noqa: E402

YOUNG = 1000.0
LENGTH = 2.0
REF, ROT, AXIS_NODE = 1000, 1001, 1002
TIP_FORCE = 0.1


def prism():
    return cc.Box(np.linspace(0, LENGTH, 5), np.linspace(0, 1, 3), np.linspace(0, 1, 3))


def at(box, x, y, z):
    nodes = box.nodes_where(lambda px, py, pz: abs(px - x) < 1e-9 and abs(py - y) < 1e-9 and
                            abs(pz - z) < 1e-9)
    assert len(nodes) == 1
    return nodes[0]


def rotation_vector(case):
    if case == 'rigid90':
        return np.array([0.0, 0.0, np.pi / 2])
    return np.array([np.pi / 3, 0.0, 0.0])


def line_nodes(box):
    return [at(box, x, 0, 0) for x in (0.0, LENGTH, 0.5, 1.0, 1.5)]


def plane_nodes(box):
    defining = [at(box, LENGTH, 0, 1), at(box, LENGTH, 1, 1), at(box, 0, 0, 1)]
    others = [n for n in box.nodes_where(lambda x, y, z: abs(z - 1) < 1e-9 and x < LENGTH - 1e-9)
              if n not in defining]
    return defining + others


def make_deck(path, case):
    box = prism()
    lines = ['*HEADING', 'Nonlinear constraints %s (tests/integration/constraints/nonlinear_mpc.py)'
             % case]
    lines += box.mesh_cards('PRISM')
    lines += cc.nset_cards('END', box.face_nodes(0, 1))
    lines += cc.nset_cards('ALL', box.node_ids)
    if case in ('rigid90', 'line_plane'):
        lines += ['*NODE', '%d, %g, 0.5, 0.5' % (REF, LENGTH), '%d, %g, 0.5, 0.5' % (ROT, LENGTH)]
        lines += ['*RIGID BODY, NSET=END, REF NODE=%d, ROT NODE=%d' % (REF, ROT)]
    if case == 'line_plane':
        lines += ['*MPC', 'STRAIGHT, ' + ', '.join(str(n) for n in line_nodes(box))]
        nodes = plane_nodes(box)
        lines += ['*MPC', 'PLANE, ' + ', '.join(str(n) for n in nodes[:15])]
        if nodes[15:]:
            lines += [', '.join(str(n) for n in nodes[15:])]
    if case.startswith('meanrot'):
        lines += ['*NODE', '%d, 1., 0., 0.' % AXIS_NODE]
        members = end_members(box)
        entries = [str(n) for n in members for _ in range(3)] + [str(AXIS_NODE)]
        lines += ['*MPC', 'MEANROT, ' + ', '.join(entries[:15])]
        lines += [', '.join(entries[s:s + 16]) for s in range(15, len(entries), 16)]
    lines += cc.material_cards('MAT', 'PRISM', YOUNG, 0.3)
    lines += ['*STEP' + ('' if case == 'meanrot_linear' else ', NLGEOM'), '*STATIC', '1., 1.',
              '*BOUNDARY']
    if case in ('rigid90', 'line_plane'):
        w = rotation_vector(case)
        lines += ['%d, 1, 3' % REF] + ['%d, %d, %d, %.15g' % (ROT, d + 1, d + 1, w[d]) for d in range(3)]
    else:
        lines += ['%d, 1, 3' % n for n in box.face_nodes(0, 0)]
        lines += ['%d, 1, 1, %.15g' % (AXIS_NODE, 0.3 if case == 'meanrot' else 1e-3)]
    if case == 'line_plane':
        lines += ['*CLOAD', '%d, 2, 0.5' % at(box, 1.0, 0, 0), '%d, 3, 0.5' % at(box, 1.0, 0.5, 1)]
    if case == 'rigid90':
        lines += ['*CLOAD', '%d, 3, %g' % (at(box, 0, 0.5, 0.5), TIP_FORCE)]
    lines += ['*NODE PRINT, NSET=ALL', 'U', '*EL PRINT, ELSET=PRISM', 'S', '*END STEP']
    cc.write_deck(path, lines)


class Checker:
    def __init__(self):
        self.failures = 0

    def check(self, ok, text):
        print(('ok   ' if ok else 'FAIL ') + text)
        if not ok:
            self.failures += 1

    def finish(self):
        sys.exit(1 if self.failures else 0)


def last_frame(job):
    """Initial coordinates, displacements (both by node id) and stresses of the last frame."""
    with h5py.File(job + '.h5', 'r') as f:
        ids = f['mesh/node_ids'][()]
        x0 = f['mesh/coordinates'][()]
        last = sorted(f['frames'].keys())[-1]
        u = f['frames/%s/nodal/displacement' % last][()]
        stress = f['frames/%s/integration_points/stress' % last][()]
    return ({int(n): x0[k] for k, n in enumerate(ids)}, {int(n): u[k] for k, n in enumerate(ids)},
            stress)


def rodrigues(w):
    t = np.linalg.norm(w)
    k = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
    return np.cos(t) * np.eye(3) + np.sin(t) / t * k + (1 - np.cos(t)) / t**2 * np.outer(w, w)


def check_rigid_end(checker, box, x, case):
    rotation = rodrigues(rotation_vector(case))
    x_ref = np.array([LENGTH, 0.5, 0.5])
    worst = max(np.abs(x[n] - x_ref - rotation @ (box.coordinates(n) - x_ref)).max()
                for n in box.face_nodes(0, 1))
    checker.check(worst <= 1e-10 * LENGTH, 'end face at x_ref + C(w) (X - X_ref): largest '
                  'deviation %.2e (tolerance 1e-10 L)' % worst)


def collinearity(x, nodes):
    a, b = x[nodes[0]], x[nodes[1]]
    e = (b - a) / np.linalg.norm(b - a)
    return max(np.linalg.norm(np.cross(x[n] - a, e)) for n in nodes[2:])


def coplanarity(x, nodes):
    a, b, c = x[nodes[0]], x[nodes[1]], x[nodes[2]]
    normal = np.cross(b - a, c - a)
    normal /= np.linalg.norm(normal)
    return max(abs(np.dot(x[n] - a, normal)) for n in nodes[3:])


def end_members(box):
    """The nodes of the end face off its centre (which lies on the axis)."""
    return [n for n in box.face_nodes(0, 1) if n != at(box, LENGTH, 0.5, 0.5)]


def mean_rotation(box, x0, u, axis):
    members = end_members(box)
    p0 = np.array([x0[n] for n in members])
    q0 = p0 + np.array([u[n] for n in members])
    p = p0 - p0.mean(axis=0)
    q = q0 - q0.mean(axis=0)
    p -= np.outer(p @ axis, axis)
    q -= np.outer(q @ axis, axis)
    angles, linear = [], []
    for k in range(len(members)):
        if p[k] @ p[k] < 1e-10 * np.mean(np.sum((p0 - p0.mean(axis=0))**2, axis=1)):
            continue
        angles.append(np.arcsin(axis @ np.cross(p[k], q[k]) / (np.linalg.norm(p[k]) * np.linalg.norm(q[k]))))
        du = u[members[k]] - np.mean([u[n] for n in members], axis=0)
        linear.append(np.cross(axis, p[k]) @ du / (p[k] @ p[k]))
    return np.mean(angles), np.mean(linear)


def check(job, case):
    checker = Checker()
    box = prism()
    x0, u, stress = last_frame(job)
    x = {n: x0[n] + u[n] for n in x0}
    if case == 'rigid90':
        check_rigid_end(checker, box, x, case)
        nodes = box.face_nodes(0, 1)
        p0 = np.array([x0[n] for n in nodes])
        p1 = np.array([x[n] for n in nodes])
        d0 = np.linalg.norm(p0[:, None, :] - p0[None, :, :], axis=2)
        d1 = np.linalg.norm(p1[:, None, :] - p1[None, :, :], axis=2)
        worst = np.abs(d1 - d0).max()
        checker.check(worst <= 1e-10 * LENGTH, 'all %d x %d distances between the rigid body\'s '
                      'nodes kept: largest change %.2e (tolerance 1e-10 L)' % (len(nodes), len(nodes), worst))
        # The far end follows the turned end face as a cantilever: 2 / 1 along -y, bent by
        # the tip force F L^3 / (3 E I) = 0.1 * 8 / (3 * 1000 / 12) = 3.2e-3 in z.
        turned = x[at(box, 0, 0.5, 0.5)] - np.array([LENGTH, 0.5, 0.5])
        deflection = TIP_FORCE * LENGTH**3 / (3 * YOUNG / 12.0)
        checker.check(np.abs(turned[:2] - np.array([0, -LENGTH])).max() <= 1e-3 * LENGTH and
                      abs(turned[2] - deflection) <= 0.3 * deflection,
                      'the far end turned by 90 degrees about z and bent by the tip force: '
                      '(x - x_ref) = %s (beam theory: (0, -2, %.2e) within 30 %% of the bending, '
                      'shear and C3D8 stiffness)' % (np.round(turned, 6), deflection))
    elif case == 'line_plane':
        check_rigid_end(checker, box, x, case)
        line = collinearity(x, line_nodes(box))
        checker.check(line <= 1e-10 * LENGTH, 'STRAIGHT: the %d line nodes collinear to %.2e '
                      '(tolerance 1e-10 L)' % (len(line_nodes(box)), line))
        plane = coplanarity(x, plane_nodes(box))
        checker.check(plane <= 1e-10 * LENGTH, 'PLANE: the %d face nodes coplanar to %.2e '
                      '(tolerance 1e-10 L)' % (len(plane_nodes(box)), plane))
        rotation = rodrigues(rotation_vector(case))
        x_ref = np.array([LENGTH, 0.5, 0.5])
        bent = max(np.linalg.norm(x[n] - x_ref - rotation @ (x0[n] - x_ref))
                   for n in (at(box, 1.0, 0, 0), at(box, 1.0, 0.5, 1)))
        checker.check(bent > 1e-4, 'the loads deform the prism against the constraints: the '
                      'loaded nodes are %.3e off the rigid motion' % bent)
    else:
        nonlinear, linear = mean_rotation(box, x0, u, np.array([1.0, 0.0, 0.0]))
        if case == 'meanrot':
            checker.check(abs(nonlinear - 0.3) <= 1e-10, 'MEANROT: mean asin rotation of the '
                          'members %.15f (prescribed 0.3, tolerance 1e-10)' % nonlinear)
        else:
            checker.check(abs(linear - 1e-3) <= 1e-9, 'MEANROT without NLGEOM: linearised mean '
                          'rotation %.12e (prescribed 1e-3, tolerance 1e-9)' % linear)
    checker.finish()


def main():
    cases = ['rigid90', 'line_plane', 'meanrot', 'meanrot_linear']
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    sub = parser.add_subparsers(dest='command', required=True)
    d = sub.add_parser('deck')
    d.add_argument('path')
    d.add_argument('case', choices=cases)
    c = sub.add_parser('check')
    c.add_argument('job')
    c.add_argument('case', choices=cases)
    args = parser.parse_args()
    if args.command == 'deck':
        make_deck(args.path, args.case)
    else:
        check(args.job, args.case)


if __name__ == '__main__':
    main()
