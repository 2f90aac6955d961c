"""*TRANSFORM (issue 17): a block on a roller on an inclined face, under uniaxial load.

    transform_roller.py deck JOB.inp
    transform_roller.py check JOB

A block 2 x 1 x 1 (4 x 2 x 2 C3D8, E = 1000, nu = 0.3) whose long axis n = (cos a, sin a, 0)
is inclined at a = 30 degrees to the global x axis; t = (-sin a, cos a, 0), z the third
axis. The face s = 0 (s the coordinate along n) is on a roller given in local axes: its
nodes get *TRANSFORM, TYPE=R with local x = n and local y = t, and *BOUNDARY local dof 1
(the normal displacement) = 0; one of its nodes is also held in local 2 and 3, another in
local 3 (the rigid-body modes in the roller's plane). A pressure p = 10 on the face s = 2.
Exact solution: the uniaxial stress sigma = -p n n^T (global components), strain -p/E along
n and nu p / E across, displacement u(x) = -p/E (s n) + nu p / E (t_c t + z e_z) with t_c,
z measured from the node held in local 2 and 3. Checked: every integration-point stress
(global components) within 1e-6 p of -p n n^T (7-digit print); the displacements of the
roller nodes, printed in local axes (rows marked L, as ccx prints them), have local x = 0
(1e-6 of the largest, print) and local y, z = the lateral expansion; the sum of the roller
nodes' local RF_x = p A (1e-6; the reaction along the roller's normal, in local axes);
the loaded face's displacement along n = -p L / E (1e-6).
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'contact'))
import contact_common as cc  # noqa: E402

YOUNG = 1000.0
POISSON = 0.3
PRESSURE = 10.0
LENGTH = 2.0
ANGLE = math.radians(30.0)
N = np.array([math.cos(ANGLE), math.sin(ANGLE), 0.0])
T = np.array([-math.sin(ANGLE), math.cos(ANGLE), 0.0])
Z = np.array([0.0, 0.0, 1.0])


def rotate(s, t, z):
    return tuple(s * N + t * T + z * Z)


def block():
    return cc.Box(np.linspace(0, LENGTH, 5), np.linspace(0, 1, 3), np.linspace(0, 1, 3), warp=rotate)


def local(box, node):
    x = box.coordinates(node)
    return np.array([np.dot(x, N), np.dot(x, T), x[2]])


def node_at(box, s, t, z):
    found = [n for n in box.node_ids if np.allclose(local(box, n), (s, t, z), atol=1e-9)]
    assert len(found) == 1
    return found[0]


def make_deck(path):
    box = block()
    held = node_at(box, 0, 0, 0)
    second = node_at(box, 0, 1, 0)
    lines = ['*HEADING', 'Inclined roller by *TRANSFORM (tests/integration/constraints/transform_roller.py)']
    lines += box.mesh_cards('BLOCK')
    lines += cc.nset_cards('ROLLER', box.face_nodes(0, 0))
    lines += cc.nset_cards('FAR', box.face_nodes(0, 1))
    lines += cc.face_surface_cards('LOADED', box, 0, 1)
    lines += ['*TRANSFORM, NSET=ROLLER, TYPE=R', '%.17g, %.17g, 0., %.17g, %.17g, 0.' % (N[0], N[1], T[0], T[1])]
    lines += cc.material_cards('MAT', 'BLOCK', YOUNG, POISSON)
    lines += ['*STEP', '*STATIC', '1., 1.', '*BOUNDARY', 'ROLLER, 1, 1', '%d, 2, 3' % held,
              '%d, 3, 3' % second, '*DSLOAD', 'LOADED, P, %.12g' % PRESSURE,
              '*NODE PRINT, NSET=ROLLER', 'U, RF', '*NODE PRINT, NSET=FAR', 'U',
              '*EL PRINT, ELSET=BLOCK', 'S', '*END STEP']
    cc.write_deck(path, lines)


def read_tables(path):
    """{(title word, set): {key: (values, local)}} of the last block of each table; rows may end
    in L (local axes)."""
    tables = {}
    current = None
    with open(path) as dat:
        for line in dat:
            if ' for set ' in line and ' and time' in line:
                title = line.split()[0]
                name = line.split(' for set ')[1].split()[0]
                current = {}
                tables[(title, name)] = current
                continue
            fields = line.split()
            if current is None or not fields:
                continue
            is_local = fields[-1] == 'L'
            if is_local:
                fields = fields[:-1]
            keys = []
            while fields and fields[0].lstrip('+-').isdigit():
                keys.append(int(fields.pop(0)))
            current[tuple(keys)] = (np.array([float(f) for f in fields]), is_local)
    return tables


def check(job):
    checker = cc.Checker()
    box = block()
    tables = read_tables(job + '.dat')
    exact = -PRESSURE * np.outer(N, N)
    exact = np.array([exact[0, 0], exact[1, 1], exact[2, 2], exact[0, 1], exact[0, 2], exact[1, 2]])
    stresses = tables[('stresses', 'BLOCK')]
    worst = max(np.abs(v - exact).max() for v, _ in stresses.values())
    checker.check(len(stresses) == 4 * 2 * 2 * 8 and worst <= 1e-6 * PRESSURE,
                  'uniaxial stress -p n n^T at all %d integration points: largest error %.2e '
                  '(tolerance 1e-6 p, print)' % (len(stresses), worst))
    roller_u = tables[('displacements', 'ROLLER')]
    checker.check(all(is_local for _, is_local in roller_u.values()),
                  'the roller nodes are printed in local axes (rows marked L)')
    held = local(box, node_at(box, 0, 0, 0))
    strain_lateral = POISSON * PRESSURE / YOUNG
    scale = PRESSURE * LENGTH / YOUNG
    worst_normal = max(abs(v[0]) for v, _ in roller_u.values())
    worst_lateral = max(np.abs(v[1:] - strain_lateral * (local(box, k[0])[1:] - held[1:])).max()
                        for k, (v, _) in roller_u.items())
    checker.check(worst_normal <= 1e-6 * scale, 'roller nodes: local u_x (normal) = 0, largest %.2e '
                  '(tolerance 1e-6 p L / E, print)' % worst_normal)
    checker.check(worst_lateral <= 1e-6 * scale, 'roller nodes: local u_y, u_z = the lateral '
                  'expansion nu p / E, largest error %.2e (tolerance 1e-6 p L / E)' % worst_lateral)
    reaction = sum(v[0] for v, _ in tables[('forces', 'ROLLER')].values())
    checker.relative('sum of the roller nodes\' local RF_x = p A', reaction, PRESSURE, 1e-6)
    far = tables[('displacements', 'FAR')]
    along = max(abs(np.dot(v, N) + scale) for v, is_local in far.values() if not is_local)
    checker.check(along <= 1e-6 * scale, 'loaded face (global axes): u . n = -p L / E, largest '
                  'error %.2e (tolerance 1e-6 p L / E)' % along)
    checker.finish()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    sub = parser.add_subparsers(dest='command', required=True)
    d = sub.add_parser('deck')
    d.add_argument('path')
    c = sub.add_parser('check')
    c.add_argument('job')
    args = parser.parse_args()
    if args.command == 'deck':
        make_deck(args.path)
    else:
        check(args.job)


if __name__ == '__main__':
    main()
