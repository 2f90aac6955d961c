"""How the rigid-rotation result depends on the rotation increment (rigid_rotation.py, one step):
amplitude points every 0.05, 0.1, 0.2 and 0.5 degrees (one increment per interval), and
points every 1 degree with *RMIN, MAX ROTATION INCREMENT=0.25 (four increments per interval,
ending on the chord between amplitude points).

    rotation_increment_study.py [--markdown FILE]     (runs $FCS3D in the current directory)

Measured at 90 degrees, before the final hold: the largest difference of the stress from
R sigma_1 R^T (relative to |sigma_1|) and the change of the Mises stress; after the hold: the
same difference. Checks: the offset during the rotation grows as dtheta^2 (observed order 2 +-
0.1 between the single-increment-per-interval runs) and is no larger than the predictor estimate
C:(nu/(1-nu) dtheta^2 e_z e_z) + 10 %; after the hold the rotation is exact to 1e-5 in every run.
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fcs_check as fc  # noqa: E402
import rigid_rotation as rr  # noqa: E402

RUNS = ((0.05, None), (0.1, None), (0.2, None), (0.5, None), (1.0, 0.25))


def measure(spacing, rotation_limit):
    name = 'rotation_%g' % spacing + ('_limit_%g' % rotation_limit if rotation_limit else '')
    rr.make_deck(name + '.inp', 1, spacing, rotation_limit)
    fc.run_fcs3d(name + '.inp')
    records, _ = fc.read_increments(name + '.log')
    stresses = [s.mean(axis=0) for _, s in fc.stress_blocks(fc.read_dat(name + '.dat'))]
    if len(stresses) != len(rr.ANGLES) + 2:
        fc.fail('%s.dat: %d stress blocks, expected %d' % (name, len(stresses), len(rr.ANGLES) + 2))
    sigma1 = rr.tensor(stresses[0])
    scale = np.abs(sigma1).max()
    expected = rr.rotation(90.0) @ sigma1 @ rr.rotation(90.0).T
    during = np.abs(rr.tensor(stresses[-2]) - expected).max() / scale
    after = np.abs(rr.tensor(stresses[-1]) - expected).max() / scale
    mises = fc.mises(stresses[-2]) / fc.mises(stresses[0]) - 1.0
    increment = rotation_limit if rotation_limit else spacing
    lam, shear = rr.lame()
    dz = rr.POISSON / (1.0 - rr.POISSON) * np.radians(increment) ** 2
    predicted = (lam + 2.0 * shear) * dz / scale
    rotation_increments = len([r for r in records if rr.rotation_time(1, 0.0) < r['time']
                               <= rr.rotation_time(1, 90.0) + 1e-12])
    return dict(spacing=spacing, limit=rotation_limit, increment=increment,
                increments=rotation_increments, during=during, after=after, mises=mises,
                predicted=predicted)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--markdown', help='also write the table to this file')
    args = parser.parse_args()
    checker = fc.Checker()
    results = [measure(spacing, limit) for spacing, limit in RUNS]
    table = ['| amplitude points every | MAX ROTATION INCREMENT | rotation increments | '
             'offset at 90 deg | Mises change at 90 deg | predictor estimate | '
             'error after the hold |', '|---|---|---|---|---|---|---|']
    for r in results:
        table.append('| %g deg | %s | %d | %.2e | %+.2e | %.2e | %.1e |' % (
            r['spacing'], '%g deg' % r['limit'] if r['limit'] else '0.5 deg (default)',
            r['increments'], r['during'], r['mises'], r['predicted'], r['after']))
        checker.check(r['during'] <= 1.1 * r['predicted'], 'increment %g deg: offset %.2e '
                      'within the predictor estimate %.2e + 10 %%'
                      % (r['increment'], r['during'], r['predicted']))
        checker.check(r['after'] <= 1e-5, 'increment %g deg: exact after the hold (%.1e)'
                      % (r['increment'], r['after']))
    single = [r for r in results if r['limit'] is None]
    for a, b in zip(single, single[1:]):
        order = math.log(b['during'] / a['during']) / math.log(b['increment'] / a['increment'])
        checker.check(abs(order - 2.0) <= 0.1, 'increment %g -> %g deg: offset order %.2f is '
                      '2 +- 0.1' % (a['increment'], b['increment'], order))
    print('\n'.join(table))
    if args.markdown:
        with open(args.markdown, 'w') as out:
            out.write('\n'.join(table) + '\n')
    checker.finish()


if __name__ == '__main__':
    main()
