#!/usr/bin/python3
"""A slave surface of one node (a node-based surface whose node lies on no face of it):
its contact area is CalculiX's, the sum over the exterior element faces at the node of each
face's area divided by its number of nodes (src/contact/fcs_contact_areas.f90).

Usage: single_node_slave.py deck JOB.inp --height H
       single_node_slave.py check JOB.dat --height H [--tolerance 2e-3]

Model (consistent units): a lower block of two C3D8 (x in [0, 0.6] and [0.6, 1.0], y and z in
[0, 1]; E = 1000, nu = 0.3), base fixed; its top faces are the master surface. An upper block
of one C3D8, w x w x H (w = 0.4) standing on it at x in [0.1, 0.5], y in [0.3, 0.7]: every node
held in x and y, so it can only move down. Its corner node 21 at (0.1, 0.3, 1) is the only
slave node; a force F = 1 pushes it down. Linear pressure-overclosure, slope K = 1000.

The upper block moves rigidly and the contact force is F, so the overclosure at node 21 is
g = F / (K A), with A = (w^2 + 2 w H) / 4: the node is a corner of three exterior faces of its
element (the bottom, w x w, and two sides, w x H), each giving a quarter of its area. The check
takes g from the printed displacements: the master point is where the deformed master face
(bilinear in its four nodes' current positions) lies under the slave node's current position,
and g the height of that point above the node. Tolerance: the printed displacements have 7
digits, the equilibrium tolerance of the default step is 1e-3 of the force scale at most
(doc/user_guide.md, *STATIC), so 2e-3 of A; the master face's area (0.6, CalculiX's rule for a
node in no element) or no area at all would be far off (for H = 0.4 A = 0.12; for H = 0.8, 0.2).
"""

import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
import datfile  # noqa: E402

W = 0.4
FORCE = 1.0
SLOPE = 1000.0
LOWER = {1: (0.0, 0.0, 0.0), 2: (0.6, 0.0, 0.0), 3: (1.0, 0.0, 0.0), 4: (0.0, 1.0, 0.0),
         5: (0.6, 1.0, 0.0), 6: (1.0, 1.0, 0.0), 7: (0.0, 0.0, 1.0), 8: (0.6, 0.0, 1.0),
         9: (1.0, 0.0, 1.0), 10: (0.0, 1.0, 1.0), 11: (0.6, 1.0, 1.0), 12: (1.0, 1.0, 1.0)}
MASTER_FACE = (7, 8, 11, 10)  # top face of element 1, counter-clockwise seen from above
SLAVE = 21


def nodes(height):
    x0, y0 = 0.1, 0.3
    upper = {}
    for k, (dx, dy) in enumerate([(0, 0), (W, 0), (W, W), (0, W)]):
        upper[21 + k] = (x0 + dx, y0 + dy, 1.0)
        upper[25 + k] = (x0 + dx, y0 + dy, 1.0 + height)
    return {**LOWER, **upper}


def write_deck(path, height):
    lines = ["** One slave node on a master face (tests/integration/contact/single_node_slave.py)",
             "*NODE, NSET=NALL"]
    lines += [f"{n}, {x:.6g}, {y:.6g}, {z:.6g}" for n, (x, y, z) in sorted(nodes(height).items())]
    lines += ["*ELEMENT, TYPE=C3D8, ELSET=LOWER",
              "1, 1, 2, 5, 4, 7, 8, 11, 10",
              "2, 2, 3, 6, 5, 8, 9, 12, 11",
              "*ELEMENT, TYPE=C3D8, ELSET=UPPER",
              "3, 21, 22, 23, 24, 25, 26, 27, 28",
              "*NSET, NSET=BASE", "1, 2, 3, 4, 5, 6",
              "*NSET, NSET=BLOCK", "21, 22, 23, 24, 25, 26, 27, 28",
              f"*NSET, NSET=SLAVE", f"{SLAVE}",
              "*MATERIAL, NAME=SOFT", "*ELASTIC", "1000., 0.3",
              "*SOLID SECTION, ELSET=LOWER, MATERIAL=SOFT",
              "*SOLID SECTION, ELSET=UPPER, MATERIAL=SOFT",
              "*SURFACE, NAME=TOP, TYPE=ELEMENT", "LOWER, S2",
              "*SURFACE, NAME=POINT, TYPE=NODE", "SLAVE",
              "*CONTACT PAIR, INTERACTION=PRESS, TYPE=NODE TO SURFACE", "POINT, TOP",
              "*SURFACE INTERACTION, NAME=PRESS",
              "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR", f"{SLOPE:g}",
              "*BOUNDARY", "BASE, 1, 3", "BLOCK, 1, 2",
              "*STEP", "*STATIC", "*CLOAD", f"{SLAVE}, 3, {-FORCE:g}",
              "*NODE PRINT, NSET=NALL", "U", "*END STEP"]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def overclosure(dat, height):
    block = [b for b in datfile.read_blocks(dat) if b.kind == "displacements"][-1]
    position = {}
    for key in block.order:
        n = key[0] if isinstance(key, tuple) else key
        position[n] = np.array(nodes(height)[n]) + np.array(block.rows[key])
    xm = np.array([position[n] for n in MASTER_FACE])
    xs = position[SLAVE]
    signs = np.array([[-1, -1], [1, -1], [1, 1], [-1, 1]], dtype=float)
    xi = np.zeros(2)
    for _ in range(50):  # Newton on the in-plane position: x_m(xi)[x, y] = x_s[x, y]
        shape = 0.25 * (1 + signs[:, 0] * xi[0]) * (1 + signs[:, 1] * xi[1])
        dshape = np.array([0.25 * signs[:, 0] * (1 + signs[:, 1] * xi[1]),
                           0.25 * signs[:, 1] * (1 + signs[:, 0] * xi[0])])
        residual = (shape @ xm)[:2] - xs[:2]
        jacobian = (dshape @ xm)[:, :2].T
        xi -= np.linalg.solve(jacobian, residual)
        if np.linalg.norm(residual) < 1e-15:
            break
    shape = 0.25 * (1 + signs[:, 0] * xi[0]) * (1 + signs[:, 1] * xi[1])
    return (shape @ xm)[2] - xs[2]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("action", choices=["deck", "check"])
    parser.add_argument("path")
    parser.add_argument("--height", type=float, required=True)
    parser.add_argument("--tolerance", type=float, default=2e-3)
    args = parser.parse_args()
    if args.action == "deck":
        write_deck(args.path, args.height)
        return 0
    expected = (W * W + 2 * W * args.height) / 4
    g = overclosure(args.path, args.height)
    area = FORCE / (SLOPE * g) if g > 0 else float("inf")
    error = abs(area - expected) / expected
    ok = error <= args.tolerance
    print(f"{'ok  ' if ok else 'FAIL'} H = {args.height:g}: overclosure {g:.6e}, area F/(K g) = "
          f"{area:.6f}, expected (w^2 + 2 w H)/4 = {expected:.6f}, error {error:.1e} "
          f"(tolerance {args.tolerance:g})")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
