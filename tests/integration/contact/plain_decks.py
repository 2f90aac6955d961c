"""The contact step on plain decks: blocks of ordinary proportions, several elements,
non-matching meshes, default increments and penalties, against closed forms (issue 21).

    plain_decks.py deck CASE JOB.inp [--penalty E] [--max-increment F] [--law LAW]
    plain_decks.py check CASE JOB [--law LAW] [--tolerance T]
    plain_decks.py run CASE [CASE ...] [--penalty E] [--law LAW] [--tolerance T]
                                        (writes, runs and checks each, in the current directory)
    plain_decks.py tie [--tolerance T]  (the tie patch tests: see make_tie_deck)
    plain_decks.py rotation [--tolerance T]  (a cube under follower pressure turned rigidly:
                                              see make_rotation_deck)
    plain_decks.py turn [--tolerance T]      (the coulomb pair turned rigidly by 90 degrees:
                                              see make_turn_deck)

Units mm, N, MPa. E = 1000, nu = 0.3 for every body. The slider is pressed by p = 1 on its top
(N = p A = 1: the pressure resultant, A = 1) in step 1, its top nodes (TOP) held in x and y;
in step 2 TOP is moved in x (held in y, free in z). Quantities read from the history (every
increment: *HISTORY, CONTACT, PAIR and NSET, TOP, RF) and the log:
  T = RF_x of TOP (the reaction: the push), F_n and F_t the contact's total normal and
  tangential forces (F_t the magnitude of the vector sum), and the out-of-balance ratio the
  log prints for every increment (it must stay below the EQUILIBRIUM TOLERANCE, 1e-3).

Cases (default increments unless said; penalties default unless --penalty):
  frictionless  4x4x2 slider 1 x 1 x 0.25 on a 3x3x2 base 1.5 x 1.5 x 0.5 (non-matching), no
                *FRICTION, push 0.01: T = 0 and F_t = 0 (|T|, F_t <= tol N), F_n = N.
  coulomb       the same with Coulomb mu = 0.3, push 0.01 (gross slip from about 2e-3):
                T/N = mu within tol in gross slip (push >= half), nowhere above mu (1 + tol);
                F_n = N within tol at every increment.
  capped        coulomb with the increment capped at 0.05 of the step: the same checks.
  edge1, edge2, edge4
                the slider on a base of its own footprint (1 x 1 x 0.5 in 1x1x2, 2x2x2, 4x4x2
                elements), Coulomb mu = 0.3, pushed 0.2 off the base's edge: its leading
                nodes slide off the master surface and open; F_t/F_n = mu within tol and
                F_n = N within tol at every increment of gross slip, the slid-off nodes open
                at the end. (T: the base's top tilts under the eccentric load while contact
                is taken on the deformed geometry, so T/N = mu only to about 1 %: reported.)
  long          a 4x4x1 slider 1 x 1 x 0.25 pushed 2 along a base 5 x 1.5 x 0.5 (10x3x2),
                NLGEOM: crosses 4 master segments; T/(mu N) and F_n/N within 2 % at every
                increment of gross slip.
  kink          as long, the base's top rising at 5.6 degrees beyond x = 2, pushed 3 (the
                slider crosses the kink): on the flat part T = mu N, F_n = N; fully on the
                slope (the follower pressure normal to the tilted top) F_n = N / (1 - mu tan
                t), T = mu N / (cos t - mu sin t); crossing: F_t/F_n never above mu, and T and
                F_n within the bounds of rigid-block statics (see check; no spike).
  joint1        as long, the base made of two blocks that share no node, side by side at
                x = 2, one contact pair over both tops: the checks of long at every increment.
  joint2        the same with two pairs (one per block, the same slave surface).
  ratestate     the edge1 slider and base (one element each, the same footprint), Dieterich-
                Ruina friction (slip law, a = 0.015, b = 0.010, mu0 = 0.6 at V0 = 1e-3,
                DC = 1e-3), the top driven at 1e-3 for 40 s then at 1e-2 for 4 s: T/N = 0.6
                then 0.6 + (a - b) ln 10 = 0.61151 (steady state) within tol at the end of
                each step.
--law (coulomb, capped, long...): COULOMB (default), SLIP WEAKENING (mu 0.35 -> 0.3 over
DC = 1e-4), RATE STATE (ageing or slip law, a = 0.010, b = 0.015, DC = 1e-4, V0 = the push rate,
VC = 1e-4 V0, steady state at V0 initially): in gross slip (more than 25 DC) T/N = 0.3, the
steady state at the push rate, within tol; the static peak of these laws above 0.3 is reported.
"""
import argparse
import math
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import contact_common as cc  # noqa: E402

