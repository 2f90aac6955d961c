"""The rate-and-state friction state survives a restart: a run restarted from a checkpoint
written in the middle of a velocity-step transient ends bit for bit where the uninterrupted
run ends.

    restart_state.py DIRECTORY

Model: friction_common.py (block pushed at its top), *FRICTION, LAW=RATE STATE (ageing law,
MU0=0.6, A=0.010, B=0.015, DC=1e-3 mm, V0=1e-3 mm/s, VC=1e-9 mm/s, VINIT=1e-3 mm/s). Step 2: the
top at 1e-3 mm/s for 5 s (steady state, theta = DC/V = 1 s); step 3: at 1e-2 mm/s for 0.3 s
(3 DC), increments of at most 1e-3 s: theta relaxes from 1 s towards 0.1 s. *RESTART, WRITE,
FREQUENCY=20, GENERATIONS=100 (every checkpoint kept); results frames every 10 increments.

1. reference/: the uninterrupted run.
2. The checkpoint of the reference run nearest to 0.04 s into step 3 (0.4 DC after the
   velocity step, theta far from both steady states) is the restart point; its theta must lie
   strictly between 0.1 and 1 s at every node (otherwise the test would not test the state).
3. fresh/: only the deck and that checkpoint; fcs3d --restart. Checks: the final checkpoint
   equal to the reference's in every dataset (displacements, stresses, the contact state
   with theta = friction_state, slip rate, mu, ...) but /meta/sizes (which counts the result
   frames of the run's own results file); the history CSV byte for byte; every results frame
   equal to the reference's frame of the same step and increment, dataset by dataset.
4. interrupted/: the reference's outputs (as an interrupted run would have left them, and
   more) plus that checkpoint; fcs3d --restart. Checks: <job>.h5 (every dataset and
   attribute), <job>.dat and the history CSV identical to the reference's.
"""
import glob
import os
import shutil
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import friction_common as fc  # noqa: E402

JOB = 'rs_restart'
V1, V2 = 1.0e-3, 1.0e-2
STEP2, STEP3 = 5.0, 0.3
RESTART_AT = 0.04   # s into step 3


def make_deck(path):
    p = fc.RS
    friction = fc.friction_card('RATE STATE', 1.0e5, MU0=p['MU0'], A=p['A'], B=p['B'],
                                DC=p['DC'], V0=p['V0'], VC=p['VC'], STATE_LAW='AGEING', VINIT=V1)
    steps = [dict(velocity=V1, period=STEP2, initial=5e-3, max=0.1),
             dict(velocity=V2, period=STEP3, initial=1e-4, max=1e-3)]
    fc.slider_deck(path, friction, steps, title='restart in a velocity-step transient',
                   restart='FREQUENCY=20, GENERATIONS=100', contact_file=10)


def run(directory, *args):
    binary = os.environ.get('FCS3D')
    result = subprocess.run([binary, '-q', JOB + '.inp', *args], cwd=directory,
                            capture_output=True, text=True)
    if result.returncode != 0:
        fc.fail('fcs3d %s in %s: exit status %d\n%s%s' % (' '.join(args), directory,
                                                          result.returncode, result.stdout,
                                                          result.stderr))


def h5_objects(path):
    import h5py
    out = {}
    with h5py.File(path, 'r') as f:
        def visit(name, obj):
            data = obj[()] if isinstance(obj, h5py.Dataset) else None
            out[name] = (data, {k: obj.attrs[k] for k in obj.attrs})
        f.visititems(visit)
        out['/'] = (None, {k: f.attrs[k] for k in f.attrs})
    return out


def same(a, b):
    a, b = np.asarray(a), np.asarray(b)
    return a.dtype == b.dtype and a.shape == b.shape and np.array_equal(a, b)


def differences(a, b, skip=()):
    """Datasets and attributes of two h5_objects dicts that differ (names in skip ignored)."""
    problems = []
    for name in sorted(set(a) | set(b)):
        if name in skip:
            continue
        if name not in a or name not in b:
            problems.append('%s only in one file' % name)
            continue
        (da, aa), (db, ab) = a[name], b[name]
        if (da is None) != (db is None) or (da is not None and not same(da, db)):
            problems.append('%s: values differ' % name)
        for key in set(aa) | set(ab):
            if (name, key) in skip:
                continue
            if key not in aa or key not in ab or not same(aa[key], ab[key]):
                problems.append('%s: attribute %s differs' % (name, key))
    return problems


def checkpoint_time(path):
    import h5py
    with h5py.File(path, 'r') as f:
        return float(f['meta/values'][()][0])


def contact_state(path):
    """theta (friction_state) of every slave from a checkpoint's /contact/scalars."""
    import h5py
    with h5py.File(path, 'r') as f:
        scalars = f['contact/scalars'][()]
    return scalars[6] if scalars.shape[0] == 9 else scalars[:, 6]


def frames_by_increment(objects):
    """{(step, increment): frame group name} of a results file's h5_objects."""
    out = {}
    for name, (data, attrs) in objects.items():
        if name.startswith('frames/') and name.count('/') == 1:
            out[(int(attrs['step']), int(attrs['increment']))] = name
    return out


