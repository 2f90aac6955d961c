#!/usr/bin/python3
"""Check a run of tests/integration/gmsh_kinds.sh: the box [0,2] x [0,1] x [0,1] meshed by gmsh
(tests/data/gmsh/kinds.geo), on rollers on its faces x = 0, y = 0, z = 0 (physical surfaces
XMIN, YMIN, ZMIN) and pushed by a pressure p = 100 on its face x = 2 (*DSLOAD on the physical
surface XMAX), E = 210000, nu = 0.3.

Usage: check_gmsh_kinds.py JOB.h5 JOB.dat --cells CODE[,CODE...] [--points N]

The exact solution is the uniaxial stress sxx = -p, all other components 0, with the linear
displacement field u = (-p x / E, nu p y / E, nu p z / E): it lies in the finite element space of
every kind, so the run must reproduce it to round-off, whatever the mesh. Checks:
  - the cells are of exactly the XDMF types CODE (6 tetrahedron, 8 wedge, 9 hexahedron, 38
    10-node tetrahedron, 40 15-node wedge, 48 20-node hexahedron; /mesh/topology, or all
    8-node hexahedra without it); the integration-point datasets have as many points as the
    element with the most (CalculiX's rules: C3D4 1, C3D6 2, C3D8 8, C3D10 4, C3D15 9, C3D20 27;
    --points N for the hexahedra, 8 for C3D20R), the rows of elements with fewer padded with 0;
  - every integration-point stress of the last frame is (-p, 0, 0, 0, 0, 0) to 1e-10 p and
    every nodal displacement is the exact field to 1e-10 of its largest value: round-off
    amplified by the condition number of these small stiffness matrices (1e3 to 1e4) stays
    near 1e-12, so 1e-10 leaves a margin of about 100 (the figure of the patch test,
    tests/tools/patch_test.py);
  - the total reaction on XMIN in JOB.dat is (p A, 0, 0) with A = 1, to the print precision of
    the .dat table (7 significant digits: 1e-6 of p A). This is the resultant of the pressure
    on the faces of XMAX: the faces matched from gmsh's surface elements must be the right
    ones, with the right area.
"""

import argparse
import sys

import h5py
import numpy as np

import datfile

PRESSURE, MODULUS, POISSON, AREA = 100.0, 210000.0, 0.3, 1.0
TOLERANCE, PRINT_TOLERANCE = 1.0e-10, 1.0e-6
#: Nodes of each XDMF cell type of /mesh/topology.
CELL_NODES = {6: 4, 8: 6, 9: 8, 38: 10, 40: 15, 48: 20}
#: Integration points of the default kind of each XDMF cell type (CalculiX's e_c3d.f rules).
CELL_POINTS = {6: 1, 8: 2, 9: 8, 38: 4, 40: 9, 48: 27}


def cell_types(mesh):
    """The XDMF cell type of every element (from /mesh/topology; 8-node hexahedra without it)."""
    if "topology" not in mesh:
        return [9] * mesh["element_ids"].shape[0]
    topology = mesh["topology"][...]
    types, k = [], 0
    while k < len(topology):
        types.append(int(topology[k]))
        k += 1 + CELL_NODES.get(int(topology[k]), len(topology))
    return types


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("h5")
    parser.add_argument("dat")
    parser.add_argument("--cells", required=True)
    parser.add_argument("--points", type=int)
    args = parser.parse_args()
    problems = []

    def expect(condition, text):
        if not condition:
            problems.append(text)

    with h5py.File(args.h5, "r") as f:
        types = cell_types(f["mesh"])
        x = f["mesh/coordinates"][...]
        last = f["frames"][sorted(f["frames"].keys())[-1]]
        u = last["nodal/displacement"][...]
        stress = last["integration_points/stress"][...]
        names = last["integration_points/stress"].attrs["components"]
        names = (names.decode() if isinstance(names, bytes) else str(names)).split()
    wanted = sorted(int(code) for code in args.cells.split(","))
    found = sorted(set(types))
    counts = {code: types.count(code) for code in found}
    print(f"{args.h5}: {len(types)} elements, XDMF cell types {counts}, {len(x)} nodes, "
          f"{stress.shape[1]} integration points at most")
    expect(found == wanted, f"cell types {found}, expected {wanted}")
    points = dict(CELL_POINTS)
    if args.points is not None:
        points[9] = points[48] = args.points
    per_element = np.array([points.get(code, 0) for code in types])
    expect(stress.shape[1] == per_element.max(),
           f"{stress.shape[1]} integration points per element, expected {per_element.max()}")
    used = np.arange(stress.shape[1])[None, :] < per_element[:, None]
    expect(not stress[~used].any(), "padding rows of the integration-point stresses are not 0")
    exact_stress = np.zeros(6)
    exact_stress[names.index("xx")] = -PRESSURE
    error = np.abs(stress[used] - exact_stress).max()
    print(f"  max |stress - (-p, 0, ...)| / p = {error / PRESSURE:.2e} (tolerance {TOLERANCE:g})")
    expect(error <= TOLERANCE * PRESSURE, "integration-point stresses are not uniaxial -p")
    exact_u = np.column_stack([-PRESSURE * x[:, 0], POISSON * PRESSURE * x[:, 1],
                               POISSON * PRESSURE * x[:, 2]]) / MODULUS
    error = np.abs(u - exact_u).max() / np.abs(exact_u).max()
    print(f"  max |u - exact| / max |u| = {error:.2e} (tolerance {TOLERANCE:g})")
    expect(error <= TOLERANCE, "displacements are not the exact linear field")
    totals = [b for b in datfile.read_blocks(args.dat) if b.kind == "total" and b.set_name == "XMIN"]
    expect(len(totals) == 1, f"{args.dat}: no total force for XMIN")
    if totals:
        total = totals[-1].values()[-1]
        print(f"  total reaction on XMIN {total} (p A = {PRESSURE * AREA:g})")
        expect(np.abs(total - [PRESSURE * AREA, 0.0, 0.0]).max() <= PRINT_TOLERANCE * PRESSURE * AREA,
               "total reaction on XMIN is not (p A, 0, 0)")
    for text in problems:
        print(f"  FAILED: {text}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