YOUNG = 1000.0
POISSON = 0.3
PRESSURE = 1.0
MU = 0.3
KINK_X = 2.0
KINK_DEG = 5.6
PAIR = 'PAIR'
HISTORY = 'H'
LAWS = ('COULOMB', 'SLIP WEAKENING', 'RATE STATE AGEING', 'RATE STATE SLIP')
EQUILIBRIUM_TOLERANCE = 1.0e-3
TIE_PENALTY = 1.0e5
SHEAR_STRAIN = 1.0e-3


def law_card(law, rate):
    """*FRICTION for one of LAWS; rate-state laws have mu_ss(rate) = MU (V0 = rate)."""
    if law == 'COULOMB':
        return ['*FRICTION', '%g' % MU]
    if law == 'SLIP WEAKENING':
        return ['*FRICTION, LAW=SLIP WEAKENING, MU0=%g, MUK=%g, DC=1e-4' % (MU + 0.05, MU)]
    state_law = law.split()[-1]
    return ['*FRICTION, LAW=RATE STATE, STATE LAW=%s, MU0=%g, A=0.010, B=0.015, DC=1e-4, '
            'V0=%g, VINIT=%g, VC=%g' % ('AGEING' if state_law == 'AGEING' else 'SLIP', MU, rate,
                                         rate, 1e-4 * rate)]


def rise(x, angle):
    return np.where(x > KINK_X, (x - KINK_X) * math.tan(math.radians(angle)), 0.0)


def bases(case):
    """The base block(s) of a case: list of cc.Box."""
    if case in ('frictionless', 'coulomb', 'capped'):
        grid = np.linspace(-0.25, 1.25, 4)
        return [cc.Box(grid, grid, np.linspace(-0.5, 0.0, 3))]
    if case.startswith('edge') or case == 'ratestate':
        n = 1 if case == 'ratestate' else int(case[4:])
        grid = np.linspace(0.0, 1.0, n + 1)
        return [cc.Box(grid, grid, np.linspace(-0.5, 0.0, 3))]
    ys, zs = np.linspace(-0.25, 1.25, 4), np.linspace(-0.5, 0.0, 3)
    if case in ('long', 'kink'):
        angle = KINK_DEG if case == 'kink' else 0.0

        def warp(x, y, z):
            return (x, y, z + (1.0 + z / 0.5) * float(rise(np.array(x), angle)))
        return [cc.Box(np.linspace(-0.5, 4.5, 11), ys, zs, warp=warp)]
    # joint1, joint2: two blocks meeting at x = KINK_X, not sharing nodes
    return [cc.Box(np.linspace(-0.5, KINK_X, 6), ys, zs, first_node=1, first_element=1),
            cc.Box(np.linspace(KINK_X, 4.5, 6), ys, zs, first_node=501, first_element=501)]


def slider(case):
    thin = case in ('long', 'kink', 'joint1', 'joint2')
    grid = np.linspace(0.0, 1.0, 2 if case == 'ratestate' else 5)
    zs = np.linspace(0.0, 0.25, 2 if (thin or case == 'ratestate') else 3)
    return cc.Box(grid, grid, zs, first_node=10001, first_element=10001)


def push_of(case):
    if case in ('frictionless', 'coulomb', 'capped'):
        return 0.01
    if case.startswith('edge'):
        return 0.2
    return 3.0 if case == 'kink' else 2.0


