"""restart_sigterm.sh: SIGTERM (and SIGINT) stop a run cleanly: exit status 3, a message that
names the checkpoint, and a valid checkpoint from which the restart completes with the
one-go run's outputs.

1. one-go run of the stick-slip deck (restart_common.py);
2. the same deck; once its first checkpoint exists, after a random delay in [0, 0.6 T] (T the
   one-go run's wall time; $FCS3D_TEST_SEED, else the clock), kill -TERM. Expected: exit
   status 3; on stderr "stopped by signal 15 after increment N (time t); checkpoint written
   to job.rst.h5; continue with --restart job.rst.h5", the same line in job.log; job.rst.h5
   holds increment N and time t (the increment under way was finished, not cut); the log ends
   with the run summary ("stopped: N increment(s), ...", phase times, linear solver); the restart
   from it ends with status 0 and every output (job.h5 bit for bit, job.dat, CSVs, XDMF
   frames) equals the one-go run's;
3. SIGINT (signal 2, as Ctrl-C sends): the same exit status, messages and checkpoint (the
   restart from it is not repeated).
usage: sigterm.py WORKDIR
"""
import os
import re
import shutil
import signal
import sys
import time

import restart_common as rc

JOB = 'job'
STOPPED = re.compile(r'stopped by signal (\d+) after increment (\d+) \(time ([^)]+)\); checkpoint '
                     r'written to (\S+); continue with --restart (\S+)')


def stop(directory, sig, rng, window):
    """Run, send `sig` at a random moment after the first checkpoint; returns the message
    (a run that ends first is tried again with a shorter window)."""
    for attempt in range(6):
        rc.remove_checkpoints(directory, JOB)  # only the checkpoints of this attempt count
        process = rc.start(directory, JOB)
        seen = rc.wait_for_checkpoint(process, os.path.join(directory, JOB + '.rst.h5'))
        delay = rng.uniform(0.0, window)
        if seen is not None:
            time.sleep(delay)
            process.send_signal(sig)
        status = process.wait()
        message = process.stderr.read()
        if status != 0:
            print('  signal %d sent %.3f s after the first checkpoint: exit status %d' % (
                sig, delay, status))
            return status, message
        print('  the run ended before the signal; again with a shorter window')
        window *= 0.5
    raise SystemExit('could not stop the run before its end')


def check_stop(directory, sig, status, message):
    problems = []
    if status != 3:
        problems.append('exit status %d, expected 3' % status)
    found = STOPPED.search(message)
    if not found:
        problems.append('no "stopped by signal ... checkpoint written to job.rst.h5" message')
        return problems, None
    number, increment, t = int(found.group(1)), int(found.group(2)), float(found.group(3))
    print('  message: ' + found.group(0))
    if number != sig:
        problems.append('the message names signal %d, not %d' % (number, sig))
    if found.group(4) != JOB + '.rst.h5' or found.group(5) != JOB + '.rst.h5':
        problems.append('the message names %s and %s, not job.rst.h5' % (found.group(4),
                                                                            found.group(5)))
    with open(os.path.join(directory, JOB + '.log')) as f:
        log = f.read()
    if found.group(0) not in log:
        problems.append('job.log lacks the message')
    summary = re.search(r'^stopped: (\d+) increment\(s\),', log, re.M)
    if not summary:
        problems.append('job.log lacks the run summary ("stopped: N increment(s), ...")')
    elif int(summary.group(1)) != increment:
        problems.append('the summary counts %s increments, the message %d' % (summary.group(1),
                                                                             increment))
    elif 'linear solver:' not in log[summary.end():]:
        problems.append('the summary lacks the linear solver line')
    step, saved_increment, saved_time, _ = rc.checkpoint_info(os.path.join(directory,
                                                                           JOB + '.rst.h5'))
    if saved_increment != increment or abs(saved_time - t) > 1e-5 * max(1.0, abs(t)):
        problems.append('job.rst.h5 holds increment %d, time %.9g, the message says %d, %s' % (
            saved_increment, saved_time, increment, found.group(3)))
    return problems, increment


def main():
    rc.require_h5py()
    work = sys.argv[1]
    rng = rc.seeded_random('restart_sigterm')
    failures = 0
    reference = rc.fresh_dir(os.path.join(work, 'reference'))
    rc.write_deck(os.path.join(reference, JOB + '.inp'))
    t0 = time.monotonic()
    rc.run(reference, JOB)
    wall = time.monotonic() - t0
    print('one-go run: %.2f s' % wall)
    for sig in (signal.SIGTERM, signal.SIGINT):
        name = signal.Signals(sig).name
        directory = rc.fresh_dir(os.path.join(work, name.lower()))
        shutil.copy(os.path.join(reference, JOB + '.inp'), directory)
        print(name + ':')
        status, message = stop(directory, sig, rng, 0.6 * wall)
        problems, increment = check_stop(directory, sig, status, message)
        if not problems and sig == signal.SIGTERM:
            code, text = rc.run(directory, JOB, '--restart', JOB + '.rst.h5', check=False)
            if code != 0:
                problems.append('the restart from job.rst.h5 failed (exit status %d): %s' % (
                    code, text.strip()))
            else:
                problems += rc.compare_runs(reference, directory, JOB,
                                            '  %s at increment %d, restarted' % (name, increment))
        if problems:
            failures += 1
            print('FAIL %s: %d problem(s), the first: %s' % (name, len(problems), problems[0]))
            print('  stderr: ' + message.strip())
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
