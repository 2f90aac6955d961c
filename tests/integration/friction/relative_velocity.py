"""The literal reading of eq. (3) of Xing, Mora & Makinouchi (2003), *FRICTION, VELOCITY=RELATIVE:
the paper's law mu = 0.60 + (0.010 - 0.025) ln(V/0.001) evaluated at the total relative
tangential velocity (elastic stick part + slip), on a block sheared between two blocks.

Model (mm, s, MPa, N; granite E = 44800 MPa, nu = 0.12, G = 20000 MPa): a double-direct-shear
stack of three blocks, so that the push makes no couple and the contact pressure stays uniform:
  * base  [4, 20] x [2, 10] x [-8, 0], 4 x 2 x 2 hexahedra, bottom fixed;
  * slider [0, 24] x [0, 12] x [0, 8], 6 x 3 x 2 hexahedra (wider than the others, so that
    their nodes stay on its faces), its mid-plane nodes (z = 4, set MID) held in x and y in
    step 1, then moved in x at the load-point velocity v (step 2);
  * cover [4, 20] x [2, 10] x [8, 16], 4 x 2 x 2 hexahedra, pressed by p = 10 MPa on its top,
    whose nodes are held in x and y. Base and cover have the contact's footprint, so the
    mean contact pressure is p.
Two node-to-point pairs, BOTTOM (the base's top on the slider's bottom) and TOP (the cover's
bottom on the slider's top), slaves on the smaller blocks, E_n = 1e5 MPa/mm, the paper's law
with REGULARISATION=FLOOR below VC = 1e-9 mm/s and STICK SLOPE E_t = 10 MPa/mm.

Closed form of the onset. In stick the slider's relative tangential motion at each contact is
its load-point displacement less the shear of half the slider and of the base or cover:
compliances per unit area 1/E_t = 0.1 mm/MPa against 4/G + 8/G = 6e-4 mm/MPa, so the stick
spring takes 99.4 % of the motion (the Poisson expansion of base and cover under p adds
E_t nu p/E x 8 mm = 2e-3 MPa of shear at their edges, 0.04 % of the onset's) and the shear traction is tau = E_t v t to 0.6 %. Its
relative tangential velocity is therefore the elastic rate V_e = tau_dot / E_t = v (to 0.6 %)
and the literal law's static level is mu_s = mu_ss(v) = 0.60 - 0.015 ln(v / 0.001): sliding
starts at
    t_s = mu_ss(v) p / (E_t v)    (VELOCITY=RELATIVE)
and, read with the slip rate (0 in stick, mu held at the floor mu_ss(VC)),
    t_s = mu_ss(VC) p / (E_t v)   (VELOCITY=SLIP).
v = 0.01 mm/s: mu_ss = 0.5655, t_s = 56.55 s (relative) against mu_ss(1e-9) = 0.8072,
t_s = 80.72 s (slip); v = 0.001 mm/s: mu_ss = 0.60, t_s = 600 s (relative). The onset is the
first slipping node. Tolerance 2.5 %: the blocks are not rigid against the penalties (normal:
8/E against 1/E_n, 1.8 %; tangential 0.6 %), so the pressure and shear differ from node to node
by up to about 2 % and the first node slips that much early (measured: 0.8-1.6 %); the
increment lands on the crossing (R-minimum stick->slip). The two readings' onsets differ by
43 %.
After the onset the slider moves at v, and so does the relative tangential velocity (elastic +
slip) whatever the split: with VELOCITY=RELATIVE the contact's friction ratio |F_t| / F_n never
exceeds mu_ss(v) (+2.5 %), and at v = 0.01 mm/s (--steady) it slides at mu_ss(v) with no stress
drop. (At v = 0.001 mm/s it does not stay there: the slip of one node reloads its neighbours
through the slider's elasticity, and over increments cut to the floor by the R-minimum that
relative motion is a rate of several v, so the explicit cone drops and the contact stick-slips
with drops of about 0.06: the elastic part regularises the static level, not the events.)
With VELOCITY=SLIP the ratio peaks at mu_ss(VC) (-5 %, partial slip before the peak) and then
drops towards mu_ss(v) (by more than 0.1).

Usage: relative_velocity.py deck JOB.inp --velocity RELATIVE|SLIP --rate V --end T
       relative_velocity.py check JOB --velocity RELATIVE|SLIP --rate V [--steady]
"""
import argparse
import csv
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'nlgeom'))
import fcs_check  # noqa: E402

MU0, A, B, V0, VC = 0.60, 0.010, 0.025, 1.0e-3, 1.0e-9
PRESSURE = 10.0
STICK_SLOPE = 10.0
NORMAL_STIFFNESS = 100.0
YOUNG, POISSON = 44800.0, 0.12
ONSET_TOLERANCE = 0.025


