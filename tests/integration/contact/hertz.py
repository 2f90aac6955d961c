"""Hertz line contact and Cattaneo-Mindlin partial slip: a cylinder pressed on a block in plane
strain (tests/data/contact/hertz_cylinder.geo, meshed by gmsh).

    hertz.py mesh JOB.msh --hc H            (runs gmsh on the .geo)
    hertz.py deck JOB.inp --mesh JOB.msh --hc H [--cattaneo]
    hertz.py check JOB --hc H [--cattaneo] [--tolerance T] [--stick-tolerance T]
                       [--stick-resolution] [--table-row FILE]

Model (plane strain: a slab one element thick, every node held in z): the lower part of a
cylinder, R = 20, on a block 30 x 15, both E = 1000, nu = 0.3 (identical materials: no
normal-tangential coupling, Dundurs beta = 0, as both closed forms assume). The contact zone
|x| <= 1.6 has uniform elements of size hc on both surfaces; elsewhere the mesh grows to 2.
Slave: the cylinder's arc (CAP_BOTTOM); master: the block's top (BLOCK_TOP). E_n = 10 E / hc:
the formula of the fcs3d default with the contact-zone element size (the default itself
averages h over the whole master surface, whose elements grow to 2 away from the contact).
The block's base is fixed; the cylinder's top (CAP_TOP) is moved rigidly: u_y = -0.08
(step 1), which gives a contact half-width a of about 1 = 10 hc at hc = 0.1; held in x.

Hertz (Johnson, Contact Mechanics, 1985, section 4.3): load per unit length P' = F / t (F the
y reaction of CAP_TOP, t the slab thickness), 1/E* = 2 (1 - nu^2) / E,
a = sqrt(4 P' R / (pi E*)), p0 = 2 P' / (pi a), p(x) = p0 sqrt(1 - x^2 / a^2).
Measured from the last frame of <job>.h5 (contact grid: slave positions, 'pressure'): the
peak nodal pressure p_max (the node at x = 0), and a and p0 from a least-squares fit of
p^2 = p0^2 - (p0/a)^2 x^2 to the closed nodes with |x| < 0.8 x_last (x_last the outermost
closed node; the outer nodes carry part of an element beyond the edge of the zone), and the
bracket [x_last, x_first_open] which must contain the theoretical a.

--cattaneo (Cattaneo 1938, Mindlin 1949; Johnson section 7.1): mu = 0.3, stick slope
E_t = E_n. Step 2 moves CAP_TOP by u_x (ramped to 0.035: Q/(mu P) up to 0.88, below gross
sliding; still held in y, so that the cylinder cannot rock), output at five points. Closed
form for the cylinder: the stick zone |x| <= c with c / a = sqrt(1 - Q / (mu P)), Q, P the
tangential and normal loads (from the CAP_TOP reactions). Measured: c from the 'status'
field (stick = 1, slip = 2) of the closed nodes, halfway between the outermost stick node
and the innermost slip node on each side (the resolution is half an element, reported),
compared with a_Hertz(P) sqrt(1 - Q / (mu P)): within --stick-tolerance (10 %), plus the
resolution with --stick-resolution (coarse meshes, where half an element is 10 % of a or
more). The slip nodes must lie on the cone (|q| = mu p to 1e-6).
"""
import argparse
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import contact_common as cc  # noqa: E402

YOUNG = 1000.0
POISSON = 0.3
RADIUS = 20.0
MU = 0.3
APPROACH = 0.08
PUSH = 0.035
PUSH_FRACTIONS = (0.2, 0.4, 0.6, 0.8, 1.0)
E_STAR = YOUNG / (2.0 * (1.0 - POISSON ** 2))
PAIR = 'CAP_BOTTOM-BLOCK_TOP'


def geo_path():
    data = os.environ.get('FCS3D_TEST_DATA',
                          os.path.join(os.path.dirname(__file__), '..', '..', 'data'))
    return os.path.join(data, 'contact', 'hertz_cylinder.geo')


def make_mesh(path, hc):
    result = subprocess.run(['gmsh', '-3', '-format', 'msh41', '-setnumber', 'hc', repr(hc),
                             geo_path(), '-o', path], capture_output=True, text=True)
    if result.returncode != 0 or not os.path.exists(path):
        cc.fail('gmsh failed (status %d):\n%s%s' % (result.returncode, result.stdout[-2000:],
                                                    result.stderr[-2000:]))


