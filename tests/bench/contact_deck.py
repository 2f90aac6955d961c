#!/usr/bin/python3
"""Write the contact benchmark deck: a block pressed on a larger block, then pushed until it slides.

Usage: contact_deck.py N JOB.inp [--own-increments]

The same file runs unchanged in fcs3d and in CalculiX (ccx 2.20): it uses only keywords both
read, and no fcs3d extension (*SOLVER, *RMIN: the solver is chosen on fcs3d's command line).

Model (consistent units, e.g. mm, N, MPa), after tests/data/mpi/block_slide.inp and
tests/integration/contact/block_sliding.py:
  lower block  x, y in [-0.5, 1.5], z in [0, 1]: M x M x M/2 C3D8 elements, M about 1.5 N
               and even (spacing 2/M, about 1.33/N); base z = 0 fixed (node set BASE);
  upper block  x, y in [0, 1], z in [1, 1.5]: N x N x (N+1)//2 elements (spacing 1/N); its
               bottom faces are the slave surface, the lower block's top faces the master
               surface: the interface meshes do not match (slave finer than master). Height
               0.5 so that the push does not lift the trailing edge (rigid-block estimate: the
               resultant's eccentricity mu h = 0.15 stays inside the middle third, 1/6).
  E = 1000, nu = 0.3 in both; penalty E_n = 10 E / h_master (h_master = 2/M), Coulomb friction
  mu = 0.3 with the stick slope E_t = E_n (*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR;
  *FRICTION mu, E_t; *CONTACT PAIR, TYPE=NODE TO SURFACE).
  Step 1 (NLGEOM, *STATIC 1., 1.: each program's own increments): pressure P = 1 on the upper
  block's top (surface LOADED, *DSLOAD); the top nodes (node set TOP) are held in x and y.
  Step 2 (NLGEOM): the TOP nodes are moved by PUSH = 0.01 in x (ramped; still held in y, free
  in z), about 25 times the push at which the block starts sliding (its shear mu P h / G =
  3.9e-4, plus the lower block's shear and the stick displacement mu P / E_t), so the step ends
  in gross slip. The increment is capped at MAX_INCREMENT = 0.05 of the step (slide 5e-4 per
  increment): fcs3d's explicit friction update needs it (with increments of 0.25 of this step
  T/N ends 8 % above mu; doc/validation/contact.md reports the same overshoot, 5.8 %, for its
  deck at default increments). ccx does not need the cap: --own-increments writes both steps
  as *STATIC 1., 1. (the cost of CalculiX as one would run it; tests/bench/contact_bench.py
  runs both forms through ccx).
Output: *NODE PRINT, NSET=TOP, TOTALS=ONLY of RF in each step. At the end of step 2
T = RF_x (the force that pushes the block) and N = -RF_z (at these loaded nodes, the applied
pressure load P x 1 x 1): in gross slip T / N = mu, up to the tilt of the lower block's surface
under the slider (doc/validation/contact.md section 1). ccx prints the table after every
increment, fcs3d at the end of each step; the last table of each .dat file is the final one
(time 2).

Degrees of freedom 3 (N+1)^2 ((N+1)//2 + 1) + 3 (M+1)^2 (M/2 + 1): N = 13, 24, 35 give
19,257, 102,408 and 301,401; (N+1)^2 slave nodes (196, 625, 1,296). `dofs(N)` computes it.
"""

import sys

YOUNG = 1000.0
POISSON = 0.3
MU = 0.3
PRESSURE = 1.0
PUSH = 0.01
MAX_INCREMENT = 0.05


def lower_count(n):
    """Element count across the lower block for N across the upper one."""
    m = int(round(1.5 * n))
    return m + (m % 2)


