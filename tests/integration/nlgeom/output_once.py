"""Each output block is printed once: *NODE PRINT / *EL PRINT requests that are due on the
last increment of a step (a *TIME POINTS time equal to the step end, or FREQUENCY) must not
be printed again by the end-of-step output; the same for the result frames (*NODE FILE).

    output_once.py deck JOB.inp
    output_once.py check JOB

One hexahedron stretched in x over one step of period 1 (no NLGEOM: one increment per
breakpoint); *TIME POINTS 0.5, 1 on a *NODE PRINT (U, RF with TOTALS=YES), FREQUENCY=1 on an
*EL PRINT (S, E) and on a *NODE FILE. Expected: in job.dat every block (title, set, time)
once, at times 0.5 and 1; in job.xdmf one frame per time (0, 0.5, 1).
"""
import argparse
import collections
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fcs_check as fc  # noqa: E402


def make_deck(path):
    block = fc.Block()
    sets = {'X0': block.face(0, 0), 'X1': block.face(0, 1), 'Y0': block.face(1, 0),
            'Z0': block.face(2, 0)}
    lines = ['*HEADING', 'Output once per time (tests/integration/nlgeom/output_once.py)']
    lines += block.mesh_cards(sets)
    lines += fc.material_cards(1000.0, 0.3)
    lines += ['*BOUNDARY', 'X0, 1, 1', 'Y0, 2, 2', 'Z0, 3, 3',
              '*TIME POINTS, NAME=OUT', '0.5, 1.',
              '*STEP', '*STATIC', '1., 1.', '*BOUNDARY', 'X1, 1, 1, 0.01',
              '*NODE PRINT, NSET=X1, TIME POINTS=OUT, TOTALS=YES', 'U, RF',
              '*EL PRINT, ELSET=ALL_ELEMENTS, FREQUENCY=1', 'S, E',
              '*NODE FILE, FREQUENCY=1', 'U', '*END STEP']
    fc.write_deck(path, lines)


def check(job):
    checker = fc.Checker()
    blocks = fc.read_dat(job + '.dat')
    count = collections.Counter((title, name, time) for title, name, time, _ in blocks)
    for (title, name, time), n in sorted(count.items(), key=lambda kv: kv[0][2]):
        checker.check(n == 1, '"%s" for set %s at time %g printed %d time(s)'
                      % (title, name, time, n))
    times = sorted(set(time for _, _, time in count))
    checker.check(fc.same_times(times, [0.5, 1.0]), 'output times %s are 0.5 and 1' % times)
    with open(job + '.xdmf') as xdmf:
        frames = [float(t) for t in re.findall(r'<Time Value="([^"]+)"', xdmf.read())]
    checker.check(frames == sorted(set(frames)) and len(frames) == 3,
                  'one result frame per time in %s.xdmf: %s' % (job, frames))
    checker.finish()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    sub = parser.add_subparsers(dest='command', required=True)
    sub.add_parser('deck').add_argument('path')
    sub.add_parser('check').add_argument('job')
    args = parser.parse_args()
    if args.command == 'deck':
        make_deck(args.path)
    else:
        check(args.job)


if __name__ == '__main__':
    main()
