"""Restart next to damaged results (issue 15, item 9).

The deck with step 1 only runs to its end (checkpoint at the end of the step); then the deck
with both steps continues from job.rst.h5 after the outputs of the first run were damaged:
  - job.dat emptied (truncated to 0 bytes): it used to come back padded with thousands of NUL
    bytes (truncate() lengthened it to the size the checkpoint recorded);
  - job.h5 deleted: the run used to continue silently with a new file holding only the later
    frames;
  - job.h5 with its last frame removed (h5py).
The restart must continue (exit status 0) and warn, on standard error and in job.log, saying
which file holds less than at the checkpoint and what is lost; job.dat must hold no NUL byte
and end with exactly the tables the uninterrupted run printed after the checkpoint; a new
job.h5 must hold the frames written after the checkpoint, the same as the uninterrupted run's
last frames; job.xdmf must list what job.h5 holds. With undamaged outputs the restart must
warn about nothing. (doc/restart.md, "Outputs damaged before a restart".)
Usage: restart_damaged.py <work directory>
"""
import os
import shutil
import sys

import h5py
import numpy as np

import reliability_common as r


def first_part(work, name):
    where = r.fresh_dir(os.path.join(work, name))
    r.rc.write_deck(os.path.join(where, 'job.inp'), steps=1)
    status, _, stderr = r.run(where, 'job.inp')
    r.check(status == 0, '%s: step 1 alone: exit status %s: %s' % (name, status, stderr))
    info = r.rc.checkpoint_info(os.path.join(where, 'job.rst.h5'))
    with h5py.File(os.path.join(where, 'job.h5'), 'r') as f:
        frames = len(f['frames'])
    r.rc.write_deck(os.path.join(where, 'job.inp'), steps=2)
    return where, os.path.getsize(os.path.join(where, 'job.dat')), frames, info


def restart(where):
    status, _, stderr = r.run(where, 'job.inp', '--restart', 'job.rst.h5')
    warnings = [line for line in stderr.splitlines() if line.startswith('warning: ')]
    return status, stderr, warnings


def frame_times(path):
    with h5py.File(path, 'r') as f:
        return [float(f['frames'][k].attrs['time']) for k in sorted(f['frames'])]


def main():
    r.rc.require_h5py()
    work = sys.argv[1]
    reference = r.fresh_dir(os.path.join(work, 'reference'))
    r.rc.write_deck(os.path.join(reference, 'job.inp'), steps=2)
    status, _, stderr = r.run(reference, 'job.inp')
    if status != 0:
        sys.exit('the uninterrupted run failed: %s' % stderr)
    ref_dat = r.read(os.path.join(reference, 'job.dat'), 'rb')
    ref_times = frame_times(os.path.join(reference, 'job.h5'))

    where, dat_size, frames, _ = first_part(work, 'undamaged')
    status, stderr, warnings = restart(where)
    r.check(status == 0 and not warnings, 'undamaged outputs: exit status %s, warnings %s' % (
        status, warnings))

    where, dat_size, frames, _ = first_part(work, 'emptied_dat')
    open(os.path.join(where, 'job.dat'), 'w').close()
    status, stderr, warnings = restart(where)
    print('job.dat emptied: exit status %s: %s' % (status, warnings))
    r.check(status == 0, 'emptied job.dat: exit status %s: %s' % (status, stderr))
    r.check(any('job.dat holds 0 bytes, fewer than the %d' % dat_size in w for w in warnings),
            'emptied job.dat: no warning naming it and its size at the checkpoint')
    dat = r.read(os.path.join(where, 'job.dat'), 'rb')
    r.check(b'\0' not in dat, 'emptied job.dat: NUL bytes after the restart')
    r.check(dat == ref_dat[dat_size:], 'emptied job.dat: it does not hold exactly the tables '
            'printed after the checkpoint (%d bytes, expected %d)' % (len(dat),
                                                                       len(ref_dat) - dat_size))
    r.check('warning: job.dat holds 0 bytes' in r.read(os.path.join(where, 'job.log')),
            'emptied job.dat: the warning is not in job.log')

    where, dat_size, frames, _ = first_part(work, 'deleted_h5')
    os.remove(os.path.join(where, 'job.h5'))
    status, stderr, warnings = restart(where)
    print('job.h5 deleted: exit status %s: %s' % (status, warnings))
    r.check(status == 0, 'deleted job.h5: exit status %s: %s' % (status, stderr))
    r.check(any('job.h5 is missing: the %d frame(s) written before the checkpoint are lost' %
                frames in w for w in warnings), 'deleted job.h5: no warning saying %d frames '
            'are lost' % frames)
    times = frame_times(os.path.join(where, 'job.h5'))
    r.check(times == ref_times[frames:], 'deleted job.h5: the new file holds frames at %s, '
            'expected those after the checkpoint %s' % (times[:5], ref_times[frames:frames + 5]))
    r.check(r.xdmf_frame_count(os.path.join(where, 'job.xdmf')) == len(times),
            'deleted job.h5: job.xdmf does not list the frames of the new job.h5')

    where, dat_size, frames, _ = first_part(work, 'frame_missing')
    with h5py.File(os.path.join(where, 'job.h5'), 'a') as f:
        del f['frames/%06d' % frames]
    status, stderr, warnings = restart(where)
    print('last frame removed: exit status %s: %s' % (status, warnings))
    r.check(status == 0, 'last frame removed: exit status %s: %s' % (status, stderr))
    r.check(any('job.h5 holds %d complete frame(s), fewer than the %d' % (frames - 1, frames) in w
                for w in warnings), 'last frame removed: no warning')
    times = frame_times(os.path.join(where, 'job.h5'))
    r.check(times == ref_times[:frames - 1] + ref_times[frames:], 'last frame removed: frames '
            'at the wrong times after the restart')
    r.finish('restart_damaged')


if __name__ == '__main__':
    main()
