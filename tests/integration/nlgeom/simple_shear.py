"""Simple shear of a hypoelastic block to shear strain gamma (NLGEOM, Jaumann rate).

    simple_shear.py deck JOB.inp [--strain-limit X] [--rotation-limit DEG] [--gamma G]
    simple_shear.py check JOB [--gamma G] [--tolerance T] [--min-gamma G0]

Block: 1 x 2 x 1 hexahedra on the unit cube (height H = 1 along y, two elements over the
height so that the mid-height nodes are "side" nodes). Every node is prescribed:
u_x = gamma(t) * Y (linear in height: bottom fixed, top moved by gamma * H, mid-height nodes by
gamma * H / 2), u_y = u_z = 0, with gamma(t) = gamma_end * t over a step of period 1, so the
deformation is homogeneous simple shear x = X + gamma Y. Output: *EL PRINT S at gamma_end *
(1/4, 1/2, 3/4, 1) through *TIME POINTS.

Closed form (hypoelastic sigma^J = C:D under simple shear at a constant rate; Dienes 1979,
method notes section 4): s12 = G sin(gamma), s11 = -s22 = G (1 - cos(gamma)), s33 = s13 = s23 = 0.

`check` also replays the midpoint Hughes-Winget update sigma <- Q (sigma + C:dD/2) Q^T + C:dD/2,
Q = (I - W/2)^-1 (I + W/2), with the increments fcs3d logged (job.log times): for simple shear
the increment gradient on the mid-increment configuration is exactly dgamma e1 x e2, so this
replay is the exact discrete answer of the algorithm and fcs3d must match it to printing
precision, whatever the step size.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fcs_check as fc  # noqa: E402

YOUNG = 1000.0
POISSON = 0.3
SHEAR_MODULUS = YOUNG / (2.0 * (1.0 + POISSON))
FRACTIONS = (0.25, 0.5, 0.75, 1.0)


def make_deck(path, strain_limit, rotation_limit, gamma):
    block = fc.Block(nx=1, ny=2, nz=1)
    heights = sorted(set(block.x[:, 1]))
    sets = {'LEVEL%d' % k: block.nodes_where(lambda x, y, z, h=h: abs(y - h) < 1e-12)
            for k, h in enumerate(heights)}
    lines = ['*HEADING', 'Simple shear to gamma = %g (tests/integration/nlgeom/simple_shear.py)'
             % gamma]
    lines += block.mesh_cards(sets)
    lines += fc.material_cards(YOUNG, POISSON)
    lines += ['*TIME POINTS, NAME=OUT', ', '.join('%.17g' % f for f in FRACTIONS)]
    lines += ['*STEP, NLGEOM', '*STATIC', '1., 1.']
    rmin = []
    if strain_limit is not None:
        rmin.append('MAX STRAIN INCREMENT=%.17g' % strain_limit)
    if rotation_limit is not None:
        rmin.append('MAX ROTATION INCREMENT=%.17g' % rotation_limit)
    if rmin:
        lines.append('*RMIN, ' + ', '.join(rmin))
    lines += ['*BOUNDARY', 'ALL_NODES, 2, 3, 0.']
    for k, h in enumerate(heights):
        lines.append('LEVEL%d, 1, 1, %.17g' % (k, gamma * h))
    lines += ['*EL PRINT, ELSET=ALL_ELEMENTS, TIME POINTS=OUT', 'S', '*END STEP']
    fc.write_deck(path, lines)


def closed_form(gamma):
    """Voigt stress (11 22 33 12 13 23) of the Jaumann hypoelastic simple shear."""
    g = SHEAR_MODULUS
    return np.array([g * (1.0 - np.cos(gamma)), -g * (1.0 - np.cos(gamma)), 0.0,
                     g * np.sin(gamma), 0.0, 0.0])


def hughes_winget_replay(gamma_steps):
    """Stress after each increment of the Hughes-Winget update for simple-shear increments."""
    lam = YOUNG * POISSON / ((1.0 + POISSON) * (1.0 - 2.0 * POISSON))
    sigma = np.zeros((3, 3))
    history = []
    for dg in gamma_steps:
        h = np.zeros((3, 3))
        h[0, 1] = dg
        d = 0.5 * (h + h.T)
        w = 0.5 * (h - h.T)
        q = np.linalg.solve(np.eye(3) - 0.5 * w, np.eye(3) + 0.5 * w)
        # Midpoint form used by fcs3d: half of C:dD before the rotation, half after.
        increment = lam * np.trace(d) * np.eye(3) + 2.0 * SHEAR_MODULUS * d
        sigma = q @ (sigma + 0.5 * increment) @ q.T + 0.5 * increment
        history.append(np.array([sigma[0, 0], sigma[1, 1], sigma[2, 2], sigma[0, 1],
                                 sigma[0, 2], sigma[1, 2]]))
    return history


def check(job, gamma, tolerance, min_gamma):
    checker = fc.Checker()
    records, _ = fc.read_increments(job + '.log')
    blocks = fc.stress_blocks(fc.read_dat(job + '.dat'))
    times = sorted(set(t for t, _ in blocks))
    # Output lands on the requested times (E14.7 in the header: 7 significant digits).
    checker.check(fc.same_times(times, FRACTIONS),
                  'output times %s are the requested %s' % (times, list(FRACTIONS)))
    steps = np.diff([0.0] + [r['time'] for r in records]) * gamma
    replay = hughes_winget_replay(steps)
    increment_times = np.array([r['time'] for r in records])
    for t, stress in blocks:
        g = gamma * t
        # Homogeneous deformation: all integration points carry the same stress (round-off).
        spread = np.abs(stress - stress.mean(axis=0)).max() / SHEAR_MODULUS
        checker.check(spread <= 1e-9, 'gamma %.4g: integration points agree (spread %.1e G)'
                      % (g, spread))
        s = stress.mean(axis=0)
        # Discrete oracle: printing precision is 7 significant digits (es14.6) -> 5e-7 of the
        # largest component; 2e-6 G allows for the 11-digit times of the log.
        k = int(np.argmin(np.abs(increment_times - t)))
        replay_error = np.abs(s - replay[k]).max() / SHEAR_MODULUS
        checker.check(replay_error <= 2e-6, 'gamma %.4g: equals the Hughes-Winget replay of '
                      'the %d logged increments (max difference %.1e G)' % (g, k + 1, replay_error))
        expected = closed_form(g)
        checker.relative('gamma %.4g: s12 vs G sin(gamma)' % g, s[3], expected[3], tolerance)
        if g >= min_gamma:
            checker.relative('gamma %.4g: s11 vs G (1 - cos gamma)' % g, s[0], expected[0],
                             tolerance)
            checker.relative('gamma %.4g: s22 vs -G (1 - cos gamma)' % g, s[1], expected[1],
                             tolerance)
        others = np.abs(s[[2, 4, 5]]).max() / SHEAR_MODULUS
        checker.check(others <= 1e-9, 'gamma %.4g: s33, s13, s23 are zero (%.1e G)' % (g, others))
    checker.finish()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    sub = parser.add_subparsers(dest='command', required=True)
    deck = sub.add_parser('deck')
    deck.add_argument('path')
    deck.add_argument('--strain-limit', type=float)
    deck.add_argument('--rotation-limit', type=float)
    deck.add_argument('--gamma', type=float, default=1.0)
    chk = sub.add_parser('check')
    chk.add_argument('job')
    chk.add_argument('--gamma', type=float, default=1.0)
    chk.add_argument('--tolerance', type=float, default=0.01)
    chk.add_argument('--min-gamma', type=float, default=0.0,
                     help='check s11 and s22 only from this shear strain on')
    args = parser.parse_args()
    if args.command == 'deck':
        make_deck(args.path, args.strain_limit, args.rotation_limit, args.gamma)
    else:
        check(args.job, args.gamma, args.tolerance, args.min_gamma)


if __name__ == '__main__':
    main()
