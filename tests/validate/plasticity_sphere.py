#!/usr/bin/python3
"""Thick-walled sphere under internal pressure, elastic-perfectly plastic, against Hill's
closed form (`make validate`: plasticity_sphere.sh).

    plasticity_sphere.py --fcs3d BIN --work DIR [--meshes 2x4,4x8,8x16] [--markdown FILE]
                         [--assert-limit 0.02] [--rmin '...']

The octant a <= r <= b (a = 1, b = 2) of a hollow sphere, meshed with C3D8 (B-bar) as a cube
sphere: the three faces x = 1, y = 1, z = 1 of the unit cube's corner, each divided n x n at
equal angles and projected on the sphere, extruded in m layers of geometrically growing
thickness. Symmetry conditions on the three coordinate planes, a pressure p on the inner
surface (*DSLOAD, small strain), rising at the same rate through the step to 1.15 times the
limit pressure. E = 200000, nu = 0.3, von Mises with s_y = 200 and no hardening.

Hill (1950), "The Mathematical Theory of Plasticity", chapter V.3 (the spherical shell):
with the plastic zone a <= r <= c,
    p(c) = 2 s_y ln(c/a) + 2 s_y / 3 (1 - c^3 / b^3),      u(b) = s_y c^3 (1 - nu) / (E b^2)
exact for any nu (by symmetry von Mises and Tresca coincide: s_theta - s_r = s_y), first
yield at p_e = p(a) = 2 s_y / 3 (1 - a^3 / b^3), the limit at c = b: p_L = 2 s_y ln(b/a),
u(b) = s_y b (1 - nu) / E. The pressure-expansion curve is compared through the outer radial
displacement: from u(b) of a frame, c follows, then Hill's p(c) against the applied p (while
c <= b). The FE limit pressure is taken as the pressure at which u(b) reaches 3 times Hill's
u(b) at the limit (beyond the limit the expansion grows without bound at constant pressure;
3 times is on the flat part of the curve). Under pressure control the run stops when no
equilibrium exists any more ("no equilibrium", exit status 1: the load has reached the FE
limit), which is expected; if it stops before u(b) reaches 3 times Hill's, the FE limit is the
pressure of its last equilibrium increment (from below, within the minimum increment).

Prints a convergence table (elements, increments, wall time, first-yield pressure, largest
error of the curve, limit pressure and its error) and writes it as Markdown.
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
import plastic_common as pc  # noqa: E402

A, B = 1.0, 2.0
YOUNG, POISSON, YIELD = 200000.0, 0.3, 200.0
P_LIMIT = 2.0 * YIELD * math.log(B / A)
P_FIRST = 2.0 * YIELD / 3.0 * (1.0 - A ** 3 / B ** 3)
U_LIMIT = YIELD * B * (1.0 - POISSON) / YOUNG
OVERLOAD = 1.15
HEX = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]


def hill_pressure(c):
    return 2.0 * YIELD * math.log(c / A) + 2.0 * YIELD / 3.0 * (1.0 - c ** 3 / B ** 3)


def mesh(n, m):
    """Nodes {id: xyz}, elements [(id, 8 node ids)], node sets; inner faces are S1."""
    ids, coords = {}, []

    def node(p):
        key = tuple(np.round(p, 10))
        if key not in ids:
            ids[key] = len(coords) + 1
            coords.append(p)
        return ids[key]

    radii = [A * (B / A) ** (k / m) for k in range(m + 1)]
    angles = [math.tan(math.pi / 4.0 * i / n) for i in range(n + 1)]
    elements = []
    for axis in range(3):
        def point(i, j, k):
            p = np.ones(3)
            others = [d for d in range(3) if d != axis]
            p[others[0]] = angles[i]
            p[others[1]] = angles[j]
            return radii[k] * p / np.linalg.norm(p)
        for i in range(n):
            for j in range(n):
                for k in range(m):
                    corners = [point(i + di, j + dj, k + dk) for di, dj, dk in HEX]
                    # Positive orientation: the bottom face (inner, k) counter-clockwise seen
                    # from outside, i.e. (x1 - x0) x (x3 - x0) pointing outwards (+r).
                    c = corners
                    normal = np.cross(c[1] - c[0], c[3] - c[0])
                    if np.dot(normal, c[0]) < 0.0:
                        c = [c[0], c[3], c[2], c[1], c[4], c[7], c[6], c[5]]
                    elements.append((len(elements) + 1, [node(p) for p in c]))
    xyz = np.array(coords)
    sets = {'X0': np.nonzero(np.abs(xyz[:, 0]) < 1e-9)[0] + 1,
            'Y0': np.nonzero(np.abs(xyz[:, 1]) < 1e-9)[0] + 1,
            'Z0': np.nonzero(np.abs(xyz[:, 2]) < 1e-9)[0] + 1}
    outer = [i + 1 for i, p in enumerate(xyz) if abs(np.linalg.norm(p) - B) < 1e-9 and
             abs(p[1]) < 1e-9 and abs(p[2]) < 1e-9]
    inner = [i + 1 for i, p in enumerate(xyz) if abs(np.linalg.norm(p) - A) < 1e-9 and
             abs(p[1]) < 1e-9 and abs(p[2]) < 1e-9]
    inner_elements = [e for e, conn in elements if all(abs(np.linalg.norm(xyz[conn[q] - 1]) - A)
                                                       < 1e-9 for q in range(4))]
    return xyz, elements, sets, outer[0], inner[0], inner_elements


def write_deck(path, n, m, rmin):
    xyz, elements, sets, outer, inner, inner_elements = mesh(n, m)
    lines = ['*HEADING', 'Hill thick sphere a=1 b=2, mesh %dx%d (plasticity_sphere.py)' % (n, m),
             '*NODE, NSET=ALL_NODES']
    lines += ['%d, %.17g, %.17g, %.17g' % (i + 1, *p) for i, p in enumerate(xyz)]
    lines.append('*ELEMENT, TYPE=C3D8, ELSET=ALL_ELEMENTS')
    lines += ['%d, %s' % (e, ', '.join(map(str, conn))) for e, conn in elements]
    for name, members in sets.items():
        lines.append('*NSET, NSET=%s' % name)
        lines += [', '.join(map(str, members[i:i + 12])) for i in range(0, len(members), 12)]
    lines += ['*NSET, NSET=PROBE', '%d, %d' % (outer, inner)]
    lines += ['*SURFACE, NAME=BORE'] + ['%d, S1' % e for e in inner_elements]
    lines += pc.von_mises_cards(YOUNG, POISSON, [(YIELD, 0.0)], bbar=True)
    lines += ['*BOUNDARY', 'X0, 1, 1', 'Y0, 2, 2', 'Z0, 3, 3',
              '*STEP', '*STATIC', '0.02, 1., 1e-6, 0.02']
    if rmin:
        lines.append(rmin)
    lines += ['*DSLOAD', 'BORE, P, %.17g' % (OVERLOAD * P_LIMIT),
              '*NODE PRINT, NSET=PROBE, FREQUENCY=1', 'U', '*END STEP']
    with open(path, 'w') as f:
        f.write('\n'.join(lines) + '\n')
    return len(elements), outer, inner


def analyse(job, outer):
    """(pressure, u_b) per increment from the .dat (7 digits are plenty here)."""
    sys.path.insert(0, os.path.join(HERE, '..', 'tools'))
    import datfile
    points = []
    for block in datfile.read_blocks(job + '.dat'):
        if block.kind == 'displacements':
            points.append((OVERLOAD * P_LIMIT * block.time, block.rows[(outer,)][0]))
    return np.array(points)


def run_mesh(fcs3d, work, n, m, rmin):
    job = os.path.join(work, 'sphere_%dx%d' % (n, m))
    n_elements, outer, inner = write_deck(job + '.inp', n, m, rmin)
    t0 = time.monotonic()
    result = subprocess.run([fcs3d, '-q', job + '.inp'], capture_output=True, text=True)
    wall = time.monotonic() - t0
    curve = analyse(job, outer)
    increments = sum(1 for line in open(job + '.log') if line.startswith('inc '))
    pressure, u = curve[:, 0], curve[:, 1]
    # First yield: the first increment limited by a yield event.
    first = None
    for line in open(job + '.log'):
        if line.startswith('inc ') and ' limit yield ' in line:
            first = OVERLOAD * P_LIMIT * float(line.split()[5])
            break
    # The curve, where the plastic zone is inside the wall: c from u(b), then p(c).
    errors = []
    for p, ub in zip(pressure, u):
        c = (ub * YOUNG * B * B / (YIELD * (1.0 - POISSON))) ** (1.0 / 3.0)
        if P_FIRST < p and A < c < B:
            errors.append(abs(p - hill_pressure(c)) / P_LIMIT)
    beyond = np.nonzero(u >= 3.0 * U_LIMIT)[0]
    if len(beyond):
        k = beyond[0]
        # Linear between the two frames around 3 u_limit.
        limit = pressure[k - 1] + (pressure[k] - pressure[k - 1]) * (3.0 * U_LIMIT - u[k - 1]) / \
            (u[k] - u[k - 1])
    elif result.returncode != 0 and 'no equilibrium' in result.stderr:
        limit = pressure[-1]
    else:
        limit = float('nan')
    return dict(mesh='%dx%d' % (n, m), elements=n_elements, increments=increments, wall=wall,
                status=result.returncode, first=first, curve=max(errors) if errors else float('nan'),
                limit=limit, limit_error=(limit - P_LIMIT) / P_LIMIT, stopped=result.stderr.strip())


def table(rows):
    lines = ['| mesh (n x m) | elements | increments | wall [s] | first yield p / p_e - 1 | '
             'curve: max abs(p - Hill) / p_L | limit pressure p / p_L | error |',
             '|---|---|---|---|---|---|---|---|']
    for r in rows:
        first = '%.1e' % (r['first'] / P_FIRST - 1.0) if r['first'] else '-'
        lines.append('| %s | %d | %d | %.0f | %s | %.2e | %.4f | %+.2f %% |'
                     % (r['mesh'], r['elements'], r['increments'], r['wall'], first, r['curve'],
                        r['limit'] / P_LIMIT, 100 * r['limit_error']))
    return '\n'.join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--fcs3d', required=True)
    parser.add_argument('--work', required=True)
    parser.add_argument('--meshes', default='2x4,4x8,8x16')
    parser.add_argument('--rmin', default='')
    parser.add_argument('--markdown')
    parser.add_argument('--assert-limit', type=float)
    args = parser.parse_args()
    os.makedirs(args.work, exist_ok=True)
    rows = []
    for spec in args.meshes.split(','):
        n, m = (int(v) for v in spec.split('x'))
        row = run_mesh(args.fcs3d, args.work, n, m, args.rmin)
        rows.append(row)
        print('mesh %s: %d elements, %d increments, %.0f s, limit %.4f p_L (%+.2f %%), curve %.2e; '
              'run: %s' % (row['mesh'], row['elements'], row['increments'], row['wall'],
                           row['limit'] / P_LIMIT, 100 * row['limit_error'], row['curve'],
                           'completed' if row['status'] == 0 else 'stopped past the limit'),
              flush=True)
    text = table(rows)
    print(text)
    if args.markdown:
        with open(args.markdown, 'w') as f:
            f.write(text + '\n')
    if args.assert_limit is not None:
        final = rows[-1]
        if not abs(final['limit_error']) <= args.assert_limit:
            print('FAIL: limit pressure error %.2f %% on the finest mesh exceeds %.1f %%'
                  % (100 * final['limit_error'], 100 * args.assert_limit))
            return 1
        print('limit pressure on the finest mesh within %.1f %% of Hill\'s: %+.2f %%'
              % (100 * args.assert_limit, 100 * final['limit_error']))
    return 0


if __name__ == '__main__':
    sys.exit(main())
