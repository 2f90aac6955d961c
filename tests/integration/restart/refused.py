"""restart_refused_keeps_outputs.sh (pending): a refused restart must leave the outputs of
the earlier run as they were.

The stick-slip deck (restart_common.py) is run to its end; its outputs are saved. Then three
restarts that fcs3d refuses, each from fresh copies of the outputs and checkpoints:
  - from job.rst.h5, damaged (one bit flipped in the data of /state/u);
  - from job.rst.2.h5 (a few increments before the end), Young's modulus changed in the
    deck (the model section differs);
  - from job.rst.2.h5, a step changed that the checkpoint had begun (step 2);
each must exit with status 2, and job.dat, job.h5, job.xdmf, job_fault.csv and
job_events.csv must be byte for byte what they were.

Fails at 798158c: the history and event CSVs are replaced before the checkpoint is read
and checked (fcs_monitors init writes their headers; read_checkpoint rewrites them from the
checkpoint's rows before the deck is checked), so a refused restart leaves header-only
CSVs (damaged checkpoint) or CSVs cut back to the checkpoint (changed deck).
usage: refused.py WORKDIR
"""
import os
import shutil
import sys

import restart_common as rc

JOB = 'job'
OUTPUTS = [JOB + '.dat', JOB + '.h5', JOB + '.xdmf', JOB + '_' + rc.HISTORY + '.csv',
           JOB + '_events.csv']


def main():
    rc.require_h5py()
    import h5py
    work = sys.argv[1]
    complete = rc.fresh_dir(os.path.join(work, 'complete'))
    rc.write_deck(os.path.join(complete, JOB + '.inp'))
    rc.run(complete, JOB)
    with h5py.File(os.path.join(complete, JOB + '.rst.h5'), 'r') as f:
        offset = f['state/u'].id.get_offset() + f['state/u'].id.get_storage_size() // 2

    def damage(directory):
        with open(os.path.join(directory, JOB + '.rst.h5'), 'r+b') as f:
            f.seek(offset)
            byte = f.read(1)[0]
            f.seek(offset)
            f.write(bytes([byte ^ 0x10]))

    def new_deck(text):
        def change(directory):
            with open(os.path.join(directory, JOB + '.inp'), 'w') as f:
                f.write(text)
        return change

    failures = 0
    step2 = rc.deck_text(step_changes={2: [('TOP, 1, 1, 0.025', 'TOP, 1, 1, 0.03')]})
    for what, checkpoint, change in [
            ('damaged checkpoint', JOB + '.rst.h5', damage),
            ('changed Young\'s modulus', JOB + '.rst.2.h5', new_deck(rc.deck_text(young='1001.'))),
            ('changed step 2', JOB + '.rst.2.h5', new_deck(step2))]:
        directory = rc.fresh_dir(os.path.join(work, 'case'))
        for name in os.listdir(complete):
            shutil.copy(os.path.join(complete, name), directory)
        change(directory)
        status, message = rc.run(directory, JOB, '--restart', checkpoint, check=False)
        changed = rc.compare_files(complete, directory, OUTPUTS)
        if status != 2 or changed:
            failures += 1
            print('FAIL %s: exit status %d (expected 2); %s' % (
                what, status, '; '.join(changed) if changed else 'outputs unchanged'))
            print('  message: ' + message.strip().splitlines()[0])
        else:
            print('%s: refused, %s unchanged' % (what, ', '.join(OUTPUTS)))
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
