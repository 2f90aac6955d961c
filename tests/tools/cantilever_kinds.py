#!/usr/bin/python3
"""Slender cantilever under a tip shear load with any element kind, against Timoshenko.

  cantilever_kinds.py [--kinds C3D20R,C3D10,C3D8I] [--meshes 10x2x2,20x2x2]
                      [--work DIR] [--markdown FILE] [--assert-error KIND:MESH:BOUND ...]
                      [--assert-converging]

The beam, material, supports and theory are those of tests/tools/cantilever.py (L = 10,
section 1 x 1, E = 1000, nu = 0.3, root face clamped, tip force P = 1 in y; Timoshenko with
Cowper's shear coefficient). The mesh is the grid of hexahedra of that script cut into
elements of the kind (tests/tools/kind_meshes.py: hexahedra, 20-node hexahedra, six
tetrahedra or two wedges per cell, mid-side nodes at the middle of straight edges).

The load is a uniform shear traction t = P / (b h) on the tip face, as the consistent nodal
forces of the faces lying on x = L (flat rectangles and right triangles, so exact): QUAD4
corners 1/4 of the face's force; QUAD8 corners -1/12, mid-sides 1/3; TRI3 corners 1/3; TRI6
corners 0, mid-sides 1/3. The tip deflection is the load's work-conjugate displacement
delta = sum_a F_a u_a,y / P (for bilinear faces the mean of the nodes' deflections with the
load's weights), so that P delta / 2 is the strain energy the load puts in.

Prints the convergence table (and writes it as Markdown with --markdown); --assert-error
KIND:MESH:BOUND fails when |error| of that kind on that mesh exceeds BOUND; with
--assert-converging, when the error of a kind does not shrink with each refinement.
"""

import argparse
import os
import shlex
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cantilever  # noqa: E402
import kind_meshes  # noqa: E402

#: Consistent nodal loads of a uniform traction on a flat face, as fractions of its force:
#: (corner share, mid-side share) by the number of corners of the face.
FACE_SHARES = {("linear", 4): (0.25, 0.0), ("quadratic", 4): (-1.0 / 12.0, 1.0 / 3.0),
               ("linear", 3): (1.0 / 3.0, 0.0), ("quadratic", 3): (0.0, 1.0 / 3.0)}
CORNERS = {"C3D4": 4, "C3D10": 4, "C3D6": 6, "C3D15": 6, "C3D8": 8, "C3D8R": 8, "C3D8I": 8,
           "C3D20": 8, "C3D20R": 8}


def tip_forces(coords, elements, length, traction):
    """{node: force} of the uniform traction on the faces of the elements on x = length."""
    forces = {}
    for kind, nodes in elements:
        corners = [n for n in nodes[:CORNERS[kind]] if abs(coords[n][0] - length) < 1e-9]
        if len(corners) not in (3, 4):
            continue
        mids = [n for n in nodes[CORNERS[kind]:] if abs(coords[n][0] - length) < 1e-9]
        order = "quadratic" if mids else "linear"
        yz = np.array([coords[n][1:] for n in corners])
        if len(corners) == 4:
            area = np.ptp(yz[:, 0]) * np.ptp(yz[:, 1])
        else:
            area = 0.5 * abs(np.cross(yz[1] - yz[0], yz[2] - yz[0]))
        corner_share, mid_share = FACE_SHARES[(order, len(corners))]
        for n in corners:
            forces[n] = forces.get(n, 0.0) + corner_share * traction * area
        for n in mids:
            forces[n] = forces.get(n, 0.0) + mid_share * traction * area
    return forces


def write_deck(path, kind, nx, ny, nz):
    coords, hexes, _ = kind_meshes.hex_grid([nx, ny, nz], [cantilever.LENGTH, cantilever.WIDTH,
                                                          cantilever.HEIGHT], 0.0,
                                       np.random.default_rng(0))
    elements = kind_meshes.convert(coords, hexes, kind)
    cards, _ = kind_meshes.element_cards(elements, "BEAM")
    traction = cantilever.LOAD / (cantilever.WIDTH * cantilever.HEIGHT)
    forces = tip_forces(coords, elements, cantilever.LENGTH, traction)
    total = sum(forces.values())
    if abs(total - cantilever.LOAD) > 1e-12:
        raise AssertionError(f"tip forces add up to {total}, not {cantilever.LOAD}")
    root = sorted(n for n, x in coords.items() if abs(x[0]) < 1e-9)
    lines = ["*HEADING", f"Cantilever {nx}x{ny}x{nz}, {kind}, tip shear", "*NODE, NSET=NALL"]
    lines += [f"{n}, {x[0]!r}, {x[1]!r}, {x[2]!r}" for n, x in sorted(coords.items())]
    lines += cards
    lines.append("*NSET, NSET=ROOT")
    lines += [", ".join(str(v) for v in root[i:i + 16]) for i in range(0, len(root), 16)]
    lines += ["*MATERIAL, NAME=MAT", "*ELASTIC",
              f"{cantilever.YOUNGS_MODULUS!r}, {cantilever.POISSON_RATIO!r}",
              "*SOLID SECTION, ELSET=BEAM, MATERIAL=MAT",
              "*STEP", "*STATIC", "*BOUNDARY", "ROOT, 1, 3", "*CLOAD"]
    lines += [f"{n}, 2, {f!r}" for n, f in sorted(forces.items())]
    lines += ["*END STEP"]
    with open(path, "w") as handle:
        handle.write("\n".join(lines) + "\n")
    return forces, len(coords)


