"""Too little memory (issue 15, item 4).

A cube of 16^3 hexahedra (tests/bench/cube_deck.py, 14,739 degrees of freedom, one result
frame at the start and one at the end) runs under address-space limits (`ulimit -v` in a
subshell) from 150 to 450 MB in steps of 20 MB, with UMFPACK and with MUMPS; unlimited it
needs about 280 MB resident. Before issue 15 such limits made fcs3d hang for ever in OpenBLAS's
allocation retry loop (200-300 MB), segfault, or stop with gfortran's bare "Error allocating".
Each run must now:
  - end within 120 s (no hang);
  - exit with status 0, or with status 1 and a line "fcs3d: ... out of memory while ..."; never
    a signal (segmentation fault) and never status 2;
  - leave job.h5, when it exists, readable by h5py with every frame complete; when the message
    says the last good increment is in the last frame of job.h5, that frame must be there;
  - end job.log, when the run got as far as opening it, with "exit status 1 (run failure)".
Across the limits at least one run must fail for want of memory after its first frame was
written (so that the last good state is saved), and the unlimited runs must succeed.
Usage: memory_limit.py <work directory> <tests/bench directory>
"""
import os
import subprocess
import sys

import reliability_common as r

LIMITS_MB = range(150, 451, 20)


def one_run(work, deck, solver, mb):
    where = r.fresh_dir(os.path.join(work, '%s_%s' % (solver.lower(), mb or 'unlimited')))
    with open(os.path.join(where, 'job.inp'), 'w') as f:
        f.write(deck)
    status, _, stderr = r.run(where, '--solver', solver, 'job.inp', timeout=120,
                              limit_kib=None if mb is None else mb * 1024)
    what = '%s, %s MB' % (solver, mb if mb is not None else 'unlimited')
    lines = [line for line in stderr.splitlines() if line.startswith('fcs3d: ')]
    print('%s: exit status %s: %s' % (what, status, lines[-1][:160] if lines else ''))
    r.check(status is not None, '%s: did not end within 120 s' % what)
    r.check(status in (0, 1), '%s: exit status %s (a signal or bad input): %s' % (
        what, status, stderr[-400:]))
    if status == 1:
        r.check(any('out of memory while' in line for line in lines),
                '%s: no "out of memory while" message: %s' % (what, stderr[-400:]))
    h5 = os.path.join(where, 'job.h5')
    frames = r.frames_readable(h5) if os.path.exists(h5) else 0
    saved = 'is in the last frame of job.h5' in stderr
    if saved:
        r.check(frames >= 1, '%s: the message says the last good state is in job.h5, which '
                'holds no frame' % what)
    log = os.path.join(where, 'job.log')
    if status == 1 and os.path.exists(log):
        tail = r.read(log).rstrip().splitlines()[-1:]
        r.check(tail == ['exit status 1 (run failure)'], '%s: job.log ends with %s' % (what, tail))
    return status, saved


def main():
    r.rc.require_h5py()
    work, bench = sys.argv[1], sys.argv[2]
    deck_path = os.path.join(work, 'cube16.inp')
    subprocess.run([sys.executable, os.path.join(bench, 'cube_deck.py'), '16', deck_path],
                   check=True, stdout=subprocess.DEVNULL)
    deck = r.read(deck_path).replace('*END STEP', '*NODE FILE\nU\n*EL FILE\nS\n*END STEP')
    out_of_memory, saved_states = 0, 0
    for solver in ('UMFPACK', 'MUMPS'):
        status, _ = one_run(work, deck, solver, None)
        r.check(status == 0, '%s without a limit: exit status %s' % (solver, status))
        for mb in LIMITS_MB:
            status, saved = one_run(work, deck, solver, mb)
            out_of_memory += status == 1
            saved_states += saved
    print('%d runs out of memory, %d of them with the last good state saved' % (
        out_of_memory, saved_states))
    r.check(out_of_memory > 0, 'no run ran out of memory: the limits are too generous')
    r.check(saved_states > 0, 'no run ran out of memory after its first frame')
    r.finish('memory_limit')


if __name__ == '__main__':
    main()
