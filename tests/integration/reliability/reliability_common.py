"""Shared helpers of the reliability tests (tests/integration/reliability_*.sh, issue 15): the
stick-slip deck of the restart tests (restart/restart_common.py), running fcs3d with a timeout,
small file systems (tmpfs), and the checks that the results a failed run leaves are readable:
every frame of job.h5 complete and readable by h5py, the XDMF parseable, the CSV files and the
.dat made of whole rows and a prefix of what a run that did not fail wrote.
"""
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', 'restart'))
import restart_common as rc  # noqa: E402  (the deck, comparisons of two runs)

FCS3D = os.environ.get('FCS3D', 'fcs3d')
JOB = 'job'
failures = []


def check(condition, message):
    """Record a failed check (the script goes on and reports them all at the end)."""
    if not condition:
        failures.append(message)
        print('FAIL: ' + message)
    return condition


def finish(name):
    if failures:
        print('%s: %d check(s) failed' % (name, len(failures)))
        sys.exit(1)
    print('%s: all checks passed' % name)


def fresh_dir(path):
    os.makedirs(path, exist_ok=True)
    for name in os.listdir(path):
        full = os.path.join(path, name)
        if os.path.isdir(full) and not os.path.islink(full):
            continue
        os.remove(full)
    return path


def run(job_dir, *args, timeout=600, env=None, limit_kib=None):
    """fcs3d -q <args> in job_dir (under `ulimit -v limit_kib` in a subshell when given);
    returns (exit status, stdout, stderr). A run that does not end within `timeout` is
    killed and reported as exit status None."""
    command = [FCS3D, '-q', *args]
    if limit_kib is not None:
        command = ['sh', '-c', 'ulimit -v %d && exec "$@"' % limit_kib, 'sh', *command]
    try:
        p = subprocess.run(command, cwd=job_dir, timeout=timeout, env=env,
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                           errors='replace')
    except subprocess.TimeoutExpired:
        return None, '', 'timed out after %g s' % timeout
    return p.returncode, p.stdout, p.stderr


def mount_tmpfs(path, kib):
    """A tmpfs of `kib` KiB at `path` (remounted if one is there); False where mounting is
    not allowed."""
    os.makedirs(path, exist_ok=True)
    if os.path.ismount(path):
        command = ['mount', '-o', 'remount,size=%dk' % kib, path]
    else:
        command = ['mount', '-t', 'tmpfs', '-o', 'size=%dk' % kib, 'tmpfs', path]
    return subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).returncode == 0


def unmount(path):
    if os.path.ismount(path):
        subprocess.run(['umount', path], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)


def read(path, mode='r'):
    with open(path, mode) as f:
        return f.read()


def frames_readable(h5_path, reference_h5=None):
    """Number of frames of a results file left by a failed run, after checking that h5py
    opens it, that every frame is complete and every dataset readable, and (given the results
    of a run that did not fail) that each frame is bit for bit that run's frame of the same
    number. Returns -1 when the file cannot be read."""
    import h5py
    import numpy as np
    try:
        with h5py.File(h5_path, 'r') as f:
            frames = f['frames']
            names = sorted(frames)
            for name in names:
                check(int(frames[name].attrs['complete']) == 1,
                      '%s: frame %s is not complete' % (h5_path, name))
                datasets = []
                frames[name].visititems(lambda n, o: datasets.append(n)
                                        if isinstance(o, h5py.Dataset) else None)
                for d in datasets:
                    values = frames[name][d][()]
                    if reference_h5 is None:
                        continue
                    with h5py.File(reference_h5, 'r') as g:
                        check(np.array_equal(values, g['frames'][name][d][()]),
                              '%s: frame %s %s differs from the run without failure' % (
                                  h5_path, name, d))
            return len(names)
    except Exception as e:  # any failure to read is what the test is about
        check(False, '%s cannot be read by h5py: %s' % (h5_path, e))
        return -1


def xdmf_frame_count(path):
    try:
        root = ET.parse(path).getroot()
        return len(root.find('Domain/Grid').findall('Grid'))
    except Exception as e:
        check(False, '%s is not a readable XDMF file: %s' % (path, e))
        return -1


def check_prefix(path, reference, what):
    """A text output of a failed run: whole lines, no NUL byte, and the beginning of the same
    output of the run that did not fail."""
    if not os.path.exists(path):
        return
    data = read(path, 'rb')
    check(b'\0' not in data, '%s holds NUL bytes' % path)
    check(data == b'' or data.endswith(b'\n'), '%s ends inside a line' % path)
    check(read(reference, 'rb').startswith(data), '%s is not a prefix of the %s of the run '
          'without failure' % (path, what))
