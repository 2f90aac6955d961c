"""Loading histories of a bar: tabular *AMPLITUDE and prescribed velocities (*BOUNDARY,
TYPE=VELOCITY, with and without an amplitude), over several steps, against the closed-form
reaction history R(t) = E A u(t) / L.

    bar_history.py deck JOB.inp [--steps 3|1] [--nlgeom] [--scale S]
    bar_history.py check JOB [--steps 3|1] [--nlgeom] [--scale S]

Bars 4 x 1 x 1 (L = 4, A = 1) of 4 hexahedra, E = 1000, nu = 0.25, with symmetry conditions
u_x = 0 on x = 0, u_y = 0 on y = 0, u_z = 0 on z = 0; the end x = L carries the prescribed
u_x(t), the lateral faces are free: uniaxial stress, which the hexahedra represent exactly.

--steps 3 (default; the multi-step test of the issue), one bar:
  step 1 (period 1): u = S a1(t), a1 tabular and non-monotonic:
        (0, 0) (0.2, 1) (0.45, -0.5) (0.7, 0.25) (1, 0.8)
  step 2 (period 2): *BOUNDARY, TYPE=VELOCITY, v = -0.5 S: u = u(1) + v t (through 0 at t = 1.6)
  step 3 (period 1): *BOUNDARY, TYPE=VELOCITY, AMPLITUDE=V3, v = S, V3 in total time
        (3, 0) (3.5, 1) (4, 1): u = u(3) + S * integral of V3
  *TIME POINTS in step time (steps 1, 2) and in total time (step 3).
--steps 1: the same loadings in a single step of period 2, on two separate bars: bar A by
  the amplitude a1 (extended by the point (2, -0.2)), bar B (beside it) by a velocity
  S * vb(t), vb tabular (0, 1) (0.5, 1) (1, -1) (2, 0).
Output: *NODE PRINT of each end's RF with TOTALS=ONLY and of one end node's U at the time
points (on and between amplitude points).

Checks: the .dat header times are the requested ones to printing precision (7 digits), and at
each time the total reaction equals E A u(t)/L and the end displacement u(t), u(t) computed here
from the tables independently of fcs3d: within 1e-6 of the largest value without NLGEOM (a
linear problem: exact up to the 7 printed digits); with --nlgeom (use S = 1e-5: strains below
2.5e-6) within 1e-5, since geometric nonlinearity changes the force by O(strain).
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fcs_check as fc  # noqa: E402

YOUNG = 1000.0
POISSON = 0.25
LENGTH = 4.0
AREA = 1.0
A1 = ([0.0, 0.2, 0.45, 0.7, 1.0], [0.0, 1.0, -0.5, 0.25, 0.8])
V2 = -0.5                                   # step 2 velocity / S
A3 = ([3.0, 3.5, 4.0], [0.0, 1.0, 1.0])     # step 3 velocity amplitude, total time
STEP_TIMES = {1: [0.1, 0.2, 0.3, 0.45, 0.6, 0.7, 0.85, 1.0],
              2: [0.25, 0.5, 1.0, 1.6, 2.0]}
TOTAL_TIMES_3 = [3.2, 3.5, 3.75, 4.0]
A1_EXTENDED = (A1[0] + [2.0], A1[1] + [-0.2])  # one-step variant, bar A
VB = ([0.0, 0.5, 1.0, 2.0], [1.0, 1.0, -1.0, 0.0])  # one-step variant, bar B velocity
ONE_STEP_TIMES = [0.1, 0.2, 0.3, 0.45, 0.6, 0.7, 0.85, 1.0, 1.25, 1.5, 1.75, 2.0]
MAX_A = 1.0  # largest |amplitude| (and largest |u| / S) of every history here


def bar(index):
    """Bar number index (0, 1), side by side in y, and its node sets (suffix _A, _B)."""
    block = fc.Block(lx=LENGTH, nx=4, origin=(0.0, 2.0 * index, 0.0),
                     first_node=1 + 20 * index, first_element=1 + 4 * index)
    suffix = '_' + 'AB'[index]
    end = block.face(0, 1)
    sets = {'X0' + suffix: block.face(0, 0), 'Y0' + suffix: block.face(1, 0),
            'Z0' + suffix: block.face(2, 0), 'END' + suffix: end, 'END_NODE' + suffix: end[:1]}
    return block, sets


def prints(bars, time_points):
    lines = []
    for suffix in bars:
        lines += ['*NODE PRINT, NSET=END%s, TOTALS=ONLY, TIME POINTS=%s' % (suffix, time_points),
                  'RF', '*NODE PRINT, NSET=END_NODE%s, TIME POINTS=%s' % (suffix, time_points), 'U']
    return lines


def make_deck(path, steps, nlgeom, scale):
    step = '*STEP, NLGEOM' if nlgeom else '*STEP'
    n_bars = 1 if steps == 3 else 2
    lines = ['*HEADING', 'Bar under amplitude and velocity loading, %d step(s) '
             '(tests/integration/nlgeom/bar_history.py)' % steps]
    suffixes = []
    for index in range(n_bars):
        block, sets = bar(index)
        lines += block.mesh_cards(sets)
        suffix = '_' + 'AB'[index]
        suffixes.append(suffix)
        lines += ['*BOUNDARY', 'X0%s, 1, 1' % suffix, 'Y0%s, 2, 2' % suffix, 'Z0%s, 3, 3' % suffix]
    lines += fc.material_cards(YOUNG, POISSON)
    if steps == 3:
        lines += fc.amplitude_card('A1', *A1)
        lines += fc.amplitude_card('V3', *A3, time='TOTAL TIME')
        lines += ['*TIME POINTS, NAME=T1', ', '.join('%.17g' % t for t in STEP_TIMES[1]),
                  '*TIME POINTS, NAME=T2', ', '.join('%.17g' % t for t in STEP_TIMES[2]),
                  '*TIME POINTS, NAME=T3, TIME=TOTAL TIME',
                  ', '.join('%.17g' % t for t in TOTAL_TIMES_3)]
        lines += [step, '*STATIC', '1., 1.', '*BOUNDARY, AMPLITUDE=A1',
                  'END_A, 1, 1, %.17g' % scale] + prints(suffixes, 'T1') + ['*END STEP']
        lines += [step, '*STATIC', '1., 2.', '*BOUNDARY, TYPE=VELOCITY',
                  'END_A, 1, 1, %.17g' % (V2 * scale)] + prints(suffixes, 'T2') + ['*END STEP']
        lines += [step, '*STATIC', '1., 1.', '*BOUNDARY, TYPE=VELOCITY, AMPLITUDE=V3',
                  'END_A, 1, 1, %.17g' % scale] + prints(suffixes, 'T3') + ['*END STEP']
    else:
        lines += fc.amplitude_card('A1', *A1_EXTENDED)
        lines += fc.amplitude_card('VB', *VB)
        lines += ['*TIME POINTS, NAME=T', ', '.join('%.17g' % t for t in ONE_STEP_TIMES)]
        lines += [step, '*STATIC', '1., 2.',
                  '*BOUNDARY, AMPLITUDE=A1', 'END_A, 1, 1, %.17g' % scale,
                  '*BOUNDARY, TYPE=VELOCITY, AMPLITUDE=VB', 'END_B, 1, 1, %.17g' % scale] + \
            prints(suffixes, 'T') + ['*END STEP']
    fc.write_deck(path, lines)


def integral(times, values, t0, t1):
    """Integral of the piecewise-linear table (constant outside its points) from t0 to t1,
    exactly: trapezoids between the table points and the two limits."""
    knots = sorted(set([t0, t1] + [t for t in times if t0 < t < t1]))
    v = np.interp(knots, times, values)
    return float(np.sum(0.5 * (v[1:] + v[:-1]) * np.diff(knots)))


def end_displacements(steps, total_time, scale):
    """{suffix: u(t)} of the bar ends at total time t (closed form of the loading above)."""
    t = total_time
    if steps == 1:
        return {'_A': scale * np.interp(t, *A1_EXTENDED),
                '_B': scale * integral(VB[0], VB[1], 0.0, t)}
    if t <= 1.0:
        return {'_A': scale * np.interp(t, *A1)}
    u1 = scale * A1[1][-1]
    if t <= 3.0:
        return {'_A': u1 + V2 * scale * (t - 1.0)}
    return {'_A': u1 + V2 * scale * 2.0 + scale * integral(A3[0], A3[1], 3.0, t)}


def requested_total_times(steps):
    if steps == 1:
        return ONE_STEP_TIMES
    return STEP_TIMES[1] + [1.0 + t for t in STEP_TIMES[2]] + TOTAL_TIMES_3


def check(job, steps, nlgeom, scale):
    checker = fc.Checker()
    fc.read_increments(job + '.log')
    blocks = fc.read_dat(job + '.dat')
    requested = requested_total_times(steps)
    tolerance = 1e-5 if nlgeom else 1e-6
    stiffness = YOUNG * AREA / LENGTH
    scale_force = stiffness * scale * MAX_A
    for suffix in (['_A'] if steps == 3 else ['_A', '_B']):
        forces = fc.unique_times(fc.blocks_of(blocks, 'total force', 'END' + suffix))
        displacements = fc.unique_times(fc.blocks_of(blocks, 'displacements', 'END_NODE' + suffix))
        for name, found in (('RF totals', forces), ('U', displacements)):
            times = [t for _, _, t, _ in found]
            checker.check(fc.same_times(times, requested), 'bar %s: %s printed at the requested '
                          'times: %s' % (suffix[1], name, times))
        worst_force = worst_u = lateral = 0.0
        for (_, _, t, rows), (_, _, _, urows) in zip(forces, displacements):
            u = end_displacements(steps, t, scale)[suffix]
            worst_force = max(worst_force, abs(rows[0, 0] - stiffness * u) / scale_force)
            worst_u = max(worst_u, abs(urows[0, 1] - u) / (scale * MAX_A))
            lateral = max(lateral, np.abs(rows[0, 1:]).max() / scale_force)
            print('     bar %s t = %-9.7g u = %+.6e  RF = %+.6e  E A u / L = %+.6e' % (
                suffix[1], t, urows[0, 1], rows[0, 0], stiffness * u))
        checker.check(worst_force <= tolerance, 'bar %s: reaction history = E A u(t)/L within '
                      '%.0e of its largest value (worst %.2e)'
                      % (suffix[1], tolerance, worst_force))
        checker.check(worst_u <= tolerance, 'bar %s: end displacement history = u(t) within %.0e '
                      '(worst %.2e)' % (suffix[1], tolerance, worst_u))
        checker.check(lateral <= 1e-9, 'bar %s: no lateral reaction on the end (%.1e)'
                      % (suffix[1], lateral))
    checker.finish()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    sub = parser.add_subparsers(dest='command', required=True)
    for name in ('deck', 'check'):
        p = sub.add_parser(name)
        p.add_argument('path' if name == 'deck' else 'job')
        p.add_argument('--steps', type=int, choices=(1, 3), default=3)
        p.add_argument('--nlgeom', action='store_true')
        p.add_argument('--scale', type=float, default=0.01)
    args = parser.parse_args()
    if args.command == 'deck':
        make_deck(args.path, args.steps, args.nlgeom, args.scale)
    else:
        check(args.job, args.steps, args.nlgeom, args.scale)


if __name__ == '__main__':
    main()
