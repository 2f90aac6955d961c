"""Convergence of the R-minimum stepper as its limits are tightened: simple shear to gamma = 1
(simple_shear.py), run with *RMIN, MAX STRAIN INCREMENT = 1e-2, 3e-3, 1e-3 and with
MAX ROTATION INCREMENT = 2, 0.5, 0.1 degrees (strain limit 0.1, so that the rotation limit
governs), error against the Jaumann closed form at gamma = 1.

    convergence.py [--markdown FILE]      (runs $FCS3D in the current directory)

Checks: every increment line of every job.log names its limiting criterion in the documented
format, and the limit the run was meant to exercise governs (almost) every increment; the error
decreases monotonically as each limit is tightened; the observed order of convergence is 2
within 0.3 (fcs3d rotates half of C:dD with sigma_n and adds the other half after the rotation,
the midpoint form of the Hughes-Winget update, second order in the increment; the earlier
first-order splitting, C:dD added after the rotation, converged at order 1, see
doc/validation/nlgeom.md). Prints the table
(Markdown) and writes it to FILE if given.
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fcs_check as fc  # noqa: E402
import simple_shear  # noqa: E402

SERIES = (
    ('MAX STRAIN INCREMENT', 'strain-limit', (1e-2, 3e-3, 1e-3)),
    ('MAX ROTATION INCREMENT', 'rotation-limit', (2.0, 0.5, 0.1)),
)


def run_case(name, strain_limit, rotation_limit):
    simple_shear.make_deck(name + '.inp', strain_limit, rotation_limit, 1.0)
    fc.run_fcs3d(name + '.inp')
    records, n_increments = fc.read_increments(name + '.log')
    stresses = fc.stress_blocks(fc.read_dat(name + '.dat'))
    final = [s for t, s in stresses if abs(t - 1.0) < 1e-7]
    if not final:
        fc.fail('%s.dat: no stresses at gamma = 1' % name)
    s = final[0].mean(axis=0)
    exact = simple_shear.closed_form(1.0)
    tensor = lambda v: np.array([[v[0], v[3], v[4]], [v[3], v[1], v[5]], [v[4], v[5], v[2]]])
    error = np.linalg.norm(tensor(s) - tensor(exact)) / np.linalg.norm(tensor(exact))
    limits = {}
    for r in records:
        limits[r['limit']] = limits.get(r['limit'], 0) + 1
    return dict(increments=n_increments, error=error,
                s11=(s[0] - exact[0]) / exact[0], s12=(s[3] - exact[3]) / exact[3],
                limits=limits)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--markdown', help='also write the table to this file')
    args = parser.parse_args()
    checker = fc.Checker()
    table = ['| limit | value | increments | limiting criterion (increments) | '
             'error s11 | error s12 | error norm | observed order |',
             '|---|---|---|---|---|---|---|---|']
    for keyword, criterion, values in SERIES:
        results = []
        for value in values:
            if criterion == 'strain-limit':
                result = run_case('shear_strain_%g' % value, value, 10.0)
            else:
                result = run_case('shear_rotation_%g' % value, 0.1, value)
            results.append(result)
            # The limit under test governs every increment except the few cut short by an
            # output time (logged as "full": the trial increment ended at the breakpoint).
            governed = result['limits'].get(criterion, 0)
            checker.check(governed >= result['increments'] - 4,
                          '%s = %g: %d of %d increments limited by %s (%s)'
                          % (keyword, value, governed, result['increments'], criterion,
                             result['limits']))
        for k, (value, result) in enumerate(zip(values, results)):
            order = ''
            if k > 0:
                previous = results[k - 1]
                p = math.log(previous['error'] / result['error']) / math.log(values[k - 1] / value)
                order = '%.2f' % p
                checker.check(result['error'] < previous['error'],
                              '%s %g -> %g: error decreases (%.3e -> %.3e)'
                              % (keyword, values[k - 1], value, previous['error'], result['error']))
                checker.check(1.7 <= p <= 2.3, '%s %g -> %g: observed order %.2f is 2 +- 0.3'
                              % (keyword, values[k - 1], value, p))
            table.append('| %s | %g%s | %d | %s | %+.3e | %+.3e | %.3e | %s |' % (
                keyword, value, ' deg' if criterion == 'rotation-limit' else '',
                result['increments'],
                ', '.join('%s %d' % kv for kv in sorted(result['limits'].items())),
                result['s11'], result['s12'], result['error'], order))
    print('\n'.join(table))
    if args.markdown:
        with open(args.markdown, 'w') as out:
            out.write('\n'.join(table) + '\n')
    checker.finish()


if __name__ == '__main__':
    main()
