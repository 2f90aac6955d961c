"""restart_deck_changes.sh: what a restart accepts of a changed deck.

Runs: the stick-slip deck with 2 steps (its checkpoints: job.rst.h5 after step 2, job.rst.1.h5
a few increments before, within step 2), the deck with an added step 3 in one go, and the
deck with step 1 only (its end-of-step checkpoint). Then, each from fresh copies of the outputs:
  refused (exit 2, message names what differs):
  - Young's modulus 1000 -> 1001 (model section): "the model definition ... differs";
  - one node moved by 1e-3 (the mesh is part of the model): the same;
  - step 1 changed (pressure 10 -> 11) under a checkpoint within step 2: "step 1 of the deck
    differs";
  - step 2 changed (end displacement 0.025 -> 0.03) under a checkpoint within step 2:
    "step 2 of the deck differs";
  - the 1-step deck under the checkpoint after step 2: "the checkpoint is after step 2 but
    the deck has only 1 step(s)";
  accepted:
  - step 3 added, from the checkpoint after step 2 and from the one within step 2: step 3
    runs ("end of step 3" in job.log), the outputs equal the 3-step one-go run's bit for bit
    (job.h5, job.dat, CSVs, XDMF frames), and what steps 1 and 2 wrote is unchanged: the
    frames of steps 1-2 equal the 2-step run's, its job.dat and CSVs are prefixes;
  - step 2 changed (shortened to 0.1) under the end-of-step-1 checkpoint (step 2 not begun):
    exit 0, and job.log shows the changed step 2 ran to time 1.1.
usage: deck_changes.py WORKDIR
"""
import os
import re
import shutil
import sys

import restart_common as rc

JOB = 'job'


def copy_dir(source, target):
    rc.fresh_dir(target)
    for name in os.listdir(source):
        shutil.copy(os.path.join(source, name), target)
    return target


class Cases:
    def __init__(self, work):
        self.work = work
        self.failures = 0

    def fail(self, what, text):
        self.failures += 1
        print('FAIL %s: %s' % (what, text))

    def refused(self, what, source, checkpoint, deck, expected):
        directory = copy_dir(source, os.path.join(self.work, 'case'))
        with open(os.path.join(directory, JOB + '.inp'), 'w') as f:
            f.write(deck)
        status, message = rc.run(directory, JOB, '--restart', checkpoint, check=False)
        missing = [text for text in expected if text not in message]
        if status != 2 or missing:
            self.fail(what, 'exit status %d (expected 2), message lacks %s:\n  %s' % (
                status, missing, message.strip()))
        else:
            print('refused, %s: %s' % (what, message.strip().splitlines()[0][:160]))

    def accepted(self, what, source, checkpoint, deck):
        directory = copy_dir(source, os.path.join(self.work, what.replace(' ', '_')))
        with open(os.path.join(directory, JOB + '.inp'), 'w') as f:
            f.write(deck)
        status, message = rc.run(directory, JOB, '--restart', checkpoint, check=False)
        if status != 0:
            self.fail(what, 'exit status %d: %s' % (status, message.strip()))
            return None
        return directory


def prefix_problems(short_dir, long_dir):
    """What the 2-step run wrote must be the start of what the 3-step run wrote."""
    problems = []
    for name in rc.output_names(JOB):
        with open(os.path.join(short_dir, name), 'rb') as f:
            short = f.read()
        with open(os.path.join(long_dir, name), 'rb') as f:
            long = f.read()
        if not long.startswith(short) or len(long) == len(short) and name != JOB + '_events.csv':
            problems.append('%s of the 2-step run is not a proper prefix of the 3-step one' % name)
    import h5py
    with h5py.File(os.path.join(short_dir, JOB + '.h5'), 'r') as f:
        frames = sorted(f['frames'])
    problems += rc.compare_h5(os.path.join(short_dir, JOB + '.h5'),
                              os.path.join(long_dir, JOB + '.h5'),
                              select=lambda n: n.startswith('/frames/') and
                              n.split('/')[2] in frames or n.startswith('/mesh') or
                              n.startswith('/surfaces'))
    return problems, len(frames)


