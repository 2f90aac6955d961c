#!/usr/bin/python3
"""Strip footing on a von Mises half-space against Prandtl's limit load (`make validate`:
plasticity_footing.sh).

    plasticity_footing.py --fcs3d BIN --work DIR [--meshes 12x8,24x16,48x32] [--markdown FILE]
                          [--assert-limit 0.05]

Plane strain (one C3D8 layer, B-bar, u_y = 0 everywhere), half of a rigid smooth strip
footing of width 2 (half-width 1 at x in [0, 1] on the surface z = 0) on a weightless
elastic-perfectly plastic von Mises layer 8 wide and 6 deep: symmetry u_x = 0 on x = 0,
u_x = 0 on x = 8, u = 0 on the base z = -6. The footing nodes are pushed down by a uniform
settlement (displacement control; their horizontal motion is free: a smooth footing) to
0.04, about 15 times the elastic settlement at the limit load. E = 200000, nu = 0.3,
s_y = 200. Meshes of nx x nz elements graded towards the footing edge (x = 1, z = 0).

Prandtl (1920; Hill 1950, chapter VIII): a rigid smooth strip on a weightless Tresca
half-space with cohesion k fails at the mean pressure q_u = (2 + pi) k. In plane strain the
plastic flow of a von Mises material at collapse is incompressible with eps_y = 0, so
s_y = (s_x + s_z)/2 and von Mises reduces to Tresca with k = s_y / sqrt(3):
q_u = (2 + pi) s_y / sqrt(3) = 593.8 here. The FE limit load is the largest mean pressure
(the footing force over its area) of the load-settlement curve.
"""
import argparse
import math
import os
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', 'integration', 'plasticity'))
sys.path.insert(0, os.path.join(HERE, '..', 'tools'))
import plastic_common as pc  # noqa: E402
import datfile  # noqa: E402

YOUNG, POISSON, YIELD = 200000.0, 0.3, 200.0
HALF_WIDTH, WIDTH, DEPTH, THICKNESS = 1.0, 8.0, 6.0, 0.25
SETTLEMENT = 0.04
Q_PRANDTL = (2.0 + math.pi) * YIELD / math.sqrt(3.0)
HEX = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]


def axis(points_left, points_right, left, edge, right, ratio):
    """Coordinates from `left` to `right` with cells growing geometrically (factor `ratio`)
    away from `edge`: points_left cells between left and edge, points_right beyond."""
    def series(n, length):
        widths = np.array([ratio ** i for i in range(n)])
        return np.concatenate([[0.0], np.cumsum(widths) / widths.sum() * length])
    a = edge - series(points_left, edge - left)[::-1]
    b = edge + series(points_right, right - edge)
    return np.concatenate([a, b[1:]])


