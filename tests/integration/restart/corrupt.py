"""restart_corrupt.sh: damaged checkpoints are refused, the message names the damage and
offers an older generation; restarting from the offered one works.

The stick-slip deck (restart_common.py) with *RESTART, WRITE, FREQUENCY=4, GENERATIONS=3 is
run to its end: job.rst.h5 (end of step 2), job.rst.1.h5 and job.rst.2.h5 (periodic, a few
increments before). Then, each time on fresh copies of the three checkpoints:
  - one bit flipped in the middle of the data of each dataset of job.rst.h5 in turn (every
    one of them: state, contact, monitors, meta): exit 2, the message names the dataset and
    says "checksum mismatch ... damaged";
  - one character changed in the /meta attribute model_hash: exit 2, "overall checksum";
    in the checksum attribute of /state/u: exit 2, "/state/u: checksum mismatch";
  - job.rst.h5 truncated to 0 bytes: exit 2, "the file is empty (0 bytes)"; to 2048 bytes,
    half its size, its size less one byte: exit 2, "not a readable HDF5 file (truncated or
    damaged?)";
  - every message above ends with "an older checkpoint is readable: job.rst.1.h5 (...);
    restart from it with --restart job.rst.1.h5";
  - the restart from the offered checkpoint (taken from the message) completes, and its
    outputs (job.h5 bit for bit, job.dat, CSVs, XDMF frames) equal the complete run's;
  - without older generations (job.rst.1.h5, job.rst.2.h5 removed), a damaged job.rst.h5 is
    refused with no offer.
usage: corrupt.py WORKDIR
"""
import os
import re
import shutil
import sys

import restart_common as rc

JOB = 'job'
GENERATIONS = ['job.rst.h5', 'job.rst.1.h5', 'job.rst.2.h5']
OFFER = re.compile(r'an older checkpoint is readable: (\S+) \(time [^,]+, increment (\d+)\); '
                   r'restart from it with --restart (\S+)')


def flip_bit(path, offset, bit=0x10):
    with open(path, 'r+b') as f:
        f.seek(offset)
        byte = f.read(1)[0]
        f.seek(offset)
        f.write(bytes([byte ^ bit]))


class Trial:
    """Fresh checkpoints in the run directory, damage, restart, check the message."""

    def __init__(self, directory, pristine):
        self.directory = directory
        self.pristine = pristine
        self.failures = 0
        self.count = 0

    def restore(self):
        for name in os.listdir(self.pristine):
            shutil.copy(os.path.join(self.pristine, name), self.directory)

    def expect_refusal(self, what, expected, offered='job.rst.1.h5'):
        status, message = rc.run(self.directory, JOB, '--restart', 'job.rst.h5', check=False)
        self.count += 1
        problems = []
        if status != 2:
            problems.append('exit status %d, expected 2' % status)
        for text in expected:
            if text not in message:
                problems.append('the message lacks "%s"' % text)
        offer = OFFER.search(message)
        if offered and not (offer and offer.group(1) == offered and offer.group(3) == offered):
            problems.append('the message does not offer %s' % offered)
        if not offered and 'older checkpoint' in message:
            problems.append('the message offers an older checkpoint, but there is none')
        if problems:
            self.failures += 1
            print('FAIL %s: %s\n  message: %s' % (what, '; '.join(problems),
                                                 message.strip().replace('\n', '\n    ')))
        return message


def main():
    rc.require_h5py()
    import h5py
    work = sys.argv[1]
    directory = rc.fresh_dir(os.path.join(work, 'run'))
    rc.write_deck(os.path.join(directory, JOB + '.inp'), generations=3)
    rc.run(directory, JOB)
    complete = rc.fresh_dir(os.path.join(work, 'complete'))
    for name in os.listdir(directory):
        shutil.copy(os.path.join(directory, name), complete)
    pristine = rc.fresh_dir(os.path.join(work, 'pristine'))
    for name in GENERATIONS:
        shutil.copy(os.path.join(directory, name), pristine)
    for name in GENERATIONS:
        print('%s: step %d, increment %d, time %.6g, step time %.6g' % (
            (name,) + rc.checkpoint_info(os.path.join(directory, name))))
    trial = Trial(directory, pristine)
    newest = os.path.join(directory, 'job.rst.h5')

    with h5py.File(os.path.join(pristine, 'job.rst.h5'), 'r') as f:
        datasets = []
        f.visititems(lambda name, obj: datasets.append(
            ('/' + name, obj.id.get_offset(), obj.id.get_storage_size()))
            if isinstance(obj, h5py.Dataset) else None)
        model_hash = f['meta'].attrs['model_hash']
        u_checksum = f['state/u'].attrs['checksum']
    for name, offset, size in datasets:
        trial.restore()
        flip_bit(newest, offset + size // 2)
        trial.expect_refusal('bit flip in ' + name,
                             [name + ': checksum mismatch', 'the checkpoint is damaged'])
    print('a bit flipped in the data of each of the %d datasets: refused, dataset named, '
          'job.rst.1.h5 offered' % len(datasets))

    data = open(os.path.join(pristine, 'job.rst.h5'), 'rb').read()
    for what, text, expected in [
            ('model_hash attribute', model_hash, 'the overall checksum does not match'),
            ('checksum attribute of /state/u', u_checksum, '/state/u: checksum mismatch')]:
        assert data.count(text) == 1, what
        trial.restore()
        flip_bit(newest, data.index(text) + 3, 0x01)
        trial.expect_refusal('changed ' + what, [expected])
    print('a character changed in /meta model_hash and in the checksum attribute of /state/u: '
          'refused')

    size = os.path.getsize(newest)
    for length in [0, 2048, size // 2, size - 1]:
        trial.restore()
        os.truncate(newest, length)
        expected = 'not a readable HDF5 file (truncated or damaged?)'
        if length == 0:
            expected = 'the file is empty (0 bytes): not a checkpoint'
        message = trial.expect_refusal('truncated to %d bytes' % length, [expected])
    print('job.rst.h5 (%d bytes) truncated to 0, 2048, %d, %d bytes: refused as truncated or '
          'damaged, job.rst.1.h5 offered' % (size, size // 2, size - 1))

    offer = OFFER.search(message)
    if offer:
        status, text = rc.run(directory, JOB, '--restart', offer.group(3), check=False)
        if status != 0:
            trial.failures += 1
            print('FAIL the restart from the offered %s: exit status %d\n%s' % (
                offer.group(3), status, text))
        elif rc.compare_runs(complete, directory, JOB, 'restart from the offered ' +
                             offer.group(3) + ' (increment ' + offer.group(2) + ')'):
            trial.failures += 1

    trial.restore()
    for name in GENERATIONS[1:]:
        os.remove(os.path.join(directory, name))
    flip_bit(newest, datasets[0][1] + datasets[0][2] // 2)
    trial.expect_refusal('no older generation', ['checksum mismatch'], offered=None)
    print('no older generation: a damaged job.rst.h5 is refused without an offer')
    print('%d damaged checkpoints tried, %d failures' % (trial.count, trial.failures))
    return 1 if trial.failures else 0


if __name__ == '__main__':
    sys.exit(main())
