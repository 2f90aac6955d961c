"""Patch test of *EQUATION (issue 17): two blocks with non-matching meshes tied by linear
equations carry a uniform stress state exactly.

    equation_patch_test.py deck JOB.inp --upper N --lower M [--pressure P]
    equation_patch_test.py check JOB [--pressure P]

Blocks 1 x 1 x 0.5, one on the other (lower z in [0, 0.5] with M x M x 2 hexahedra, upper z
in [0.5, 1] with N x N x 2), E = 1000, nu = 0.3. Every node of the upper block's bottom face
is tied to the lower block's top face: for each direction d,

    u_d(s) - sum_i N_i(s) u_d(m_i) = 0

with m_i the four nodes of the lower face under s and N_i their bilinear shape functions at
s (the first term, the upper node, is dependent). Supports: u_z = 0 on the base, u_x = 0 on
x = 0 and u_y = 0 on y = 0 (symmetry planes; not on the tied nodes, which follow the lower
block). Loads: pressure p (default 10) on the top face and q = 4 on the x = 1 faces of both
blocks. The exact solution is the uniform state s_zz = -p, s_xx = -q, the other components
zero, with a displacement field linear in x, y, z in both blocks, which the bilinear
interpolation of the tie reproduces exactly.

Equilibrium of the reduced system (T^T (K u - f) = 0) at a lower-face node i adds the upper
block's interface forces through the tie coefficients: it holds for the linear field when
sum_s N_i(s) A_s = int N_i dA, i.e. when the upper nodes' tributary areas A_s integrate the
lower face's shape functions exactly. That is so when the upper mesh refines the lower one
(N a multiple of M: every lower node is an upper node, N_i is bilinear on every upper face),
and whatever the meshes when no traction crosses the interface (p = 0). So the patch test
(Taylor & Papadopoulos 1991) is passed to round-off for N = 2M with p != 0 and for any N, M
with p = 0; for N = 3, M = 2 and p = 10 it is not (largest stress error 1.94, i.e. 0.19 p,
and ccx 2.20 prints the same stresses to all 7 digits): node-to-surface collocation is not
a mortar tie (the *TIE is, doc/theory.md 4.7). Checked from the .dat: every integration-point stress component within 1e-6 p of
the exact value (the .dat prints 7 significant digits: 5e-7 relative), the base reaction
p A (1e-6, print), and the displacement of the top corner (1, 1, 1), which is the strain
of Hooke's law (eps_xx = (-q + nu p) / E, eps_yy = nu (q + p) / E, eps_zz = (-p + nu q) / E)
times the unit lengths (1e-6 relative, print).
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'contact'))
import contact_common as cc  # noqa: E402

YOUNG = 1000.0
POISSON = 0.3
PRESSURE = 10.0
LATERAL = 4.0
UPPER_FIRST = 100001


def tie_equations(lower, upper, m):
    """*EQUATION lines tying the upper block's bottom nodes to the lower block's top face."""
    lines = ['*EQUATION']
    h = 1.0 / m
    for node in upper.face_nodes(2, 0):
        x, y, z = upper.coordinates(node)
        i = min(int(x / h + 1e-12), m - 1)
        j = min(int(y / h + 1e-12), m - 1)
        xi = (x - i * h) / h
        eta = (y - j * h) / h
        corners = [(i, j, (1 - xi) * (1 - eta)), (i + 1, j, xi * (1 - eta)),
                   (i + 1, j + 1, xi * eta), (i, j + 1, (1 - xi) * eta)]
        terms = [(node, 1.0)]
        for ci, cj, weight in corners:
            if weight == 0.0:
                continue
            master = lower.nodes_where(lambda px, py, pz, ci=ci, cj=cj: abs(px - ci * h) < 1e-9
                                       and abs(py - cj * h) < 1e-9 and abs(pz - 0.5) < 1e-9)
            assert len(master) == 1
            terms.append((master[0], -weight))
        for d in (1, 2, 3):
            lines.append(str(len(terms)))
            fields = ['%d, %d, %.17g' % (n, d, c) for n, c in terms]
            for s in range(0, len(fields), 4):
                lines.append(', '.join(fields[s:s + 4]))
    return lines


def make_deck(path, n, m, pressure, steps=1):
    lower = cc.Box(np.linspace(0, 1, m + 1), np.linspace(0, 1, m + 1), np.linspace(0, 0.5, 3),
                   first_node=1, first_element=1)
    upper = cc.Box(np.linspace(0, 1, n + 1), np.linspace(0, 1, n + 1), np.linspace(0.5, 1.0, 3),
                   first_node=UPPER_FIRST, first_element=UPPER_FIRST)
    tied = set(upper.face_nodes(2, 0))
    lines = ['*HEADING', 'Patch test of *EQUATION: %d x %d upper faces tied to %d x %d lower faces '
             '(tests/integration/constraints/equation_patch_test.py)' % (n, n, m, m)]
    lines += lower.mesh_cards('LOWER') + upper.mesh_cards('UPPER')
    lines += ['*ELSET, ELSET=BOTH', 'LOWER, UPPER']
    lines += cc.nset_cards('BASE', lower.face_nodes(2, 0))
    lines += cc.nset_cards('SYM_X', lower.face_nodes(0, 0) +
                           [k for k in upper.face_nodes(0, 0) if k not in tied])
    lines += cc.nset_cards('SYM_Y', lower.face_nodes(1, 0) +
                           [k for k in upper.face_nodes(1, 0) if k not in tied])
    lines += cc.nset_cards('CORNER', upper.nodes_where(
        lambda px, py, pz: abs(px - 1) < 1e-9 and abs(py - 1) < 1e-9 and abs(pz - 1) < 1e-9))
    lines += cc.face_surface_cards('TOP', upper, 2, 1)
    lines += cc.face_surface_cards('SIDE_LOWER', lower, 0, 1)
    lines += cc.face_surface_cards('SIDE_UPPER', upper, 0, 1)
    lines += cc.material_cards('MAT', 'BOTH', YOUNG, POISSON)
    lines += tie_equations(lower, upper, m)
    for step in range(1, steps + 1):
        # Further steps (the restart test) double the loads, in increments of a quarter.
        static = '1., 1.' if steps == 1 else '0.25, 1., , 0.25'
        lines += ['*STEP', '*STATIC', static, '*BOUNDARY', 'BASE, 3, 3', 'SYM_X, 1, 1',
                  'SYM_Y, 2, 2', '*DSLOAD', 'TOP, P, %.12g' % (step * pressure),
                  'SIDE_LOWER, P, %.12g' % (step * LATERAL),
                  'SIDE_UPPER, P, %.12g' % (step * LATERAL),
                  '*EL PRINT, ELSET=BOTH', 'S', '*NODE PRINT, NSET=BASE, TOTALS=ONLY', 'RF',
                  '*NODE PRINT, NSET=CORNER', 'U', '*END STEP']
    cc.write_deck(path, lines)


def check(job, pressure):
    checker = cc.Checker()
    blocks = cc.read_dat(job + '.dat')
    stress = [b for b in blocks if b['title'].startswith('stresses')][-1]
    exact = np.array([-LATERAL, 0.0, -pressure, 0.0, 0.0, 0.0])
    worst = max(np.abs(values - exact).max() for _, values in stress['rows'])
    checker.check(len(stress['rows']) > 0, '%d integration points printed' % len(stress['rows']))
    checker.check(worst <= 1e-6 * LATERAL, 'uniform stress s_xx = -q, s_zz = -p, others 0 at '
                  'every integration point of both blocks: largest error %.2e (tolerance 1e-6 q, '
                  'the 7-digit print)' % worst)
    _, base = cc.totals(blocks, 'BASE')
    checker.relative('base reaction = p A', base[-1][2], pressure, 1e-6, scale=LATERAL)
    corner = [b for b in blocks if b['title'].startswith('displacements')][-1]['rows'][0][1]
    strain = np.array([-LATERAL + POISSON * pressure, POISSON * (LATERAL + pressure),
                       -pressure + POISSON * LATERAL]) / YOUNG
    for d in range(3):
        checker.relative('corner (1, 1, 1) u_%s = eps_%s (Hooke)' % ('xyz'[d], 'xyz'[d] * 2),
                         corner[d], strain[d], 1e-6)
    checker.finish()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    sub = parser.add_subparsers(dest='command', required=True)
    d = sub.add_parser('deck')
    d.add_argument('path')
    d.add_argument('--upper', type=int, required=True)
    d.add_argument('--lower', type=int, required=True)
    d.add_argument('--pressure', type=float, default=PRESSURE)
    d.add_argument('--steps', type=int, default=1,
                   help='steps (the second and later double the loads; restart test)')
    c = sub.add_parser('check')
    c.add_argument('job')
    c.add_argument('--pressure', type=float, default=PRESSURE)
    args = parser.parse_args()
    if args.command == 'deck':
        make_deck(args.path, args.upper, args.lower, args.pressure, args.steps)
    else:
        check(args.job, args.pressure)


if __name__ == '__main__':
    main()
