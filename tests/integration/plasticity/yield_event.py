"""The R-minimum yield event and the plastic strain limit (plasticity_yield_event.sh).

    yield_event.py WORKDIR

One C3D8 on the unit cube, symmetry conditions on x = 0, y = 0, z = 0, a force on the four
top nodes rising linearly to a uniform axial stress of 300 over the step (load control),
E = 200000, nu = 0.3, s_y = 200, linear isotropic hardening H = 2000 (stress against plastic
strain). Closed form: eps = s / E + max(0, s - s_y) / H, first yield at t = 2/3. Trial
increments of 0.25: the third crosses the yield point.

1. With the events (default): the third increment is cut by a yield event (the log names the
   element and integration point) and ends on the yield surface: the Mises stress of every
   point equals s_y within 1e-10 and no plastic strain was taken (PEEQ below 1e-10 of the
   yield strain): the elastic-plastic transition does not overshoot. Then the plastic increments are limited by MAX PLASTIC
   STRAIN INCREMENT (default 1e-3): PEEQ grows by at most 1e-3 (1 + 1e-9) per increment, by
   exactly 1e-3 in the increments it limits (its estimate is exact for proportional loading on
   one segment of the curve), and *RMIN, MAX PLASTIC STRAIN INCREMENT=5e-4 halves the growth.
   The displacement of every increment agrees with the closed form within 1e-10, and the
   out-of-balance force stays at round-off (1e-10 of the force).
2. A large fixed increment (*STATIC 0.25, 1., 0.25, 0.25: minimum = maximum, so the yield
   event is floored and the whole increment taken with the elastic tangent), and no
   equilibrium iterations (*RMIN, EQUILIBRIUM TOLERANCE=1: they would return-map the
   increment onto the curve, as an implicit step does): the transition increment's elastic
   predictor overshoots the yield surface by 12.5 % of s_y (225 against 200); the
   displacement after it is the elastic one, far from the closed form, and it leaves an
   out-of-balance force of several percent of the force scale. Both must show (displacement
   error > 50 %, out-of-balance > 5 %).
"""
import os
import sys

import numpy as np

import plastic_common as pc

fc = pc.fc
YOUNG, POISSON, YIELD, HARDENING = 200000.0, 0.3, 200.0, 2000.0
STRESS = 300.0
LIMIT = 1e-3
EXACT = 1e-10


def deck(path, static='0.25, 1.', rmin=None):
    block = fc.Block()
    sets = {'X0': block.face(0, 0), 'Y0': block.face(1, 0), 'Z0': block.face(2, 0),
            'TOP': block.face(2, 1)}
    lines = ['*HEADING', 'load-controlled uniaxial stress through yield '
             '(tests/integration/plasticity/yield_event.py)']
    lines += block.mesh_cards(sets)
    lines += pc.von_mises_cards(YOUNG, POISSON, [(YIELD, 0.0), (YIELD + HARDENING, 1.0)])
    lines += ['*BOUNDARY', 'X0, 1, 1', 'Y0, 2, 2', 'Z0, 3, 3', '*STEP', '*STATIC', static]
    if rmin:
        lines.append(rmin)
    lines += ['*CLOAD', 'TOP, 3, %r' % (STRESS / 4.0),
              '*NODE FILE, FREQUENCY=1', 'U', '*EL FILE, FREQUENCY=1', 'S, PEEQ', '*END STEP']
    fc.write_deck(path, lines)


def run(work, name, **options):
    job = os.path.join(work, name)
    deck(job + '.inp', **options)
    fc.run_fcs3d(job + '.inp')
    frames = pc.Frames(job + '.h5')
    records, _ = fc.read_increments(job + '.log')
    top = frames.node(fc.Block().face(2, 1)[0])
    return frames, records, frames.displacement[:, top, 2]


def closed_strain(stress):
    return stress / YOUNG + np.maximum(0.0, stress - YIELD) / HARDENING


