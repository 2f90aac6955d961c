#!/usr/bin/python3
"""Write the benchmark deck: a unit cube of n x n x n C3D8 elements, one linear static step.

Usage: cube_deck.py N JOB.inp

Bottom face z = 0 clamped, pressure 10 on the top face z = 1 (*SURFACE from the top layer of
elements, face S2, and *DSLOAD), E = 210000, nu = 0.3, no NLGEOM. 3 (N+1)^3 degrees of
freedom: N = 20, 40, 61 give 27,783, 206,763 and 714,984. The only printed output is the
displacement of the top corner node (set MONITOR), so that the job.dat of fcs3d and of
CalculiX can be compared (tests/bench/run_bench.sh). The deck runs unchanged in both.
"""

import sys


def write_deck(n, path):
    m = n + 1

    def node(i, j, k):
        return 1 + i + m * (j + m * k)

    out = ["*HEADING", f"Benchmark cube {n}x{n}x{n}, {3 * m ** 3} degrees of freedom", "*NODE, NSET=NALL"]
    h = 1.0 / n
    for k in range(m):
        for j in range(m):
            for i in range(m):
                out.append(f"{node(i, j, k)}, {i * h:.12g}, {j * h:.12g}, {k * h:.12g}")
    out.append("*ELEMENT, TYPE=C3D8, ELSET=EALL")
    e = 0
    for k in range(n):
        for j in range(n):
            for i in range(n):
                e += 1
                out.append(f"{e}, {node(i, j, k)}, {node(i + 1, j, k)}, {node(i + 1, j + 1, k)}, "
                           f"{node(i, j + 1, k)}, {node(i, j, k + 1)}, {node(i + 1, j, k + 1)}, "
                           f"{node(i + 1, j + 1, k + 1)}, {node(i, j + 1, k + 1)}")
    out.append("*NSET, NSET=BOTTOM, GENERATE")
    out.append(f"1, {m * m}, 1")
    out.append("*ELSET, ELSET=TOPLAYER, GENERATE")
    out.append(f"{n * n * (n - 1) + 1}, {n ** 3}, 1")
    out += ["*NSET, NSET=MONITOR", str(node(n, n, n)),
            "*SURFACE, NAME=TOP, TYPE=ELEMENT", "TOPLAYER, S2",
            "*MATERIAL, NAME=STEEL", "*ELASTIC", "210000., 0.3",
            "*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL",
            "*STEP", "*STATIC", "*BOUNDARY", "BOTTOM, 1, 3", "*DSLOAD", "TOP, P, 10.",
            "*NODE PRINT, NSET=MONITOR", "U", "*END STEP"]
    with open(path, "w") as handle:
        handle.write("\n".join(out) + "\n")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    write_deck(int(sys.argv[1]), sys.argv[2])