def make_deck(path, case, penalty=None, max_increment=None, law='COULOMB'):
    blocks = bases(case)
    top = slider(case)
    nlgeom = case in ('long', 'kink', 'joint1', 'joint2')
    lines = ['*HEADING', 'Plain contact deck "%s" (tests/integration/contact/plain_decks.py)' % case]
    for k, b in enumerate(blocks):
        lines += b.mesh_cards('BASE%d' % (k + 1))
    lines += top.mesh_cards('SLIDER')
    lines += cc.nset_cards('BOTTOM', sorted(n for b in blocks for n in b.face_nodes(2, 0)))
    lines += cc.nset_cards('TOP', top.face_nodes(2, 1))
    for k, b in enumerate(blocks):
        lines += cc.face_surface_cards('MASTER%d' % (k + 1), b, 2, 1)
    if len(blocks) == 2 and case == 'joint1':
        lines += ['*SURFACE, NAME=MASTER, TYPE=ELEMENT', 'MASTER1_EL, S2', 'MASTER2_EL, S2']
    elif len(blocks) == 1:
        lines += ['*SURFACE, NAME=MASTER, TYPE=ELEMENT', 'MASTER1_EL, S2']
    lines += cc.face_surface_cards('SLAVE', top, 2, 0)
    lines += cc.face_surface_cards('LOADED', top, 2, 1)
    lines += ['*ELSET, ELSET=BODIES'] + [', '.join(['BASE%d' % (k + 1) for k in range(len(blocks))]
                                                    + ['SLIDER'])]
    lines += cc.material_cards('MAT', 'BODIES', YOUNG, POISSON)
    lines += ['*SURFACE INTERACTION, NAME=SI']
    if penalty:
        lines += ['*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR', '%g' % penalty]
    if case == 'ratestate':
        lines += ['*FRICTION, LAW=RATE STATE, STATE LAW=SLIP, MU0=0.6, A=0.015, B=0.010, '
                  'DC=1e-3, V0=1e-3, VINIT=1e-3, VC=1e-12']
    elif case != 'frictionless':
        lines += law_card(law, push_of(case))
    items = ['CONTACT, %s' % PAIR, 'NSET, TOP, RF', 'RESIDUAL']
    if case == 'joint2':
        lines += ['*CONTACT PAIR, INTERACTION=SI, NAME=PAIR', 'SLAVE, MASTER1',
                  '*CONTACT PAIR, INTERACTION=SI, NAME=PAIR2', 'SLAVE, MASTER2']
        items.insert(1, 'CONTACT, PAIR2')
    else:
        lines += ['*CONTACT PAIR, INTERACTION=SI, NAME=%s' % PAIR, 'SLAVE, MASTER']
    lines += ['*HISTORY, NAME=%s, FREQUENCY=1' % HISTORY] + items
    step = '*STEP, NLGEOM' if nlgeom else '*STEP'
    lines += [step, '*STATIC', '0.25, 1.', '*BOUNDARY', 'BOTTOM, 1, 3', 'TOP, 1, 2',
              '*DSLOAD', 'LOADED, P, %g' % PRESSURE, '*END STEP']
    if case == 'ratestate':
        lines += [step, '*STATIC', '0.5, 20.', '*BOUNDARY, TYPE=VELOCITY', 'TOP, 1, 1, 1e-3',
                  '*END STEP', step, '*STATIC', '0.05, 2.', '*BOUNDARY, TYPE=VELOCITY',
                  'TOP, 1, 1, 1e-2', '*END STEP']
    else:
        static = '*STATIC' if max_increment is None else \
            '*STATIC\n%g, 1., 1e-5, %g' % (min(max_increment, 0.01), max_increment)
        lines += [step] + static.split('\n') + ['*BOUNDARY', 'TOP, 1, 1, %g' % push_of(case),
                                                '*END STEP']
    cc.write_deck(path, lines)


class Run:
    """What one run printed: the history columns and the log's increment lines."""

    def __init__(self, job, top='TOP'):
        data = np.genfromtxt('%s_%s.csv' % (job, HISTORY.lower()), delimiter=',', names=True)
        self.time = data['time']
        names = data.dtype.names
        pairs = sorted({n.split('_FN')[0] for n in names if n.endswith('_FN')})
        self.fn = sum(data[p + '_FN'] for p in pairs)
        ft = sum(np.column_stack([data[p + '_FT%d' % i] for i in (1, 2, 3)]) for p in pairs)
        self.ft = np.linalg.norm(ft, axis=1)
        self.open = sum(data[p + '_OPEN'] for p in pairs)
        self.rf = np.column_stack([data['%s_RF%d' % (top, i)] for i in (1, 2, 3)])
        self.t = self.rf[:, 0]
        self.rf_z = self.rf[:, 2]
        self.history_residual = data['RESIDUAL']
        self.residuals = []
        with open(job + '.log') as log:
            for line in log:
                m = re.match(r'^inc \d+ .* residual (\S+)$', line.rstrip())
                if m:
                    self.residuals.append(float(m.group(1)))