def main(directory):
    checker = fc.Checker()
    os.makedirs(directory, exist_ok=True)
    reference = os.path.join(directory, 'reference')
    fresh = os.path.join(directory, 'fresh')
    interrupted = os.path.join(directory, 'interrupted')
    for d in (reference, fresh, interrupted):
        shutil.rmtree(d, ignore_errors=True)
        os.makedirs(d)
    make_deck(os.path.join(reference, JOB + '.inp'))
    run(reference)
    t_restart = fc.STEP1_PERIOD + STEP2 + RESTART_AT
    checkpoints = glob.glob(os.path.join(reference, JOB + '.rst.*.h5'))
    chosen = min(checkpoints, key=lambda c: abs(checkpoint_time(c) - t_restart))
    theta = contact_state(chosen)
    p = fc.RS
    checker.check(np.all(theta > p['DC'] / V2 * 1.01) and np.all(theta < p['DC'] / V1 * 0.99),
                  'restart point %s at t = %.5f s (%.3f s into the velocity step): theta = %s s, '
                  'between the steady states DC/V2 = %g and DC/V1 = %g s'
                  % (os.path.basename(chosen), checkpoint_time(chosen),
                     checkpoint_time(chosen) - fc.STEP1_PERIOD - STEP2,
                     ', '.join('%.6f' % x for x in theta), p['DC'] / V2, p['DC'] / V1))
    final_theta = contact_state(os.path.join(reference, JOB + '.rst.h5'))
    print('     theta at the end of the reference run: %s s' % ', '.join('%.6f' % x
                                                                       for x in final_theta))

    # 3. fresh directory: the deck and the checkpoint only.
    shutil.copy(os.path.join(reference, JOB + '.inp'), fresh)
    shutil.copy(chosen, os.path.join(fresh, 'restart_point.h5'))
    run(fresh, '--restart', 'restart_point.h5')
    problems = differences(h5_objects(os.path.join(reference, JOB + '.rst.h5')),
                           h5_objects(os.path.join(fresh, JOB + '.rst.h5')),
                           skip=('meta/sizes', ('meta', 'checksum'), ('meta/sizes', 'checksum')))
    checker.check(not problems, 'fresh restart: final checkpoint identical to the reference\'s '
                  'in every dataset but /meta/sizes (contact state incl. theta, u, stresses): %s'
                  % ('; '.join(problems[:5]) or 'yes'))
    with open(os.path.join(reference, JOB + '_' + fc.HISTORY + '.csv'), 'rb') as a, \
            open(os.path.join(fresh, JOB + '_' + fc.HISTORY + '.csv'), 'rb') as b:
        checker.check(a.read() == b.read(), 'fresh restart: history CSV byte for byte')
    ref_objects = h5_objects(os.path.join(reference, JOB + '.h5'))
    new_objects = h5_objects(os.path.join(fresh, JOB + '.h5'))
    ref_frames, new_frames = frames_by_increment(ref_objects), frames_by_increment(new_objects)
    bad = []
    for key, name in new_frames.items():
        if key not in ref_frames:
            bad.append('%s (step %d, increment %d) not in the reference' % (name, *key))
            continue
        mine = {n[len(name):]: v for n, v in new_objects.items() if n.startswith(name + '/')}
        theirs = {n[len(ref_frames[key]):]: v for n, v in ref_objects.items()
                  if n.startswith(ref_frames[key] + '/')}
        bad += ['%s%s' % (name, x) for x in differences(theirs, mine)]
    checker.check(len(new_frames) > 0 and not bad, 'fresh restart: %d results frames, each equal '
                  'to the reference frame of the same step and increment (all fields, incl. the '
                  'contact grid\'s mu and slip_rate): %s' % (len(new_frames),
                                                            '; '.join(bad[:5]) or 'yes'))

    # 4. an interrupted run's directory: the outputs are there (and go beyond the checkpoint).
    for name in os.listdir(reference):
        if name.endswith(('.h5', '.dat', '.csv', '.xdmf', '.log', '.echo', '.inp')) and \
                '.rst' not in name:
            shutil.copy(os.path.join(reference, name), interrupted)
    shutil.copy(chosen, os.path.join(interrupted, 'restart_point.h5'))
    run(interrupted, '--restart', 'restart_point.h5')
    problems = differences(ref_objects, h5_objects(os.path.join(interrupted, JOB + '.h5')))
    checker.check(not problems, 'restart over the outputs: %s.h5 identical to the reference\'s '
                  '(every dataset and attribute): %s' % (JOB, '; '.join(problems[:5]) or 'yes'))
    for name in (JOB + '.dat', JOB + '_' + fc.HISTORY + '.csv'):
        with open(os.path.join(reference, name), 'rb') as a, \
                open(os.path.join(interrupted, name), 'rb') as b:
            checker.check(a.read() == b.read(), 'restart over the outputs: %s byte for byte' % name)
    checker.finish()


if __name__ == '__main__':
    if len(sys.argv) != 2:
        raise SystemExit(__doc__)
    main(sys.argv[1])