def make_deck(path, mesh, hc, cattaneo):
    kind = ', Cattaneo-Mindlin' if cattaneo else ''
    lines = ['*HEADING', 'Cylinder on a block, plane strain, hc = %g%s '
             '(tests/integration/contact/hertz.py)' % (hc, kind),
             '*MESH, FILE=%s' % os.path.basename(mesh),
             '*ELSET, ELSET=BODIES', 'CAP, BLOCK']
    lines += cc.material_cards('MAT', 'BODIES', YOUNG, POISSON)
    lines += cc.interaction_cards('INTERFACE', 10.0 * YOUNG / hc, MU if cattaneo else None)
    lines += ['*CONTACT PAIR, INTERACTION=INTERFACE, TYPE=NODE TO SURFACE', 'CAP_BOTTOM, BLOCK_TOP']
    lines += ['*TIME POINTS, NAME=PUSH'] + [', '.join('%.12g' % f for f in PUSH_FRACTIONS)]
    lines += ['*STEP', '*STATIC', '1., 1.', '*BOUNDARY', 'CAP, 3, 3', 'BLOCK, 3, 3',
              'BLOCK_BOTTOM, 1, 2', 'CAP_TOP, 1, 1', 'CAP_TOP, 2, 2, %.12g' % -APPROACH,
              '*NODE PRINT, NSET=CAP_TOP, TOTALS=ONLY', 'RF', '*CONTACT PRINT', 'CSTR',
              '*CONTACT FILE', 'CSTR', '*END STEP']
    if cattaneo:
        lines += ['*STEP', '*STATIC', '0.05, 1.', '*BOUNDARY', 'CAP_TOP, 1, 1, %.12g' % PUSH,
                  '*NODE PRINT, NSET=CAP_TOP, TOTALS=ONLY, TIME POINTS=PUSH', 'RF',
                  '*CONTACT PRINT, TIME POINTS=PUSH', 'CSTR',
                  '*CONTACT FILE, TIME POINTS=PUSH', 'CSTR', '*END STEP']
    cc.write_deck(path, lines)


def layer(frame):
    """The slave nodes of the z = 0 layer (the other layer is identical), sorted by x."""
    z0 = np.abs(frame['x'][:, 2]) < 1e-9
    order = np.argsort(frame['x'][z0, 0])
    return {key: frame[key][z0][order] for key in ('x', 'pressure', 'status', 'shear')}


def hertz_measure(frame, force_y, thickness):
    """Closed-form and measured a, p0 at one frame."""
    load = force_y / thickness
    a_theory = np.sqrt(4.0 * load * RADIUS / (np.pi * E_STAR))
    p0_theory = 2.0 * load / (np.pi * a_theory)
    nodes = layer(frame)
    x = nodes['x'][:, 0]
    p = nodes['pressure']
    closed = (nodes['status'] != cc.OPEN) & (p > 0)
    x_closed = x[closed]
    x_last = np.max(np.abs(x_closed))
    right_open = x[(~closed) & (x > 0)]
    left_open = x[(~closed) & (x < 0)]
    x_open = min(right_open.min() if len(right_open) else np.inf,
                 -left_open.max() if len(left_open) else np.inf)
    inner = closed & (np.abs(x) < 0.8 * x_last)
    slope, intercept = np.polyfit(x[inner] ** 2, p[inner] ** 2, 1)
    p0_fit = np.sqrt(intercept)
    a_fit = np.sqrt(-intercept / slope)
    return dict(load=load, a=a_theory, p0=p0_theory, p_max=p[closed].max(), p0_fit=p0_fit,
                a_fit=a_fit, x_last=x_last, x_open=x_open, n_closed=int(closed.sum()),
                x=x, p=p, status=nodes['status'], shear=nodes['shear'])


def stick_zone(nodes):
    """Stick-zone half-width c from the status of the closed nodes (sorted by x): the
    contiguous run of stick nodes around x = 0, bounded on each side halfway between its last
    stick node and the next (slip) node; returns c (the mean of both sides), the difference
    of the two sides, half the node spacing there (the resolution) and the number of stick
    nodes outside the zone. Isolated stick nodes
    in the slip zone (a slipping node whose pressure grew a little returns to stick until its
    friction catches up) are not part of the stick zone."""
    x, status = nodes['x'][:, 0], nodes['status']
    centre = int(np.argmin(np.abs(x)))
    if status[centre] != cc.STICK:
        return 0.0, 0.0, 0.0, int(np.sum(status == cc.STICK))
    hi = centre
    while hi + 1 < len(x) and status[hi + 1] == cc.STICK:
        hi += 1
    lo = centre
    while lo > 0 and status[lo - 1] == cc.STICK:
        lo -= 1
    right = 0.5 * (x[hi] + x[hi + 1])
    left = -0.5 * (x[lo] + x[lo - 1])
    spacing = 0.5 * max(x[hi + 1] - x[hi], x[lo] - x[lo - 1])
    outside = int(np.sum(status == cc.STICK)) - (hi - lo + 1)
    return 0.5 * (left + right), right - left, spacing, outside