def check(case, job, tolerance, law='COULOMB'):
    checker = cc.Checker()
    run = Run(job)
    n = PRESSURE
    worst = max(run.residuals) if run.residuals else 0.0
    checker.check(worst <= EQUILIBRIUM_TOLERANCE, 'out-of-balance ratio <= %g at every increment '
                  '(%d increments, largest %.3g)' % (EQUILIBRIUM_TOLERANCE, len(run.residuals), worst))
    checker.check(abs(run.history_residual.max() - worst) <= 1e-6 * max(worst, 1e-30),
                  'the history\'s RESIDUAL column has the log\'s largest ratio (%.6g)'
                  % run.history_residual.max())
    push = push_of(case)
    step2 = (run.time > 1.0 + 1e-9) & (run.time <= 2.0 + 1e-9)
    u = push * (run.time - 1.0)
    if case == 'frictionless':
        checker.check(np.abs(run.t[step2]).max() <= tolerance * n and run.ft[step2].max() <= tolerance * n,
                      'frictionless: |T| max %.3g, F_t max %.3g (<= %g N)'
                      % (np.abs(run.t[step2]).max(), run.ft[step2].max(), tolerance))
        checker.relative('F_n = N at the end', run.fn[-1], n, tolerance)
    elif case in ('coulomb', 'capped'):
        gross = step2 & (u >= 0.5 * push)
        ratio = run.t / n
        checker.check(np.abs(ratio[gross] / MU - 1).max() <= tolerance, 'gross slip (%d increments): '
                      'T/N = %.5f .. %.5f, mu = %g (tolerance %g)'
                      % (gross.sum(), ratio[gross].min(), ratio[gross].max(), MU, tolerance))
        if law == 'COULOMB':
            checker.check(ratio[step2].max() <= MU * (1 + tolerance), 'T/N never above mu (1 + %g): '
                          'max %.5f' % (tolerance, ratio[step2].max()))
        else:
            print('     peak T/N %.5f (the static peak of the law)' % ratio[step2].max())
        errors = np.abs(run.fn[run.time > 0.5] / n - 1)
        checker.check(errors.max() <= tolerance, 'F_n = N within %g at every increment from the '
                      'half of step 1 (max error %.3g)' % (tolerance, errors.max()))
    elif case.startswith('edge'):
        gross = step2 & (u >= 0.1 * push)
        ratio = run.ft[gross] / run.fn[gross]
        checker.check(np.abs(ratio / MU - 1).max() <= tolerance, 'gross slip (%d increments): '
                      'F_t/F_n = %.5f .. %.5f (tolerance %g)' % (gross.sum(), ratio.min(), ratio.max(),
                                                                 tolerance))
        errors = np.abs(run.fn[gross] / n - 1)
        checker.check(errors.max() <= tolerance, 'F_n = N within %g (max error %.3g)'
                      % (tolerance, errors.max()))
        checker.check(run.open[-1] > 0, '%d slave nodes open at the end (slid off the base)'
                      % run.open[-1])
        print('     T/N in gross slip %.5f .. %.5f (the base top tilts: see the docstring)'
              % ((run.t[gross] / n).min(), (run.t[gross] / n).max()))
    elif case in ('long', 'joint1', 'joint2'):
        gross = step2 & (u >= 0.05)
        mu = MU
        t_err = np.abs(run.t[gross] / (mu * n) - 1)
        f_err = np.abs(run.fn[gross] / n - 1)
        checker.check(t_err.max() <= tolerance, 'T/(mu N) within %g at every increment of gross slip '
                      '(%d, max error %.3g)' % (tolerance, gross.sum(), t_err.max()))
        checker.check(f_err.max() <= tolerance, 'F_n = N within %g at every increment (max error %.3g)'
                      % (tolerance, f_err.max()))
    elif case == 'kink':
        theta = math.radians(KINK_DEG)
        t_slope = MU * n / (math.cos(theta) - MU * math.sin(theta))
        f_slope = n / (1.0 - MU * math.tan(theta))
        # leading edge at x = 1 + u reaches the kink at u = 1; trailing edge leaves it at u = 2
        flat = step2 & (u >= 0.05) & (u <= KINK_X - 1.0)
        slope = step2 & (u >= KINK_X + 0.05)
        crossing = step2 & (u > KINK_X - 1.0) & (u < KINK_X + 0.05)
        checker.check(np.abs(run.t[flat] / (MU * n) - 1).max() <= tolerance and
                      np.abs(run.fn[flat] / n - 1).max() <= tolerance,
                      'flat part (%d increments): T/(mu N) %.4f .. %.4f, F_n/N %.4f .. %.4f'
                      % (flat.sum(), (run.t[flat] / (MU * n)).min(), (run.t[flat] / (MU * n)).max(),
                         (run.fn[flat] / n).min(), (run.fn[flat] / n).max()))
        if slope.any():
            checker.check(np.abs(run.t[slope] / t_slope - 1).max() <= tolerance and
                          np.abs(run.fn[slope] / f_slope - 1).max() <= tolerance,
                          'on the slope (%d increments): T %.4f .. %.4f vs %.4f, F_n %.4f .. %.4f '
                          'vs %.4f' % (slope.sum(), run.t[slope].min(), run.t[slope].max(), t_slope,
                                       run.fn[slope].min(), run.fn[slope].max(), f_slope))
        # While the slider bridges the kink it rests on its trailing part (flat) and its
        # leading row (slope) and tilts by phi in [0, t]; the statics of a rigid block with
        # both contacts sliding bound the push and the total normal force whatever the split
        # of the load: T between N (mu cos t - sin t) (all load on the flat, tilted by t: the
        # follower pressure helps) and N (sin t + mu cos t) / (cos t - mu sin t) (all on the
        # slope, untilted); F_n between N cos t and N / (cos t - mu sin t).
        ratio = run.ft[crossing] / run.fn[crossing]
        checker.check(ratio.max() <= MU * (1 + tolerance), 'crossing (%d increments): F_t/F_n '
                      '%.4f .. %.4f, never above mu (1 + %g)' % (crossing.sum(), ratio.min(),
                                                                ratio.max(), tolerance))
        t_lo = n * (MU * math.cos(theta) - math.sin(theta))
        t_hi = n * (math.sin(theta) + MU * math.cos(theta)) / (math.cos(theta) - MU * math.sin(theta))
        f_lo, f_hi = n * math.cos(theta), n / (math.cos(theta) - MU * math.sin(theta))
        checker.check(run.t[crossing].min() >= t_lo * (1 - tolerance) and
                      run.t[crossing].max() <= t_hi * (1 + tolerance),
                      'crossing: T in [%.4f, %.4f], within the rigid-block bounds [%.4f, %.4f]'
                      % (run.t[crossing].min(), run.t[crossing].max(), t_lo, t_hi))
        checker.check(run.fn[crossing].min() >= f_lo * (1 - tolerance) and
                      run.fn[crossing].max() <= f_hi * (1 + tolerance),
                      'crossing: F_n in [%.4f, %.4f], within the rigid-block bounds [%.4f, %.4f]'
                      % (run.fn[crossing].min(), run.fn[crossing].max(), f_lo, f_hi))
    elif case == 'ratestate':
        for end, expected in ((21.0, 0.6), (23.0, 0.6 + 0.005 * math.log(10.0))):
            k = np.argmin(np.abs(run.time - end))
            checker.relative('T/N at time %g' % run.time[k], run.t[k] / n, expected, tolerance)
    checker.finish()


