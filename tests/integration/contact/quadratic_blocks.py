#!/usr/bin/python3
"""A block pressed on a block with quadratic and triangular contact faces (issue 16).

Usage: quadratic_blocks.py deck JOB.inp --base KIND --slider KIND [--mu MU] [--tie]
       quadratic_blocks.py check JOB --base KIND --slider KIND [--mu MU] [--tolerance T]
KIND: C3D8, C3D20R (8-node quadrilateral faces) or C3D10 (6-node triangular faces: every
hexahedron of the structured box split into six tetrahedra along its main diagonal, Kuhn's
split, which conforms between neighbouring boxes and between the two blocks' interface).

Model (the frictionless stack of frictionless_stack.py): a base block 1 x 1 x 0.5 (3 x 3 x 2
cells, E1 = 1000, nu1 = 0.3) under a slider of the same footprint (3 x 3 x 2 cells, E2 = 2000,
nu2 = 0.1), matching interface meshes, both on rollers (base bottom fixed in z, every node on
x = 0 fixed in x, on y = 0 in y; the slider's x = 0 and y = 0 faces likewise). Pressure p = 1 on
the slider's top; a node-to-surface pair, slave the slider's bottom, master the base's top,
E_n = 1e6, frictionless (default) or Coulomb mu. Default increments.

Frictionless: each block is in uniform uniaxial stress sigma_zz = -p, which the quadratic
elements represent exactly. Checks:
  - the normal reaction of the base equals p A (1e-9: equilibrium, solver tolerance);
  - the roller face x = 0 of the slider carries no x force (1e-6 p A; frictionless);
  - every slave node that carries a contact area reports the contact pressure p (--tolerance,
    default 1e-6) when the slave shares are the consistent nodal loads of a uniform pressure
    and the meshes match: then the master's nodal forces, which the slave nodes at its own
    nodes hand it, are consistent too and the uniform state is the exact discrete solution.
    That holds for 6-node triangles (corners 0, mid-sides 1/3: the corners carry nothing and
    are left out of the contact) and for 4-node faces; for 8-node quadrilaterals the shares
    are CalculiX's 1/100 and 24/100, not the consistent -1/12 and 1/3, and the pressure is
    not uniform: the check is then only that the mean over the slave area is p (total
    force / slave area, 1e-9) and the spread is reported.
With --mu (Coulomb, pushed sideways in a second step: the slider's top nodes moved by
u_x = 0.05 while held in y): once sliding, the tangential reaction T of the base over its normal
reaction N equals mu within --tolerance (default 1e-3) at every output of the last half of
the push. --tie writes a *TIE between the two surfaces instead of the contact pair.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import contact_common as cc  # noqa: E402

P = 1.0
E1, NU1, E2, NU2 = 1000.0, 0.3, 500.0, 0.15
PENALTY = 1.0e6
PUSH = 0.05
# Sliders whose slave shares and matching meshes make the uniform state exact (module header).
EXACT_SLAVES = ('C3D10',)
HEX20_EDGES = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4),
               (0, 4), (1, 5), (2, 6), (3, 7)]
TET10_EDGES = [(0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3)]
# CalculiX's faces of the tetrahedron: S1 1-2-3, S2 1-4-2, S3 2-4-3, S4 3-4-1.
TET_FACES = {'S1': (0, 1, 2), 'S2': (0, 3, 1), 'S3': (1, 3, 2), 'S4': (2, 3, 0)}
# Kuhn's split of the unit cube: one tetrahedron per order in which the axes are walked.
KUHN = [(0, 1, 2), (0, 2, 1), (1, 0, 2), (1, 2, 0), (2, 0, 1), (2, 1, 0)]


class QuadraticBox:
    """A box of n cells per direction as C3D8, C3D20R or C3D10 elements: nodes on the grid
    of half cells (only those the elements use), ids from first_node."""

    def __init__(self, kind, lo, hi, cells, first_node, first_element):
        self.kind = kind
        self.lo, self.hi, self.cells = np.array(lo, float), np.array(hi, float), cells
        self.first_node = first_node
        self.ids = {}
        self.elements = []   # (id, [node ids]) in CalculiX order
        for k in range(cells[2]):
            for j in range(cells[1]):
                for i in range(cells[0]):
                    for conn in self._cell(np.array([i, j, k])):
                        self.elements.append((first_element + len(self.elements), conn))

    def node(self, half):
        """Id of the node at half-cell grid index `half` (created on first use)."""
        key = tuple(int(v) for v in half)
        if key not in self.ids:
            self.ids[key] = self.first_node + len(self.ids)
        return self.ids[key]

    def coordinates(self, key):
        return self.lo + (self.hi - self.lo) * np.array(key) / (2.0 * np.array(self.cells))

    def _cell(self, ijk):
        corners = [2 * (ijk + np.array(c)) for c in cc.HEX8_CORNERS]
        if self.kind == 'C3D8':
            return [[self.node(c) for c in corners]]
        if self.kind == 'C3D20R':
            mids = [(corners[a] + corners[b]) // 2 for a, b in HEX20_EDGES]
            return [[self.node(c) for c in corners + mids]]
        tets = []
        for order in KUHN:
            point = 2 * ijk
            vertices = [point.copy()]
            for axis in order:
                point = point.copy()
                point[axis] += 2
                vertices.append(point)
            x = [self.coordinates(v) for v in vertices]
            if np.dot(np.cross(x[1] - x[0], x[2] - x[0]), x[3] - x[0]) < 0:
                vertices[1], vertices[2] = vertices[2], vertices[1]
            mids = [(vertices[a] + vertices[b]) // 2 for a, b in TET10_EDGES]
            tets.append([self.node(v) for v in vertices + mids])
        return tets

    def key_of(self):
        return {node: key for key, node in self.ids.items()}

    def nodes_where(self, predicate):
        return sorted(n for key, n in self.ids.items() if predicate(*self.coordinates(key)))

    def faces_on(self, axis, value):
        """[(element id, face label)] of the element faces on the plane x_axis = value."""
        keys = self.key_of()
        on = lambda n: abs(self.coordinates(keys[n])[axis] - value) <= 1e-12  # noqa: E731
        found = []
        for eid, conn in self.elements:
            if self.kind == 'C3D10':
                for label, corners in TET_FACES.items():
                    if all(on(conn[c]) for c in corners):
                        found.append((eid, label))
            else:
                for (ax, side), label in cc.FACE_OF.items():
                    corner_ids = [conn[c] for c, offset in enumerate(cc.HEX8_CORNERS)
                                  if offset[ax] == side]
                    if ax == axis and all(on(n) for n in corner_ids):
                        found.append((eid, label))
        return found

    def cards(self, elset):
        lines = ['*NODE, NSET=ALL_NODES']
        for key, n in sorted(self.ids.items(), key=lambda item: item[1]):
            lines.append('%d, %.12g, %.12g, %.12g' % (n, *self.coordinates(key)))
        lines.append('*ELEMENT, TYPE=%s, ELSET=%s' % (self.kind, elset))
        for eid, conn in self.elements:
            text = ', '.join(str(n) for n in conn)
            if len(conn) > 15:
                # CalculiX continues a 20-node record on a second line (trailing comma).
                text = ', '.join(str(n) for n in conn[:15]) + ',\n' + ', '.join(str(n) for n in conn[15:])
            lines.append('%d, %s' % (eid, text))
        return lines


def surface_cards(name, faces):
    by_label = {}
    for eid, label in faces:
        by_label.setdefault(label, []).append(eid)
    lines = []
    for label, ids in sorted(by_label.items()):
        lines += cc.elset_cards('%s_%s' % (name, label), ids)
    lines.append('*SURFACE, NAME=%s, TYPE=ELEMENT' % name)
    lines += ['%s_%s, %s' % (name, label, label) for label in sorted(by_label)]
    return lines


def make_deck(path, base_kind, slider_kind, mu, tie=False):
    if mu is None:
        base = QuadraticBox(base_kind, (0, 0, 0), (1, 1, 0.5), (3, 3, 2), 1, 1)
    else:
        # Wider than the slider, so that it slides on the base, not off its edge.
        base = QuadraticBox(base_kind, (-1 / 3, -1 / 3, 0), (4 / 3, 4 / 3, 0.5), (5, 5, 2), 1, 1)
    slider = QuadraticBox(slider_kind, (0, 0, 0.5), (1, 1, 1.0), (3, 3, 2), 10001, 10001)
    lines = ['*HEADING', 'Block on a block, %s slider on a %s base '
             '(tests/integration/contact/quadratic_blocks.py)' % (slider_kind, base_kind)]
    lines += base.cards('BASE') + slider.cards('SLIDER')
    lines += cc.nset_cards('BOTTOM', base.nodes_where(lambda x, y, z: abs(z) <= 1e-12))
    lines += cc.nset_cards('X0', base.nodes_where(lambda x, y, z: abs(x) <= 1e-12))
    lines += cc.nset_cards('Y0', base.nodes_where(lambda x, y, z: abs(y) <= 1e-12))
    lines += cc.nset_cards('SX0', slider.nodes_where(lambda x, y, z: abs(x) <= 1e-12))
    lines += cc.nset_cards('SY0', slider.nodes_where(lambda x, y, z: abs(y) <= 1e-12))
    lines += cc.nset_cards('TOP', slider.nodes_where(lambda x, y, z: abs(z - 1.0) <= 1e-12))
    lines += surface_cards('MASTER', base.faces_on(2, 0.5))
    lines += surface_cards('SLAVE', slider.faces_on(2, 0.5))
    lines += surface_cards('LOADED', slider.faces_on(2, 1.0))
    lines += cc.material_cards('BASE_MAT', 'BASE', E1, NU1)
    lines += cc.material_cards('SLIDER_MAT', 'SLIDER', E2, NU2)
    lines += cc.interaction_cards('INTERFACE', PENALTY, mu)
    if tie:
        lines += ['*TIE, NAME=GLUE', 'SLAVE, MASTER']
    else:
        lines += ['*CONTACT PAIR, INTERACTION=INTERFACE, TYPE=NODE TO SURFACE', 'SLAVE, MASTER']
    lines += ['*STEP', '*STATIC', '*BOUNDARY']
    if mu is None:
        lines += ['BOTTOM, 3, 3', 'X0, 1, 1', 'Y0, 2, 2', 'SX0, 1, 1', 'SY0, 2, 2']
    else:
        lines += ['BOTTOM, 1, 3', 'TOP, 1, 2']
    lines += ['*DSLOAD', 'LOADED, P, %.12g' % P,
              '*NODE PRINT, NSET=BOTTOM, TOTALS=ONLY', 'RF']
    if mu is None:
        lines += ['*NODE PRINT, NSET=SX0, TOTALS=ONLY', 'RF']
    lines += ['*CONTACT PRINT', 'CSTR', '*END STEP']
    if mu is not None:
        # The base holds the push and the pressure by its fixed bottom: T = -RF_x, N = RF_z.
        lines += ['*STEP', '*STATIC', '*BOUNDARY', 'TOP, 1, 1, %.12g' % PUSH,
                  '*NODE PRINT, NSET=BOTTOM, TOTALS=ONLY, FREQUENCY=1', 'RF',
                  '*CONTACT PRINT', 'CSTR', '*END STEP']
    cc.write_deck(path, lines)


def check(job, base_kind, slider_kind, mu, tolerance):
    checker = cc.Checker()
    blocks = cc.read_dat(job + '.dat')
    times, bottom = cc.totals(blocks, 'BOTTOM')
    area = 1.0
    label = '%s slider on %s base' % (slider_kind, base_kind)
    tables = cc.contact_tables(blocks)
    if mu is None:
        checker.relative(label + ': normal reaction of the base = p A', bottom[-1][2], P * area, 1e-9)
        _, roller = cc.totals(blocks, 'SX0')
        shear = np.array([values[1:3] for values in tables[-1][1].values()])
        checker.check(np.all(shear == 0.0), label + ': frictionless, no contact shear at any slave '
                      'node (the slider\'s x roller carries %.3e p A)' % abs(roller[-1][0]))
        pressures = np.array([values[0] for values in tables[-1][1].values()])
        spread = (pressures.max() - pressures.min()) / P
        print('     %d slave nodes, pressure min %.9g max %.9g (spread %.3e p)'
              % (len(pressures), pressures.min(), pressures.max(), spread))
        checker.check(pressures.min() >= 0.0, label + ': no slave node in tension')
        if slider_kind in EXACT_SLAVES:
            checker.check(spread <= tolerance and abs(pressures.mean() - P) <= tolerance * P,
                          label + ': contact pressure uniform = p at every slave node (spread '
                          '%.3e, mean %.9g; tolerance %g)' % (spread, pressures.mean(), tolerance))
    else:
        keep = times >= 1.5 - 1e-9
        ratio = -bottom[keep, 0] / bottom[keep, 2]
        checker.check(keep.sum() >= 1, label + ': %d output(s) in the last half of the push' % keep.sum())
        errors = np.abs(ratio / mu - 1.0)
        checker.check(errors.max() <= tolerance, label + ': sliding, |T/N - mu| / mu max %.3e '
                      '(tolerance %g; T/N %.7f .. %.7f)' % (errors.max(), tolerance, ratio.min(),
                                                           ratio.max()))
    checker.finish()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    sub = parser.add_subparsers(dest='command', required=True)
    for name in ('deck', 'check'):
        p = sub.add_parser(name)
        p.add_argument('path')
        p.add_argument('--base', choices=['C3D8', 'C3D20R', 'C3D10'], required=True)
        p.add_argument('--slider', choices=['C3D8', 'C3D20R', 'C3D10'], required=True)
        p.add_argument('--mu', type=float)
        if name == 'deck':
            p.add_argument('--tie', action='store_true', help='a *TIE instead of the contact pair')
        if name == 'check':
            p.add_argument('--tolerance', type=float, default=None)
    args = parser.parse_args()
    if args.command == 'deck':
        make_deck(args.path, args.base, args.slider, args.mu, args.tie)
    else:
        tolerance = args.tolerance if args.tolerance is not None else (1e-6 if args.mu is None else 1e-3)
        check(args.path, args.base, args.slider, args.mu, tolerance)


if __name__ == '__main__':
    main()
