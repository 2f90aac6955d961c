#!/usr/bin/python3
"""Write the classic decks of every element kind compared with CalculiX (issue 16).

  classic_kind_decks.py [DIR]     (default: tests/decks/classic)

For each kind, DIR/kind_<KIND>.inp: a cantilever 4 x 1 x 1 (4 x 2 x 2 cells of
tests/tools/kind_meshes.py: hexahedra, 20-node hexahedra, six tetrahedra or two wedges per
cell), root face x = 0 clamped, a tip load *CLOAD on every node of the tip face x = 4 (in y
and z), E = 210000, nu = 0.3; *NODE PRINT U and RF, *EL PRINT S and E of every element. The
grid's interior nodes are moved at random (fixed seed) by up to 15 % of a cell, so that the
Jacobian varies inside the elements, except for C3D8R and C3D8I, whose meshes stay regular:
on distorted elements fcs3d keeps Flanagan & Belytschko's hourglass vectors and Taylor's
det J0 / det J factor of the modes, which make both pass the patch test, where CalculiX keeps
one term of the former and drops the latter (doc/theory.md 1.5); on parallelepipeds the two
codes compute the same element.

The decks are committed; tests/integration/calculix_compare.sh runs each through ccx and
fcs3d and compares the .dat files (tests/tools/compare_dat.py, 1e-6 of each block's largest
value). Rerun this script only to change them.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import kind_meshes  # noqa: E402

KINDS = ["C3D4", "C3D6", "C3D8R", "C3D8I", "C3D10", "C3D15", "C3D20", "C3D20R"]
REGULAR = ("C3D8R", "C3D8I")
SIZE, CELLS, DISTORTION = (4.0, 1.0, 1.0), (4, 2, 2), 0.15


def write(directory, kind):
    rng = np.random.default_rng(20261126)
    coords, hexes, _ = kind_meshes.hex_grid(list(CELLS), list(SIZE),
                                            0.0 if kind in REGULAR else DISTORTION, rng)
    elements = kind_meshes.convert(coords, hexes, kind)
    cards, _ = kind_meshes.element_cards(elements, "EALL")
    root = [n for n, x in sorted(coords.items()) if x[0] == 0.0]
    tip = [n for n, x in sorted(coords.items()) if x[0] == SIZE[0]]
    shape = "regular" if kind in REGULAR else "distorted"
    lines = [f"** Classic deck: a {shape} cantilever of {kind} elements (written by",
             "** tests/tools/classic_kind_decks.py). Runs unchanged in CalculiX (ccx) and fcs3d;",
             "** tests/integration/calculix_compare.sh compares their job.dat.",
             "*HEADING", f"Cantilever of {kind} elements with a tip load", "*NODE, NSET=NALL"]
    lines += [f"{n}, {x[0]:.12g}, {x[1]:.12g}, {x[2]:.12g}" for n, x in sorted(coords.items())]
    lines += cards
    for name, ids in (("ROOT", root), ("TIP", tip)):
        lines.append(f"*NSET, NSET={name}")
        lines += [", ".join(str(n) for n in ids[i:i + 12]) for i in range(0, len(ids), 12)]
    lines += ["*MATERIAL, NAME=STEEL", "*ELASTIC", "210000., 0.3",
              "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL",
              "*STEP", "*STATIC", "*BOUNDARY", "ROOT, 1, 3", "*CLOAD", "TIP, 2, 10.", "TIP, 3, -4.",
              "*NODE PRINT, NSET=NALL", "U, RF", "*EL PRINT, ELSET=EALL", "S, E", "*END STEP"]
    path = os.path.join(directory, f"kind_{kind}.inp")
    with open(path, "w") as handle:
        handle.write("\n".join(lines) + "\n")
    return path


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    directory = sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "decks", "classic")
    for kind in KINDS:
        print(write(directory, kind))


if __name__ == "__main__":
    main()