def mu_ss(v):
    return MU0 + (A - B) * math.log(max(v, VC) / V0)


class Mesh:
    """Structured C3D8 blocks with global node and element numbering."""

    def __init__(self):
        self.nodes = {}
        self.elements = []   # (id, elset, 8 nodes)
        self.sets = {}

    def block(self, name, x, y, z, n, first_node, first_element):
        nx, ny, nz = n
        ids = {}
        for k in range(nz + 1):
            for j in range(ny + 1):
                for i in range(nx + 1):
                    node = first_node + i + (nx + 1) * (j + (ny + 1) * k)
                    ids[i, j, k] = node
                    self.nodes[node] = (x[0] + (x[1] - x[0]) * i / nx,
                                        y[0] + (y[1] - y[0]) * j / ny,
                                        z[0] + (z[1] - z[0]) * k / nz)
        element = first_element
        for k in range(nz):
            for j in range(ny):
                for i in range(nx):
                    corners = [ids[i, j, k], ids[i + 1, j, k], ids[i + 1, j + 1, k],
                               ids[i, j + 1, k], ids[i, j, k + 1], ids[i + 1, j, k + 1],
                               ids[i + 1, j + 1, k + 1], ids[i, j + 1, k + 1]]
                    layer = name + ('_BOTTOM_LAYER' if k == 0 else '') + \
                        ('_TOP_LAYER' if k == nz - 1 else '')
                    self.elements.append((element, name, layer, corners))
                    element += 1
        return ids


def write_deck(path, velocity, rate, end):
    mesh = Mesh()
    base = mesh.block('BASE', (4, 20), (2, 10), (-8, 0), (4, 2, 2), 1, 1)
    slider = mesh.block('SLIDER', (0, 24), (0, 12), (0, 8), (6, 3, 2), 1001, 101)
    cover = mesh.block('COVER', (4, 20), (2, 10), (8, 16), (4, 2, 2), 2001, 201)
    base_bottom = sorted(v for (i, j, k), v in base.items() if k == 0)
    mid = sorted(v for (i, j, k), v in slider.items() if k == 1)
    cover_top = sorted(v for (i, j, k), v in cover.items() if k == 2)
    out = ['*HEADING',
           'Double-direct shear of granite blocks, the paper\'s law read with VELOCITY=%s, '
           'v = %g mm/s (tests/integration/friction/relative_velocity.py)' % (velocity, rate),
           '*NODE, NSET=ALL_NODES']
    out += ['%d, %.10g, %.10g, %.10g' % ((n,) + mesh.nodes[n]) for n in sorted(mesh.nodes)]
    for block in ('BASE', 'SLIDER', 'COVER'):
        out.append('*ELEMENT, TYPE=C3D8, ELSET=%s' % block)
        out += ['%d, %s' % (e, ', '.join(map(str, c))) for e, b, _, c in mesh.elements
                if b == block]
    for layer in ('BASE_TOP_LAYER', 'SLIDER_BOTTOM_LAYER', 'SLIDER_TOP_LAYER',
                  'COVER_BOTTOM_LAYER', 'COVER_TOP_LAYER'):
        members = [e for e, _, name, _ in mesh.elements if layer in name]
        out.append('*ELSET, ELSET=%s' % layer)
        out += [', '.join(map(str, members[i:i + 8])) for i in range(0, len(members), 8)]
    for name, nodes in (('BASE_BOTTOM', base_bottom), ('MID', mid), ('COVER_TOP', cover_top)):
        out.append('*NSET, NSET=%s' % name)
        out += [', '.join(map(str, nodes[i:i + 8])) for i in range(0, len(nodes), 8)]
    out += ['*SURFACE, NAME=BASE_TOP', 'BASE_TOP_LAYER, S2',
            '*SURFACE, NAME=SLIDER_BOTTOM', 'SLIDER_BOTTOM_LAYER, S1',
            '*SURFACE, NAME=SLIDER_TOP', 'SLIDER_TOP_LAYER, S2',
            '*SURFACE, NAME=COVER_BOTTOM', 'COVER_BOTTOM_LAYER, S1',
            '*SURFACE, NAME=LOADED', 'COVER_TOP_LAYER, S2',
            '*MATERIAL, NAME=GRANITE', '*ELASTIC', '%g, %g' % (YOUNG, POISSON)]
    out += ['*SOLID SECTION, ELSET=%s, MATERIAL=GRANITE' % b for b in ('BASE', 'SLIDER', 'COVER')]
    out += ['*SURFACE INTERACTION, NAME=PAPER',
            '*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR', '%g' % NORMAL_STIFFNESS,
            '*FRICTION, LAW=RATE DEPENDENT, MU0=%g, A=%g, B=%g, V0=%g, VC=%g, '
            'REGULARISATION=FLOOR, STICK SLOPE=%g, VELOCITY=%s' % (MU0, A, B, V0, VC, STICK_SLOPE,
                                                                   velocity),
            '*CONTACT PAIR, INTERACTION=PAPER, NAME=BOTTOM', 'BASE_TOP, SLIDER_BOTTOM',
            '*CONTACT PAIR, INTERACTION=PAPER, NAME=TOP', 'COVER_BOTTOM, SLIDER_TOP',
            '*HISTORY, NAME=slider, FREQUENCY=1', 'CONTACT, BOTTOM', 'CONTACT, TOP',
            'NSET, MID, RF', 'NSET, MID, U',
            '*BOUNDARY', 'BASE_BOTTOM, 1, 3',
            '*STEP, NAME=PRESS', '*STATIC', '0.25, 1.',
            '*BOUNDARY', 'MID, 1, 2', 'COVER_TOP, 1, 2',
            '*DSLOAD', 'LOADED, P, %g' % PRESSURE, '*END STEP',
            '*STEP, NAME=SHEAR', '*STATIC', '%g, %g, , %g' % (end / 50.0, end, end / 20.0),
            '*BOUNDARY, FIXED', 'COVER_TOP, 3, 3',
            '*BOUNDARY, TYPE=VELOCITY', 'MID, 1, 1, %g' % rate, '*END STEP']
    with open(path, 'w') as f:
        f.write('\n'.join(out) + '\n')


