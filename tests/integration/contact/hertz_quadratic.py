#!/usr/bin/python3
"""Hertz line contact with C3D20R meshes: the cylinder on a block of hertz.py, with every
hexahedron of gmsh's mesh turned into a 20-node one (issue 16).

    hertz_quadratic.py deck JOB.inp --mesh JOB.msh --hc H
    hertz_quadratic.py check JOB --hc H [--tolerance T] [--table-row FILE]

The linear mesh comes from hertz.py (tests/data/contact/hertz_cylinder.geo through gmsh,
ASCII msh 4.1). Each hexahedron gets its 12 mid-side nodes; a mid-side node between two nodes
of the cylinder's circular arc is put on the circle (radius R about (0, R)), so that the slave
surface is the quadratic interpolation of the arc, not the chord. The deck writes the mesh as
*NODE and *ELEMENT, TYPE=C3D20R, and the physical groups of the .msh as element sets (CAP,
BLOCK), node sets (every node of the group's elements or faces, mid-side nodes included) and
element-face surfaces (CAP_BOTTOM: slave, 8-node faces; BLOCK_TOP: master, 8-node faces;
CAP_TOP, BLOCK_BOTTOM). The model, the loading and the checks are hertz.py's (frictionless,
E_n = 10 E / hc, the cylinder's top moved down by 0.08), measured on the z = 0 layer of slave
nodes, which holds the corner and the mid-side nodes along the arc.

What differs from the 8-node mesh: the slave shares of the 8-node faces are CalculiX's 1/100
(corners) and 24/100 (mid-sides) of the face area (doc/theory.md 4.2), so the mid-side nodes
carry the load and pull the two surfaces together there; the corner nodes between them end
with a small positive gap and stay open (measured: every corner node in the contact zone).
`check` therefore takes the closed nodes as the contact and ignores the open corner nodes
between them: the peak nodal pressure against p0 (Hertz: p0 = 2 P' / (pi a)), p0 and a from
a least-squares fit of p^2 = p0^2 - (p0/a)^2 x^2 to the closed nodes with |x| < 0.8 x_last,
all within --tolerance (default 5 %), and the edge bracket [x_last, first open node past it]
containing a (to hc/2), as in hertz.py.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import contact_common as cc  # noqa: E402
import hertz  # noqa: E402

HEX20_EDGES = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4),
               (0, 4), (1, 5), (2, 6), (3, 7)]
# CalculiX's faces of the hexahedron (corner positions, 0-based) and their mid-side edges.
HEX_FACES = {'S1': (0, 1, 2, 3), 'S2': (4, 7, 6, 5), 'S3': (0, 4, 5, 1), 'S4': (1, 5, 6, 2),
             'S5': (2, 6, 7, 3), 'S6': (3, 7, 4, 0)}
GMSH_HEX, GMSH_QUAD = 5, 3


def read_msh(path):
    """Nodes {tag: xyz}, hexahedra [(tag, nodes, volume entity)], quads [(nodes, surface
    entity)], physical names {(dim, tag): name} and entity physicals {(dim, entity): [tags]}
    of an ASCII msh 4.1 file."""
    with open(path) as f:
        lines = [line.strip() for line in f]
    sections = {}
    i = 0
    while i < len(lines):
        if lines[i].startswith('$') and not lines[i].startswith('$End'):
            name = lines[i][1:]
            j = lines.index('$End' + name, i)
            sections[name] = lines[i + 1:j]
            i = j
        i += 1
    names = {}
    for line in sections['PhysicalNames'][1:]:
        dim, tag, name = line.split(maxsplit=2)
        names[(int(dim), int(tag))] = name.strip('"')
    entity_physicals = {}
    ent = sections['Entities']
    counts = [int(v) for v in ent[0].split()]
    row = 1
    for dim, count in enumerate(counts):
        for _ in range(count):
            fields = ent[row].split()
            row += 1
            tag = int(fields[0])
            at = 4 if dim == 0 else 7
            n_phys = int(fields[at])
            entity_physicals[(dim, tag)] = [int(v) for v in fields[at + 1:at + 1 + n_phys]]
    nodes = {}
    sec = sections['Nodes']
    n_blocks = int(sec[0].split()[0])
    row = 1
    for _ in range(n_blocks):
        _, _, _, count = (int(v) for v in sec[row].split())
        row += 1
        tags = [int(sec[row + k]) for k in range(count)]
        for k, tag in enumerate(tags):
            nodes[tag] = np.array([float(v) for v in sec[row + count + k].split()[:3]])
        row += 2 * count
    hexes, quads = [], []
    sec = sections['Elements']
    n_blocks = int(sec[0].split()[0])
    row = 1
    for _ in range(n_blocks):
        dim, entity, etype, count = (int(v) for v in sec[row].split())
        row += 1
        for k in range(count):
            fields = [int(v) for v in sec[row + k].split()]
            if etype == GMSH_HEX:
                hexes.append((fields[0], fields[1:9], entity))
            elif etype == GMSH_QUAD:
                quads.append((fields[1:5], entity))
        row += count
    return nodes, hexes, quads, names, entity_physicals


def on_arc(x):
    return abs(np.hypot(x[0], x[1] - hertz.RADIUS) - hertz.RADIUS) <= 1e-6 and x[1] < 5.0


def make_deck(path, mesh, hc):
    nodes, hexes, quads, names, physicals = read_msh(mesh)
    next_tag = [max(nodes) + 1]
    mid = {}
    elements = []
    for tag, corners, entity in hexes:
        conn = list(corners)
        for a, b in HEX20_EDGES:
            conn.append(mid_node(nodes, mid, corners[a], corners[b], next_tag))
        elements.append((tag, conn, entity))
    lines = ['*HEADING', 'Cylinder on a block, plane strain, C3D20R, hc = %g '
             '(tests/integration/contact/hertz_quadratic.py)' % hc, '*NODE, NSET=ALL_NODES']
    lines += ['%d, %.15g, %.15g, %.15g' % (tag, *x) for tag, x in sorted(nodes.items())]
    lines.append('*ELEMENT, TYPE=C3D20R, ELSET=ALL_ELEMENTS')
    for tag, conn, _ in elements:
        lines.append('%d, %s,' % (tag, ', '.join(str(n) for n in conn[:15])))
        lines.append(', '.join(str(n) for n in conn[15:]))
    lines += group_cards(names, physicals, elements, quads, 8, face_of, face_all_nodes, 1)
    lines += model_cards(hc)
    cc.write_deck(path, lines)


def mid_node(nodes, mid, a, b, next_tag):
    """The mid-side node of edge (a, b), made on first use (tag next_tag[0], then advanced):
    the mid-point, or on the circle when a and b lie on the cylinder's arc."""
    key = tuple(sorted((a, b)))
    if key not in mid:
        x = 0.5 * (nodes[key[0]] + nodes[key[1]])
        if on_arc(nodes[key[0]]) and on_arc(nodes[key[1]]):
            centre = np.array([0.0, hertz.RADIUS])
            d = x[:2] - centre
            x = np.array([*(centre + hertz.RADIUS * d / np.linalg.norm(d)), x[2]])
        nodes[next_tag[0]] = x
        mid[key] = next_tag[0]
        next_tag[0] += 1
    return mid[key]


