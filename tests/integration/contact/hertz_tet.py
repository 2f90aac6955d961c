#!/usr/bin/python3
"""Hertz line contact with C3D10 meshes: the cylinder on a block of hertz.py, each hexahedron
of gmsh's mesh split into tetrahedra with their mid-side nodes (issue 16).

    hertz_tet.py deck JOB.inp --mesh JOB.msh --hc H
    hertz_tet.py check JOB --hc H [--tolerance T] [--table-row FILE]

The linear mesh comes from hertz.py (tests/data/contact/hertz_cylinder.geo through gmsh,
ASCII msh 4.1): one layer of hexahedra extruded in z. Each hexahedron is cut into two wedges
by a diagonal of its base quadrangle (the same diagonal on the top), and each wedge into three
tetrahedra by the smallest-vertex rule of Dompierre et al. (1999, "How to subdivide pyramids,
prisms and hexahedra into tetrahedra"): the diagonal of every quadrilateral side runs through
its smallest node id, so two wedges sharing a side cut it the same way and the tetrahedral mesh
is conforming. Every edge gets a mid-side node; one between two nodes of the cylinder's
circular arc is put on the circle (radius R about (0, R)), as in hertz_quadratic.py. Faces:
CalculiX's numbering of C3D10 (S1 = 1-2-3, S2 = 1-4-2, S3 = 2-4-3, S4 = 3-4-1).

The slave faces are 6-node triangles: their consistent shares of a uniform pressure are 0 at
the corners and 1/3 of the face area at each mid-side node (doc/theory.md 4.2), so the corner
nodes carry nothing and are not slave nodes; the pressure is read at the mid-side nodes of
the z = 0 layer (on the arc edges). The model, the loading and the checks are those of
hertz_quadratic.py (frictionless, E_n = 10 E / hc, the cylinder's top moved down by 0.08).
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import contact_common as cc  # noqa: E402
import hertz  # noqa: E402
import hertz_quadratic as hq  # noqa: E402

# C3D10 edges (corner positions, 0-based) in CalculiX's mid-side node order 5..10.
TET10_EDGES = [(0, 1), (1, 2), (2, 0), (0, 3), (1, 3), (2, 3)]
TET_FACES = {'S1': (0, 1, 2), 'S2': (0, 3, 1), 'S3': (1, 3, 2), 'S4': (2, 3, 0)}


def hex_layers(corners, nodes):
    """The base (z = 0) and top corners of an extruded hexahedron, top[i] above base[i]."""
    low = [n for n in corners if abs(nodes[n][2]) < 1e-9]
    if len(low) != 4:
        cc.fail('hexahedron %s is not one z layer' % corners)
    # gmsh's hexahedron: corners i and i + 4 share an edge.
    if corners[0] in low:
        return corners[:4], corners[4:]
    return corners[4:], corners[:4]


def wedge_tets(bottom, top):
    """Three tetrahedra of the wedge (bottom triangle, top triangle above it) by the
    smallest-vertex rule (Dompierre et al. 1999, table 2)."""
    v = list(bottom) + list(top)
    k = v.index(min(v))
    # Rotate (and flip) so that the smallest vertex is v0, the wedge (v0 v1 v2 | v3 v4 v5).
    if k >= 3:
        v = v[3:] + v[:3]
        k -= 3
    r = [(k + i) % 3 for i in range(3)]
    v = [v[r[0]], v[r[1]], v[r[2]], v[3 + r[0]], v[3 + r[1]], v[3 + r[2]]]
    if min(v[1], v[5]) < min(v[2], v[4]):
        return [(v[0], v[1], v[2], v[5]), (v[0], v[1], v[5], v[4]), (v[0], v[4], v[5], v[3])]
    return [(v[0], v[1], v[2], v[4]), (v[0], v[4], v[2], v[5]), (v[0], v[4], v[5], v[3])]


def positive(tet, nodes):
    a, b, c, d = (nodes[n] for n in tet)
    if np.dot(np.cross(b - a, c - a), d - a) < 0:
        return (tet[0], tet[2], tet[1], tet[3])
    return tet


def make_deck(path, mesh, hc):
    nodes, hexes, quads, names, physicals = hq.read_msh(mesh)
    tets = []
    for _, corners, entity in hexes:
        base, top = hex_layers(corners, nodes)
        for tri in ((0, 1, 2), (0, 2, 3)):
            for tet in wedge_tets([base[i] for i in tri], [top[i] for i in tri]):
                tets.append((positive(tet, nodes), entity))
    next_tag = [max(nodes) + 1]
    mid = {}
    elements = []
    for number, (corners, entity) in enumerate(tets, start=1):
        conn = list(corners)
        for a, b in TET10_EDGES:
            conn.append(hq.mid_node(nodes, mid, corners[a], corners[b], next_tag))
        elements.append((number, conn, entity))
    lines = ['*HEADING', 'Cylinder on a block, plane strain, C3D10, hc = %g '
             '(tests/integration/contact/hertz_tet.py)' % hc, '*NODE, NSET=ALL_NODES']
    used = sorted({n for e in elements for n in e[1]})
    lines += ['%d, %.15g, %.15g, %.15g' % (tag, *nodes[tag]) for tag in used]
    lines.append('*ELEMENT, TYPE=C3D10, ELSET=ALL_ELEMENTS')
    lines += ['%d, %s' % (tag, ', '.join(str(n) for n in conn)) for tag, conn, _ in elements]
    # Each quadrangle of gmsh's surfaces is cut by a diagonal into two tetrahedron faces.
    lines += hq.group_cards(names, physicals, elements, quads, 4, face_of, face_all_nodes, 2)
    lines += hq.model_cards(hc)
    cc.write_deck(path, lines)


def face_of(conn, corners):
    """The label of the face of tetrahedron `conn` whose three corners lie in `corners`."""
    for label, positions in TET_FACES.items():
        if {conn[p] for p in positions} <= corners:
            return label
    return None


def face_all_nodes(conn, label):
    positions = TET_FACES[label]
    out = [conn[p] for p in positions]
    for k, (a, b) in enumerate(TET10_EDGES):
        if a in positions and b in positions:
            out.append(conn[4 + k])
    return out


if __name__ == '__main__':
    hq.main(make_deck, 'C3D10', __doc__)
