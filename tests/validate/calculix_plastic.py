#!/usr/bin/python3
"""fcs3d against CalculiX on *PLASTIC decks (`make validate`: calculix_plastic.sh).

    calculix_plastic.py --fcs3d BIN --work DIR [--tolerance 1e-2] [--markdown FILE] DECK...

Every deck (tests/decks/plastic/*.inp) runs unchanged in ccx (Debian's calculix-ccx 2.20) and
in fcs3d. CalculiX prints its tables at every increment of its own, fcs3d at the end of each
step: the comparison takes, from ccx's .dat, the blocks at fcs3d's times (the step ends) and
requires each to agree with fcs3d's within the tolerance times the block's largest magnitude
(tests/tools/compare_dat.py's measure). Prints the largest difference of every block kind
per deck and writes them as a Markdown table.
"""
import argparse
import os
import shutil
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', 'tools'))
import datfile  # noqa: E402


def compare(ccx_path, fcs_path):
    """{(kind, time): relative difference} and the list of problems."""
    ccx = datfile.read_blocks(ccx_path)
    ours = datfile.read_blocks(fcs_path)
    results, problems = {}, []
    for block in ours:
        match = [b for b in ccx if b.title == block.title and b.set_name == block.set_name and
                 abs(b.time - block.time) <= 1e-9 * max(1.0, abs(block.time))]
        if not match:
            problems.append('no ccx block "%s" at time %g' % (block.title, block.time))
            continue
        other = match[-1]
        if other.order != block.order:
            problems.append('%s: the rows differ' % block.label())
            continue
        a, b = other.values(), block.values()
        scale = max(np.abs(a).max(), np.abs(b).max())
        kind = block.title.split(' (')[0]
        results[(kind, block.time)] = float(np.abs(a - b).max() / scale) if scale > 0 else 0.0
    return results, problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--fcs3d', required=True)
    parser.add_argument('--work', required=True)
    parser.add_argument('--tolerance', type=float, default=1e-2)
    parser.add_argument('--markdown')
    parser.add_argument('decks', nargs='+')
    args = parser.parse_args()
    os.makedirs(os.path.join(args.work, 'fcs3d'), exist_ok=True)
    rows, failed = [], False
    for deck in args.decks:
        job = os.path.splitext(os.path.basename(deck))[0]
        shutil.copy(deck, args.work)
        ccx = subprocess.run(['ccx', job], cwd=args.work, capture_output=True, text=True,
                             env=dict(os.environ, OMP_NUM_THREADS='1'))
        if ccx.returncode != 0 or '*ERROR' in ccx.stdout:
            print('ccx failed on %s:\n%s' % (job, ccx.stdout[-2000:]))
            failed = True
            continue
        ours = subprocess.run([args.fcs3d, '-q', '-o', 'fcs3d', job + '.inp'], cwd=args.work,
                              capture_output=True, text=True)
        if ours.returncode != 0:
            print('fcs3d failed on %s:\n%s' % (job, ours.stderr))
            failed = True
            continue
        results, problems = compare(os.path.join(args.work, job + '.dat'),
                                    os.path.join(args.work, 'fcs3d', job + '.dat'))
        for p in problems:
            print('%s: %s' % (job, p))
        failed |= bool(problems) or not results
        for (kind, time), difference in sorted(results.items(), key=lambda item: (item[0][1], item[0][0])):
            ok = difference <= args.tolerance
            failed |= not ok
            rows.append((job, time, kind, difference, ok))
            print('%s %s, time %g: %s: largest difference %.2e of the block\'s largest value'
                  % ('ok  ' if ok else 'FAIL', job, time, kind, difference))
    lines = ['| deck | time | table | largest difference / largest value |', '|---|---|---|---|']
    lines += ['| %s | %g | %s | %.1e |' % (job, time, kind, d) for job, time, kind, d, _ in rows]
    if args.markdown:
        with open(args.markdown, 'w') as f:
            f.write('\n'.join(lines) + '\n')
    print('\n'.join(lines))
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
