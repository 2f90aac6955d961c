"""Two stacked blocks under CalculiX's exponential pressure-overclosure law (fcs3d issue 17).

p = p0 exp(-beta g), beta = ln(100) / c0 (ccx 2.20, *SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=
EXPONENTIAL), g the clearance. A lower block (1 x 1 x 1, 2 x 2 x 2 C3D8) fixed at its base and
an upper block (1 x 1 x 0.5, 2 x 2 x 1 C3D8, matching) resting on it; every node is held in
x and y, so that each block is in uniform uniaxial stress and the contact pressure is uniform:
a pressure q on the upper block's top gives p(g) = q at every slave node, i.e. the closed form
g = c0 ln(p0 / q) / ln(100): a penetration for q > p0, a positive clearance held by the law for
q < p0 (the law acts up to g = c0).

  deck FILE --load Q --p0 P0 --c0 C0   write the deck (node-to-surface pair, the upper block's
                                       bottom the slave)
  changes FILE --load Q --p0 P0 --c0 C0 --stiffness K
                                       the same blocks in three steps under the same load:
                                       LINEAR penalty K, then *CHANGE SURFACE BEHAVIOR to K / 10,
                                       then to EXPONENTIAL c0, p0
  check-changes JOB --load Q --p0 P0 --c0 C0 --stiffness K --tolerance T
                                       the gaps of the three steps: -q/K, -10 q/K (within T of
                                       them, relative) and the exponential closed form
  check JOB --load Q --p0 P0 --c0 C0 --tolerance T
                                       read JOB.dat (*CONTACT PRINT: CDIS normal = gap, CSTR
                                       pressure): every slave node's pressure within T of q
                                       (relative) and its gap within T / ln(100) c0 of the
                                       closed form (the gap error that a pressure error T makes,
                                       dg = dp / (beta p))
"""
import argparse
import math
import sys

E, NU = 210000.0, 0.3


def block(n, nz, height, z0, first_node, first_element):
    nodes, ids, ident = {}, {}, first_node
    for k in range(nz + 1):
        for j in range(n + 1):
            for i in range(n + 1):
                nodes[ident] = (i / n, j / n, z0 + height * k / nz)
                ids[(i, j, k)] = ident
                ident += 1
    elements, e = {}, first_element
    for k in range(nz):
        for j in range(n):
            for i in range(n):
                c = [ids[(i, j, k)], ids[(i + 1, j, k)], ids[(i + 1, j + 1, k)], ids[(i, j + 1, k)]]
                t = [ids[(i, j, k + 1)], ids[(i + 1, j, k + 1)], ids[(i + 1, j + 1, k + 1)], ids[(i, j + 1, k + 1)]]
                elements[e] = c + t
                e += 1
    return nodes, ids, elements


def two_block_cards(title, lower, upper):
    """The cards of the two blocks (each a block() result): nodes, elements LOWER and UPPER,
    the element sets LOWER_TOP and UPPER_ALL, the node set BASE."""
    (lower_nodes, lower_ids, lower_el), (upper_nodes, _, upper_el) = lower, upper
    lines = [title, "*NODE, NSET=NALL"]
    for ident, (x, y, z) in {**lower_nodes, **upper_nodes}.items():
        lines.append(f"{ident}, {x:.12g}, {y:.12g}, {z:.12g}")
    lines.append("*ELEMENT, TYPE=C3D8, ELSET=LOWER")
    lines += [f"{e}, " + ", ".join(map(str, c)) for e, c in lower_el.items()]
    lines.append("*ELEMENT, TYPE=C3D8, ELSET=UPPER")
    lines += [f"{e}, " + ", ".join(map(str, c)) for e, c in upper_el.items()]
    lines.append("*ELSET, ELSET=LOWER_TOP")
    lines.append(", ".join(str(e) for e in list(lower_el)[4:]))
    lines.append("*ELSET, ELSET=UPPER_ALL")
    lines.append(", ".join(str(e) for e in upper_el))
    lines.append("*NSET, NSET=BASE")
    lines.append(", ".join(str(v) for (i, j, k), v in lower_ids.items() if k == 0))
    return lines


