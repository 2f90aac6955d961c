"""Nucleation of a slip event on a velocity-weakening interface (issue 19): Ruina's slip law
with radiation damping, loaded slowly from one end.

    nucleation.py deck JOB.inp --xi XI
    nucleation.py check JOB [--compare JOB2]

Model (units mm, s, MPa, N, t): a granite strip 100 x 10 x 10 mm (20 x 1 x 1 hexahedra, E =
44800 MPa, nu = 0.12, rho = 2.6e-9 t/mm^3: the fault-bend material) pressed by sigma_n = 10 MPa
onto a fixed base (one hexahedron, all nodes held) and pushed in x at V_load = 1e-2 mm/s by
the two nodes of the top edge of its end x = 0 (y held everywhere). Node-to-point contact
STRIP (42 slave nodes at 5 mm spacing) with the fault-bend reference law: *FRICTION, LAW=RATE
STATE, MU0=0.60, A=0.010, B=0.025, V0=0.001, DC=L, VC=1e-9, STATE LAW=SLIP, VINIT=0.001,
RADIATION DAMPING=MATERIAL, and *RMIN, MAX SLIP INCREMENT=XI, EQUILIBRIUM TOLERANCE=5e-3, no
NO EQUILIBRIUM=CARRY (an increment whose equilibrium iterations fail is cut, and the run stops
at the minimum one, 1e-7 s). The tolerance: with the default 1e-3, an increment that the
R-minimum control puts at the minimum for a stick-to-slip change (node 27, 3.17 s, with XI =
0.1) stops at 2.5e-3 (its iterations diverge and it cannot be cut); 5e-3 of the mean nodal
force is the largest out-of-balance left, against 10.8 % carried by the paper's-law run.

Nucleation size. The strip is thin on the scale of a slipping patch, so a patch of length l
has the stiffness per unit area of a bar, k ~ E H / l^2 (H = 10 mm the strip's height), and
the patch becomes unstable (Ruina 1983: k < k_c = sigma_n (B - A) / L) once it is longer than
l* ~ sqrt(E H L / (sigma_n (B - A))) = 39 mm for L = 5e-4 mm: about 8 node spacings, and 0.4 of
the strip. Pushed at one end, the strip's shear is concentrated near the end: slip starts
there and a creeping zone grows along the strip with the load until it is about l* long; then
an event runs over the whole strip. The time between the first slipping node and the onset
of that event is the nucleation phase.

What check asserts (the job's <job>_strip.csv history, <job>_events.csv catalog and log):
  * the run went through without an out-of-balance increment carried ("(carried)" in the
    log; NO EQUILIBRIUM=STOP is the default, so a failure would have stopped it);
  * the first slipping node (first history row with a slip count > 0) precedes the onset of
    the first catalogued event over at least half of the slave nodes by at least half of the
    loading time to that onset (measured: first slip 0.10 s after the push starts, onset
    11.7 s later; a simultaneous slip of the whole interface, as with the paper's law held
    at steady state in the fault-bend model, gives 0);
  * the event is resolved: its peak slip rate is the quasi-dynamic one, far above the load
    rate (>= 100 V_load), and at least 20 increments lie between its onset and its end;
  * --compare JOB2 (the same deck with MAX SLIP INCREMENT halved): the first-slip time, the
    event's onset and the nucleation duration agree within 1 %, and the event's mean stress
    drop within 5 % (the increment control limits slip per increment, a first-order error in
    xi; the measured differences are listed in tests/integration/friction_nucleation.sh).

*RMIN limits as in input/fault_bend/fault_bend.inp: MAX STATE CHANGE = 2 and MAX FRICTION
CHANGE = 0.05, so that MAX SLIP INCREMENT governs inside the event.
"""
import argparse
import math
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', 'nlgeom'))
sys.path.insert(0, HERE)
import fcs_check  # noqa: E402
import friction_common as fc  # noqa: E402

PAIR = 'STRIP'
HISTORY = 'strip'
LENGTH, WIDTH, HEIGHT = 100.0, 10.0, 10.0
ELEMENTS = 20
YOUNG, POISSON, DENSITY = 44800.0, 0.12, 2.6e-9
SIGMA_N = 10.0
V_LOAD = 1.0e-2
DC = 5.0e-4
FRICTION = ('*FRICTION, LAW=RATE STATE, MU0=0.60, A=0.010, B=0.025, V0=0.001, DC=%g, VC=1e-9, '
            'STATE LAW=SLIP, VINIT=0.001, RADIATION DAMPING=MATERIAL' % DC)