def make_tie_deck(path, load):
    """Two blocks 1 x 1 x 0.5 stacked (lower 3x3x2, upper 4x4x2 hexahedra: the interface meshes
    do not match), the upper one's bottom tied to the lower one's top (*TIE, default penalty).
    load 'normal': pressure -1 (tension) on the top, rollers on x = 0, y = 0, z = 0: uniaxial
    stress s_zz = 1 across the tie; 'inplane': pressure -1 on the faces x = 1 of both blocks,
    the same rollers: s_xx = 1 along the tie; 'shear': every exterior node moved by
    u = (0.001 z, 0, 0), plus the uniform offset t / k the tie needs to carry the shear
    traction t (a tied pair with penalty k = TIE_PENALTY) on the upper block: uniform shear
    stress across the tie."""
    lower = cc.Box(np.linspace(0, 1, 4), np.linspace(0, 1, 4), np.linspace(0, 0.5, 3))
    upper = cc.Box(np.linspace(0, 1, 5), np.linspace(0, 1, 5), np.linspace(0.5, 1.0, 3),
                   first_node=1001, first_element=1001)
    lines = ['*HEADING', 'Tie patch test, %s load (tests/integration/contact/plain_decks.py)' % load]
    lines += lower.mesh_cards('LOWER') + upper.mesh_cards('UPPER')
    lines += ['*ELSET, ELSET=BODIES', 'LOWER, UPPER']
    lines += cc.material_cards('MAT', 'BODIES', YOUNG, POISSON)
    lines += cc.face_surface_cards('LOWERTOP', lower, 2, 1)
    lines += cc.face_surface_cards('UPPERBOTTOM', upper, 2, 0)
    boxes = (lower, upper)
    if load == 'shear':
        # A tied pair with a given penalty k: the tie carries the shear traction t by a
        # uniform relative displacement t / k, which the upper block's prescribed boundary
        # takes on top of the linear field.
        lines += ['*SURFACE INTERACTION, NAME=GLUE', '*SURFACE BEHAVIOR, '
                  'PRESSURE-OVERCLOSURE=TIED', '%g' % TIE_PENALTY,
                  '*CONTACT PAIR, INTERACTION=GLUE, NAME=GLUE', 'UPPERBOTTOM, LOWERTOP']
        shear = YOUNG / (2 * (1 + POISSON)) * SHEAR_STRAIN
        outer = sorted({n for b in boxes for axis in range(2) for side in (0, 1)
                        for n in b.face_nodes(axis, side)} |
                       set(lower.face_nodes(2, 0)) | set(upper.face_nodes(2, 1)))
        bcs = []
        for n in outer:
            b = lower if n < 1001 else upper
            x = b.coordinates(n)
            offset = shear / TIE_PENALTY if n >= 1001 else 0.0
            bcs += ['%d, 1, 1, %.12g' % (n, SHEAR_STRAIN * x[2] + offset), '%d, 2, 3, 0.' % n]
        lines += ['*STEP', '*STATIC', '*BOUNDARY'] + bcs
    else:
        lines += ['*TIE, NAME=GLUE', 'UPPERBOTTOM, LOWERTOP']
    if load != 'shear':
        lines += cc.nset_cards('X0', sorted(n for b in boxes for n in b.face_nodes(0, 0)))
        lines += cc.nset_cards('Y0', sorted(n for b in boxes for n in b.face_nodes(1, 0)))
        lines += cc.nset_cards('Z0', lower.face_nodes(2, 0))
        lines += ['*BOUNDARY', 'X0, 1, 1', 'Y0, 2, 2', 'Z0, 3, 3']
        if load == 'normal':
            lines += cc.face_surface_cards('PULLED', upper, 2, 1)
        else:
            lines += cc.face_surface_cards('PULLEDA', lower, 0, 1)
            lines += cc.face_surface_cards('PULLEDB', upper, 0, 1)
            lines += ['*SURFACE, NAME=PULLED, TYPE=ELEMENT', 'PULLEDA_EL, S4', 'PULLEDB_EL, S4']
        lines += ['*STEP', '*STATIC', '*DSLOAD', 'PULLED, P, -1.']
    lines += ['*EL PRINT, ELSET=BODIES', 'S', '*END STEP']
    cc.write_deck(path, lines)


