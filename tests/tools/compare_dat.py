#!/usr/bin/python3
"""Compare the result tables of two CalculiX-layout .dat files (fcs3d's and ccx's).

Usage: /usr/bin/python3 tests/tools/compare_dat.py [--tolerance 1e-6] REFERENCE.dat OTHER.dat

The files must hold the same blocks (title, set, time) in the same order, each with the same
rows (node, or element and integration point). Within a block every value must agree with
the reference to the tolerance times the largest magnitude in the block (both files):
|a - b| <= tolerance * max|block|. The block scale is also the absolute floor for values that
are round-off noise (forces of 1e-14 at free nodes, shear stresses of 1e-12 that should be 0).

Why 1e-6 works: both programs print 7 significant digits (1.234567E+02). Two roundings of
values that agree to much better than that differ by at most one unit in the last printed
place, 1e-6 times the printed magnitude at most, hence at most 1e-6 of the block's largest
value. Prints one line per block and exits 0 when all agree, 1 otherwise.
"""

import argparse
import sys

import numpy as np

import datfile

SLACK = 1.0 + 1.0e-9  # decimal-to-binary conversion of the printed numbers


def compare(reference_path, other_path, tolerance):
    reference = datfile.read_blocks(reference_path)
    other = datfile.read_blocks(other_path)
    problems = []
    if not reference:
        problems.append(f"{reference_path}: no result blocks")
    if len(reference) != len(other):
        problems.append(f"{len(reference)} blocks in {reference_path}, {len(other)} in {other_path}")
    for a, b in zip(reference, other):
        if (a.title, a.set_name) != (b.title, b.set_name) or abs(a.time - b.time) > 1e-9 * max(1.0, abs(a.time)):
            problems.append(f"block mismatch: '{a.label()}' vs '{b.label()}'")
            continue
        if a.order != b.order:
            missing = sorted(set(a.rows) - set(b.rows))[:5]
            extra = sorted(set(b.rows) - set(a.rows))[:5]
            problems.append(f"{a.label()}: rows differ (missing {missing}, extra {extra}, "
                            "or another order)")
            continue
        va, vb = a.values(), b.values()
        if va.shape != vb.shape:
            problems.append(f"{a.label()}: shapes {va.shape} and {vb.shape}")
            continue
        scale = max(np.abs(va).max(), np.abs(vb).max())
        difference = np.abs(va - vb).max()
        relative = difference / scale if scale > 0 else 0.0
        worst = a.order[int(np.unravel_index(np.argmax(np.abs(va - vb)), va.shape)[0])]
        print(f"  {a.label()}: {len(a.rows)} rows, max |difference| {difference:.3e} = "
              f"{relative:.2e} of the largest value {scale:.4e} (row {worst})")
        if not difference <= tolerance * scale * SLACK:
            problems.append(f"{a.label()}: difference {relative:.2e} of the block's largest "
                            f"value exceeds {tolerance:g} (row {worst}: {a.rows[worst]} vs {b.rows[worst]})")
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--tolerance", type=float, default=1.0e-6)
    parser.add_argument("reference")
    parser.add_argument("other")
    args = parser.parse_args()
    print(f"{args.other} against {args.reference}:")
    problems = compare(args.reference, args.other, args.tolerance)
    for problem in problems:
        print("FAIL: " + problem)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