def group_cards(names, physicals, elements, quads, n_corners, face_of, face_all_nodes,
                faces_per_quad):
    """The gmsh physical groups as deck cards: volumes as element and node sets; surfaces as
    element-face surfaces (faces_per_quad element faces on each of gmsh's quadrangles, found
    by face_of(conn, corners)) and node sets of every node of those faces."""
    lines = []
    for (dim, tag), name in sorted(names.items()):
        if dim != 3:
            continue
        members = [e for e in elements if tag in physicals.get((3, e[2]), [])]
        lines += cc.elset_cards(name, [e[0] for e in members])
        lines += cc.nset_cards(name, sorted({n for e in members for n in e[1]}))
    node_elements = {}
    for e in elements:
        for n in e[1][:n_corners]:
            node_elements.setdefault(n, []).append(e)
    for (dim, tag), name in sorted(names.items()):
        if dim != 2:
            continue
        faces, face_nodes = {}, set()
        for quad, entity in quads:
            if tag not in physicals.get((2, entity), []):
                continue
            found = 0
            for e in {e[0]: e for n in quad for e in node_elements[n]}.values():
                label = face_of(e[1], set(quad))
                if label:
                    faces.setdefault(label, []).append(e[0])
                    face_nodes.update(face_all_nodes(e[1], label))
                    found += 1
            if found != faces_per_quad:
                cc.fail('quadrangle %s of %s: %d element faces on it, expected %d'
                        % (quad, name, found, faces_per_quad))
        for label, ids in sorted(faces.items()):
            lines += cc.elset_cards('%s_%s' % (name, label), sorted(ids))
        lines.append('*SURFACE, NAME=%s, TYPE=ELEMENT' % name)
        lines += ['%s_%s, %s' % (name, label, label) for label in sorted(faces)]
        lines += cc.nset_cards(name, sorted(face_nodes))
    return lines