def make_rotation_deck(path):
    """A cube 1 x 1 x 1 (2x2x2 hexahedra, E = 1000, nu = 0.3) under a follower pressure p = 1
    on all six faces, on statically determinate supports (corner 1 fixed, corner (1, 0, 0) held
    in y and z, corner (0, 1, 0) in z), NLGEOM. Step 1 raises the pressure; the cube shrinks to
    s = exp(-p (1 - 2 nu) / E) (hypoelastic, logarithmic strain). Step 2 turns it rigidly by 90
    degrees about z: corner (1, 0, 0) moves on the circle of radius s, its x and y displacements
    following s cos(theta) - 1 and s sin(theta) through tabular amplitudes (points every half
    degree: the increments end on them, on the circle, where the Hughes-Winget update of a
    rigid increment is exact). Expected: sigma = -p I throughout and zero reactions (the
    pressure on a closed surface is self-equilibrated)."""
    cube = cc.Box(np.linspace(0, 1, 3), np.linspace(0, 1, 3), np.linspace(0, 1, 3))
    s = math.exp(-PRESSURE * (1 - 2 * POISSON) / YOUNG)
    lines = ['*HEADING', 'Rigid rotation of a cube under a follower pressure '
             '(tests/integration/contact/plain_decks.py)']
    lines += cube.mesh_cards('CUBE') + cc.material_cards('MAT', 'CUBE', YOUNG, POISSON)
    faces = []
    for axis in range(3):
        for side in (0, 1):
            name = 'F%d%d' % (axis, side)
            lines += cc.face_surface_cards(name, cube, axis, side)
            faces.append(name)
    corner = {key: cube.ids[key] for key in [(0, 0, 0), (2, 0, 0), (0, 2, 0)]}
    turn_x, turn_y = [], []
    for k in range(181):
        t = k / 180.0
        turn_x.append('%.15g, %.15g' % (t, s * math.cos(math.radians(90.0 * t)) - 1.0))
        turn_y.append('%.15g, %.15g' % (t, s * math.sin(math.radians(90.0 * t))))
    lines += ['*AMPLITUDE, NAME=TURNX'] + turn_x + ['*AMPLITUDE, NAME=TURNY'] + turn_y
    lines += cc.nset_cards('SUPPORTS', sorted(corner.values()))
    lines += ['*BOUNDARY', '%d, 1, 3' % corner[(0, 0, 0)], '%d, 2, 3' % corner[(2, 0, 0)],
              '%d, 3, 3' % corner[(0, 2, 0)]]
    lines += ['*STEP, NLGEOM', '*STATIC', '*DSLOAD'] + ['%s, P, %g' % (f, PRESSURE) for f in faces]
    lines += ['*END STEP', '*STEP, NLGEOM', '*STATIC', '*BOUNDARY, AMPLITUDE=TURNX',
              '%d, 1, 1, 1.' % corner[(2, 0, 0)], '*BOUNDARY, AMPLITUDE=TURNY',
              '%d, 2, 2, 1.' % corner[(2, 0, 0)],
              '*NODE PRINT, NSET=SUPPORTS', 'RF', '*EL PRINT, ELSET=CUBE', 'S', '*END STEP']
    cc.write_deck(path, lines)


def check_rotation(job, tolerance):
    """sigma = -p I at every integration point and zero reactions, within tolerance of p (and of
    the pressure load of a face, p)."""
    checker = cc.Checker()
    blocks = cc.read_dat(job + '.dat')
    stress = np.array([v for k, v in [b for b in blocks if b['title'].startswith('stresses')][-1]['rows']])
    expected = np.array([-PRESSURE] * 3 + [0.0] * 3)
    error = np.abs(stress - expected).max() / PRESSURE
    checker.check(error <= tolerance, 'after the 90-degree turn: sigma = -p I within %.2e of p at '
                  'every integration point (tolerance %g)' % (error, tolerance))
    rows = {k[0]: v for k, v in [b for b in blocks if b['title'].startswith('forces')][-1]['rows']}
    # The supported degrees of freedom (RF at a free one is the pressure load applied there).
    supported = [(1, [0, 1, 2]), (3, [0, 1, 2]), (7, [2])]
    reaction = max(np.abs(rows[node][dofs]).max() for node, dofs in supported) / PRESSURE
    checker.check(reaction <= tolerance, 'reactions at the supports: largest %.2e of a face load p '
                  '(tolerance %g)' % (reaction, tolerance))
    checker.finish()


