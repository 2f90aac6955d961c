"""restart_damaged_generations.sh (pending): which older generation a refused restart offers,
and the exit status for a checkpoint HDF5 cannot read.

The stick-slip deck (restart_common.py) with GENERATIONS=3 is run to its end (job.rst.h5,
job.rst.1.h5, job.rst.2.h5, all readable). Then, from fresh copies each time:
  1. job.rst.h5 and job.rst.1.h5 damaged (a bit flipped in the data of /state/u), restart
     from job.rst.h5: the message must offer job.rst.2.h5, the newest one that can be read;
  2. job.rst.1.h5 damaged, restart from it: the message ("an older checkpoint is readable")
     must offer job.rst.2.h5, not the newer job.rst.h5;
  3. the object header of /state/strain in job.rst.h5 damaged (its version byte), so that
     HDF5 cannot open the dataset: exit status 2 (a bad checkpoint is bad input, as
     `fcs3d --help` says), and job.rst.1.h5 offered;
  and the restart from each offered checkpoint must succeed.

Fails at 798158c: the offer checks only the /meta of a candidate (read_checkpoint_info), so a
generation with damaged data is offered (case 1); candidates are tried from generation 0,
so the newer job.rst.h5 is offered as "older" (case 2); an HDF5 failure inside the file
("H5Dopen of /state/strain failed") keeps the internal-failure status 1 (case 3).
usage: damaged_generations.py WORKDIR
"""
import os
import re
import shutil
import sys

import restart_common as rc

JOB = 'job'
OFFER = re.compile(r'an older checkpoint is readable: (\S+) .*restart from it with --restart (\S+)')


def main():
    rc.require_h5py()
    import h5py
    work = sys.argv[1]
    complete = rc.fresh_dir(os.path.join(work, 'complete'))
    rc.write_deck(os.path.join(complete, JOB + '.inp'), generations=3)
    rc.run(complete, JOB)
    places = {}
    for name in ['job.rst.h5', 'job.rst.1.h5']:
        with h5py.File(os.path.join(complete, name), 'r') as f:
            u = f['state/u']
            places[name] = (u.id.get_offset() + u.id.get_storage_size() // 2,
                            h5py.h5o.get_info(f['state/strain'].id).addr)

    def flip(directory, name, offset, bit=0x10):
        with open(os.path.join(directory, name), 'r+b') as f:
            f.seek(offset)
            byte = f.read(1)[0]
            f.seek(offset)
            f.write(bytes([byte ^ bit]))

    cases = [
        ('job.rst.h5 and job.rst.1.h5 damaged', 'job.rst.h5',
         [('job.rst.h5', places['job.rst.h5'][0]), ('job.rst.1.h5', places['job.rst.1.h5'][0])],
         'job.rst.2.h5'),
        ('job.rst.1.h5 damaged, restart from it', 'job.rst.1.h5',
         [('job.rst.1.h5', places['job.rst.1.h5'][0])], 'job.rst.2.h5'),
        ('object header of /state/strain damaged', 'job.rst.h5',
         [('job.rst.h5', places['job.rst.h5'][1])], 'job.rst.1.h5'),
    ]
    failures = 0
    for what, start, damage, expected in cases:
        directory = rc.fresh_dir(os.path.join(work, 'case'))
        for name in os.listdir(complete):
            shutil.copy(os.path.join(complete, name), directory)
        for name, offset in damage:
            flip(directory, name, offset)
        status, message = rc.run(directory, JOB, '--restart', start, check=False)
        offer = OFFER.search(message)
        offered = offer.group(2) if offer else None
        problems = []
        if status != 2:
            problems.append('exit status %d, expected 2' % status)
        if offered != expected:
            problems.append('offers %s, expected %s' % (offered, expected))
        elif rc.run(directory, JOB, '--restart', offered, check=False)[0] != 0:
            problems.append('the restart from the offered %s failed' % offered)
        if problems:
            failures += 1
            print('FAIL %s: %s\n  message: %s' % (what, '; '.join(problems),
                                                 message.strip().replace('\n', '\n    ')))
        else:
            print('%s: exit status 2, %s offered, the restart from it runs' % (what, offered))
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
