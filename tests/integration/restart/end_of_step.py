"""restart_end_of_step_checkpoint.sh: a restart from the periodic checkpoint of the last
increment of a step must not write that step's end-of-step frame a second time.

With *RESTART, FREQUENCY=1 every increment gets a periodic checkpoint, the last one of a step
included: it is written after the increment (step k, step time = period), BEFORE the
end-of-step outputs (the end-of-step frame, *NODE PRINT at the step end) and the end-of-step
checkpoint (step k + 1, step time 0). A kill between the two (the end-of-step checkpoint is
being written: fsync) leaves the periodic one as the newest: job.rst.1.h5 of a completed
step. Step 2 is shortened to 0.1 time units (push 0.005) to keep the FREQUENCY=1 runs short. Cases,
each compared with the one-go run of the same deck (job.h5 bit for bit, job.dat, CSVs, XDMF
frames):
  1. the deck with step 1 only, run to its end; the whole deck restarted from its
     job.rst.1.h5 (the last increment of step 1);
  2. the whole deck run to its end, restarted from its job.rst.1.h5 (the last increment of
     step 2).

Failed up to 418dfd4: the restart kept the frames up to the checkpoint's increment, the
end-of-step frame included (same increment), and the restarted run wrote it again: job.h5
and job.xdmf got one frame too many (two frames of the same step and increment). Fixed in
70d89cb: a checkpoint records the number of frames written, and a restart keeps those.
usage: end_of_step.py WORKDIR
"""
import os
import shutil
import sys

import restart_common as rc

JOB = 'job'
SHORT_STEP_2 = {2: [('TOP, 1, 1, 0.025', 'TOP, 1, 1, 0.005'), ('0.01, 0.5', '0.01, 0.1'),
                    ('0.05, 0.5, 0.05', '0.05, 0.1, 0.05')]}


def main():
    rc.require_h5py()
    work = sys.argv[1]
    failures = 0
    reference = rc.fresh_dir(os.path.join(work, 'reference'))
    rc.write_deck(os.path.join(reference, JOB + '.inp'), frequency=1, step_changes=SHORT_STEP_2)
    rc.run(reference, JOB)

    first = rc.fresh_dir(os.path.join(work, 'step1'))
    rc.write_deck(os.path.join(first, JOB + '.inp'), steps=1, frequency=1,
                  step_changes=SHORT_STEP_2)
    rc.run(first, JOB)
    shutil.copy(os.path.join(reference, JOB + '.inp'), first)
    last = os.path.join(reference, 'last')
    rc.fresh_dir(last)
    for name in os.listdir(reference):
        if os.path.isfile(os.path.join(reference, name)):
            shutil.copy(os.path.join(reference, name), last)
    for what, directory in [('step 1 alone, whole deck restarted from job.rst.1.h5', first),
                            ('whole deck restarted from job.rst.1.h5', last)]:
        print('%s: step %d, increment %d, time %g, step time %g' % (
            (what,) + rc.checkpoint_info(os.path.join(directory, 'job.rst.1.h5'))))
        rc.run(directory, JOB, '--restart', 'job.rst.1.h5')
        failures += bool(rc.compare_runs(reference, directory, JOB, what))
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