PERIOD = 14.0             # s, stage 2 (to just after the first event)
SLAVE_NODES = 2 * (ELEMENTS + 1)
EQUILIBRIUM = 5.0e-3      # *RMIN, EQUILIBRIUM TOLERANCE (module doc)
TOL_TIME = 0.01           # relative, first slip, onset, nucleation duration (xi against xi/2)
TOL_DROP = 0.05           # relative, mean stress drop of the event (xi against xi/2)


def nucleation_length(dc=DC):
    """l* ~ sqrt(E H L / (sigma_n (B - A))) [mm], the bar estimate of the module doc."""
    return math.sqrt(YOUNG * HEIGHT * dc / (SIGMA_N * 0.015))


def make_deck(path, xi):
    strip = fcs_check.Block(LENGTH, WIDTH, HEIGHT, ELEMENTS, 1, 1, first_node=1, first_element=1)
    base = fcs_check.Block(LENGTH + 20.0, WIDTH + 20.0, 10.0, 1, 1, 1, origin=(-10.0, -10.0, -10.0),
                           first_node=1001, first_element=1001)
    driven = strip.nodes_where(lambda x, y, z: abs(x) < 1e-9 and abs(z - HEIGHT) < 1e-9)
    lines = ['*HEADING', 'nucleation on a strip (tests/integration/friction/nucleation.py)',
             '*NODE']
    for block in (strip, base):
        lines += ['%d, %.17g, %.17g, %.17g' % (block.first_node + n, *p)
                  for n, p in enumerate(block.x)]
    for name, block in (('STRIP_ELEMENTS', strip), ('BASE', base)):
        lines.append('*ELEMENT, TYPE=C3D8, ELSET=%s' % name)
        lines += ['%d, %s' % (block.first_element + e, ', '.join(str(n) for n in conn))
                  for e, conn in enumerate(block.elements)]
    sets = {'STRIP_NODES': [strip.first_node + n for n in range(len(strip.x))],
            'BASE_NODES': [base.first_node + n for n in range(len(base.x))],
            'DRIVEN': driven}
    for name, ids in sets.items():
        lines.append('*NSET, NSET=%s' % name)
        lines += [', '.join(str(n) for n in ids[i:i + 12]) for i in range(0, len(ids), 12)]
    lines += ['*SURFACE, NAME=SLAVE', 'STRIP_ELEMENTS, S1', '*SURFACE, NAME=MASTER', 'BASE, S2',
              '*SURFACE, NAME=LOADED', 'STRIP_ELEMENTS, S2',
              '*MATERIAL, NAME=GRANITE', '*ELASTIC', '%g, %g' % (YOUNG, POISSON),
              '*DENSITY', '%g' % DENSITY,
              '*SOLID SECTION, ELSET=STRIP_ELEMENTS, MATERIAL=GRANITE',
              '*SOLID SECTION, ELSET=BASE, MATERIAL=GRANITE',
              '*SURFACE INTERACTION, NAME=FAULT', FRICTION,
              '*CONTACT PAIR, INTERACTION=FAULT, NAME=%s' % PAIR, 'SLAVE, MASTER',
              '*HISTORY, NAME=%s, FREQUENCY=1' % HISTORY, 'CONTACT, %s' % PAIR,
              '*EVENT CATALOG, SLIP RATE=%g, MIN SLIP=%g' % (10.0 * V_LOAD, DC),
              '*BOUNDARY', 'BASE_NODES, 1, 3', 'STRIP_NODES, 2, 2',
              '*STEP, NAME=PRESS', '*STATIC', '0.1, 1.', '*BOUNDARY', 'DRIVEN, 1, 1',
              '*DSLOAD', 'LOADED, P, %g' % SIGMA_N, '*END STEP',
              '*STEP, NAME=PUSH', '*STATIC', '0.1, %g, 1e-7, 1.' % PERIOD,
              '*RMIN, MAX SLIP INCREMENT=%g, MAX STATE CHANGE=2, MAX FRICTION CHANGE=0.05, '
              'EQUILIBRIUM TOLERANCE=%g' % (xi, EQUILIBRIUM),
              '*BOUNDARY, TYPE=VELOCITY', 'DRIVEN, 1, 1, %g' % V_LOAD, '*END STEP']
    with open(path, 'w') as out:
        out.write('\n'.join(lines) + '\n')


