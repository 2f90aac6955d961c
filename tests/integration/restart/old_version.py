"""restart_old_version.sh: a checkpoint of an older format version is refused, and the message
names both versions.

The stick-slip deck (restart_common.py) is run to its end. Its job.rst.h5 is copied and the
/meta attribute `version` of the copy set two lower than this build's (h5py; the data are
left as they are): the version before this build's (4, the same layout without the recorded
command-line options) is still read (restart_command_line_options.sh), the one before that is
not. A restart from it must exit with status 2 and say "checkpoint format version <old>; this
fcs3d reads versions <new - 1> to <new> only". The unchanged checkpoint is accepted (restart to
the end, exit 0), so the refusal is the version's.
usage: old_version.py WORKDIR
"""
import os
import re
import shutil
import sys

import restart_common as rc

JOB = 'job'


def main():
    rc.require_h5py()
    import h5py
    work = sys.argv[1]
    directory = rc.fresh_dir(os.path.join(work, 'run'))
    rc.write_deck(os.path.join(directory, JOB + '.inp'))
    rc.run(directory, JOB)
    newest = os.path.join(directory, JOB + '.rst.h5')
    old = os.path.join(directory, 'old.rst.h5')
    shutil.copy(newest, old)
    with h5py.File(old, 'r+') as f:
        version = int(f['meta'].attrs['version'])
        f['meta'].attrs['version'] = version - 2
    failures = 0
    status, message = rc.run(directory, JOB, '--restart', old, check=False)
    wanted = 'checkpoint format version %d; this fcs3d reads versions %d to %d only' % (
        version - 2, version - 1, version)
    if status != 2 or wanted not in message:
        failures += 1
        print('FAIL restart from a version-%d checkpoint: exit status %d (expected 2), message '
              '%s (expected it to contain "%s")' % (version - 2, status, message.strip(), wanted))
    else:
        print('a version-%d checkpoint is refused: %s' % (
            version - 2, re.sub(r'\s+', ' ', message.strip())[:200]))
    status, message = rc.run(directory, JOB, '--restart', newest, check=False)
    if status != 0:
        failures += 1
        print('FAIL restart from the unchanged version-%d checkpoint: exit status %d\n%s' % (
            version, status, message))
    else:
        print('the unchanged version-%d checkpoint is accepted' % version)
    sys.exit(1 if failures else 0)


if __name__ == '__main__':
    main()
