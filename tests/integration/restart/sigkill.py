"""restart_sigkill.sh: a run killed with SIGKILL and restarted from its newest checkpoint gives
the one-go run's outputs bit for bit; so does a restart at a step boundary.

1. one-go run of the stick-slip deck (restart_common.py; checkpoints every 4 increments);
2. the same deck killed with SIGKILL at a random moment after its first checkpoint appeared,
   restarted from job.rst.h5, that run killed again at a random moment after it wrote a
   checkpoint of its own, and restarted again to the end (the kills land anywhere: within an
   increment, a frame, a checkpoint being written; up to 3 increments after the checkpoint,
   whose outputs the restart must drop); every dataset and attribute of job.h5, job.dat,
   job_fault.csv and job_events.csv byte for byte, and the frames of job.xdmf, must equal
   the one-go run's; the job.xdmf left by the first kill must pass post/check_xdmf.py;
3. step boundary: the deck with step 1 only, run to its end; the full deck restarted from its
   end-of-step checkpoint (step 2, step time 0): outputs equal to the one-go run's.

The random moments come from $FCS3D_TEST_SEED (else the clock; printed). A kill is drawn
uniformly in [0, 0.7 T] after the awaited checkpoint appeared, T the one-go run's wall time
(times the fraction of the increments left, for the restarted run), so that it falls before
the end; a run that ends first is tried again with a shorter window.
usage: sigkill.py WORKDIR
"""
import os
import shutil
import signal
import subprocess
import sys
import time

import restart_common as rc

JOB = 'job'
POST = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', '..', 'post')


def xdmf_readable(directory, what):
    """post/check_xdmf.py on the job.xdmf a killed run left (it is rewritten atomically at
    every frame, so it must always be valid)."""
    check = subprocess.run([sys.executable, os.path.join(POST, 'check_xdmf.py'),
                            os.path.join(directory, JOB + '.xdmf')], stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, text=True)
    print('  check_xdmf.py %s: %s' % (what, check.stdout.strip().splitlines()[-1]))
    return check.returncode == 0


def newest(directory):
    """The newest checkpoint after a kill: job.rst.h5, or job.rst.1.h5 when the kill fell
    between the renames of a checkpoint being written (doc/restart.md, "Atomic writing")."""
    name = JOB + '.rst.h5'
    if not os.path.exists(os.path.join(directory, name)):
        name = JOB + '.rst.1.h5'
        print('  job.rst.h5 missing (killed between the renames of a checkpoint); using ' + name)
    return name


def kill_at_random(directory, rng, window, restart_from=None, newer_than=-1):
    """Start fcs3d (from checkpoint restart_from, if given), wait for a checkpoint newer than
    increment `newer_than`, kill -9 after a random delay in [0, window]. Tries again with
    half the window when the run ends first."""
    args = ['--restart', restart_from] if restart_from else []
    checkpoint = os.path.join(directory, JOB + '.rst.h5')
    for attempt in range(6):
        rc.remove_checkpoints(directory, JOB)  # only the checkpoints of this attempt count
        process = rc.start(directory, JOB, *args)
        seen = rc.wait_for_checkpoint(process, checkpoint, newer_than)
        delay = rng.uniform(0.0, window)
        if seen is not None:
            time.sleep(delay)
            process.send_signal(signal.SIGKILL)
        status = process.wait()
        if status == -signal.SIGKILL:
            step, increment, t, _ = rc.checkpoint_info(os.path.join(directory, newest(directory)))
            print('  killed %.3f s after checkpoint %d appeared; newest checkpoint: step %d, '
                  'increment %d, time %.6g' % (delay, seen, step, increment, t))
            return increment
        if status != 0:
            raise SystemExit('fcs3d %s: exit status %d\n%s' % (' '.join(args), status,
                                                               process.stderr.read()))
        print('  the run ended before the kill (%.3f s); again with a shorter window' % delay)
        window *= 0.5
    raise SystemExit('could not kill the run before its end')


def main():
    rc.require_h5py()
    work = sys.argv[1]
    rng = rc.seeded_random('restart_sigkill')
    failures = 0

    reference = rc.fresh_dir(os.path.join(work, 'reference'))
    rc.write_deck(os.path.join(reference, JOB + '.inp'))
    t0 = time.monotonic()
    rc.run(reference, JOB)
    wall = time.monotonic() - t0
    datasets, frames = rc.h5_summary(os.path.join(reference, JOB + '.h5'))
    total = rc.checkpoint_info(os.path.join(reference, JOB + '.rst.h5'))[1]
    print('one-go run: %.2f s, %d increments, %d datasets, %d frames' % (wall, total, datasets,
                                                                        frames))

    killed = rc.fresh_dir(os.path.join(work, 'killed'))
    shutil.copy(os.path.join(reference, JOB + '.inp'), killed)
    print('kill 1:')
    first = kill_at_random(killed, rng, 0.7 * wall)
    failures += not xdmf_readable(killed, 'after the kill')
    # A copy, so that a second attempt starts from the same checkpoint.
    saved = os.path.join(killed, 'first.rst.h5')
    shutil.copy(os.path.join(killed, newest(killed)), saved)
    print('kill 2 (the run restarted from that checkpoint):')
    kill_at_random(killed, rng, 0.7 * wall * (total - first) / total,
                   restart_from='first.rst.h5', newer_than=first)
    os.remove(saved)
    rc.run(killed, JOB, '--restart', newest(killed))
    failures += bool(rc.compare_runs(reference, killed, JOB, 'killed twice, restarted twice'))

    boundary = rc.fresh_dir(os.path.join(work, 'boundary'))
    rc.write_deck(os.path.join(boundary, JOB + '.inp'), steps=1)
    rc.run(boundary, JOB)
    shutil.copy(os.path.join(reference, JOB + '.inp'), boundary)
    print('step 1 alone: end-of-step checkpoint at step %d, increment %d, time %g, step time %g'
          % rc.checkpoint_info(os.path.join(boundary, JOB + '.rst.h5')))
    rc.run(boundary, JOB, '--restart', JOB + '.rst.h5')
    failures += bool(rc.compare_runs(reference, boundary, JOB,
                                     'step 1 alone, then the whole deck restarted'))
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
