"""Bad states during a run (issue 9): each deck below is valid (fcs3d --check accepts it) but
drives the run into a state it cannot continue from. For each the run must
  - exit with status 1 (a run-time failure, not an input error);
  - print one message naming the step, the increment, the time and the entity (node,
    element, contact node) and saying the likely cause;
  - say where the last good increment is, and have it there: the last frame of job.h5 is
    complete and readable (coordinates, displacements) at the increment and time named,
    and the checkpoint job.rst.h5 exists.

The decks (a unit cube, or a block pressed on a block with non-matching meshes):
  nan          a load of 1e10 on a cube of modulus 1e-300 -> the trial solution overflows;
  singular_*   the upper block starts 0.1 above the lower one, held only against x and y:
               nothing holds it in z until contact closes -> singular matrix, for UMFPACK,
               MUMPS and the skyline solver;
  penetration  a normal penalty E_n far too small for the pressure -> the contact node
               would end deep inside the master body;
  min_increment a strain limit that cuts the increment below *STATIC's minimum;
  inverted     one corner node driven through the opposite face -> inverted element.

In a DEBUG=1 build (fcs3d --version says "debug") floating-point traps are on: the overflow of
the nan case stops the run at once with SIGFPE and a backtrace, which is what the traps are
for; there the nan case checks that instead.

Usage: bad_states.py <work directory>   ($FCS3D names the binary)
"""
import os
import re
import subprocess
import sys

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(HERE, '..', '..', 'data')
FCS3D = os.environ['FCS3D']

CUBE = """*HEADING
unit cube for a bad-state test
*NODE, NSET=NALL
1, 0, 0, 0
2, 1, 0, 0
3, 1, 1, 0
4, 0, 1, 0
5, 0, 0, 1
6, 1, 0, 1
7, 1, 1, 1
8, 0, 1, 1
*ELEMENT, TYPE=C3D8, ELSET=E
1, 1, 2, 3, 4, 5, 6, 7, 8
*NSET, NSET=BOT
1, 2, 3, 4
*NSET, NSET=TOP
5, 6, 7, 8
*MATERIAL, NAME=M
*{law}
{elastic}
*SOLID SECTION, ELSET=E, MATERIAL=M
*BOUNDARY
BOT, 1, 3
*STEP, NLGEOM
*STATIC
{static}
{rmin}
{load}
*END STEP
"""


def cube(static, load, rmin='*RMIN', elastic='1000., 0.3', law='ELASTIC'):
    return CUBE.format(static=static, load=load, rmin=rmin, elastic=elastic, law=law)


def block_on_block(solver=None, lift=0.0, penalty=None):
    """The MPI test's block-on-block deck, optionally with the upper block lifted by `lift`,
    another solver, or another normal penalty."""
    text = open(os.path.join(DATA, 'mpi', 'block_slide.inp')).read()
    out = []
    for line in text.splitlines():
        m = re.match(r'^(100\d\d), ([-\d.]+), ([-\d.]+), ([-\d.]+)$', line)
        if m and lift:
            line = '%s, %s, %s, %.6g' % (m.group(1), m.group(2), m.group(3),
                                         float(m.group(4)) + lift)
        if solver and line.startswith('*SOLVER'):
            line = '*SOLVER, TYPE=%s' % solver
        if penalty and line == '1.e4' and out and out[-1].startswith('*SURFACE BEHAVIOR'):
            line = penalty
        out.append(line)
    return '\n'.join(out) + '\n'


CASES = [
    # name, deck, words the message must contain, the entity it must name
    ('nan', cube('1., 1., 1., 1.', '*CLOAD\nTOP, 3, 1e10', elastic='1e-300, 0.3'),
     ['not finite', 'overflows'], 'node 5'),
    ('singular_umfpack', block_on_block(solver='UMFPACK', lift=0.1),
     ['singular', 'supported'], 'UMFPACK'),
    ('singular_mumps', block_on_block(solver='MUMPS', lift=0.1),
     ['singular', 'null pivot'], 'MUMPS'),
    ('singular_skyline', block_on_block(solver='SKYLINE', lift=0.1),
     ['pivot', 'singular'], 'node 100'),
    ('penetration', block_on_block(penalty='1.e-1'),
     ['excessive penetration', 'penalty'], 'slave node 100'),
    ('min_increment', cube('1., 1., 1., 1.', '*BOUNDARY\nTOP, 3, 3, -0.5'),
     ['below the minimum', 'too fast'], 'element 1'),
    # The rate form (*HYPOELASTIC) keeps its stiffness in compression up to the inversion;
    # St Venant-Kirchhoff (*ELASTIC under NLGEOM) has a limit point at the stretch 1/sqrt(3)
    # (P = E lambda (lambda^2 - 1)/2), where the strain limit stops the run first.
    ('inverted', cube('0.1, 1., 1e-6, 0.1', '*BOUNDARY\n7, 1, 3, -1.2',
                      rmin='*RMIN, MAX STRAIN INCREMENT=0.1', law='HYPOELASTIC'),
     ['inverted', 'Jacobian'], 'element 1'),
]

