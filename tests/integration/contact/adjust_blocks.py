"""*CONTACT PAIR, ADJUST= on two stacked blocks (fcs3d issue 17 item 5).

The blocks of exponential_blocks.py (lower 1 x 1 x 1, 2 x 2 x 2 C3D8, base held in z; upper
1 x 1 x 0.5, 2 x 2 x 1 C3D8; every node held in x and y: uniaxial strain), LINEAR penalty K
(per unit area), the upper block's bottom the slave. The nine slave nodes start at chosen
signed gaps g0 (positive open, negative penetrating) above the master plane z = 1, and the
upper block's top is pushed down by d in one increment.

  deck FILE --mode MODE --adjust A --d D --stiffness K
      MODE=mixed: gaps A/2, 0, -0.3 A (moved by ADJUST=A) and 2 A, 3 A (left) on the
      slave nodes, ADJUST=A.  MODE=close: every gap in [-0.3 A, 0.99 A], ADJUST=A.
      MODE=set: gaps up to 3 A, ADJUST=<node set of all slave nodes> (all moved).
  check JOB --mode MODE --adjust A --d D --stiffness K --tolerance T
      mixed: each moved node is on the master after adjustment, so its gap under d is in
      [-d, 0] (it can sink no more than the top moves); each node left keeps its gap within
      d of g0 > A, d < A: it stays open, out of the contact table (which lists the
      contact elements, as CalculiX's does).  close, set: every node moved, so the blocks touch over the
      whole plane from the first increment and the pressure at every slave node is the
      closed form p = d / (h1/M + h2/M + 1/K), M = E (1-nu)/((1+nu)(1-2nu)) (uniaxial
      strain, blocks and penalty in series), within T (relative).
  check-total JOB --d D --stiffness K --tolerance T
      the total z reaction of the top (*NODE PRINT, NSET=TOP, TOTALS=ONLY: RF) is -p x 1
      (the closed form above over the unit area), within T: for TYPE=SURFACE TO SURFACE,
      which has no *CONTACT PRINT table.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from exponential_blocks import E, NU, block, read_contact, two_block_cards  # noqa: E402

H_LOWER, H_UPPER = 1.0, 0.5


def slave_gaps(mode, adjust):
    """Signed initial gap of each slave node (i, j) of the upper block's bottom."""
    if mode == "mixed":
        table = [0.5, 0.0, -0.3, 2.0, 3.0, 0.5, 0.0, 2.0, 0.9]
    elif mode == "close":
        table = [0.5, 0.0, -0.3, 0.99, 0.9, 0.5, 0.0, 0.2, 0.7]
    else:
        table = [0.5, 3.0, -0.3, 2.0, 0.9, 0.5, 0.0, 2.5, 0.7]
    return {(i, j): adjust * table[3 * j + i] for j in range(3) for i in range(3)}