def check_events(work, checker):
    frames, records, u = run(work, 'events')
    first = next(k for k, r in enumerate(records) if r['limit'] == 'yield')
    frame = first + 1  # frame 0 is the initial state
    mises = fc.mises(frames.stress[frame]).ravel()
    landing = np.abs(mises / YIELD - 1.0).max()
    crossing = next(k for k, r in enumerate(records) if r['time'] - r['dt'] + r['dt'] / r['r'] > 2.0 / 3.0)
    checker.check(first == crossing and records[first]['entity'].startswith('element 1 ip'),
                  'the increment whose trial crosses the yield point (%d) is limited by a yield '
                  'event at %s, r = %.6g' % (records[first]['inc'], records[first]['entity'],
                                             records[first]['r']))
    checker.check(landing <= EXACT and frames.peeq[frame].max() <= EXACT * YIELD / YOUNG,
                  'it lands on the yield surface: |Mises / s_y - 1| = %.2e at every point '
                  '(tolerance %.0e), PEEQ %.1e: no overshoot' % (landing, EXACT, frames.peeq[frame].max()))
    checker.relative('it ends at the yield time 2/3', frames.times[frame], 2.0 / 3.0, 1e-12)
    stress = STRESS * frames.times
    error = np.abs(u - closed_strain(stress)).max() / closed_strain(STRESS)
    checker.check(error <= EXACT, 'displacement of every increment vs the closed form: %.2e of the '
                  'final one (tolerance %.0e)' % (error, EXACT))
    worst = max(r['residual'] for r in records[1:])
    checker.check(worst <= EXACT, 'out-of-balance force at round-off: %.2e of the force scale' % worst)
    growth = np.diff(frames.peeq.max(axis=(1, 2)))
    limited = [k for k, r in enumerate(records) if r['limit'] == 'plastic-strain-limit']
    checker.check(len(limited) >= 10 and growth.max() <= LIMIT * (1 + 1e-9) and
                  all(abs(growth[k] - LIMIT) <= 1e-9 * LIMIT for k in limited) and
                  all(r['entity'].startswith('element 1 ip') for k, r in enumerate(records) if k in limited),
                  '%d increments limited by the plastic-strain-limit (log names element and point), '
                  'PEEQ growing by %.6g at most (MAX PLASTIC STRAIN INCREMENT %g)'
                  % (len(limited), growth.max(), LIMIT))
    half, records_half, _ = run(work, 'events_half', rmin='*RMIN, MAX PLASTIC STRAIN INCREMENT=5e-4')
    growth_half = np.diff(half.peeq.max(axis=(1, 2)))
    checker.check(growth_half.max() <= 0.5 * LIMIT * (1 + 1e-9) and len(records_half) > 1.8 * len(records) - 10,
                  'MAX PLASTIC STRAIN INCREMENT=5e-4: growth %.6g at most, %d increments (%d with 1e-3)'
                  % (growth_half.max(), len(records_half), len(records)))


def check_fixed_increment(work, checker):
    frames, records, u = run(work, 'fixed', static='0.25, 1., 0.25, 0.25',
                             rmin='*RMIN, EQUILIBRIUM TOLERANCE=1.')
    transition = next(k for k in range(1, len(frames.times)) if frames.peeq[k].max() > 0.0)
    t = frames.times[transition]
    applied = STRESS * t
    overshoot = (applied - YIELD) / YIELD
    displacement_error = abs(u[transition] - closed_strain(applied)) / closed_strain(applied)
    residual = records[transition - 1]['residual']
    checker.check(abs(t - 0.75) < 1e-12 and records[transition - 1]['floored'],
                  'large fixed increment: the yield event is floored, the transition increment '
                  'ends at t = %.6g' % t)
    checker.check(overshoot > 0.1, 'its elastic predictor overshoots the yield surface by %.1f %% '
                  'of s_y' % (100 * overshoot))
    checker.check(displacement_error > 0.5 and residual > 0.05,
                  'the overshoot shows: displacement %.0f %% off the closed form after it, '
                  'out-of-balance force %.1f %% of the force scale left by it'
                  % (100 * displacement_error, 100 * residual))


def main():
    pc.require_h5py()
    work = sys.argv[1]
    os.makedirs(work, exist_ok=True)
    checker = fc.Checker()
    check_events(work, checker)
    check_fixed_increment(work, checker)
    checker.finish()


if __name__ == '__main__':
    main()