FAILURE = re.compile(r'fcs3d: step (\d+), increment (\d+), time ([-+.\dEe]+): (.*)')
LAST_GOOD = re.compile(r'last good increment \((\d+), time ([-+.\dEe]+)\) is in the last '
                       r'frame of (\S+) and in the checkpoint (\S+)')


def trapping_build():
    version = subprocess.run([FCS3D, '--version'], capture_output=True, text=True, timeout=60)
    return 'debug' in version.stdout


def check_trap(directory):
    """The overflow case in a build with floating-point traps: SIGFPE with a backtrace."""
    run = subprocess.run([FCS3D, '-q', 'job.inp'], cwd=directory, capture_output=True,
                         text=True, timeout=300)
    if run.returncode != 0 and 'Floating-point exception' in run.stderr:
        return []
    return ['expected the floating-point trap (SIGFPE), got status %d: %s'
            % (run.returncode, run.stderr.strip()[-300:])]


def check_case(work, name, deck, words, entity):
    """Problems found (empty when the case passes)."""
    directory = os.path.join(work, name)
    os.makedirs(directory, exist_ok=True)
    with open(os.path.join(directory, 'job.inp'), 'w') as f:
        f.write(deck)
    check = subprocess.run([FCS3D, '--check', '-q', 'job.inp'], cwd=directory,
                           capture_output=True, text=True, timeout=120)
    if check.returncode != 0:
        return ['--check refuses the deck (status %d): %s' % (check.returncode,
                                                              check.stderr.strip()[:300])]
    if name == 'nan' and trapping_build():
        return check_trap(directory)
    run = subprocess.run([FCS3D, '-q', 'job.inp'], cwd=directory, capture_output=True,
                         text=True, timeout=300)
    text = run.stdout + run.stderr
    problems = []
    if run.returncode != 1:
        problems.append('exit status %d, expected 1' % run.returncode)
    failure = FAILURE.search(text)
    if not failure:
        return problems + ['no "fcs3d: step N, increment N, time T: ..." message in: ' +
                           text.strip()[-400:]]
    message = failure.group(4)
    for word in words + [entity]:
        if word not in message:
            problems.append('the message lacks "%s": %s' % (word, message[:300]))
    last = LAST_GOOD.search(text)
    if not last:
        return problems + ['no "last good increment" sentence in: ' + text.strip()[-300:]]
    increment, time = int(last.group(1)), float(last.group(2))
    if increment != int(failure.group(2)) - 1:
        problems.append('last good increment %d is not the one before the failed %s'
                        % (increment, failure.group(2)))
    results = os.path.join(directory, last.group(3))
    if not os.path.isfile(os.path.join(directory, last.group(4))):
        problems.append('no checkpoint %s' % last.group(4))
    try:
        with h5py.File(results, 'r') as f:
            frames = f['frames']
            final = frames[sorted(frames.keys())[-1]]
            if int(final.attrs['complete']) != 1:
                problems.append('the last frame is not marked complete')
            if int(final.attrs['increment']) != increment:
                problems.append('the last frame is increment %d, not %d'
                                % (final.attrs['increment'], increment))
            if abs(float(final.attrs['time']) - time) > 1e-5 * max(1.0, abs(time)):
                problems.append('the last frame is at time %g, not %g'
                                % (final.attrs['time'], time))
            u = np.asarray(final['nodal']['displacement'])
            if not np.all(np.isfinite(u)):
                problems.append('the last good displacements are not finite')
    except (OSError, KeyError) as error:
        problems.append('%s unreadable: %s' % (results, error))
    return problems


def main():
    work = sys.argv[1]
    failures = 0
    for name, deck, words, entity in CASES:
        problems = check_case(work, name, deck, words, entity)
        failures += bool(problems)
        print('%s %s' % ('FAIL' if problems else 'ok  ', name))
        for p in problems:
            print('     ' + p)
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