def check(job, hc, cattaneo, tolerance, stick_tolerance, stick_resolution, table_row):
    checker = cc.Checker()
    blocks = cc.read_dat(job + '.dat')
    times, forces = cc.totals(blocks, 'CAP_TOP')
    frames = cc.contact_frames(job + '.h5', PAIR)
    thickness = hc
    end1 = [f for f in frames if f['step'] == 1][-1]
    f1 = forces[np.argmin(np.abs(times - 1.0))]
    m = hertz_measure(end1, -f1[1], thickness)
    print('Hertz (end of step 1): P\' = %.6g, a = %.5f, p0 = %.5f; %d closed nodes per layer'
          % (m['load'], m['a'], m['p0'], m['n_closed']))
    checker.relative('peak nodal pressure p_max vs p0', m['p_max'], m['p0'], tolerance)
    checker.relative('fitted p0', m['p0_fit'], m['p0'], tolerance)
    checker.relative('fitted half-width a', m['a_fit'], m['a'], tolerance)
    inside = m['x_last'] - 0.5 * hc <= m['a'] <= m['x_open'] + 0.5 * hc
    checker.check(inside, 'contact edge: outermost closed node %.4f, first open node %.4f, '
                  'theory a = %.4f within [x_last - hc/2, x_open + hc/2]'
                  % (m['x_last'], m['x_open'], m['a']))
    row = dict(hc=hc, a_over_h=m['a'] / hc, load=m['load'], a=m['a'], p0=m['p0'],
               p_max=m['p_max'], p0_fit=m['p0_fit'], a_fit=m['a_fit'], x_last=m['x_last'],
               x_open=m['x_open'])
    print('summary hertz hc %g: a/hc %.2f, p_max/p0 - 1 = %+.4f, p0_fit/p0 - 1 = %+.4f, '
          'a_fit/a - 1 = %+.4f, edge bracket [%.4f, %.4f] vs a %.4f'
          % (hc, m['a'] / hc, m['p_max'] / m['p0'] - 1, m['p0_fit'] / m['p0'] - 1,
             m['a_fit'] / m['a'] - 1, m['x_last'], m['x_open'], m['a']))
    if cattaneo:
        rows = []
        for fraction in PUSH_FRACTIONS:
            t = 1.0 + fraction
            frame = min(frames, key=lambda f: abs(f['time'] - t))
            force = forces[np.argmin(np.abs(times - t))]
            if abs(frame['time'] - t) > 1e-9:
                checker.check(False, 'no frame at time %g' % t)
                continue
            normal, tangential = -force[1], abs(force[0])
            ratio = tangential / (MU * normal)
            hm = hertz_measure(frame, normal, thickness)
            c, asymmetry, half_spacing, outside = stick_zone(layer(frame))
            c_theory = hm['a'] * np.sqrt(max(0.0, 1.0 - ratio))
            error = c / c_theory - 1.0
            bound = half_spacing / c_theory
            rows.append((fraction, ratio, hm['a'], c, c_theory, error, bound, asymmetry, outside))
            allowed = stick_tolerance + (bound if stick_resolution else 0.0)
            checker.check(abs(error) <= allowed, 'Q/(mu P) = %.4f: stick zone c = %.4f '
                          '(right - left %+.3f; %d stick nodes in the slip zone), closed form a '
                          'sqrt(1 - Q/(mu P)) = %.4f, error %+.2f %% (resolution +-%.1f %%, '
                          'tolerance %.1f %%)' % (ratio, c, asymmetry, outside, c_theory,
                                                  100 * error, 100 * bound, 100 * allowed))
            slipping = layer(frame)
            slip = slipping['status'] == cc.SLIP
            if slip.any():
                q = np.linalg.norm(slipping['shear'][slip], axis=1)
                p = slipping['pressure'][slip]
                checker.check(np.all(np.abs(q - MU * p) <= 1e-6 * MU * p.max()),
                              '  slip nodes on the cone: max |q - mu p| / (mu p_max) = %.1e'
                              % (np.abs(q - MU * p).max() / (MU * p.max())))
        print('summary cattaneo hc %g: ' % hc + '; '.join(
            'Q/muP %.3f c %.4f theory %.4f (%+.1f %% +- %.1f %%)'
            % (r[1], r[3], r[4], 100 * r[5], 100 * r[6]) for r in rows))
        row['cattaneo'] = rows
    if table_row:
        with open(table_row, 'w') as out:
            out.write(repr(row) + '\n')
    checker.finish()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    sub = parser.add_subparsers(dest='command', required=True)
    m = sub.add_parser('mesh')
    m.add_argument('path')
    m.add_argument('--hc', type=float, required=True)
    d = sub.add_parser('deck')
    d.add_argument('path')
    d.add_argument('--mesh', required=True)
    d.add_argument('--hc', type=float, required=True)
    d.add_argument('--cattaneo', action='store_true')
    c = sub.add_parser('check')
    c.add_argument('job')
    c.add_argument('--hc', type=float, required=True)
    c.add_argument('--cattaneo', action='store_true')
    c.add_argument('--tolerance', type=float, default=0.05)
    c.add_argument('--stick-tolerance', type=float, default=0.10)
    c.add_argument('--stick-resolution', action='store_true',
                   help='add the half node spacing to the stick-zone tolerance (coarse meshes)')
    c.add_argument('--table-row')
    args = parser.parse_args()
    if args.command == 'mesh':
        make_mesh(args.path, args.hc)
    elif args.command == 'deck':
        make_deck(args.path, args.mesh, args.hc, args.cattaneo)
    else:
        check(args.job, args.hc, args.cattaneo, args.tolerance, args.stick_tolerance,
              args.stick_resolution, args.table_row)


if __name__ == '__main__':
    main()