def write_deck(path, load, p0, c0, stiffness=None):
    lower = block(2, 2, 1.0, 0.0, 1, 1)
    upper = block(2, 1, 0.5, 1.0, 101, 101)
    lines = two_block_cards("** Two blocks, exponential pressure-overclosure "
                            "(tests/integration/contact/exponential_blocks.py)", lower, upper)
    lines += ["*SURFACE, NAME=MASTER", "LOWER_TOP, S2", "*SURFACE, NAME=SLAVE", "UPPER_ALL, S1",
              "*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E}, {NU}",
              "*SOLID SECTION, ELSET=LOWER, MATERIAL=STEEL",
              "*SOLID SECTION, ELSET=UPPER, MATERIAL=STEEL",
              "*CONTACT PAIR, INTERACTION=SOFT, TYPE=NODE TO SURFACE", "SLAVE, MASTER",
              "*SURFACE INTERACTION, NAME=SOFT"]
    if stiffness is None:
        lines += ["*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL", f"{c0}, {p0}"]
    else:
        lines += ["*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR", f"{stiffness}"]
    lines += ["*FRICTION", "0.2",
              "*BOUNDARY", "BASE, 3, 3", "NALL, 1, 2",
              "*STEP", "*STATIC",
              "*DLOAD", "UPPER_ALL, P2, %g" % load,
              "*CONTACT PRINT", "CDIS, CSTR", "*END STEP"]
    if stiffness is not None:
        lines += ["*STEP", "*STATIC", "*CHANGE SURFACE BEHAVIOR, INTERACTION=SOFT",
                  "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR", f"{stiffness / 10}",
                  "*CONTACT PRINT", "CDIS, CSTR", "*END STEP",
                  "*STEP", "*STATIC", "*CHANGE SURFACE BEHAVIOR, INTERACTION=SOFT",
                  "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL", f"{c0}, {p0}",
                  "*CONTACT PRINT", "CDIS, CSTR", "*END STEP"]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def read_contact(path, every=False):
    """Last CDIS and CSTR tables of a .dat: {node: value} of the normal columns (every: the
    lists of all of them, in order)."""
    gaps, pressures, table = {}, {}, None
    all_gaps, all_pressures = [], []
    with open(path) as f:
        for line in f:
            if "relative contact displacement" in line:
                table, gaps = "gap", {}
                all_gaps.append(gaps)
            elif "contact stress" in line:
                table, pressures = "pressure", {}
                all_pressures.append(pressures)
            elif not line.strip():
                continue
            elif table and line.split()[0].isdigit():
                fields = line.split()
                (gaps if table == "gap" else pressures)[int(fields[0])] = float(fields[1])
            else:
                table = None
    if every:
        return all_gaps, all_pressures
    return gaps, pressures


def check_changes(job, load, p0, c0, stiffness, tolerance):
    """The three steps' gaps: -q/K, -10 q/K, then the exponential closed form."""
    all_gaps, _ = read_contact(job + ".dat", every=True)
    if len(all_gaps) != 3:
        print(f"{job}: expected 3 contact tables (one per step), found {len(all_gaps)}")
        return 1
    expected = [-load / stiffness, -10.0 * load / stiffness, c0 * math.log(p0 / load) / math.log(100.0)]
    bounds = [tolerance * abs(expected[0]), tolerance * abs(expected[1]), tolerance * c0 / math.log(100.0)]
    fail = 0
    for k, (gaps, g, bound) in enumerate(zip(all_gaps, expected, bounds)):
        worst = max(abs(v - g) for v in gaps.values())
        print(f"{job}: step {k + 1}: closed-form gap {g:.6e}, error {worst:.2e} (bound {bound:.2e})")
        if len(gaps) != 9 or worst > bound:
            fail = 1
    return fail


def check(job, load, p0, c0, tolerance):
    gaps, pressures = read_contact(job + ".dat")
    if len(gaps) != 9 or len(pressures) != 9:
        print(f"{job}: expected 9 slave nodes in the contact tables, found {len(gaps)}, {len(pressures)}")
        return 1
    expected_gap = c0 * math.log(p0 / load) / math.log(100.0)
    worst_p = max(abs(p - load) / load for p in pressures.values())
    worst_g = max(abs(g - expected_gap) for g in gaps.values())
    bound_g = tolerance * c0 / math.log(100.0)
    print(f"{job}: q {load}, closed-form gap {expected_gap:.6e}; pressure error {worst_p:.2e} "
          f"(bound {tolerance}), gap error {worst_g:.2e} (bound {bound_g:.2e})")
    fail = worst_p > tolerance or worst_g > bound_g
    if load < p0 and min(gaps.values()) <= 0.0:
        print(f"{job}: q < p0 must hold the block at a positive clearance")
        fail = True
    return 1 if fail else 0


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("action", choices=["deck", "check", "changes", "check-changes"])
    parser.add_argument("name")
    parser.add_argument("--load", type=float, required=True)
    parser.add_argument("--p0", type=float, required=True)
    parser.add_argument("--c0", type=float, required=True)
    parser.add_argument("--tolerance", type=float, default=1e-3)
    parser.add_argument("--stiffness", type=float)
    a = parser.parse_args()
    if a.action == "changes":
        write_deck(a.name, a.load, a.p0, a.c0, a.stiffness)
        return 0
    if a.action == "check-changes":
        return check_changes(a.name, a.load, a.p0, a.c0, a.stiffness, a.tolerance)
    if a.action == "deck":
        write_deck(a.name, a.load, a.p0, a.c0)
        return 0
    return check(a.name, a.load, a.p0, a.c0, a.tolerance)


if __name__ == "__main__":
    sys.exit(main())