def mesh(nx, nz):
    """Nodes, C3D8 elements, node sets. x graded towards the footing edge x = 1 (nx/4 cells
    under the footing, the rest beyond), z towards the surface."""
    under = max(2, nx // 4)
    xs = axis(under, nx - under, 0.0, HALF_WIDTH, WIDTH, 1.12 if nx >= 24 else 1.25)
    zs = -axis(0, nz, 0.0, 0.0, DEPTH, 1.08 if nz >= 16 else 1.2)[::-1]
    zs = np.sort(zs)
    ys = np.array([0.0, THICKNESS])
    ids = {}
    coords = []
    for k, z in enumerate(zs):
        for j, y in enumerate(ys):
            for i, x in enumerate(xs):
                ids[(i, j, k)] = len(coords) + 1
                coords.append((x, y, z))
    elements = []
    for k in range(len(zs) - 1):
        for i in range(len(xs) - 1):
            elements.append((len(elements) + 1,
                             [ids[(i + a, b, k + c)] for a, b, c in HEX]))
    xyz = np.array(coords)
    top = np.abs(xyz[:, 2]) < 1e-12
    sets = {'ALL': np.arange(1, len(coords) + 1),
            'X0': np.nonzero(np.abs(xyz[:, 0]) < 1e-12)[0] + 1,
            'XW': np.nonzero(np.abs(xyz[:, 0] - WIDTH) < 1e-12)[0] + 1,
            'BASE': np.nonzero(np.abs(xyz[:, 2] + DEPTH) < 1e-12)[0] + 1,
            'FOOT': np.nonzero(top & (xyz[:, 0] <= HALF_WIDTH + 1e-12))[0] + 1}
    return xyz, elements, sets


def write_deck(path, nx, nz, rmin=''):
    xyz, elements, sets = mesh(nx, nz)
    lines = ['*HEADING', 'Prandtl strip footing, mesh %dx%d (plasticity_footing.py)' % (nx, nz),
             '*NODE, NSET=ALL_NODES']
    lines += ['%d, %.17g, %.17g, %.17g' % (i + 1, *p) for i, p in enumerate(xyz)]
    lines.append('*ELEMENT, TYPE=C3D8, ELSET=ALL_ELEMENTS')
    lines += ['%d, %s' % (e, ', '.join(map(str, conn))) for e, conn in elements]
    for name, members in sets.items():
        lines.append('*NSET, NSET=%s' % name)
        lines += [', '.join(map(str, members[i:i + 12])) for i in range(0, len(members), 12)]
    lines += pc.von_mises_cards(YOUNG, POISSON, [(YIELD, 0.0)], bbar=True)
    lines += ['*BOUNDARY', 'ALL, 2, 2', 'X0, 1, 1', 'XW, 1, 1', 'BASE, 1, 3',
              '*STEP', '*STATIC', '0.02, 1., 1e-6, 0.02'] + ([rmin] if rmin else []) + \
             ['*BOUNDARY', 'FOOT, 3, 3, %r' % -SETTLEMENT,
              '*NODE PRINT, NSET=FOOT, TOTALS=ONLY, FREQUENCY=1', 'RF', '*END STEP']
    with open(path, 'w') as f:
        f.write('\n'.join(lines) + '\n')
    return len(elements)


def run_mesh(fcs3d, work, nx, nz, rmin=''):
    job = os.path.join(work, 'footing_%dx%d' % (nx, nz))
    n_elements = write_deck(job + '.inp', nx, nz, rmin)
    t0 = time.monotonic()
    result = subprocess.run([fcs3d, '-q', job + '.inp'], capture_output=True, text=True)
    wall = time.monotonic() - t0
    curve = []
    for block in datfile.read_blocks(job + '.dat'):
        if block.kind == 'total':
            force = -list(block.rows.values())[0][2]
            curve.append((SETTLEMENT * block.time, force / (HALF_WIDTH * THICKNESS)))
    curve = np.array(curve)
    increments = sum(1 for line in open(job + '.log') if line.startswith('inc '))
    limit = curve[:, 1].max()
    # The mean pressure at a quarter of the settlement (on the rising part of the curve).
    quarter = np.interp(0.25 * SETTLEMENT, curve[:, 0], curve[:, 1])
    # How flat the end of the curve is: the rise over the last quarter of the settlement.
    last = curve[curve[:, 0] >= 0.75 * SETTLEMENT * (1 - 1e-9)]
    rise = (last[-1, 1] - last[0, 1]) / last[-1, 1]
    return dict(mesh='%dx%d' % (nx, nz), elements=n_elements, increments=increments, wall=wall,
                status=result.returncode, limit=limit, error=(limit - Q_PRANDTL) / Q_PRANDTL,
                rise=rise, quarter=quarter, stderr=result.stderr.strip())


def table(rows):
    lines = ['| mesh (nx x nz) | elements | increments | wall [s] | limit pressure q / (2 + pi) k '
             '| error | rise over the last quarter of the settlement |', '|---|---|---|---|---|---|---|']
    for r in rows:
        lines.append('| %s | %d | %d | %.0f | %.4f | %+.2f %% | %.2f %% |'
                     % (r['mesh'], r['elements'], r['increments'], r['wall'], r['limit'] / Q_PRANDTL,
                        100 * r['error'], 100 * r['rise']))
    return '\n'.join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--fcs3d', required=True)
    parser.add_argument('--work', required=True)
    parser.add_argument('--meshes', default='12x8,24x16,48x32')
    parser.add_argument('--markdown')
    parser.add_argument('--rmin', default='')
    parser.add_argument('--assert-limit', type=float)
    args = parser.parse_args()
    os.makedirs(args.work, exist_ok=True)
    rows = []
    for spec in args.meshes.split(','):
        nx, nz = (int(v) for v in spec.split('x'))
        row = run_mesh(args.fcs3d, args.work, nx, nz, args.rmin)
        rows.append(row)
        print('mesh %s: %d elements, %d increments, %.0f s, limit %.4f (2 + pi) k (%+.2f %%), '
              'mean pressure at a quarter of the settlement %.5g%s'
              % (row['mesh'], row['elements'], row['increments'], row['wall'],
                 row['limit'] / Q_PRANDTL, 100 * row['error'], row['quarter'],
                 '' if row['status'] == 0 else '; run failed: ' + row['stderr']), flush=True)
    text = table(rows)
    print(text)
    if args.markdown:
        with open(args.markdown, 'w') as f:
            f.write(text + '\n')
    if any(r['status'] != 0 for r in rows):
        return 1
    if args.assert_limit is not None and not abs(rows[-1]['error']) <= args.assert_limit:
        print('FAIL: limit load error %.2f %% on the finest mesh exceeds %.0f %%'
              % (100 * rows[-1]['error'], 100 * args.assert_limit))
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main())
