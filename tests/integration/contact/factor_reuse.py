"""Factorisation reuse (*SOLVER, REUSE TOLERANCE; fcs_factor_reuse) on a frictional contact run.

    factor_reuse.py deck JOB.inp [--tolerance T]
    factor_reuse.py compare FRESH REUSED --relative R
    factor_reuse.py counts JOB

deck: the partial-slip block on a block of block_sliding.py (stick, partial slip, gross slip
at T = mu N; increments capped at 0.01 of the push), with *NODE PRINT of U at the pushed top
nodes (their z displacement is free) and, with --tolerance, a *SOLVER card that sets REUSE
TOLERANCE (so the deck parameter is exercised; without it the command line decides).

compare: the two runs' .dat files have the same tables at the same times (the same
increments: the reuse does not move the event fractions enough to change any decision), and
every value agrees within R relative to the largest magnitude of its table (the RF totals of
BASE every increment, the contact stresses of every slave node, the displacements of TOP),
T/(mu N) at the end within R. The reuse stops GMRES at a relative residual of 1e-10, which
the equilibrium correction of the next increment sees as part of its out-of-balance force
(tolerance 1e-3): measured differences between the two runs are below 1e-12 of each table's
scale (the values agree to the 7 digits printed), so R = 1e-6 is strict and a reuse that
changed the path (another increment, another event) would fail it.

counts: the run's summary line of the reuse (fcs_factor_reuse) is printed and checked:
reuse on, some solves by GMRES, fewer factorisations than solves.
"""
import argparse
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import block_sliding  # noqa: E402
import contact_common as cc  # noqa: E402


def make_deck(path, tolerance):
    block_sliding.make_deck(path, 'partial', 0.01, None)
    lines = open(path).read().splitlines()
    last = len(lines) - 1 - lines[::-1].index('*END STEP')
    lines[last:last] = ['*NODE PRINT, NSET=TOP', 'U']
    if tolerance is not None:
        first_step = lines.index('*STEP, NLGEOM')
        lines[first_step:first_step] = ['*SOLVER, TYPE=UMFPACK, REUSE TOLERANCE=%g' % tolerance]
    cc.write_deck(path, lines)


def compare(fresh, reused, relative):
    checker = cc.Checker()
    a = cc.read_dat(fresh + '.dat')
    b = cc.read_dat(reused + '.dat')
    checker.check(len(a) == len(b) and len(a) > 0, '%d tables in %s.dat, %d in %s.dat'
                  % (len(a), fresh, len(b), reused))
    worst, where, mismatched = 0.0, '', 0
    for block_a, block_b in zip(a, b):
        same = (block_a['title'] == block_b['title'] and block_a['set'] == block_b['set'] and
                block_a['time'] == block_b['time'] and
                [k for k, _ in block_a['rows']] == [k for k, _ in block_b['rows']])
        if not same:
            mismatched += 1
            continue
        scale = max((abs(v).max() for _, v in block_a['rows'] if len(v)), default=0.0)
        for (keys, va), (_, vb) in zip(block_a['rows'], block_b['rows']):
            if len(va) != len(vb):
                mismatched += 1
                continue
            if scale > 0 and len(va):
                difference = abs(va - vb).max() / scale
                if difference > worst:
                    worst = difference
                    where = '%s, time %g, row %s' % (block_a['title'], block_a['time'], keys)
    checker.check(mismatched == 0, 'same tables, times and rows (%d differ)' % mismatched)
    checker.check(worst <= relative, 'largest difference %.3e of its table\'s scale (%s), '
                  'allowed %g' % (worst, where or '-', relative))
    ratios = []
    for job in (fresh, reused):
        _, forces = cc.totals(cc.read_dat(job + '.dat'), 'BASE')
        ratios.append(-forces[-1, 0] / forces[-1, 2] / block_sliding.MU)
    checker.check(abs(ratios[1] - ratios[0]) <= relative, 'T/(mu N) at the end: %.9f fresh, %.9f '
                  'reused (difference %.2e, allowed %g)' % (ratios[0], ratios[1],
                                                            abs(ratios[1] - ratios[0]), relative))
    checker.finish()


def counts(job):
    checker = cc.Checker()
    text = open(job + '.log').read()
    line = re.search(r'^\s*(factorisation reuse.*)$', text, re.M)
    checker.check(line is not None, 'the log has the factorisation reuse summary')
    if line is None:
        checker.finish()
    print('     ' + line.group(1))
    match = re.search(r'(\d+) solve\(s\), (\d+) direct, (\d+) by GMRES with (\d+) iteration\(s\)'
                      r'.*?; (\d+) factorisation\(s\)', line.group(1))
    checker.check(match is not None, 'reuse on, with counts of solves, GMRES and factorisations')
    if match is None:
        checker.finish()
    solves, _, krylov, iterations, factorisations = (int(g) for g in match.groups())
    checker.check(krylov > 0 and iterations >= krylov, '%d solves by GMRES, %d iterations'
                  % (krylov, iterations))
    checker.check(factorisations < solves, '%d factorisations for %d solves'
                  % (factorisations, solves))
    checker.finish()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    sub = parser.add_subparsers(dest='command', required=True)
    d = sub.add_parser('deck')
    d.add_argument('path')
    d.add_argument('--tolerance', type=float)
    c = sub.add_parser('compare')
    c.add_argument('fresh')
    c.add_argument('reused')
    c.add_argument('--relative', type=float, required=True)
    n = sub.add_parser('counts')
    n.add_argument('job')
    args = parser.parse_args()
    if args.command == 'deck':
        make_deck(args.path, args.tolerance)
    elif args.command == 'compare':
        compare(args.fresh, args.reused, args.relative)
    else:
        counts(args.job)


if __name__ == '__main__':
    main()
