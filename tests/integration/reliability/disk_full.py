"""A full disk during a run (issue 15, item 1, and the text outputs of item 2).

The stick-slip deck of the restart tests, with a frame every second increment (139 frames,
about 8 MB of outputs), runs on tmpfs file systems too small for it (400 to 2000 KiB;
the disk fills while a frame, a checkpoint, the XDMF or a CSV is written). Each run must
  - stop with exit status 1 (a run failure, not 2) and a message that says the disk is full,
    naming the file; no segmentation fault;
  - leave job.h5 readable by h5py with every frame complete and equal, bit for bit, to the
    same frame of a run on a roomy disk; job.xdmf parseable, listing those frames (or one
    fewer when it is the XDMF that did not fit); the CSVs and job.dat made of whole rows, each
    the beginning of the roomy run's file; no temporary file and no job.lock left;
  - say so in job.log, ending with "exit status 1 (run failure)";
and once the file system is made larger, --restart from the checkpoint must finish the run
with outputs identical, bit for bit, to the roomy run's (as after a SIGKILL).

Also job.h5 as a link to /dev/full (a device that is always full): exit status 1, "the disk is
full" and the file's name.

Skipped (exit 77) where tmpfs cannot be mounted (not root, no user namespace).
Usage: disk_full.py <work directory>
"""
import os
import sys

import reliability_common as r

SIZES_KIB = (400, 500, 700, 900, 2000)


def failed_run(work, reference, kib):
    where = os.path.join(work, 'full_%d' % kib)
    if not r.mount_tmpfs(where, kib):
        r.unmount(where)
        return False
    try:
        r.fresh_dir(where)
        r.rc.write_deck(os.path.join(where, 'job.inp'), frame_frequency=2)
        status, _, stderr = r.run(where, 'job.inp')
        print('%d KiB: exit status %s: %s' % (kib, status, stderr.strip().splitlines()[0]
                                             if stderr.strip() else ''))
        r.check(status == 1, '%d KiB: exit status %s, expected 1' % (kib, status))
        r.check('the disk is full' in stderr, '%d KiB: the message does not say that the disk '
                'is full: %s' % (kib, stderr))
        r.check('Segmentation' not in stderr and 'SIGSEGV' not in stderr,
                '%d KiB: segmentation fault' % kib)
        files = os.listdir(where)
        r.check(not any(f.endswith('.tmp') for f in files) and 'job.lock' not in files,
                '%d KiB: temporary files or the lock left: %s' % (kib, sorted(files)))
        n = r.frames_readable(os.path.join(where, 'job.h5'), os.path.join(reference, 'job.h5'))
        r.check(n >= 1, '%d KiB: no complete frame in job.h5' % kib)
        listed = r.xdmf_frame_count(os.path.join(where, 'job.xdmf'))
        r.check(listed in (n, n - 1), '%d KiB: job.xdmf lists %d frames, job.h5 holds %d' % (
            kib, listed, n))
        for name in ('job.dat', 'job_fault.csv', 'job_events.csv'):
            r.check_prefix(os.path.join(where, name), os.path.join(reference, name), name)
        log = r.read(os.path.join(where, 'job.log')).rstrip().splitlines()
        r.check(log[-1:] == ['exit status 1 (run failure)'] and 'the disk is full' in log[-2],
                '%d KiB: job.log does not end with the error: %s' % (kib, log[-2:]))
        print('%d KiB: %d complete frames readable, %d listed in job.xdmf' % (kib, n, listed))
        # More room, and the run continues from its checkpoint to the same end.
        r.check(r.mount_tmpfs(where, 65536), 'cannot enlarge the tmpfs')
        restart = ['--restart', 'job.rst.h5'] if os.path.exists(
            os.path.join(where, 'job.rst.h5')) else []
        status, _, stderr = r.run(where, 'job.inp', *restart)
        r.check(status == 0, '%d KiB: the run after freeing space: exit status %s: %s' % (
            kib, status, stderr))
        if status == 0:
            r.check(not r.rc.compare_runs(reference, where, r.JOB, '%d KiB, then %s' % (
                kib, ' '.join(restart) or 'a new run')), '%d KiB: outputs differ' % kib)
    finally:
        r.unmount(where)
    return True


def device_full(work):
    where = r.fresh_dir(os.path.join(work, 'dev_full'))
    r.rc.write_deck(os.path.join(where, 'job.inp'), frame_frequency=2)
    os.symlink('/dev/full', os.path.join(where, 'job.h5'))
    status, _, stderr = r.run(where, 'job.inp')
    print('job.h5 -> /dev/full: exit status %s: %s' % (status, stderr.strip()))
    r.check(status == 1, 'job.h5 -> /dev/full: exit status %s, expected 1' % status)
    r.check('job.h5' in stderr and 'the disk is full' in stderr,
            'job.h5 -> /dev/full: the message does not name the file and the full disk')


def main():
    r.rc.require_h5py()
    work = sys.argv[1]
    reference = r.fresh_dir(os.path.join(work, 'reference'))
    r.rc.write_deck(os.path.join(reference, 'job.inp'), frame_frequency=2)
    status, _, stderr = r.run(reference, 'job.inp')
    if status != 0:
        sys.exit('the run on a roomy disk failed: %s' % stderr)
    device_full(work)
    for kib in SIZES_KIB:
        if not failed_run(work, reference, kib):
            print('cannot mount a tmpfs here (needs root or a user namespace): the full file '
                  'system cases are skipped')
            r.finish('disk_full')
            sys.exit(77)
    r.finish('disk_full')


if __name__ == '__main__':
    main()
