#!/usr/bin/python3
"""Surface-to-surface contact (*CONTACT PAIR, TYPE=SURFACE TO SURFACE; doc/theory.md 4.10).

Usage: surface_to_surface.py deck JOB.inp --case CASE --kind KIND [--slave N --master M]
       surface_to_surface.py check JOB --case CASE --kind KIND [--slave N --master M]
CASE: patch (frictionless contact patch test), slide (Coulomb mu = 0.3, pushed sideways),
free (frictionless, pushed sideways). KIND: C3D8, C3D20, C3D20R or C3D10 (both blocks).

Model: a base block (M x M x 2 cells) under a slider (N x N x 2 cells; N != M: the interface
meshes do not match), E1 = 1000, nu1 = 0.3 and E2 = 500, nu2 = 0.15, the slider's bottom the
slave surface, the base's top the master, penalty E_n = 1e6 [stress/length] (per unit area),
pressure p = 1 on the slider's top, default increments.

patch: base 1 x 1 x 0.5, slider 1 x 1 x 0.5 on it, both on rollers (x = 0 and y = 0 faces,
base bottom in z). The exact solution is uniaxial stress s_zz = -p in both blocks, which every
kind represents exactly. A surface-to-surface pair cuts each slave face by the master faces
(4- and 8-node faces) so that the master receives the consistent nodal forces of a uniform
pressure: the uniform state is then the discrete solution, whatever N and M. Checks: every
integration point of both blocks s_zz = -p (1e-6 relative: the 7-digit print; measured
~1e-12 in the h5), s_xx, s_yy, s_xy within 1e-6 p; every slave point's contact pressure p
within 1e-9 (h5 field; round-off); base reaction = p A (1e-9). The penalty's compliance
only shifts the slider down by p/E_n = 1e-6 and enters no stress. For C3D10 (6-node triangle
faces, not cut: Gauss points of the slave faces) the master forces are not exact on
non-matching meshes; --tolerance gives the stated bound for that kind.

slide / free: base (-1/3 .. 4/3)^2 x 0.5 (wider, so that the slider stays on it), slider
1 x 1 x 0.5; step 1 presses (base bottom fixed, slider top held in x, y), step 2 moves the
slider's top by u_x = 0.05. slide: the tangential reaction T of the base over its normal
reaction N equals mu within 0.5 % at every output of the last half of the push (Coulomb
sliding: every slave point on the cone; equilibrium). free: no shear traction at any slave
point in any frame (exactly 0), and |T| / N <= 1e-3 (the base's reaction T is not exactly 0:
the frictionless contact forces follow the master normals, which tilt with the base's
deformed surface; measured 6e-5).
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import contact_common as cc  # noqa: E402
from quadratic_blocks import QuadraticBox, surface_cards  # noqa: E402

P = 1.0
E1, NU1, E2, NU2 = 1000.0, 0.3, 500.0, 0.15
PENALTY = 1.0e6
MU = 0.3
PUSH = 0.05


def box(kind, lo, hi, cells, first):
    b = QuadraticBox('C3D20R' if kind == 'C3D20' else kind, lo, hi, cells, first, first)
    b.kind = kind
    return b


def make_deck(path, case, kind, slave, master):
    if case == 'patch':
        base = box(kind, (0, 0, 0), (1, 1, 0.5), (master, master, 2), 1)
    else:
        base = box(kind, (-1 / 3, -1 / 3, 0), (4 / 3, 4 / 3, 0.5), (master, master, 2), 1)
    slider = box(kind, (0, 0, 0.5), (1, 1, 1.0), (slave, slave, 2), 100001)
    lines = ['*HEADING', 'Surface-to-surface contact, %s, %s, %d x %d slave faces on %d x %d '
             '(tests/integration/contact/surface_to_surface.py)' % (case, kind, slave, slave,
                                                                    master, master)]
    lines += base.cards('BASE') + slider.cards('SLIDER')
    lines += ['*ELSET, ELSET=BOTH', 'BASE, SLIDER']
    lines += cc.nset_cards('BOTTOM', base.nodes_where(lambda x, y, z: abs(z) <= 1e-12))
    if case == 'patch':
        lines += cc.nset_cards('X0', base.nodes_where(lambda x, y, z: abs(x) <= 1e-12))
        lines += cc.nset_cards('Y0', base.nodes_where(lambda x, y, z: abs(y) <= 1e-12))
        lines += cc.nset_cards('SX0', slider.nodes_where(lambda x, y, z: abs(x) <= 1e-12))
        lines += cc.nset_cards('SY0', slider.nodes_where(lambda x, y, z: abs(y) <= 1e-12))
    lines += cc.nset_cards('TOP', slider.nodes_where(lambda x, y, z: abs(z - 1.0) <= 1e-12))
    lines += surface_cards('MASTER', base.faces_on(2, 0.5))
    lines += surface_cards('SLAVE', slider.faces_on(2, 0.5))
    lines += surface_cards('LOADED', slider.faces_on(2, 1.0))
    lines += cc.material_cards('BASE_MAT', 'BASE', E1, NU1)
    lines += cc.material_cards('SLIDER_MAT', 'SLIDER', E2, NU2)
    lines += cc.interaction_cards('INTERFACE', PENALTY, MU if case == 'slide' else None)
    lines += ['*CONTACT PAIR, INTERACTION=INTERFACE, TYPE=SURFACE TO SURFACE', 'SLAVE, MASTER']
    lines += ['*STEP', '*STATIC', '*BOUNDARY']
    if case == 'patch':
        lines += ['BOTTOM, 3, 3', 'X0, 1, 1', 'Y0, 2, 2', 'SX0, 1, 1', 'SY0, 2, 2']
    else:
        lines += ['BOTTOM, 1, 3', 'TOP, 1, 2']
    lines += ['*DSLOAD', 'LOADED, P, %.12g' % P, '*NODE PRINT, NSET=BOTTOM, TOTALS=ONLY', 'RF',
              '*EL PRINT, ELSET=BOTH', 'S', '*CONTACT FILE', 'CSTR', '*END STEP']
    if case != 'patch':
        lines += ['*STEP', '*STATIC', '*BOUNDARY', 'TOP, 1, 1, %.12g' % PUSH,
                  '*NODE PRINT, NSET=BOTTOM, TOTALS=ONLY, FREQUENCY=1', 'RF', '*END STEP']
    cc.write_deck(path, lines)


def check(job, case, kind, slave, master, tolerance):
    checker = cc.Checker()
    blocks = cc.read_dat(job + '.dat')
    times, bottom = cc.totals(blocks, 'BOTTOM')
    label = '%s %s, %dx%d slave faces on %dx%d' % (case, kind, slave, slave, master, master)
    if case == 'patch':
        checker.relative(label + ': base reaction = p A', bottom[-1][2], P, 1e-9)
        s_blocks = [b for b in blocks if b['title'].startswith('stresses')]
        s = np.array([values for _, values in s_blocks[-1]['rows']])
        szz = np.abs(s[:, 2] / -P - 1.0).max()
        other = np.abs(s[:, [0, 1, 3, 4, 5]]).max() / P
        checker.check(szz <= tolerance, label + ': s_zz = -p at all %d integration points, max '
                      'relative error %.3e (tolerance %g)' % (len(s), szz, tolerance))
        checker.check(other <= tolerance, label + ': other stress components max %.3e p '
                      '(tolerance %g)' % (other, tolerance))
        frames = cc.contact_frames(job + '.h5', 'SLAVE-MASTER')
        last = frames[-1]
        closed = last['status'] != cc.OPEN
        checker.check(closed.all(), label + ': %d of %d slave points closed'
                      % (closed.sum(), len(closed)))
        error = np.abs(last['pressure'][closed] / P - 1.0).max()
        limit = 1e-8 if tolerance <= 1e-6 else tolerance
        checker.check(error <= limit, label + ': contact pressure p at every slave point, max '
                      'error %.3e (tolerance %g)' % (error, limit))
        print('summary %s: s_zz error %.3e, other %.3e p, pressure error %.3e, %d points'
              % (label, szz, other, error, len(closed)))
    else:
        keep = times >= 1.5 - 1e-9
        checker.check(keep.sum() >= 1, label + ': %d output(s) in the last half of the push'
                      % keep.sum())
        tangential, normal = -bottom[keep, 0], bottom[keep, 2]
        checker.relative(label + ': normal reaction = p A', normal[-1], P, 1e-6)
        if case == 'slide':
            errors = np.abs(tangential / (MU * normal) - 1.0)
            checker.check(errors.max() <= 5e-3, label + ': sliding, |T/(mu N) - 1| max %.3e '
                          '(tolerance 5e-3; T/N %.7f .. %.7f)' % (errors.max(),
                                                                 (tangential / normal).min(),
                                                                 (tangential / normal).max()))
            print('summary %s: T/(mu N) - 1 max %.3e over %d outputs' % (label, errors.max(),
                                                                         keep.sum()))
        else:
            frames = cc.contact_frames(job + '.h5', 'SLAVE-MASTER')
            shear = max(np.abs(f['shear_magnitude']).max() for f in frames)
            checker.check(shear == 0.0, label + ': frictionless, no shear traction at any slave '
                          'point in any of %d frames (max %.3e)' % (len(frames), shear))
            ratio = np.abs(tangential / normal).max()
            checker.check(ratio <= 1e-3, label + ': frictionless, |T| / N max %.3e (tolerance '
                          '1e-3: only the tilt of the master normals on the deformed base)'
                          % ratio)
            print('summary %s: shear 0, |T|/N max %.3e over %d outputs' % (label, ratio, keep.sum()))
    checker.finish()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    sub = parser.add_subparsers(dest='command', required=True)
    for name in ('deck', 'check'):
        p = sub.add_parser(name)
        p.add_argument('path')
        p.add_argument('--case', choices=['patch', 'slide', 'free'], required=True)
        p.add_argument('--kind', choices=['C3D8', 'C3D20', 'C3D20R', 'C3D10'], required=True)
        p.add_argument('--slave', type=int, default=5)
        p.add_argument('--master', type=int, default=3)
        if name == 'check':
            p.add_argument('--tolerance', type=float, default=1e-6)
    args = parser.parse_args()
    if args.command == 'deck':
        make_deck(args.path, args.case, args.kind, args.slave, args.master)
    else:
        check(args.path, args.case, args.kind, args.slave, args.master, args.tolerance)


if __name__ == '__main__':
    main()
