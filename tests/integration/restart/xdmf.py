"""restart_xdmf.sh: the XDMF index after a restart that drops frames.

The stick-slip deck with checkpoints every 20 increments, 8 generations (all kept) and a frame
every 10 increments, run to its end; then restarted from its earliest checkpoint within step
2 (increment 20): the frames written after it must be deleted from job.h5 and the XDMF, and
written again. Checks: post/check_xdmf.py accepts job.xdmf with as
many frames as the one-go run; the frame times strictly increase (none twice); each frame's
(step, increment) appears once; the frames (times, grids, attributes, DataItems) and every
dataset of job.h5 equal the one-go run's; and, when VTK's Xdmf reader is installed,
post/check_xdmf_vtk.py reads every frame and finds the HDF5 values.
usage: xdmf.py WORKDIR
"""
import os
import shutil
import subprocess
import sys

import restart_common as rc

JOB = 'job'
POST = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', '..', 'post')


def main():
    rc.require_h5py()
    import h5py
    work = sys.argv[1]
    failures = 0
    reference = rc.fresh_dir(os.path.join(work, 'reference'))
    rc.write_deck(os.path.join(reference, JOB + '.inp'), frequency=20, generations=8)
    rc.run(reference, JOB)
    directory = rc.fresh_dir(os.path.join(work, 'restarted'))
    for name in os.listdir(reference):
        shutil.copy(os.path.join(reference, name), directory)
    within = []
    for name in os.listdir(directory):
        if name.startswith(JOB + '.rst.'):
            step, increment, t, step_time = rc.checkpoint_info(os.path.join(directory, name))
            if step == 2 and step_time > 0.0:
                within.append((increment, name))
    increment, checkpoint = min(within)
    step, increment, t, _ = rc.checkpoint_info(os.path.join(directory, checkpoint))
    with h5py.File(os.path.join(reference, JOB + '.h5'), 'r') as f:
        later = sum(1 for g in f['frames'].values() if g.attrs['increment'] > increment)
        n_frames = len(f['frames'])
    print('one-go run: %d frames; restart from %s (step %d, increment %d, time %.6g): '
          '%d frames after it' % (n_frames, checkpoint, step, increment, t, later))
    if later < 5:
        print('FAIL the restart should have at least 5 frames to drop')
        failures += 1
    rc.run(directory, JOB, '--restart', checkpoint)

    xdmf = os.path.join(directory, JOB + '.xdmf')
    check = subprocess.run([sys.executable, os.path.join(POST, 'check_xdmf.py'), '--frames',
                            str(n_frames), xdmf], stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, text=True)
    print('check_xdmf.py: ' + check.stdout.strip())
    failures += check.returncode != 0
    times = [float(frame[0]) for frame in rc.xdmf_frames(xdmf)]
    if any(b <= a for a, b in zip(times, times[1:])):
        print('FAIL the frame times do not strictly increase: %s' % times)
        failures += 1
    with h5py.File(os.path.join(directory, JOB + '.h5'), 'r') as f:
        keys = [(int(g.attrs['step']), int(g.attrs['increment'])) for g in f['frames'].values()]
    if len(set(keys)) != len(keys):
        print('FAIL a (step, increment) has two frames: %s' % keys)
        failures += 1
    else:
        print('%d frames, times strictly increasing, each (step, increment) once' % len(keys))
    failures += bool(rc.compare_runs(reference, directory, JOB, 'restart from increment %d'
                                     % increment))
    vtk = subprocess.run([sys.executable, os.path.join(POST, 'check_xdmf_vtk.py'), '--frames',
                          str(n_frames), xdmf], stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True)
    print('check_xdmf_vtk.py: ' + vtk.stdout.strip())
    if vtk.returncode not in (0, 77):
        failures += 1
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
