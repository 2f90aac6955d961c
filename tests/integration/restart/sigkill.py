"""restart_sigkill.sh: a run killed with SIGKILL and restarted from its last checkpoint gives
the one-go run's outputs bit for bit; so does a restart at a step boundary.

1. one-go run of the stick-slip deck (checkpoints every increment, the slowest setting,
   so that a kill lands anywhere: within an increment, within an output, within a checkpoint);
2. the same deck killed with SIGKILL at a random moment after its first checkpoint, restarted
   from job.rst.h5, the restarted run killed again at a random moment after it wrote a
   checkpoint of its own, restarted again to the end; every dataset and attribute of job.h5,
   job.dat, job.xdmf, job_fault.csv and job_events.csv must equal the one-go run's;
3. step boundary: the deck with step 1 only, run to its end; the full deck restarted from its
   end-of-step checkpoint: outputs equal to the one-go run's;
4. step boundary, the other checkpoint: with FREQUENCY=1 the last increment of step 1 gets a
   periodic checkpoint (step 1, step time = period) just before the end-of-step outputs and
   the end-of-step checkpoint; a kill between the two leaves it as the newest. Restarting
   from it (job.rst.1.h5 of the step-1 run) must also give the one-go outputs.

The random moments come from $FCS3D_TEST_SEED (else the clock; printed). Each kill is drawn
uniformly in [0, 0.8 T] after the checkpoint appeared, T the one-go run's wall time, so it
falls before the end of the run; a run that ends first is retried (at most 5 times).
usage: sigkill.py WORKDIR
"""
import os
import shutil
import signal
import sys
import time

import restart_common as rc

JOB = 'job'


def kill_at_random(directory, args, rng, window, newer_than):
    """Start fcs3d, wait for a checkpoint newer than `newer_than`, kill -9 after a random
    delay in [0, window]; returns (delay, checkpoint increment at the kill)."""
    for attempt in range(5):
        process = rc.start(directory, JOB, *args)
        seen = rc.wait_for_checkpoint(process, os.path.join(directory, JOB + '.rst.h5'), newer_than)
        delay = rng.uniform(0.0, window)
        if seen is not None:
            time.sleep(delay)
            process.send_signal(signal.SIGKILL)
        status = process.wait()
        if status == -signal.SIGKILL:
            step, increment, t, _ = rc.checkpoint_info(os.path.join(directory, JOB + '.rst.h5'))
            print('  killed %.3f s after checkpoint %d appeared; newest checkpoint: step %d, '
                  'increment %d, time %.6g' % (delay, seen, step, increment, t))
            return increment
        print('  the run ended (status %d) before the kill after %.3f s; again with a shorter '
              'window' % (status, delay))
        window *= 0.5
        if args:  # a restarted run that ended: restart it from the same checkpoint again
            pass
    raise SystemExit('could not kill the run before its end in 5 attempts')


def main():
    rc.require_h5py()
    work = sys.argv[1]
    rng = rc.seeded_random('restart_sigkill')
    failures = 0

    reference = rc.fresh_dir(os.path.join(work, 'reference'))
    rc.write_deck(os.path.join(reference, JOB + '.inp'), frequency=1)
    t0 = time.monotonic()
    rc.run(reference, JOB)
    wall = time.monotonic() - t0
    datasets, frames = rc.h5_summary(os.path.join(reference, JOB + '.h5'))
    print('one-go run: %.2f s, %d datasets, %d frames' % (wall, datasets, frames))

    # Two random kills, then a restart to the end.
    killed = rc.fresh_dir(os.path.join(work, 'killed'))
    shutil.copy(os.path.join(reference, JOB + '.inp'), killed)
    print('kill 1:')
    first = kill_at_random(killed, [], rng, 0.8 * wall, -1)
    # The restart must itself write a checkpoint before the second kill (one newer than the
    # first); before that, save the checkpoint so that a retry restarts from the same state.
    saved = os.path.join(killed, 'first.rst.h5')
    shutil.copy(os.path.join(killed, JOB + '.rst.h5'), saved)
    print('kill 2 (of the restarted run):')
    for attempt in range(5):
        process = rc.start(killed, JOB, '--restart', saved)
        seen = rc.wait_for_checkpoint(process, os.path.join(killed, JOB + '.rst.h5'), first)
        delay = rng.uniform(0.0, 0.8 * wall * (0.5 ** attempt))
        if seen is not None:
            time.sleep(delay)
            process.send_signal(signal.SIGKILL)
        status = process.wait()
        if status == -signal.SIGKILL:
            step, increment, t, _ = rc.checkpoint_info(os.path.join(killed, JOB + '.rst.h5'))
            print('  killed %.3f s after checkpoint %d appeared; newest checkpoint: step %d, '
                  'increment %d, time %.6g' % (delay, seen, step, increment, t))
            break
        if status != 0:
            raise SystemExit('the restarted run failed with status %d:\n%s' % (
                status, process.stderr.read()))
        print('  the restarted run ended before the kill; again')
    else:
        raise SystemExit('could not kill the restarted run before its end in 5 attempts')
    os.remove(saved)
    rc.run(killed, JOB, '--restart', JOB + '.rst.h5')
    failures += bool(rc.compare_runs(reference, killed, JOB, 'killed twice, restarted'))

    # Step boundary: step 1 alone, then the whole deck from its end-of-step checkpoint.
    boundary = rc.fresh_dir(os.path.join(work, 'boundary'))
    rc.write_deck(os.path.join(boundary, JOB + '.inp'), steps=1, frequency=1)
    rc.run(boundary, JOB)
    keep = rc.fresh_dir(os.path.join(work, 'boundary_saved'))
    for name in os.listdir(boundary):
        shutil.copy(os.path.join(boundary, name), keep)
    shutil.copy(os.path.join(reference, JOB + '.inp'), boundary)
    info = rc.checkpoint_info(os.path.join(boundary, JOB + '.rst.h5'))
    print('step 1 alone: end-of-step checkpoint at step %d, increment %d, time %g, step time %g'
          % info)
    rc.run(boundary, JOB, '--restart', JOB + '.rst.h5')
    failures += bool(rc.compare_runs(reference, boundary, JOB, 'restart at the step boundary'))

    # The periodic checkpoint of the last increment of step 1 (the newest one when a kill
    # falls between the end-of-step outputs and the end-of-step checkpoint).
    boundary2 = rc.fresh_dir(os.path.join(work, 'boundary_periodic'))
    for name in os.listdir(keep):
        shutil.copy(os.path.join(keep, name), boundary2)
    shutil.copy(os.path.join(reference, JOB + '.inp'), boundary2)
    info = rc.checkpoint_info(os.path.join(boundary2, JOB + '.rst.1.h5'))
    print('step 1 alone: periodic checkpoint of its last increment at step %d, increment %d, '
          'time %g, step time %g' % info)
    rc.run(boundary2, JOB, '--restart', JOB + '.rst.1.h5')
    failures += bool(rc.compare_runs(reference, boundary2, JOB,
                                     'restart from the last increment of step 1'))
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
