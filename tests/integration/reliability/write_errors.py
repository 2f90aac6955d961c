"""Every output file's write errors are reported (issue 15, item 2).

gfortran 12's run-time library reports no error for a failed write(2) (measured: WRITE,
FLUSH and CLOSE return iostat 0 on /dev/full), so fcs3d writes its text files through C stdio
(fcs_text_file). Here each output in turn is a link to /dev/full, a device on which every
write fails with ENOSPC: the appended files themselves (job.dat, job.log), the temporary
files that the atomic rewrites write first (job.echo.tmp, job.xdmf.tmp, job_fault.csv.tmp,
job_events.csv.tmp, job.rst.h5.tmp). Each run must exit with status 1 (a run failure, never
2, "bad input"), say "the disk is full" and name the file; job.log (when it is not the full
one) must end with the error and "exit status 1 (run failure)". A lock file that is a device
is refused before anything is written (exit status 1, naming it).

Usage: write_errors.py <work directory>
"""
import os
import sys

import reliability_common as r

#: Link to /dev/full -> what the message must say.
FULL = 'the disk is full'
TARGETS = {
    'job.dat': ['job.dat', FULL],
    'job.log': ['job.log', FULL],
    'job.echo.tmp': ['job.echo', FULL],
    'job.xdmf.tmp': ['job.xdmf', FULL],
    'job_fault.csv.tmp': ['job_fault.csv', FULL],
    'job_events.csv.tmp': ['job_events.csv', FULL],
    'job.rst.h5.tmp': ['job.rst.h5', FULL],
    'job.lock': ['job.lock', 'is a character device'],
}


def main():
    work = sys.argv[1]
    for link, named in TARGETS.items():
        where = r.fresh_dir(os.path.join(work, link.replace('.', '_')))
        r.rc.write_deck(os.path.join(where, 'job.inp'), frame_frequency=2)
        os.symlink('/dev/full', os.path.join(where, link))
        status, _, stderr = r.run(where, 'job.inp')
        first = stderr.strip().splitlines()[0] if stderr.strip() else ''
        print('%s -> /dev/full: exit status %s: %s' % (link, status, first))
        r.check(status == 1, '%s: exit status %s, expected 1' % (link, status))
        r.check(all(text in stderr for text in named),
                '%s: the message lacks %s: %s' % (link, ' or '.join(named), stderr))
        log = os.path.join(where, 'job.log')
        if link not in ('job.log', 'job.lock') and os.path.exists(log):
            lines = r.read(log).rstrip().splitlines()
            r.check(lines[-1:] == ['exit status 1 (run failure)'] and 'the disk is full' in
                    lines[-2], '%s: job.log does not end with the error: %s' % (link, lines[-2:]))
    r.finish('write_errors')


if __name__ == '__main__':
    main()