def upper_layers(n):
    """Element layers through the upper block (height 0.5)."""
    return max(1, (n + 1) // 2)


def dofs(n):
    m = lower_count(n)
    return 3 * (n + 1) ** 2 * (upper_layers(n) + 1) + 3 * (m + 1) ** 2 * (m // 2 + 1)


class Box:
    """A structured box of C3D8 elements, nodes and elements numbered from given ids."""

    def __init__(self, origin, size, counts, first_node, first_element):
        self.origin, self.size, self.counts = origin, size, counts
        self.first_node, self.first_element = first_node, first_element

    def node(self, i, j, k):
        nx, ny, _ = self.counts
        return self.first_node + i + (nx + 1) * (j + (ny + 1) * k)

    def element(self, i, j, k):
        nx, ny, _ = self.counts
        return self.first_element + i + nx * (j + ny * k)

    def node_cards(self, nset):
        out = [f"*NODE, NSET={nset}"]
        nx, ny, nz = self.counts
        for k in range(nz + 1):
            for j in range(ny + 1):
                for i in range(nx + 1):
                    x, y, z = (o + s * c / n for o, s, c, n in
                               zip(self.origin, self.size, (i, j, k), self.counts))
                    out.append(f"{self.node(i, j, k)}, {x:.12g}, {y:.12g}, {z:.12g}")
        return out

    def element_cards(self, elset):
        out = [f"*ELEMENT, TYPE=C3D8, ELSET={elset}"]
        nx, ny, nz = self.counts
        for k in range(nz):
            for j in range(ny):
                for i in range(nx):
                    corners = [self.node(i + a, j + b, k + c) for a, b, c in
                               ((0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0),
                                (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1))]
                    out.append(f"{self.element(i, j, k)}, " + ", ".join(map(str, corners)))
        return out

    def layer_nodes(self, k):
        nx, ny, _ = self.counts
        return [self.node(i, j, k) for j in range(ny + 1) for i in range(nx + 1)]

    def layer_elements(self, k):
        nx, ny, _ = self.counts
        return [self.element(i, j, k) for j in range(ny) for i in range(nx)]


def id_lines(ids, per_line=16):
    return [", ".join(map(str, ids[i:i + per_line])) for i in range(0, len(ids), per_line)]


def write_deck(n, path, cap=True):
    m = lower_count(n)
    lower = Box((-0.5, -0.5, 0.0), (2.0, 2.0, 1.0), (m, m, m // 2), 1, 1)
    first = 10 ** len(str((m + 1) ** 2 * (m // 2 + 1)))
    layers = upper_layers(n)
    upper = Box((0.0, 0.0, 1.0), (1.0, 1.0, 0.5), (n, n, layers), first + 1, first + 1)
    penalty = 10.0 * YOUNG / (2.0 / m)
    out = ["*HEADING",
           f"Contact benchmark: block on block, {n}x{n}x{layers} on {m}x{m}x{m // 2} C3D8, "
           f"{dofs(n)} degrees of freedom (tests/bench/contact_deck.py)"]
    out += lower.node_cards("NALL") + upper.node_cards("NALL")
    out += lower.element_cards("LOWER") + upper.element_cards("UPPER")
    out += ["*NSET, NSET=BASE"] + id_lines(lower.layer_nodes(0))
    out += ["*NSET, NSET=TOP"] + id_lines(upper.layer_nodes(layers))
    out += ["*ELSET, ELSET=LOWERTOPLAYER"] + id_lines(lower.layer_elements(m // 2 - 1))
    out += ["*ELSET, ELSET=UPPERBOTTOMLAYER"] + id_lines(upper.layer_elements(0))
    out += ["*ELSET, ELSET=UPPERTOPLAYER"] + id_lines(upper.layer_elements(layers - 1))
    out += ["*ELSET, ELSET=EALL", "LOWER, UPPER",
            "*SURFACE, NAME=MASTER", "LOWERTOPLAYER, S2",
            "*SURFACE, NAME=SLAVE", "UPPERBOTTOMLAYER, S1",
            "*SURFACE, NAME=LOADED", "UPPERTOPLAYER, S2",
            "*MATERIAL, NAME=M", "*ELASTIC", f"{YOUNG:.12g}, {POISSON:.12g}",
            "*SOLID SECTION, ELSET=EALL, MATERIAL=M",
            "*SURFACE INTERACTION, NAME=ROUGH",
            "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR", f"{penalty:.12g}",
            "*FRICTION", f"{MU:.12g}, {penalty:.12g}",
            "*CONTACT PAIR, INTERACTION=ROUGH, TYPE=NODE TO SURFACE", "SLAVE, MASTER",
            "*BOUNDARY", "BASE, 1, 3", "TOP, 1, 2"]
    capped = f"{MAX_INCREMENT:.12g}, 1., 1e-05, {MAX_INCREMENT:.12g}"
    out += ["*STEP, NLGEOM", "*STATIC", "1., 1.",
            "*DSLOAD", f"LOADED, P, {PRESSURE:.12g}",
            "*NODE PRINT, NSET=TOP, TOTALS=ONLY", "RF", "*END STEP",
            "*STEP, NLGEOM", "*STATIC", capped if cap else "1., 1.",
            "*BOUNDARY", f"TOP, 1, 1, {PUSH:.12g}",
            "*NODE PRINT, NSET=TOP, TOTALS=ONLY", "RF", "*END STEP"]
    with open(path, "w") as handle:
        handle.write("\n".join(out) + "\n")


if __name__ == "__main__":
    if len(sys.argv) not in (3, 4) or sys.argv[3:] not in ([], ["--own-increments"]):
        sys.exit(__doc__)
    write_deck(int(sys.argv[1]), sys.argv[2], cap=len(sys.argv) == 3)
