"""plasticity_restart.sh: a plastic run killed with SIGKILL at a random increment and restarted
from its newest checkpoint ends with the one-go run's outputs, bit for bit.

    restart_plastic.py WORKDIR [KIND]

The problem: a bar 6 x 2 x 2 (8 x 2 x 2 C3D8, B-bar) clamped at x = 0, its end x = 6 pushed
sideways by 0.3 (NLGEOM) and back to -0.1 (about 160 increments, under a second): von Mises
plasticity with combined hardening (isotropic *CYCLIC HARDENING, kinematic *PLASTIC curve), so that the checkpoint must carry the equivalent plastic strain,
the plastic strain and the back stress of every point, and the restarted run must rotate them
and return-map as the one-go run does. Step 1 bends the bar until the plastic zone spreads
from the clamp (yield events, the plastic strain limit); step 2 unloads and reverses
(unloading switches, reverse yield). Checkpoints every 5 increments.

1. One-go run.
2. The same deck killed with kill -9 at a random moment after its first checkpoint appeared
   (seeded from $FCS3D_TEST_SEED, else the clock; printed), restarted from the newest
   checkpoint to the end: every dataset and attribute of job.h5 (PEEQ, PE and ALPHA of every
   frame included), job.dat (S and PEEQ tables) byte for byte, and the frames of job.xdmf,
   equal the one-go run's; so does the final checkpoint's material state.
With KIND (e.g. C3D20R, as plasticity_restart_quadratic.sh runs it) the bar's cells are
elements of that kind (tests/tools/kind_meshes.py; no B-bar, 4 x 2 x 2 cells), so that the
checkpoint carries the state of every point of a quadratic element (8 per C3D20R).

3. The plastic fields are visible in ParaView: the one-go run's job.xdmf lists PEEQ (nodes and
   cells), PE and ALPHA (nodes), and VTK's vtkXdmfReader (ParaView's Xdmf reader) returns every
   array of every frame equal to the HDF5 data (post/check_xdmf_vtk.py; skipped without
   python3-paraview).
"""
import os
import shutil
import signal
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, '..', 'restart'))
import restart_common as rc  # noqa: E402
import plastic_common as pc  # noqa: E402

fc = pc.fc
JOB = 'job'


def write_deck(path, kind='C3D8'):
    lines = ['*HEADING', 'bar bent into the plastic range and back (restart_plastic.py), ' + kind]
    if kind == 'C3D8':
        block = fc.Block(lx=6.0, ly=2.0, lz=2.0, nx=8, ny=2, nz=2)
        sets = {'CLAMP': block.face(0, 0), 'END': block.face(0, 1)}
        lines += block.mesh_cards(sets)
    else:
        lines += pc.kind_mesh_cards((6.0, 2.0, 2.0), (4, 2, 2), kind, {
            'CLAMP': lambda x, y, z: x == 0.0, 'END': lambda x, y, z: x == 6.0})
    lines += pc.von_mises_cards(200000.0, 0.3, [(200.0, 0.0), (300.0, 0.05), (320.0, 0.5)],
                                'COMBINED', cyclic=[(200.0, 0.0), (250.0, 0.1)],
                                bbar=(kind == 'C3D8'))
    lines += ['*BOUNDARY', 'CLAMP, 1, 3', '*RESTART, WRITE, FREQUENCY=5, GENERATIONS=3',
              '*STEP, NLGEOM', '*STATIC', '0.05, 1.', '*BOUNDARY', 'END, 2, 2, 0.3',
              '*NODE FILE, FREQUENCY=10', 'U', '*EL FILE, FREQUENCY=10', 'S, PEEQ',
              '*EL PRINT, ELSET=ALL_ELEMENTS, FREQUENCY=25', 'S, PEEQ', '*END STEP',
              '*STEP, NLGEOM', '*STATIC', '0.05, 1.', '*BOUNDARY', 'END, 2, 2, -0.1',
              '*NODE FILE, FREQUENCY=10', 'U', '*EL FILE, FREQUENCY=10', 'S, PEEQ',
              '*EL PRINT, ELSET=ALL_ELEMENTS, FREQUENCY=25', 'S, PEEQ', '*END STEP']
    fc.write_deck(path, lines)