def main():
    rc.require_h5py()
    work = sys.argv[1]
    cases = Cases(work)
    two = rc.fresh_dir(os.path.join(work, 'two_steps'))
    rc.write_deck(os.path.join(two, JOB + '.inp'))
    rc.run(two, JOB)
    three = rc.fresh_dir(os.path.join(work, 'three_steps'))
    rc.write_deck(os.path.join(three, JOB + '.inp'), steps=3)
    rc.run(three, JOB)
    one = rc.fresh_dir(os.path.join(work, 'one_step'))
    rc.write_deck(os.path.join(one, JOB + '.inp'), steps=1)
    rc.run(one, JOB)
    for name in ['job.rst.h5', 'job.rst.1.h5']:
        print('2-step run, %s: step %d, increment %d, time %.6g, step time %.6g' % (
            (name,) + rc.checkpoint_info(os.path.join(two, name))))

    within = 'job.rst.1.h5'  # a few increments before the end of step 2
    assert rc.checkpoint_info(os.path.join(two, within))[0] == 2
    base = rc.deck_text()
    cases.refused('Young\'s modulus changed', two, within, rc.deck_text(young='1001.'),
                  ['the model definition', 'differs from the one the checkpoint was written for'])
    moved = base.replace('\n10001, 1.1, 1.1, 0\n', '\n10001, 1.101, 1.1, 0\n')
    assert moved != base
    cases.refused('a node moved', two, within, moved,
                  ['the model definition', 'differs from the one the checkpoint was written for'])
    cases.refused('step 1 changed', two, within,
                  rc.deck_text(step_changes={1: [('UPPERTOP, P, 10.', 'UPPERTOP, P, 11.')]}),
                  ['step 1 of the deck differs from the step the checkpoint ran'])
    cases.refused('step 2 changed', two, within,
                  rc.deck_text(step_changes={2: [('TOP, 1, 1, 0.025', 'TOP, 1, 1, 0.03')]}),
                  ['step 2 of the deck differs from the step the checkpoint ran'])
    cases.refused('steps removed', two, 'job.rst.h5', rc.deck_text(steps=1),
                  ['the checkpoint is after step 2 but the deck has only 1 step(s)'])

    deck3 = rc.deck_text(steps=3)
    for checkpoint in ['job.rst.h5', within]:
        what = 'step 3 added, restart from ' + checkpoint
        directory = cases.accepted(what, two, checkpoint, deck3)
        if directory is None:
            continue
        with open(os.path.join(directory, JOB + '.log')) as f:
            if 'end of step 3 ' not in f.read():
                cases.fail(what, 'job.log has no "end of step 3"')
        if rc.compare_runs(three, directory, JOB, what):
            cases.failures += 1
        problems, n = prefix_problems(two, directory)
        if problems:
            cases.fail(what, '; '.join(problems[:10]))
        else:
            print('%s: the %d frames of the 2-step run unchanged, its job.dat and CSVs are '
                  'prefixes' % (what, n))

    changed2 = rc.deck_text(step_changes={2: [('TOP, 1, 1, 0.025', 'TOP, 1, 1, 0.005'),
                                              ('0.01, 0.5', '0.01, 0.1'),
                                              ('0.05, 0.5, 0.05', '0.05, 0.1, 0.05')]})
    what = 'step 2 changed before it began'
    directory = cases.accepted(what, one, 'job.rst.h5', changed2)
    if directory:
        with open(os.path.join(directory, JOB + '.log')) as f:
            log = f.read()
        if not re.search(r'end of step 2 .* at time 1\.1 ', log):
            cases.fail(what, 'job.log has no "end of step 2 ... at time 1.1"')
        else:
            print('accepted, %s (restart from the end of step 1): step 2 ran' % what)
    return 1 if cases.failures else 0


if __name__ == '__main__':
    sys.exit(main())