def deflection(h5_path, forces):
    with h5py.File(h5_path, "r") as results:
        ids = results["mesh/node_ids"][...]
        frames = results["frames"]
        u = frames[sorted(frames.keys())[-1]]["nodal/displacement"][...]
    index = {node: i for i, node in enumerate(ids)}
    return sum(f * u[index[n], 1] for n, f in forces.items()) / cantilever.LOAD


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--kinds", default="C3D20R,C3D10,C3D8I")
    parser.add_argument("--meshes", default="10x2x2,20x2x2")
    parser.add_argument("--work", default=".")
    parser.add_argument("--markdown")
    parser.add_argument("--assert-error", action="append", default=[])
    parser.add_argument("--assert-converging", action="store_true")
    parser.add_argument("--fcs3d", default=os.environ.get("FCS3D", "fcs3d"))
    args = parser.parse_args()
    kinds = args.kinds.split(",")
    meshes = [tuple(int(v) for v in m.split("x")) for m in args.meshes.split(",")]
    theory, bending, shear = cantilever.timoshenko_deflection()
    print(f"Timoshenko: delta = {theory:.6f} (bending {bending:.6f} + shear {shear:.6f})")
    rows, problems = [], []
    for kind in kinds:
        for nx, ny, nz in meshes:
            name = f"cantilever_{kind}_{nx}x{ny}x{nz}"
            deck = os.path.join(args.work, name + ".inp")
            forces, n_nodes = write_deck(deck, kind, nx, ny, nz)
            outdir = os.path.join(args.work, "out")
            seconds = cantilever.run(args.fcs3d, deck, "UMFPACK", outdir)
            delta = deflection(os.path.join(outdir, name + ".h5"), forces)
            error = delta / theory - 1.0
            mesh = f"{nx}x{ny}x{nz}"
            rows.append((kind, mesh, 3 * n_nodes, delta, error, seconds))
            print(f"{kind:7s} {mesh:9s} {3 * n_nodes:7d} {delta:.6f} {100 * error:+7.2f}%  {seconds:.2f} s")
    for spec in args.assert_error:
        kind, mesh, bound = spec.split(":")
        matching = [row for row in rows if row[0] == kind and row[1] == mesh]
        if not matching:
            problems.append(f"{kind} {mesh}: not run")
        elif not abs(matching[0][4]) <= float(bound):
            problems.append(f"{kind} {mesh}: error {100 * matching[0][4]:+.2f}% exceeds "
                            f"{100 * float(bound):g}%")
    if args.assert_converging:
        for kind in kinds:
            errors = [abs(row[4]) for row in rows if row[0] == kind]
            if any(later >= earlier for earlier, later in zip(errors, errors[1:])):
                problems.append(f"{kind}: the error does not decrease with every refinement: "
                                f"{', '.join(f'{100 * e:.2f}%' for e in errors)}")
    if args.markdown:
        write_markdown(args, rows, theory, bending, shear)
    for problem in problems:
        print("FAIL: " + problem)
    return 1 if problems else 0


def write_markdown(args, rows, theory, bending, shear):
    command = (f"FCS3D=bin/fcs3d /usr/bin/python3 tests/tools/cantilever_kinds.py --kinds {args.kinds} "
               f"--meshes {args.meshes} --work <scratch dir> --markdown {shlex.quote(args.markdown)}")
    lines = ["# Validation: the cantilever with C3D20R, C3D10 and C3D8I", "",
             "Generated by `make validate` (tests/validate/cantilever_kinds.sh), which ran:", "",
             "    " + command, "",
             "The beam, supports, material and theory of doc/validation/cantilever.md (L = 10, 1 x 1,",
             "E = 1000, nu = 0.3, root clamped, tip shear P = 1 as the consistent nodal forces of a",
             "uniform traction on the tip faces), meshed by tests/tools/kind_meshes.py: the grid's",
             "cells as C3D20R (20-node hexahedra, 2x2x2 points), C3D10 (six 10-node tetrahedra per",
             "cell, 4 points) or C3D8I (8-node hexahedra with incompatible modes). Deflection: the",
             "load's work-conjugate tip displacement sum F_a u_a,y / P.",
             f"Timoshenko: delta = {bending:.6f} (bending) + {shear:.6f} (shear) = {theory:.6f}.", "",
             "| kind | mesh | DOF | deflection | error | time |", "|---|---|---:|---:|---:|---:|"]
    for kind, mesh, dofs, delta, error, seconds in rows:
        lines.append(f"| {kind} | {mesh} | {dofs} | {delta:.6f} | {100 * error:+.2f}% | {seconds:.1f} s |")
    lines += ["", "Error = fcs3d / theory - 1. The limit of refinement lies a fraction of a percent below",
              "the beam formula (the clamped root face restrains the Poisson contraction and warping",
              "that beam theory ignores; doc/validation/cantilever.md). C3D8I and C3D20R are close",
              "to it already with one element through the depth (the incompatible modes and the",
              "quadratic field carry the bending); C3D10 converges from below (stiff), as linear-strain",
              "tetrahedra do."]
    os.makedirs(os.path.dirname(args.markdown) or ".", exist_ok=True)
    with open(args.markdown, "w") as handle:
        handle.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    sys.exit(main())