class Result:
    """What check measures on one job."""

    def __init__(self, job):
        h = fc.read_csv(job + '_' + HISTORY + '.csv')
        self.t = h['time']
        slipping = np.nonzero(h[PAIR + '_SLIP'] > 0)[0]
        if len(slipping) == 0:
            fc.fail('%s: no slave node ever slips' % job)
        self.first_slip = self.t[slipping[0]]
        events = read_events(job + '_events.csv')
        big = [e for e in events if e['nodes'] >= SLAVE_NODES / 2]
        if not big:
            fc.fail('%s: no catalogued event over at least %d of the %d slave nodes (events: %s)'
                    % (job, SLAVE_NODES // 2, SLAVE_NODES, events))
        self.event = big[0]
        self.onset = self.event['onset']
        self.nucleation = self.onset - self.first_slip
        self.increments_in_event = int(np.count_nonzero((self.t > self.onset)
                                                        & (self.t <= self.event['end'])))
        with open(job + '.log') as f:
            self.carried = sum(1 for line in f if '(carried)' in line)

    def summary(self):
        e = self.event
        return ('first slip %.6f s, event onset %.6f s (%d nodes, peak %.4g mm/s, stress drop '
                '%.5g MPa, %d increments), nucleation %.6f s'
                % (self.first_slip, self.onset, e['nodes'], e['peak_slip_rate'], e['stress_drop'],
                   self.increments_in_event, self.nucleation))


def read_events(path):
    if not os.path.exists(path):
        fc.fail('%s was not written' % path)
    with open(path) as f:
        header = f.readline().strip().split(',')
        rows = [line.strip().split(',') for line in f if line.strip()]
    events = []
    for row in rows:
        item = dict(zip(header, row))
        events.append({k: (float(item[k]) if k not in ('pair',) else item[k])
                       for k in ('onset', 'end', 'nodes', 'peak_slip_rate', 'stress_drop', 'pair')})
    return events


def relative(a, b):
    return abs(a - b) / max(abs(b), 1e-300)


def check(job, compare):
    ok = fcs_check.Checker()
    r = Result(job)
    print('%s: %s' % (job, r.summary()))
    ok.check(r.carried == 0, '%s: %d increments carried their out-of-balance force (0 expected)'
             % (job, r.carried))
    loading = r.onset - 1.0    # the push starts at 1 s
    ok.check(r.nucleation >= 0.5 * loading,
             '%s: nucleation %.4g s, at least half of the loading time to the onset, %.4g s'
             % (job, r.nucleation, loading))
    ok.check(r.event['peak_slip_rate'] >= 100.0 * V_LOAD,
             '%s: peak slip rate %.4g mm/s, quasi-dynamic (>= %g)'
             % (job, r.event['peak_slip_rate'], 100.0 * V_LOAD))
    ok.check(r.increments_in_event >= 20,
             '%s: %d increments inside the event (>= 20)' % (job, r.increments_in_event))
    if compare:
        c = Result(compare)
        print('%s: %s' % (compare, c.summary()))
        for name, a, b, tol in (('first slip', r.first_slip, c.first_slip, TOL_TIME),
                                ('event onset', r.onset, c.onset, TOL_TIME),
                                ('nucleation duration', r.nucleation, c.nucleation, TOL_TIME),
                                ('stress drop', r.event['stress_drop'], c.event['stress_drop'],
                                 TOL_DROP)):
            d = relative(a, b)
            print('  %s: %.6g against %.6g (relative %.2e, tolerance %g)' % (name, a, b, d, tol))
            ok.check(d <= tol, '%s differs by %.3g relative (<= %g) between %s and %s'
                     % (name, d, tol, job, compare))
    ok.finish()
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    sub = parser.add_subparsers(dest='command', required=True)
    d = sub.add_parser('deck')
    d.add_argument('path')
    d.add_argument('--xi', type=float, required=True)
    c = sub.add_parser('check')
    c.add_argument('job')
    c.add_argument('--compare')
    args = parser.parse_args()
    if args.command == 'deck':
        make_deck(args.path, args.xi)
        print('l* ~ %.1f mm = %.1f node spacings' % (nucleation_length(), nucleation_length() /
                                                      (LENGTH / ELEMENTS)))
        return 0
    return check(args.job, args.compare)


if __name__ == '__main__':
    sys.exit(main())
