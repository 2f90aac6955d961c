#!/usr/bin/python3
"""Meshes of every element kind from a structured grid of hexahedra (for the test decks).

  hex_grid(cells, box, distortion, rng) -> coords {id: x}, hexes [[8 corner ids]], boundary ids
      A cells[0] x cells[1] x cells[2] grid of the box [0, box]; interior nodes moved by up to
      `distortion` of a cell size in each direction (boundary nodes stay on their faces).
  convert(coords, hexes, kind) -> [(kind, [node ids]), ...]
      The hexahedra as elements of `kind` (CalculiX names; node order CalculiX's):
        C3D8, C3D8R, C3D8I       the hexahedra;
        C3D20, C3D20R            with a mid-side node at the middle of each edge;
        C3D4, C3D10              six tetrahedra per hexahedron (Kuhn's subdivision along the
                                 diagonal from corner 1 to corner 7: conforming, every cell
                                 split the same way);
        C3D6, C3D15              two wedges per hexahedron (split along the diagonal 1-3 of
                                 its faces z = const, the same in every cell, so conforming);
        MIXED                    C3D8 and C3D6 (alternate cells split into wedges; a wedge's
                                 quadrilateral faces match the hexahedra's);
        MIXED20                  C3D20 and C3D15 likewise.
      Mid-side nodes are added to `coords` (ids after the largest) at the middle of the
      straight edge, shared between elements. Every element is checked to have a positive
      volume in CalculiX's node order (tetrahedra and wedges are reoriented if needed).

Node orders (CalculiX manual, section 6.2 "Element types"): C3D8 corners 1-4 on the bottom
face counter-clockwise seen from the top, 5-8 above them; C3D20 adds the mid-side nodes of
the edges 1-2, 2-3, 3-4, 4-1, 5-6, 6-7, 7-8, 8-5, 1-5, 2-6, 3-7, 4-8; C3D4 corners 1-3
counter-clockwise seen from 4; C3D10 adds the edges 1-2, 2-3, 3-1, 1-4, 2-4, 3-4; C3D6
corners 1-3 counter-clockwise seen from 4-6; C3D15 adds the edges 1-2, 2-3, 3-1, 4-5, 5-6,
6-4, 1-4, 2-5, 3-6.
"""

import itertools

import numpy as np

#: Integration points of each kind (CalculiX's rules).
POINTS = {"C3D4": 1, "C3D6": 2, "C3D8": 8, "C3D8R": 1, "C3D8I": 8, "C3D10": 4, "C3D15": 9,
          "C3D20": 27, "C3D20R": 8}
#: Nodes of each kind.
NODES = {"C3D4": 4, "C3D6": 6, "C3D8": 8, "C3D8R": 8, "C3D8I": 8, "C3D10": 10, "C3D15": 15,
         "C3D20": 20, "C3D20R": 20}
HEX20_EDGES = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4),
               (0, 4), (1, 5), (2, 6), (3, 7)]
TET10_EDGES = [(0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3)]
WEDGE15_EDGES = [(0, 1), (1, 2), (2, 0), (3, 4), (4, 5), (5, 3), (0, 3), (1, 4), (2, 5)]
#: Corner (bits i, j, k) -> local C3D8 node index.
HEX_CORNER = {(0, 0, 0): 0, (1, 0, 0): 1, (1, 1, 0): 2, (0, 1, 0): 3,
              (0, 0, 1): 4, (1, 0, 1): 5, (1, 1, 1): 6, (0, 1, 1): 7}
KINDS = ["C3D4", "C3D6", "C3D8", "C3D8R", "C3D8I", "C3D10", "C3D15", "C3D20", "C3D20R",
         "MIXED", "MIXED20"]


def hex_grid(cells, box, distortion, rng):
    cells = np.asarray(cells)
    box = np.asarray(box, dtype=float)
    n = cells + 1
    h = box / cells
    ids = np.arange(1, n.prod() + 1).reshape(n[2], n[1], n[0])  # ids[k, j, i]
    coords, boundary = {}, []
    for k, j, i in itertools.product(range(n[2]), range(n[1]), range(n[0])):
        index = np.array([i, j, k])
        inside = (index > 0) & (index < cells)
        x = index * h + np.where(inside, rng.uniform(-distortion, distortion, 3) * h, 0.0)
        coords[int(ids[k, j, i])] = x
        if not inside.all():
            boundary.append(int(ids[k, j, i]))
    hexes = []
    for k, j, i in itertools.product(range(cells[2]), range(cells[1]), range(cells[0])):
        corner = {bits: int(ids[k + bits[2], j + bits[1], i + bits[0]]) for bits in HEX_CORNER}
        hexes.append([corner[bits] for bits in sorted(HEX_CORNER, key=HEX_CORNER.get)])
    return coords, hexes, boundary


def _volume(coords, corners):
    a, b, c, d = (np.asarray(coords[n]) for n in corners[:4])
    return np.dot(np.cross(b - a, c - a), d - a)