def write_deck(path, mode, adjust, d, stiffness):
    lower_nodes, lower_ids, lower_el = block(2, 2, H_LOWER, 0.0, 1, 1)
    upper_nodes, upper_ids, upper_el = block(2, 1, H_UPPER, H_LOWER, 101, 101)
    gaps = slave_gaps(mode, adjust)
    for (i, j, k), ident in upper_ids.items():
        if k == 0:
            x, y, z = upper_nodes[ident]
            upper_nodes[ident] = (x, y, z + gaps[(i, j)])
    lines = two_block_cards("** Two blocks, *CONTACT PAIR, ADJUST= "
                            "(tests/integration/contact/adjust_blocks.py)",
                            (lower_nodes, lower_ids, lower_el), (upper_nodes, upper_ids, upper_el))
    lines.append("*NSET, NSET=TOP")
    lines.append(", ".join(str(v) for (i, j, k), v in upper_ids.items() if k == 1))
    lines.append("*NSET, NSET=SLAVE_NODES")
    lines.append(", ".join(str(v) for (i, j, k), v in upper_ids.items() if k == 0))
    value = "SLAVE_NODES" if mode == "set" else f"{adjust}"
    lines += ["*SURFACE, NAME=MASTER", "LOWER_TOP, S2", "*SURFACE, NAME=SLAVE", "UPPER_ALL, S1",
              "*MATERIAL, NAME=STEEL", "*ELASTIC", f"{E}, {NU}",
              "*SOLID SECTION, ELSET=LOWER, MATERIAL=STEEL",
              "*SOLID SECTION, ELSET=UPPER, MATERIAL=STEEL",
              f"*CONTACT PAIR, INTERACTION=SI, TYPE=NODE TO SURFACE, ADJUST={value}", "SLAVE, MASTER",
              "*SURFACE INTERACTION, NAME=SI",
              "*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR", f"{stiffness}",
              "*BOUNDARY", "BASE, 3, 3", "NALL, 1, 2", f"TOP, 3, 3, {-d}",
              "*STEP", "*STATIC", "1., 1.",
              "*CONTACT PRINT", "CDIS, CSTR", "*END STEP"]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def check(job, mode, adjust, d, stiffness, tolerance):
    all_gaps, all_pressures = read_contact(job + ".dat", every=True)
    if not all_gaps:
        print(f"{job}: no contact table in {job}.dat")
        return 1
    gaps, pressures = all_gaps[0], all_pressures[0]
    initial = slave_gaps(mode, adjust)
    ids = {101 + i + 3 * j: (i, j) for j in range(3) for i in range(3)}
    fail = 0
    if mode == "mixed":
        for node, (i, j) in sorted(ids.items()):
            g0 = initial[(i, j)]
            moved = g0 <= adjust
            if moved:
                g = gaps.get(node)
                ok = g is not None and -d * (1 + 1e-9) <= g <= 1e-12
                text = "not in contact" if g is None else f"gap under d {g:+.4e}"
            else:
                ok = node not in gaps
                text = "open (not in the table)" if ok else f"in contact, gap {gaps[node]:+.4e}"
            print(f"{job}: node {node}: initial gap {g0:+.4e} ({'moved' if moved else 'left'}), "
                  f"{text}{'' if ok else '  WRONG'}")
            fail |= not ok
        return 1 if fail else 0
    expected = closed_form_pressure(d, stiffness)
    worst = max(abs(p - expected) / expected for p in pressures.values())
    print(f"{job}: closed-form pressure {expected:.6e} at the first increment; worst relative "
          f"error of the 9 slave nodes {worst:.2e} (bound {tolerance})")
    return 1 if worst > tolerance or len(pressures) != 9 else 0


def closed_form_pressure(d, stiffness):
    modulus = E * (1 - NU) / ((1 + NU) * (1 - 2 * NU))
    return d / (H_LOWER / modulus + H_UPPER / modulus + 1.0 / stiffness)


def check_total(job, d, stiffness, tolerance):
    """The last total force of *NODE PRINT, NSET=TOP, TOTALS=ONLY, RF: -p A_top (A = 1)."""
    total = None
    with open(job + ".dat") as f:
        lines = f.read().splitlines()
    for k, line in enumerate(lines):
        if "total force" in line:
            total = [float(v) for v in next(x for x in lines[k + 1:] if x.strip()).split()]
    if total is None:
        print(f"{job}: no total force table in {job}.dat")
        return 1
    expected = -closed_form_pressure(d, stiffness)
    error = abs(total[2] - expected) / abs(expected)
    print(f"{job}: total z reaction on the top {total[2]:.6e}, closed form {expected:.6e}, "
          f"relative error {error:.2e} (bound {tolerance})")
    return 1 if error > tolerance else 0


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("action", choices=["deck", "check", "check-total"])
    parser.add_argument("name")
    parser.add_argument("--mode", choices=["mixed", "close", "set"], required=True)
    parser.add_argument("--adjust", type=float, required=True)
    parser.add_argument("--d", type=float, required=True)
    parser.add_argument("--stiffness", type=float, required=True)
    parser.add_argument("--tolerance", type=float, default=1e-3)
    a = parser.parse_args()
    if a.action == "deck":
        write_deck(a.name, a.mode, a.adjust, a.d, a.stiffness)
        return 0
    if a.action == "check-total":
        return check_total(a.name, a.d, a.stiffness, a.tolerance)
    return check(a.name, a.mode, a.adjust, a.d, a.stiffness, a.tolerance)


if __name__ == "__main__":
    sys.exit(main())
