#!/usr/bin/python3
"""Check a mesh of input/fault_bend/fault_bend.geo (gmsh MSH 4.1, ASCII) and print its statistics.

Usage:
    /usr/bin/python3 post/check_fault_mesh.py MESH.msh [--geo fault_bend.geo]
                                               [-setnumber NAME VALUE ...]
Give the same -setnumber values as to gmsh (--setnumber is accepted too): the expected
geometry (trace C-D-E-F-G, plate size, layers) is computed from the .geo file's defaults with
those overrides (fault_profile.py).

Checks (each failure is listed; exit 1 if any, 0 if none, 2 for bad usage or unreadable file):
  - the physical groups UPPER, LOWER (volumes), A, B, X0, Y0, Z0 and the eight fault sides
    CD_UPPER ... FG_LOWER (surfaces) exist and are not empty (and DF_UPPER, DF_LOWER, if
    present, are D-E + E-F of their side);
  - every 3D element is an 8-node hexahedron, and every one is right-handed (positive
    Jacobian determinant at all eight corners, gmsh/C3D8 node order);
  - the blocks share no node; each block's volume is its polygon's area x thickness, and the
    hexahedra of UPPER lie in the upper-left polygon C D E F G (0, height);
  - every quadrangle of a surface group is a face of a hexahedron of the right block;
  - A, B, X0, Y0, Z0 lie on y = height, x = width, x = 0, y = 0, z = 0, and their areas are
    the faces' areas; each fault side lies on its segment of the trace (distance below
    1e-6 x plate size) and covers it (area = segment length x thickness);
  - the nodes of the block's z = 0 face sit on layers + 1 levels z = k thickness / layers.
Reports: nodes, hexahedra, degrees of freedom (3 per node), per block; quadrangles and nodes of
each group; node spacing along each fault segment on both sides; how many upper-side fault
nodes coincide in position with a lower-side node (they are distinct nodes either way);
element quality (smallest scaled Jacobian, largest edge ratio).
"""

import argparse
import sys

import numpy as np
from matplotlib.path import Path

import fault_profile

VOLUME_GROUPS = ("UPPER", "LOWER")
FACE_GROUPS = ("A", "B", "X0", "Y0", "Z0")
FAULT_GROUPS = tuple(f"{seg}_{side}" for seg, _, _ in fault_profile.SEGMENTS
                     for side in ("UPPER", "LOWER"))
GMSH_QUAD, GMSH_HEXAHEDRON = 3, 5
#: Faces of a C3D8 / gmsh hexahedron (0-based local nodes), outward normals.
HEX_FACES = ((0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7))
#: Natural coordinates of the eight corners, gmsh order.
CORNERS = np.array([[-1, -1, -1], [1, -1, -1], [1, 1, -1], [-1, 1, -1],
                    [-1, -1, 1], [1, -1, 1], [1, 1, 1], [-1, 1, 1]], dtype=float)


class MeshError(Exception):
    """The file cannot be read as an ASCII MSH 4.1 mesh."""


def read_msh41(path):
    """Nodes {tag: xyz}, element blocks [(dim, entity, type, (n, k) tags)], physical groups
    {name: (dim, tag)} and entity -> physical tags {(dim, entity): [tags]} of an ASCII MSH 4.1
    file."""
    with open(path, "rb") as handle:
        raw = handle.read()
    try:
        lines = raw.decode("ascii").split("\n")
    except UnicodeDecodeError as error:
        raise MeshError(f"{path}: not an ASCII MSH file (binary meshes are not read here)") \
            from error
    position = {line.strip(): i for i, line in enumerate(lines) if line.startswith("$")}
    for section in ("$MeshFormat", "$Nodes", "$Elements"):
        if section not in position:
            raise MeshError(f"{path}: no {section} section")
    version, file_type = lines[position["$MeshFormat"] + 1].split()[:2]
    if not version.startswith("4.1") or file_type != "0":
        raise MeshError(f"{path}: MSH {version} (file type {file_type}); expected ASCII 4.1")
    groups = {}
    if "$PhysicalNames" in position:
        i = position["$PhysicalNames"]
        for line in lines[i + 2:i + 2 + int(lines[i + 1])]:
            dim, tag, name = line.split(maxsplit=2)
            groups[name.strip().strip('"').upper()] = (int(dim), int(tag))
    entity_groups = read_entities(lines, position.get("$Entities"))
    nodes = {}
    i = position["$Nodes"]
    n_blocks = int(lines[i + 1].split()[0])
    k = i + 2
    for _ in range(n_blocks):
        _, _, parametric, n = (int(v) for v in lines[k].split())
        if parametric:
            raise MeshError(f"{path}: parametric node coordinates are not read here")
        tags = [int(v) for v in lines[k + 1:k + 1 + n]]
        coordinates = np.loadtxt(lines[k + 1 + n:k + 1 + 2 * n], ndmin=2) if n else []
        for tag, xyz in zip(tags, coordinates):
            nodes[tag] = xyz
        k += 1 + 2 * n
    blocks = []
    i = position["$Elements"]
    n_blocks = int(lines[i + 1].split()[0])
    k = i + 2
    for _ in range(n_blocks):
        dim, entity, element_type, n = (int(v) for v in lines[k].split())
        table = np.loadtxt(lines[k + 1:k + 1 + n], dtype=np.int64, ndmin=2)
        blocks.append((dim, entity, element_type, table))
        k += 1 + n
    return nodes, blocks, groups, entity_groups