def kill_at_random(directory, rng, window):
    checkpoint = os.path.join(directory, JOB + '.rst.h5')
    for _ in range(6):
        rc.remove_checkpoints(directory, JOB)
        process = rc.start(directory, JOB)
        seen = rc.wait_for_checkpoint(process, checkpoint)
        delay = rng.uniform(0.0, window)
        if seen is not None:
            time.sleep(delay)
            process.send_signal(signal.SIGKILL)
        status = process.wait()
        if status == -signal.SIGKILL:
            name = JOB + '.rst.h5'
            if not os.path.exists(os.path.join(directory, name)):
                name = JOB + '.rst.1.h5'
            step, increment, t, _ = rc.checkpoint_info(os.path.join(directory, name))
            print('  killed %.3f s after checkpoint %d appeared; newest checkpoint: step %d, '
                  'increment %d, time %.6g' % (delay, seen, step, increment, t))
            return name
        if status != 0:
            raise SystemExit('fcs3d: exit status %d\n%s' % (status, process.stderr.read()))
        print('  the run ended before the kill (%.3f s); again with a shorter window' % delay)
        window *= 0.5
    raise SystemExit('could not kill the run before its end')


def main():
    rc.require_h5py()
    work = sys.argv[1]
    rng = rc.seeded_random('plasticity_restart')
    kind = sys.argv[2] if len(sys.argv) > 2 else 'C3D8'
    reference = rc.fresh_dir(os.path.join(work, 'reference'))
    write_deck(os.path.join(reference, JOB + '.inp'), kind)
    t0 = time.monotonic()
    rc.run(reference, JOB)
    wall = time.monotonic() - t0
    records, _ = fc.read_increments(os.path.join(reference, JOB + '.log'))
    kinds = sorted({r['limit'] for r in records})
    print('one-go run (%s): %.2f s, %d increments (limits: %s), %d switching increments'
          % (kind, wall, len(records), ', '.join(kinds),
             sum(' switches ' in line for line in open(os.path.join(reference, JOB + '.log')))))
    killed = rc.fresh_dir(os.path.join(work, 'killed'))
    shutil.copy(os.path.join(reference, JOB + '.inp'), killed)
    newest = kill_at_random(killed, rng, 0.7 * wall)
    rc.run(killed, JOB, '--restart', newest)
    problems = rc.compare_h5(os.path.join(reference, JOB + '.h5'), os.path.join(killed, JOB + '.h5'))
    problems += rc.compare_files(reference, killed, [JOB + '.dat'])
    problems += rc.compare_xdmf(os.path.join(reference, JOB + '.xdmf'),
                                os.path.join(killed, JOB + '.xdmf'))
    problems += rc.compare_h5(os.path.join(reference, JOB + '.rst.h5'),
                              os.path.join(killed, JOB + '.rst.h5'),
                              select=lambda name: name.startswith('/state'))
    if problems:
        print('the restarted run differs from the one-go run:')
        for p in problems[:20]:
            print('  ' + p)
        return 1
    print('killed and restarted: job.h5 (every dataset and attribute: PEEQ, PE, ALPHA of every '
          'frame), job.dat and the frames of job.xdmf identical to the one-go run, and the final '
          'checkpoint\'s state (material state included)')
    if not ('yield' in kinds and 'plastic-strain-limit' in kinds):
        print('the run should have yield events and plastic strain limits')
        return 1
    xdmf = os.path.join(reference, JOB + '.xdmf')
    text = open(xdmf).read()
    for name, centre in (('PEEQ', 'Node'), ('PEEQ', 'Cell'), ('PE', 'Node'), ('ALPHA', 'Node')):
        if 'Name="%s" AttributeType' % name not in text or \
                'Attribute Name="%s" AttributeType="%s" Center="%s"' % (
                    name, 'Scalar' if name == 'PEEQ' else 'Tensor6', centre) not in text:
            print('job.xdmf does not list %s at the %ss' % (name, centre.lower()))
            return 1
    check = subprocess.run([sys.executable, os.path.join(HERE, '..', '..', '..', 'post',
                                                         'check_xdmf_vtk.py'), xdmf],
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    print('ParaView\'s reader: ' + check.stdout.strip().splitlines()[-1])
    if check.returncode not in (0, 77):
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main())