def make_turn_deck(path):
    """The frictional pair of the coulomb case (4x4x2 slider 1 x 1 x 0.25 pressed by p = 1 on a
    3x3x2 base 1.5 x 1.5 x 0.5, non-matching, Coulomb mu = 0.3, default penalties), NLGEOM, the
    slider held in its plane by friction alone (no support). Step 1 raises the pressure (the
    base's bottom BOTTOM fixed); step 2 turns the whole pair rigidly by 90 degrees about the
    x-axis through the line y = 0, z = -0.5 of the bottom: the bottom nodes follow
    u_y = y (cos(theta) - 1), u_z = y sin(theta) through tabular amplitudes (points every half
    degree). Expected: the contact normal force F_n = N and the tangential force vector sum
    F_t = 0 at every increment (the follower pressure turns with the pair), the reaction of
    BOTTOM turned with the pair (R of step 1's), and no state change."""
    blocks = bases('coulomb')
    top = slider('coulomb')
    base = blocks[0]
    lines = ['*HEADING', 'A frictional pair turned rigidly by 90 degrees '
             '(tests/integration/contact/plain_decks.py)']
    lines += base.mesh_cards('BASE1') + top.mesh_cards('SLIDER')
    bottom = sorted(base.face_nodes(2, 0))
    lines += cc.nset_cards('BOTTOM', bottom)
    lines += cc.face_surface_cards('MASTER1', base, 2, 1)
    lines += ['*SURFACE, NAME=MASTER, TYPE=ELEMENT', 'MASTER1_EL, S2']
    lines += cc.face_surface_cards('SLAVE', top, 2, 0)
    lines += cc.face_surface_cards('LOADED', top, 2, 1)
    lines += ['*ELSET, ELSET=BODIES', 'BASE1, SLIDER']
    lines += cc.material_cards('MAT', 'BODIES', YOUNG, POISSON)
    lines += ['*SURFACE INTERACTION, NAME=SI'] + law_card('COULOMB', 1.0)
    lines += ['*CONTACT PAIR, INTERACTION=SI, NAME=%s' % PAIR, 'SLAVE, MASTER']
    lines += ['*HISTORY, NAME=%s, FREQUENCY=1' % HISTORY, 'CONTACT, %s' % PAIR,
              'NSET, BOTTOM, RF', 'RESIDUAL']
    cosm1, sine = [], []
    for k in range(181):
        t = k / 180.0
        cosm1.append('%.15g, %.15g' % (t, math.cos(math.radians(90.0 * t)) - 1.0))
        sine.append('%.15g, %.15g' % (t, math.sin(math.radians(90.0 * t))))
    lines += ['*AMPLITUDE, NAME=COSM1'] + cosm1 + ['*AMPLITUDE, NAME=SINE'] + sine
    lines += ['*STEP, NLGEOM', '*STATIC', '0.25, 1.', '*BOUNDARY', 'BOTTOM, 1, 3',
              '*DSLOAD', 'LOADED, P, %g' % PRESSURE, '*END STEP']
    ys = {n: base.x[n - base.first_node][1] for n in bottom}
    lines += ['*STEP, NLGEOM', '*STATIC', '*BOUNDARY', 'BOTTOM, 1, 1', '*BOUNDARY, AMPLITUDE=COSM1']
    lines += ['%d, 2, 2, %.15g' % (n, ys[n]) for n in bottom]
    lines += ['*BOUNDARY, AMPLITUDE=SINE'] + ['%d, 3, 3, %.15g' % (n, ys[n]) for n in bottom]
    lines += ['*END STEP']
    cc.write_deck(path, lines)


def check_turn(job, tolerance):
    """F_n = N, F_t = 0 and the bottom's reaction turned with the pair, within tolerance of N,
    at every increment; the out-of-balance below the equilibrium tolerance; no state change."""
    checker = cc.Checker()
    run = Run(job, top='BOTTOM')
    n = PRESSURE
    worst = max(run.residuals)
    checker.check(worst <= EQUILIBRIUM_TOLERANCE, 'out-of-balance ratio <= %g at every increment '
                  '(%d increments, largest %.3g)' % (EQUILIBRIUM_TOLERANCE, len(run.residuals), worst))
    step2 = run.time > 1.0 + 1e-9
    theta = np.radians(90.0 * (run.time[step2] - 1.0))
    errors = np.abs(run.fn[step2] / n - 1)
    checker.check(errors.max() <= tolerance, 'turning (%d increments): F_n = N within %g '
                  '(max error %.3g)' % (step2.sum(), tolerance, errors.max()))
    checker.check(run.ft[step2].max() <= tolerance * n, 'turning: F_t = %.3g N at most (<= %g N)'
                  % (run.ft[step2].max(), tolerance * n))
    first = np.array([run.rf[~step2][-1]])[0]
    turned = np.column_stack([np.full_like(theta, first[0]),
                              first[1] * np.cos(theta) - first[2] * np.sin(theta),
                              first[1] * np.sin(theta) + first[2] * np.cos(theta)])
    rf_error = np.linalg.norm(run.rf[step2] - turned, axis=1).max() / n
    checker.check(rf_error <= tolerance, 'turning: reaction of BOTTOM = R (its step-1 value %s) '
                  'within %.3g N (<= %g N)' % (np.array2string(first, precision=4), rf_error,
                                              tolerance * n))
    with open(job + '.log') as log:
        limits = [line.split(' limit ')[1].split()[0] for line in log
                  if line.startswith('inc ') and ' step 2 ' in line]
    changes = [x for x in limits if '->' in x or x in ('open', 'close')]
    checker.check(not changes, 'turning: no contact state change (%d increments limited by: %s)'
                  % (len(limits), ', '.join(sorted(set(limits)))))
    checker.finish()