def read_entities(lines, start):
    """{(dim, entity tag): [physical tags]} from the $Entities section."""
    if start is None:
        return {}
    counts = [int(v) for v in lines[start + 1].split()]
    result = {}
    k = start + 2
    for dim, count in enumerate(counts):
        for _ in range(count):
            values = lines[k].split()
            k += 1
            tag = int(values[0])
            skip = 4 if dim == 0 else 7
            n_physical = int(values[skip])
            result[(dim, tag)] = [int(v) for v in values[skip + 1:skip + 1 + n_physical]]
    return result


class Report:
    def __init__(self):
        self.problems = []

    def fail(self, text):
        self.problems.append(text)

    def check(self, condition, text):
        if not condition:
            self.fail(text)
        return condition


def group_elements(blocks, entity_groups, group, element_type):
    dim, tag = group
    tables = [table for d, entity, t, table in blocks
              if d == dim and t == element_type and tag in entity_groups.get((d, entity), [])]
    return np.vstack(tables) if tables else np.zeros((0, 9 if element_type == 5 else 5), int)


def hex_geometry(x):
    """Corner Jacobian determinants (ne, 8), volumes (ne), scaled Jacobians (ne) and edge
    ratios (ne) of hexahedra with corner coordinates x (ne, 8, 3)."""
    dets = np.empty(x.shape[:2])
    scaled = np.full(len(x), np.inf)
    for a, (xi, eta, zeta) in enumerate(CORNERS):
        dn = shape_derivatives(xi, eta, zeta)            # (8, 3)
        jac = np.einsum("eai,aj->eij", x, dn)            # dx_i / dxi_j
        dets[:, a] = np.linalg.det(jac)
        norms = np.linalg.norm(jac, axis=1).prod(axis=1)
        scaled = np.minimum(scaled, dets[:, a] / norms)
    gauss = 1.0 / np.sqrt(3.0)
    volume = np.zeros(len(x))
    for xi in (-gauss, gauss):
        for eta in (-gauss, gauss):
            for zeta in (-gauss, gauss):
                jac = np.einsum("eai,aj->eij", x, shape_derivatives(xi, eta, zeta))
                volume += np.linalg.det(jac)
    edges = [(0, 1), (1, 2), (2, 3), (3, 0), (4, 5), (5, 6), (6, 7), (7, 4),
             (0, 4), (1, 5), (2, 6), (3, 7)]
    lengths = np.stack([np.linalg.norm(x[:, b] - x[:, a], axis=1) for a, b in edges], axis=1)
    return dets, volume, scaled, lengths.max(axis=1) / lengths.min(axis=1)


def shape_derivatives(xi, eta, zeta):
    """dN_a / d(xi, eta, zeta) of the trilinear hexahedron at one point, (8, 3)."""
    c = CORNERS
    return 0.125 * np.stack([c[:, 0] * (1 + c[:, 1] * eta) * (1 + c[:, 2] * zeta),
                             c[:, 1] * (1 + c[:, 0] * xi) * (1 + c[:, 2] * zeta),
                             c[:, 2] * (1 + c[:, 0] * xi) * (1 + c[:, 1] * eta)], axis=1)


def quad_area(x):
    """Areas of quadrangles with corner coordinates x (n, 4, 3) (half the cross product of the
    diagonals: exact for planar quadrangles)."""
    return 0.5 * np.linalg.norm(np.cross(x[:, 2] - x[:, 0], x[:, 3] - x[:, 1]), axis=1)


