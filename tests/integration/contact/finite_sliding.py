"""Finite sliding of a block over many master segments, and over a kink of the master surface.

    finite_sliding.py deck JOB.inp [--angle DEG] [--push U] [--max-increment F]
    finite_sliding.py check JOB [--angle DEG] [--push U] [--jump-bound B] [--csv F] [--png F]

Model (NLGEOM): a slider 1 x 1 x 0.5 (5 x 2 x 2 hexahedra, spacing 0.2 along x) on a long
base 6 x 1 x 1 (x in [-1, 5], 24 x 2 x 2 hexahedra, spacing 0.25 along x: the interfaces do
not match). The base's top is flat for x <= 2.5 and, with --angle THETA, rises at THETA
beyond x = 2.5 (the base is sheared so that its bottom stays flat): a kink between two planar
parts. E = 1000, nu = 0.3 both; mu = 0.3, E_n = E_t = 10 E / h (h = 0.5, the base's element
height). Step 1: pressure p = 10 on the slider's top, whose nodes (TOP) are held in x and y.
Step 2: TOP moved by u_x = U (default 3: the slider crosses 10 master segments on the flat
part, then the kink, and ends on the slope), held in y, free in z (the slider may tilt and
climb). Output: *NODE PRINT, NSET=BOTTOM, TOTALS=ONLY at every 1/150 of the push (U/150 =
0.02): the reactions of the base's fixed bottom, where no load is applied, give the push and
the load the slider passes on: T = -RF_x, N = RF_z of BOTTOM.

Closed forms (Coulomb, rigid slider; N0 = p A = 10 the pressure resultant): on the flat part
T = mu N0. Fully on a slope of angle THETA, pushed horizontally, under the follower pressure
normal to its (tilted) top: the push at TOP is mu N0 / (cos THETA - mu sin THETA), and the base
also takes the x component N0 sin THETA of the pressure load:
T = -RF_x(BOTTOM) = N0 (mu / (cos THETA - mu sin THETA) + sin THETA) (0.4160 N0 for 6 degrees,
against 0.3 N0 on the flat). (fcs3d's RF is the reaction: at TOP, loaded by the pressure, it
would not include the pressure load; at the unloaded BOTTOM it is the whole force passed on.)

Checks, on T = -RF_x of BOTTOM at consecutive outputs (jumps in units of mu N0):
  - flat part (the slider crosses 5 master segments): jumps <= B_flat (default 0.03; the
    slave nodes crossing master nodes of the indented base give steps of about 0.014) and
    T / N = mu within 2 % (N = RF_z of BOTTOM; measured within 1 %);
  - crossing the kink (the leading edge reaches it at u = 1.5, the trailing edge leaves the
    flat part at u = 2.5): while the slider bridges the kink it rests on its trailing part
    and on its leading row of slave nodes, which carries about a third of the load; T rises
    by a step when that row reaches the slope (u = 1.5) and again each time it passes a
    master node of the slope (every 0.25 of push on the fine base, 0.5 on the coarse one):
    the faceted, locally indented master surface of node-to-point contact. No jump may
    exceed B_kink (default 0.2, half of the change 0.39 across the kink; measured 0.13 fine,
    0.16 coarse), and T stays between the flat and the slope values within 2 % (no spike,
    no dip);
  - fully on the slope: T = N0 (mu / (cos - mu sin) + sin) within 2 % (the slider is
    deformable: its top does not stay exactly parallel to the slope).
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import contact_common as cc  # noqa: E402

YOUNG = 1000.0
POISSON = 0.3
MU = 0.3
PRESSURE = 10.0
KINK_X = 2.5
PENALTY = 10.0 * YOUNG / 0.5
N_OUTPUTS = 150


def rise(x, angle):
    return np.where(x > KINK_X, (x - KINK_X) * np.tan(np.radians(angle)), 0.0)


MESHES = {
    # name: (base elements along x, y, z), (slider elements along x, y, z)
    'fine': ((24, 2, 2), (5, 2, 2)),
    'coarse': ((12, 1, 2), (3, 1, 1)),
}


def make_deck(path, angle, push, max_increment, mesh):
    (bx, by, bz), (sx, sy, sz) = MESHES[mesh]

    def warp(x, y, z):
        return (x, y, z + (1.0 + z) * float(rise(x, angle)))
    base = cc.Box(np.linspace(-1.0, 5.0, bx + 1), np.linspace(0.0, 1.0, by + 1),
                  np.linspace(-1.0, 0.0, bz + 1), first_node=1, first_element=1, warp=warp)
    slider = cc.Box(np.linspace(0.0, 1.0, sx + 1), np.linspace(0.0, 1.0, sy + 1),
                    np.linspace(0.0, 0.5, sz + 1), first_node=100001, first_element=100001)
    lines = ['*HEADING', 'Finite sliding over a base with a %g degree kink '
             '(tests/integration/contact/finite_sliding.py)' % angle]
    lines += base.mesh_cards('BASE') + slider.mesh_cards('SLIDER')
    lines += cc.nset_cards('BOTTOM', base.face_nodes(2, 0))
    lines += cc.nset_cards('TOP', slider.face_nodes(2, 1))
    lines += cc.face_surface_cards('MASTER', base, 2, 1)
    lines += cc.face_surface_cards('SLAVE', slider, 2, 0)
    lines += cc.face_surface_cards('LOADED', slider, 2, 1)
    lines += ['*ELSET, ELSET=BODIES', 'BASE, SLIDER']
    lines += cc.material_cards('MAT', 'BODIES', YOUNG, POISSON)
    lines += cc.interaction_cards('ROUGH', PENALTY, MU)
    lines += ['*CONTACT PAIR, INTERACTION=ROUGH, TYPE=NODE TO SURFACE', 'SLAVE, MASTER']
    lines += ['*TIME POINTS, NAME=OUT, GENERATE', '0., 1., %.12g' % (1.0 / N_OUTPUTS)]
    lines += ['*STEP, NLGEOM', '*STATIC', '0.25, 1.', '*BOUNDARY', 'BOTTOM, 1, 3', 'TOP, 1, 2',
              '*DSLOAD', 'LOADED, P, %.12g' % PRESSURE, '*END STEP']
    lines += ['*STEP, NLGEOM', '*STATIC', '%.12g, 1., 1e-7, %.12g' % (max_increment, max_increment),
              '*BOUNDARY', 'TOP, 1, 1, %.12g' % push,
              '*NODE PRINT, NSET=BOTTOM, TOTALS=ONLY, TIME POINTS=OUT', 'RF', '*END STEP']
    cc.write_deck(path, lines)


def check(job, angle, push, jump_bound, kink_bound, csv, png):
    checker = cc.Checker()
    times, forces = cc.totals(cc.read_dat(job + '.dat'), 'BOTTOM')
    keep = times > 1.0 + 1e-9
    u = push * (times[keep] - 1.0)
    t, n = -forces[keep, 0], forces[keep, 2]
    checker.check(len(u) >= N_OUTPUTS - 1, '%d outputs of the push (expected %d)'
                  % (len(u), N_OUTPUTS))
    normal = PRESSURE
    jumps = np.abs(np.diff(t)) / (MU * normal)
    # The slider's leading edge (x = 1 + u) reaches the kink at u = 1.5; its trailing edge
    # leaves the flat part at u = 2.5.
    flat = (u >= 0.2) & (u <= min(1.5, push))
    on_slope = u >= 2.5 + 0.2
    crossing = (u > 1.5) & (u < 2.5 + 0.2)
    flat_jumps = jumps[flat[1:] & flat[:-1]]
    checker.check(flat_jumps.max() <= jump_bound, 'flat part (%d outputs, u %.2f .. %.2f): '
                  'largest jump of T between outputs %.4f mu N (bound %g)'
                  % (flat.sum(), u[flat][0], u[flat][-1], flat_jumps.max(), jump_bound))
    ratio = t[flat] / n[flat]
    errors = np.abs(ratio / MU - 1)
    checker.check(errors.max() <= 0.02, 'flat part: T/N = mu within 2 %%: max error %.4f '
                  '(T/N %.5f .. %.5f)' % (errors.max(), ratio.min(), ratio.max()))
    summary = 'summary angle %g: flat jumps max %.4f mean %.4f mu N, T/N %.5f..%.5f' % (
        angle, flat_jumps.max(), flat_jumps.mean(), ratio.min(), ratio.max())
    if angle > 0:
        theta = np.radians(angle)
        expected = normal * (MU / (np.cos(theta) - MU * np.sin(theta)) + np.sin(theta))
        cross_jumps = jumps[(crossing[1:] | crossing[:-1])]
        checker.check(cross_jumps.max() <= kink_bound, 'crossing the kink (%d outputs): '
                      'largest jump of T between outputs %.4f mu N (bound %g; the whole change '
                      'is %.3f)' % (crossing.sum(), cross_jumps.max(), kink_bound,
                                    (expected - MU * normal) / (MU * normal)))
        lo, hi = t[crossing].min(), t[crossing].max()
        checker.check(lo >= 0.98 * MU * normal and hi <= 1.02 * expected, 'crossing the kink: '
                      'T in [%.4f, %.4f], between the flat value %.4f and the slope value %.4f '
                      '(2 %%)' % (lo, hi, MU * normal, expected))
        slope_t = t[on_slope]
        error = np.abs(slope_t / expected - 1).max()
        checker.check(on_slope.sum() >= 5 and error <= 0.02, 'on the slope (%d outputs): T = '
                      '%.4f .. %.4f, closed form N0 (mu / (cos - mu sin) + sin) = %.4f, max '
                      'error %.4f (tolerance 0.02)' % (on_slope.sum(), slope_t.min(),
                                                       slope_t.max(), expected, error))
        summary += '; kink jumps max %.4f mu N; slope T %.4f..%.4f vs %.4f' % (
            cross_jumps.max(), slope_t.min(), slope_t.max(), expected)
    print(summary)
    if csv:
        cc.save_csv(csv, ['u', 'T', 'N'], [u, t, n])
    if png:
        plot(png, u, t, n, angle)
    checker.finish()


def plot(png, u, t, n, angle):
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    ax.plot(u, t / PRESSURE, '.-', markersize=3, label='-RF_x / (p A) of the base (the push)')
    ax.axhline(MU, color='k', linestyle='--', linewidth=0.8, label='mu')
    if angle > 0:
        theta = np.radians(angle)
        ax.axhline(MU / (np.cos(theta) - MU * np.sin(theta)) + np.sin(theta), color='r',
                   linestyle=':', linewidth=0.8,
                   label='mu / (cos - mu sin) + sin: on the %g deg slope' % angle)
        ax.axvspan(1.5, 2.5, color='0.9', label='slider crossing the kink')
    ax.set_xlabel('push u')
    ax.set_ylabel('T / (p A)')
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    sub = parser.add_subparsers(dest='command', required=True)
    d = sub.add_parser('deck')
    d.add_argument('path')
    d.add_argument('--angle', type=float, default=0.0)
    d.add_argument('--push', type=float, default=3.0)
    d.add_argument('--max-increment', type=float, default=0.002)
    d.add_argument('--mesh', choices=sorted(MESHES), default='fine')
    c = sub.add_parser('check')
    c.add_argument('job')
    c.add_argument('--angle', type=float, default=0.0)
    c.add_argument('--push', type=float, default=3.0)
    c.add_argument('--jump-bound', type=float, default=0.03)
    c.add_argument('--kink-bound', type=float, default=0.2)
    c.add_argument('--csv')
    c.add_argument('--png')
    args = parser.parse_args()
    if args.command == 'deck':
        make_deck(args.path, args.angle, args.push, args.max_increment, args.mesh)
    else:
        check(args.job, args.angle, args.push, args.jump_bound, args.kink_bound, args.csv,
              args.png)


if __name__ == '__main__':
    main()