def read_history(job):
    with open(job + '_slider.csv') as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def check(job, velocity, rate, steady):
    c = fcs_check.Checker()
    rows = read_history(job)
    start = 1.0   # end of step 1
    slip_rows = [r for r in rows if r['time'] > start + 1e-9 and r['BOTTOM_SLIP'] + r['TOP_SLIP'] > 0]
    if not slip_rows:
        fcs_check.fail('no slip by the end of the run')
    onset = slip_rows[0]['time'] - start
    level = mu_ss(rate) if velocity == 'RELATIVE' else mu_ss(VC)
    expected = level * PRESSURE / (STICK_SLOPE * rate)
    c.relative('onset of sliding, VELOCITY=%s, v = %g mm/s: t_s = mu_s p / (E_t v) with mu_s = %.4f'
               % (velocity, rate, level), onset, expected, ONSET_TOLERANCE)
    other = mu_ss(VC) if velocity == 'RELATIVE' else mu_ss(rate)
    c.check(abs(onset - other * PRESSURE / (STICK_SLOPE * rate)) > 5 * ONSET_TOLERANCE * expected,
            'the other reading\'s onset (mu_s = %.4f, t_s = %.2f s) is excluded' %
            (other, other * PRESSURE / (STICK_SLOPE * rate)))
    ratios = [math.hypot(math.hypot(r['BOTTOM_FT1'], r['BOTTOM_FT2']), r['BOTTOM_FT3']) /
              r['BOTTOM_FN'] for r in rows if r['time'] > start + 1e-9 and r['BOTTOM_FN'] > 0]
    peak, last = max(ratios), ratios[-1]
    if velocity == 'RELATIVE':
        c.check(peak <= mu_ss(rate) * (1 + ONSET_TOLERANCE),
                'VELOCITY=RELATIVE: |F_t| / F_n never exceeds mu_ss(v) = %.4f (peak %.4f): the '
                'stick part sets the static level, no floor' % (mu_ss(rate), peak))
        if steady:
            c.relative('VELOCITY=RELATIVE: sliding friction = mu_ss(v), no stress drop', last,
                       mu_ss(rate), 1.0e-3)
    else:
        c.check(mu_ss(VC) * (1 - 2 * ONSET_TOLERANCE) <= peak <= mu_ss(VC) * (1 + ONSET_TOLERANCE),
                'VELOCITY=SLIP: peak |F_t| / F_n %.4f at the floor level mu_ss(VC) = %.4f (-5 %%, '
                '+2.5 %%)' % (peak, mu_ss(VC)))
        c.check(peak - last > 0.1, 'VELOCITY=SLIP: friction drops after the onset (%.4f -> %.4f)'
                % (peak, last))
    c.finish()


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument('action', choices=('deck', 'check'))
    parser.add_argument('target')
    parser.add_argument('--velocity', choices=('RELATIVE', 'SLIP'), required=True)
    parser.add_argument('--rate', type=float, required=True)
    parser.add_argument('--end', type=float, default=100.0)
    parser.add_argument('--steady', action='store_true')
    args = parser.parse_args()
    if args.action == 'deck':
        write_deck(args.target, args.velocity, args.rate, args.end)
    else:
        check(args.target, args.velocity, args.rate, args.steady)


if __name__ == '__main__':
    main()