def polygon_area(xy):
    x, y = xy[:, 0], xy[:, 1]
    return 0.5 * abs(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("mesh")
    parser.add_argument("--geo", default=fault_profile.DEFAULT_GEO)
    parser.add_argument("-setnumber", "--setnumber", nargs=2, action="append", default=[],
                        metavar=("NAME", "VALUE"))
    arguments = parser.parse_args()
    try:
        p = fault_profile.parameters(arguments.geo,
                                     [(n, float(v)) for n, v in arguments.setnumber])
        trace = fault_profile.FaultTrace.from_parameters(p)
        nodes, blocks, groups, entity_groups = read_msh41(arguments.mesh)
    except (OSError, ValueError, MeshError) as error:
        print(f"check_fault_mesh.py: {error}", file=sys.stderr)
        return 2
    report = Report()
    width, height, thickness = p["width"], p["height"], p["thickness"]
    layers = int(round(p["layers"]))
    tolerance = 1e-6 * max(width, height)

    tags = np.array(sorted(nodes))
    index = {tag: i for i, tag in enumerate(tags)}
    x = np.array([nodes[tag] for tag in tags])

    for name in VOLUME_GROUPS + FACE_GROUPS + FAULT_GROUPS:
        report.check(name in groups, f"physical group {name} is missing")
    if report.problems:
        return finish(report)

    other_3d = sorted({t for d, _, t, _ in blocks if d == 3 and t != GMSH_HEXAHEDRON})
    report.check(not other_3d, f"3D elements other than hexahedra (gmsh types {other_3d})")
    block_hexes, block_nodes = {}, {}
    for name in VOLUME_GROUPS:
        table = group_elements(blocks, entity_groups, groups[name], GMSH_HEXAHEDRON)
        report.check(len(table) > 0, f"volume {name} holds no hexahedra")
        block_hexes[name] = np.vectorize(index.get)(table[:, 1:]) if len(table) else \
            np.zeros((0, 8), int)
        block_nodes[name] = np.unique(block_hexes[name])
    shared = np.intersect1d(block_nodes["UPPER"], block_nodes["LOWER"])
    report.check(len(shared) == 0, f"the blocks share {len(shared)} node(s)")

    upper_polygon = trace.upper_block_polygon(width, height)
    expected_volume = {"UPPER": polygon_area(upper_polygon) * thickness}
    expected_volume["LOWER"] = width * height * thickness - expected_volume["UPPER"]
    quality = {}
    for name in VOLUME_GROUPS:
        hexes = block_hexes[name]
        dets, volume, scaled, ratio = hex_geometry(x[hexes])
        bad = np.count_nonzero((dets <= 0).any(axis=1))
        report.check(bad == 0, f"{name}: {bad} hexahedra are not right-handed "
                               f"(non-positive corner Jacobian)")
        total = volume.sum()
        report.check(abs(total - expected_volume[name]) <= 1e-6 * expected_volume[name],
                     f"{name}: volume {total:.6g} mm^3, expected {expected_volume[name]:.6g}")
        centroids = x[hexes].mean(axis=1)[:, :2]
        inside = Path(upper_polygon).contains_points(centroids)
        wrong = np.count_nonzero(~inside if name == "UPPER" else inside)
        report.check(wrong == 0, f"{name}: {wrong} hexahedra lie on the wrong side of the trace")
        quality[name] = (len(hexes), len(block_nodes[name]), scaled.min(), ratio.max(),
                         total)
        z_levels = np.unique(np.round(x[block_nodes[name], 2] / tolerance) * tolerance)
        expected_levels = np.linspace(0.0, thickness, layers + 1)
        report.check(len(z_levels) == layers + 1 and
                     np.allclose(z_levels, expected_levels, atol=1e-6 * thickness),
                     f"{name}: nodes on {len(z_levels)} z levels, expected {layers + 1} "
                     f"(layers = {layers})")

    hex_faces = {}
    for name in VOLUME_GROUPS:
        for hexahedron in block_hexes[name]:
            for face in HEX_FACES:
                hex_faces[frozenset(hexahedron[list(face)])] = name
    surface_quads = {}
    for name in FACE_GROUPS + FAULT_GROUPS:
        table = group_elements(blocks, entity_groups, groups[name], GMSH_QUAD)
        quads = np.vectorize(index.get)(table[:, 1:]) if len(table) else np.zeros((0, 4), int)
        surface_quads[name] = quads
        report.check(len(quads) > 0, f"surface {name} holds no quadrangles")
        owners = [hex_faces.get(frozenset(q)) for q in quads]
        report.check(None not in owners,
                     f"{name}: {owners.count(None)} quadrangles are not hexahedron faces")
        if name in FAULT_GROUPS:
            side = name.split("_")[1]
            report.check(all(o == side for o in owners if o is not None),
                         f"{name}: quadrangles on faces of the other block")

    for side in ("UPPER", "LOWER"):
        name = f"DF_{side}"
        if name not in groups:
            continue
        table = group_elements(blocks, entity_groups, groups[name], GMSH_QUAD)
        combined = {frozenset(index[t] for t in row[1:]) for row in table}
        parts = {frozenset(q) for seg in ("DE", "EF") for q in surface_quads[f"{seg}_{side}"]}
        report.check(combined == parts, f"{name} is not DE_{side} + EF_{side}")

    planes = {"A": (1, height, width * thickness), "B": (0, width, height * thickness),
              "X0": (0, 0.0, height * thickness), "Y0": (1, 0.0, width * thickness),
              "Z0": (2, 0.0, width * height)}
    for name, (axis, value, area) in planes.items():
        quads = surface_quads[name]
        if not len(quads):
            continue
        off = np.abs(x[np.unique(quads), axis] - value).max()
        report.check(off <= tolerance, f"{name}: nodes up to {off:.3g} mm off the plane "
                                       f"{'xyz'[axis]} = {value:g}")
        total = quad_area(x[quads]).sum()
        report.check(abs(total - area) <= 1e-6 * area,
                     f"{name}: area {total:.6g} mm^2, expected {area:.6g}")

    spacing, coincide = {}, {}
    for seg, _, _ in fault_profile.SEGMENTS:
        length = trace.lengths[seg]
        for side in ("UPPER", "LOWER"):
            name = f"{seg}_{side}"
            quads = surface_quads[name]
            if not len(quads):
                continue
            on = np.unique(quads)
            along, normal = trace.project(x[on, :2], seg)
            report.check(np.abs(normal).max() <= tolerance,
                         f"{name}: nodes up to {np.abs(normal).max():.3g} mm off the trace")
            report.check(along.min() >= -tolerance and along.max() <= length + tolerance,
                         f"{name}: nodes beyond the ends of segment {seg}")
            total = quad_area(x[quads]).sum()
            report.check(abs(total - length * thickness) <= 1e-6 * length * thickness,
                         f"{name}: area {total:.6g} mm^2, expected {length * thickness:.6g}")
            base = np.sort(along[np.abs(x[on, 2]) <= tolerance])
            steps = np.diff(base)
            spacing[name] = (len(base) - 1, steps.min(), steps.max()) if len(steps) else \
                (0, 0.0, 0.0)
        upper = x[np.unique(surface_quads[f"{seg}_UPPER"])]
        lower = x[np.unique(surface_quads[f"{seg}_LOWER"])]
        if len(upper) and len(lower):
            distance = np.min(np.linalg.norm(upper[:, None, :] - lower[None, :, :], axis=2),
                              axis=1)
            coincide[seg] = (np.count_nonzero(distance <= tolerance), len(upper))

    n_nodes = len(np.union1d(block_nodes["UPPER"], block_nodes["LOWER"]))
    n_hexes = sum(len(block_hexes[name]) for name in VOLUME_GROUPS)
    print(f"{arguments.mesh}: {n_nodes} nodes, {n_hexes} hexahedra, {3 * n_nodes} degrees of "
          f"freedom; {layers} layer(s) through the thickness")
    print("trace: " + "  ".join(f"{k} ({v[0]:.3f}, {v[1]:.3f})"
                                for k, v in trace.points.items()))
    for name in VOLUME_GROUPS:
        n_el, n_no, worst, ratio, volume = quality[name]
        print(f"  {name:6s} {n_el:7d} hexahedra {n_no:7d} nodes  volume {volume:.6g} mm^3  "
              f"min scaled Jacobian {worst:.3f}  max edge ratio {ratio:.2f}")
    for name in FACE_GROUPS:
        print(f"  {name:9s} {len(surface_quads[name]):6d} quadrangles "
              f"{len(np.unique(surface_quads[name])):6d} nodes")
    for seg, _, _ in fault_profile.SEGMENTS:
        for side in ("UPPER", "LOWER"):
            name = f"{seg}_{side}"
            if name in spacing:
                n, low, high = spacing[name]
                print(f"  {name:9s} {len(surface_quads[name]):6d} quadrangles "
                      f"{len(np.unique(surface_quads[name])):6d} nodes; {n} elements along "
                      f"{trace.lengths[seg]:.2f} mm, spacing {low:.3f}..{high:.3f} mm")
        if seg in coincide:
            same, total = coincide[seg]
            print(f"  {seg}: {same} of {total} upper-side nodes coincide in position with a "
                  f"lower-side node (distinct nodes)")
    return finish(report)


def finish(report):
    if report.problems:
        print(f"{len(report.problems)} problem(s):", file=sys.stderr)
        for text in report.problems:
            print(f"  {text}", file=sys.stderr)
        return 1
    print("mesh OK")
    return 0


if __name__ == "__main__":
    sys.exit(main())