def model_cards(hc):
    """Material, frictionless interface (E_n = 10 E / hc), pair and the step of hertz.py."""
    lines = ['*ELSET, ELSET=BODIES', 'CAP, BLOCK']
    lines += cc.material_cards('MAT', 'BODIES', hertz.YOUNG, hertz.POISSON)
    lines += cc.interaction_cards('INTERFACE', 10.0 * hertz.YOUNG / hc)
    lines += ['*CONTACT PAIR, INTERACTION=INTERFACE, TYPE=NODE TO SURFACE', 'CAP_BOTTOM, BLOCK_TOP']
    lines += ['*STEP', '*STATIC', '1., 1.', '*BOUNDARY', 'CAP, 3, 3', 'BLOCK, 3, 3',
              'BLOCK_BOTTOM, 1, 2', 'CAP_TOP, 1, 1', 'CAP_TOP, 2, 2, %.12g' % -hertz.APPROACH,
              '*NODE PRINT, NSET=CAP_TOP, TOTALS=ONLY', 'RF', '*CONTACT PRINT', 'CSTR',
              '*CONTACT FILE', 'CSTR', '*END STEP']
    return lines


def face_of(conn, corners):
    for label, positions in HEX_FACES.items():
        if {conn[p] for p in positions} == corners:
            return label
    return None


def face_all_nodes(conn, label):
    positions = HEX_FACES[label]
    out = [conn[p] for p in positions]
    for k, (a, b) in enumerate(HEX20_EDGES):
        if a in positions and b in positions:
            out.append(conn[8 + k])
    return out


def check(job, hc, tolerance, table_row, kind='C3D20R'):
    checker = cc.Checker()
    times, forces = cc.totals(cc.read_dat(job + '.dat'), 'CAP_TOP')
    frame = [f for f in cc.contact_frames(job + '.h5', hertz.PAIR) if f['step'] == 1][-1]
    load = -forces[np.argmin(np.abs(times - 1.0))][1] / hc
    a = np.sqrt(4.0 * load * hertz.RADIUS / (np.pi * hertz.E_STAR))
    p0 = 2.0 * load / (np.pi * a)
    nodes = hertz.layer(frame)
    x, p = nodes['x'][:, 0], nodes['pressure']
    closed = (nodes['status'] != cc.OPEN) & (p > 0)
    x_last = np.abs(x[closed]).max()
    beyond = (~closed) & (np.abs(x) > x_last)
    x_open = np.abs(x[beyond]).min()
    inside_open = int(np.sum((~closed) & (np.abs(x) < x_last)))
    inner = closed & (np.abs(x) < 0.8 * x_last)
    slope, intercept = np.polyfit(x[inner] ** 2, p[inner] ** 2, 1)
    p0_fit, a_fit = np.sqrt(intercept), np.sqrt(-intercept / slope)
    print('Hertz (%s, hc %g): P\' = %.6g, a = %.5f, p0 = %.5f; %d closed nodes per layer, '
          '%d open nodes between them' % (kind, hc, load, a, p0, closed.sum(), inside_open))
    checker.relative('peak nodal pressure p_max vs p0', p[closed].max(), p0, tolerance)
    checker.relative('fitted p0', p0_fit, p0, tolerance)
    checker.relative('fitted half-width a', a_fit, a, tolerance)
    checker.check(x_last - 0.5 * hc <= a <= x_open + 0.5 * hc, 'contact edge: outermost closed '
                  'node %.4f, first open node past it %.4f, theory a = %.4f' % (x_last, x_open, a))
    print('summary hertz %s hc %g: a/hc %.2f, p_max/p0 - 1 = %+.4f, p0_fit/p0 - 1 = %+.4f, '
          'a_fit/a - 1 = %+.4f, edge bracket [%.4f, %.4f] vs a %.4f'
          % (kind, hc, a / hc, p[closed].max() / p0 - 1, p0_fit / p0 - 1, a_fit / a - 1, x_last, x_open, a))
    if table_row:
        with open(table_row, 'w') as out:
            out.write(repr(dict(hc=hc, a=a, p0=p0, p_max=p[closed].max(), p0_fit=p0_fit,
                                a_fit=a_fit, x_last=x_last, x_open=x_open)) + '\n')
    checker.finish()


def main(make_deck=make_deck, kind='C3D20R', description=__doc__):
    """The command line of a Hertz deck writer and checker (also hertz_tet.py's)."""
    parser = argparse.ArgumentParser(description=description.split('\n')[0])
    sub = parser.add_subparsers(dest='command', required=True)
    d = sub.add_parser('deck')
    d.add_argument('path')
    d.add_argument('--mesh', required=True)
    d.add_argument('--hc', type=float, required=True)
    c = sub.add_parser('check')
    c.add_argument('job')
    c.add_argument('--hc', type=float, required=True)
    c.add_argument('--tolerance', type=float, default=0.05)
    c.add_argument('--table-row')
    args = parser.parse_args()
    if args.command == 'deck':
        make_deck(args.path, args.mesh, args.hc)
    else:
        check(args.job, args.hc, args.tolerance, args.table_row, kind)


if __name__ == '__main__':
    main()
