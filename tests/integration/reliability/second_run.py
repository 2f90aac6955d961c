"""A second run of the same job in the same directory (issue 15, item 3).

Before it touches any file a run takes <job>.lock (fcs_job_lock: an flock held for the whole
run, with the holder's process id in the file). Checked here, with the stick-slip deck of the
restart tests (about 140 frames):
  - while a run of job.inp is under way (its lock taken), a second `fcs3d job.inp` and a
    `fcs3d --check job.inp` in the same directory are refused at once with exit status 2 and a
    message that names the lock file and the running process; the first run ends with exit
    status 0 and outputs identical, bit for bit, to a run alone (the second one wrote nothing:
    not even job.log or job.echo changed hands), and removes job.lock;
  - a lock file left by a process that no longer runs (killed with SIGKILL while running) is
    taken over: the next run (here the restart from the killed run's checkpoint) ends with
    exit status 0 and notes in job.log that it took the lock over;
  - a lock file holding the text of a process that is gone, written by hand, is taken over
    the same way;
  - another job in the same directory runs at the same time.
Usage: second_run.py <work directory>
"""
import os
import shutil
import signal
import subprocess
import sys
import time

import reliability_common as r


def start(where, *args):
    return subprocess.Popen([r.FCS3D, '-q', *args], cwd=where, stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE, text=True)


def wait_for_lock(process, where, timeout=60.0):
    """Wait until the run holds its lock and has begun its increments (job.log written)."""
    lock, log = os.path.join(where, 'job.lock'), os.path.join(where, 'job.log')
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if process.poll() is not None:
            return False
        if os.path.exists(lock) and os.path.exists(log) and 'inc 1 ' in r.read(log):
            return True
        time.sleep(0.01)
    return False


def second_run(work, reference):
    where = r.fresh_dir(os.path.join(work, 'two_runs'))
    r.rc.write_deck(os.path.join(where, 'job.inp'), frame_frequency=2)
    first = start(where, 'job.inp')
    if not r.check(wait_for_lock(first, where), 'the first run did not start (%s)' % (
            first.stderr.read() if first.poll() is not None else 'no lock')):
        first.kill()
        return
    for args in (['job.inp'], ['--check', 'job.inp']):
        started = time.monotonic()
        status, _, stderr = r.run(where, *args, timeout=60)
        seconds = time.monotonic() - started
        print('second run (%s) while the first runs: exit status %s after %.2f s: %s' % (
            ' '.join(args), status, seconds, stderr.strip()))
        r.check(status == 2, 'second run %s: exit status %s, expected 2' % (args, status))
        r.check('job.lock' in stderr and 'already running' in stderr and
                'process %d' % first.pid in stderr,
                'second run %s: the message does not name the lock and process %d' % (
                    args, first.pid))
    r.check(first.poll() is None, 'the first run ended before the second ones were refused: '
            'make the deck longer')
    status = first.wait(timeout=600)
    r.check(status == 0, 'the first run: exit status %s: %s' % (status, first.stderr.read()))
    r.check(not os.path.exists(os.path.join(where, 'job.lock')), 'job.lock left after the run')
    r.check(not r.rc.compare_runs(reference, where, r.JOB, 'the run that met a second one'),
            'the outputs of the first run differ from a run alone')


def killed_run(work, reference):
    where = r.fresh_dir(os.path.join(work, 'killed'))
    r.rc.write_deck(os.path.join(where, 'job.inp'), frame_frequency=2)
    first = start(where, 'job.inp')
    increment = r.rc.wait_for_checkpoint(first, os.path.join(where, 'job.rst.h5'))
    r.check(increment is not None, 'the run ended before its first checkpoint')
    first.send_signal(signal.SIGKILL)
    first.wait()
    r.check(os.path.exists(os.path.join(where, 'job.lock')), 'SIGKILL left no job.lock behind '
            '(the test would not show a takeover)')
    status, _, stderr = r.run(where, 'job.inp', '--restart', 'job.rst.h5')
    r.check(status == 0, 'the restart after SIGKILL: exit status %s: %s' % (status, stderr))
    log = r.read(os.path.join(where, 'job.log'))
    r.check('job.lock was left by a run that ended without removing it (process %d' % first.pid
            in log, 'job.log does not note the lock taken over from process %d' % first.pid)
    r.check(not r.rc.compare_runs(reference, where, r.JOB, 'killed, then restarted'),
            'the restart after SIGKILL differs from the run without a kill')


def stale_text(work):
    where = r.fresh_dir(os.path.join(work, 'stale'))
    r.rc.write_deck(os.path.join(where, 'job.inp'), steps=1)
    with open(os.path.join(where, 'job.lock'), 'w') as f:
        f.write('process 4194303 on host elsewhere, started 2000-01-01 00:00:00\n')
    status, _, stderr = r.run(where, 'job.inp')
    print('a stale job.lock written by hand: exit status %s' % status)
    r.check(status == 0, 'with a stale lock file: exit status %s: %s' % (status, stderr))
    r.check('process 4194303 on host elsewhere' in r.read(os.path.join(where, 'job.log')),
            'job.log does not note the stale lock taken over')
    r.check(not os.path.exists(os.path.join(where, 'job.lock')), 'job.lock left after the run')


def other_job(work):
    where = r.fresh_dir(os.path.join(work, 'other_job'))
    r.rc.write_deck(os.path.join(where, 'job.inp'), frame_frequency=2)
    shutil.copy(os.path.join(where, 'job.inp'), os.path.join(where, 'other.inp'))
    first = start(where, 'job.inp')
    r.check(wait_for_lock(first, where), 'the first run did not start')
    status, _, stderr = r.run(where, 'other.inp')
    r.check(status == 0, 'another job in the same directory: exit status %s: %s' % (status, stderr))
    r.check(first.wait(timeout=600) == 0, 'the first job failed next to another one')


def main():
    r.rc.require_h5py()
    work = sys.argv[1]
    reference = r.fresh_dir(os.path.join(work, 'reference'))
    r.rc.write_deck(os.path.join(reference, 'job.inp'), frame_frequency=2)
    status, _, stderr = r.run(reference, 'job.inp')
    if status != 0:
        sys.exit('the reference run failed: %s' % stderr)
    second_run(work, reference)
    killed_run(work, reference)
    stale_text(work)
    other_job(work)
    r.finish('second_run')


if __name__ == '__main__':
    main()