def _tetrahedra(hex_nodes, coords):
    """Kuhn's six tetrahedra of a hexahedron: paths from corner 000 to 111 along the axes."""
    tets = []
    for order in itertools.permutations(range(3)):
        bits = [0, 0, 0]
        path = [tuple(bits)]
        for axis in order:
            bits[axis] = 1
            path.append(tuple(bits))
        nodes = [hex_nodes[HEX_CORNER[p]] for p in path]
        if _volume(coords, nodes) < 0.0:
            nodes[1], nodes[2] = nodes[2], nodes[1]
        tets.append(nodes)
    return tets


def _wedges(hex_nodes):
    """Two wedges: bottom triangles (1, 2, 3) and (1, 3, 4), extruded to the top face."""
    bottom = [[0, 1, 2], [0, 2, 3]]
    return [[hex_nodes[a] for a in tri] + [hex_nodes[a + 4] for a in tri] for tri in bottom]


class _MidSides:
    def __init__(self, coords):
        self.coords = coords
        self.next_id = max(coords) + 1
        self.ids = {}

    def node(self, a, b):
        key = (min(a, b), max(a, b))
        if key not in self.ids:
            self.ids[key] = self.next_id
            self.coords[self.next_id] = 0.5 * (np.asarray(self.coords[a]) +
                                               np.asarray(self.coords[b]))
            self.next_id += 1
        return self.ids[key]

    def add(self, corners, edges):
        return corners + [self.node(corners[a], corners[b]) for a, b in edges]


def convert(coords, hexes, kind):
    mid = _MidSides(coords)
    elements = []
    for number, h in enumerate(hexes):
        if kind in ("C3D8", "C3D8R", "C3D8I"):
            elements.append((kind, list(h)))
        elif kind in ("C3D20", "C3D20R"):
            elements.append((kind, mid.add(list(h), HEX20_EDGES)))
        elif kind in ("C3D4", "C3D10"):
            for tet in _tetrahedra(h, coords):
                elements.append((kind, tet if kind == "C3D4" else mid.add(tet, TET10_EDGES)))
        elif kind in ("C3D6", "C3D15"):
            for wedge in _wedges(h):
                elements.append((kind, wedge if kind == "C3D6" else mid.add(wedge, WEDGE15_EDGES)))
        elif kind == "MIXED":
            elements += [("C3D8", list(h))] if number % 2 == 0 else \
                [("C3D6", w) for w in _wedges(h)]
        elif kind == "MIXED20":
            elements += [("C3D20", mid.add(list(h), HEX20_EDGES))] if number % 2 == 0 else \
                [("C3D15", mid.add(w, WEDGE15_EDGES)) for w in _wedges(h)]
        else:
            raise ValueError(f"unknown kind {kind}")
    for kind_name, nodes in elements:
        if len(nodes) != NODES[kind_name]:
            raise AssertionError(f"{kind_name} element with {len(nodes)} nodes")
        if kind_name in ("C3D4", "C3D10") and _volume(coords, nodes) <= 0.0:
            raise AssertionError("inverted tetrahedron")
        if kind_name in ("C3D6", "C3D15"):
            a, b, c, d = (np.asarray(coords[n]) for n in (nodes[0], nodes[1], nodes[2], nodes[3]))
            if np.dot(np.cross(b - a, c - a), d - a) <= 0.0:
                raise AssertionError("inverted wedge")
    return elements


def mid_side_nodes(elements, n_corners):
    """[((corner a, corner b), mid-side node)] of the quadratic elements (nodes after the
    corners; n_corners: the number of corner nodes of the grid, whose ids come first)."""
    pairs = {}
    for kind, nodes in elements:
        edges = {"C3D20": HEX20_EDGES, "C3D20R": HEX20_EDGES, "C3D10": TET10_EDGES,
                 "C3D15": WEDGE15_EDGES}.get(kind)
        if edges is None:
            continue
        corners = {"C3D20": 8, "C3D20R": 8, "C3D10": 4, "C3D15": 6}[kind]
        for (a, b), node in zip(edges, nodes[corners:]):
            pairs[node] = (nodes[a], nodes[b])
    return [(pair, node) for node, pair in sorted(pairs.items())]


def element_cards(elements, elset, first_id=1):
    """*ELEMENT cards (one per kind, in order of first appearance), ids from first_id in card
    order (CalculiX prints an element set in the order it was defined, fcs3d by id: the same
    when ids increase through the cards), each
    record at most 16 entries per line (CalculiX's and Abaqus's limit), continued after a
    trailing comma. Returns the lines and [(element id, kind)] in the order of the cards (the
    order of the elements in fcs3d's results)."""
    lines, ids = [], []
    by_kind = {}
    for kind, nodes in elements:
        by_kind.setdefault(kind, []).append(nodes)
    number = first_id
    for kind, members in by_kind.items():
        members = [(number + i, nodes) for i, nodes in enumerate(members)]
        number += len(members)
        lines.append(f"*ELEMENT, TYPE={kind}, ELSET={elset}")
        for element, nodes in members:
            entries = [str(element)] + [str(n) for n in nodes]
            chunks = [entries[i:i + 16] for i in range(0, len(entries), 16)]
            lines += [", ".join(chunk) + ("," if i < len(chunks) - 1 else "")
                      for i, chunk in enumerate(chunks)]
            ids.append((element, kind))
    return lines, ids