def check_tie(job, load, tolerance):
    """Every integration point's stress equals the uniform closed form within tolerance of
    its largest component."""
    checker = cc.Checker()
    blocks = [b for b in cc.read_dat(job + '.dat') if b['title'].startswith('stresses')]
    stress = np.array([values for keys, values in blocks[-1]['rows']])
    if load == 'shear':
        g = YOUNG / (2 * (1 + POISSON))
        expected = np.array([0, 0, 0, 0, g * SHEAR_STRAIN, 0])
    else:
        expected = np.zeros(6)
        expected[2 if load == 'normal' else 0] = 1.0
    error = np.abs(stress - expected).max() / np.abs(expected).max()
    checker.check(error <= tolerance, 'tie patch test (%s, %d integration points): largest '
                  'deviation from the uniform stress %.2e of it (tolerance %g)'
                  % (load, len(stress), error, tolerance))
    checker.finish()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    sub = parser.add_subparsers(dest='command', required=True)
    d = sub.add_parser('deck')
    d.add_argument('case')
    d.add_argument('path')
    c = sub.add_parser('check')
    c.add_argument('case')
    c.add_argument('job')
    r = sub.add_parser('run')
    r.add_argument('cases', nargs='+')
    for p in (d, r):
        p.add_argument('--penalty', type=float)
        p.add_argument('--max-increment', type=float)
    for p in (d, c, r):
        p.add_argument('--law', default='COULOMB', choices=LAWS)
    rot = sub.add_parser('rotation')
    turn = sub.add_parser('turn')
    t = sub.add_parser('tie')
    ct = sub.add_parser('check-tie')
    ct.add_argument('load')
    ct.add_argument('job')
    for p in (c, r, t, ct, rot, turn):
        p.add_argument('--tolerance', type=float, default=5e-3)
    args = parser.parse_args()
    if args.command == 'deck':
        make_deck(args.path, args.case, args.penalty, args.max_increment, args.law)
    elif args.command == 'check':
        check(args.case, args.job, args.tolerance, args.law)
    elif args.command == 'tie':
        failed = 0
        for load in ('normal', 'inplane', 'shear'):
            job = 'tie_' + load
            make_tie_deck(job + '.inp', load)
            print('== %s' % job)
            code = os.system('"%s" -q %s.inp' % (os.environ.get('FCS3D', 'fcs3d'), job))
            if code != 0:
                print('FAIL fcs3d failed on %s.inp' % job)
                failed += 1
                continue
            code = os.system('"%s" "%s" check-tie %s %s --tolerance %g'
                             % (sys.executable, os.path.abspath(__file__), load, job, args.tolerance))
            failed += code != 0
        sys.exit(1 if failed else 0)
    elif args.command == 'check-tie':
        check_tie(args.job, args.load, args.tolerance)
    elif args.command in ('rotation', 'turn'):
        make, check_job = {'rotation': (make_rotation_deck, check_rotation),
                           'turn': (make_turn_deck, check_turn)}[args.command]
        job = args.command
        make(job + '.inp')
        print('== ' + job)
        if os.system('"%s" -q %s.inp' % (os.environ.get('FCS3D', 'fcs3d'), job)) != 0:
            print('FAIL fcs3d failed on %s.inp' % job)
            sys.exit(1)
        check_job(job, args.tolerance)
    else:
        failed = 0
        for case in args.cases:
            job = case if args.penalty is None else '%s_%g' % (case, args.penalty)
            if args.law != 'COULOMB':
                job += '_' + args.law.lower().replace(' ', '_')
            max_increment = args.max_increment if case != 'capped' else 0.05
            make_deck(job + '.inp', case, args.penalty, max_increment, args.law)
            print('== %s' % job)
            code = os.system('"%s" -q %s.inp' % (os.environ.get('FCS3D', 'fcs3d'), job))
            if code != 0:
                print('FAIL fcs3d failed on %s.inp' % job)
                failed += 1
                continue
            code = os.system('"%s" "%s" check %s %s --tolerance %g --law "%s"'
                             % (sys.executable, os.path.abspath(__file__), case, job,
                                args.tolerance, args.law))
            failed += code != 0
        sys.exit(1 if failed else 0)


if __name__ == '__main__':
    main()
