"""Block on a block, pressed and pushed sideways: stick, then slip at T = mu N (Coulomb).

    block_sliding.py deck JOB.inp --variant partial|soft [--max-increment F] [--push U]
    block_sliding.py check JOB --variant partial|soft [--tolerance T] [--csv F] [--png F]

Model (units consistent, e.g. mm, N, MPa): a lower block 2 x 2 x 1 (6 x 6 x 3 hexahedra,
x, y in [-0.5, 1.5], z in [0, 1]; base fixed) and on it an upper block 1 x 1 x 0.5 (5 x 5 x 2
hexahedra, x, y in [0, 1], z in [1, 1.5]): non-matching interface meshes (slave spacing 0.2,
master spacing 1/3). Slave surface: the upper block's bottom faces; master: the lower block's
top faces. E = 1000, nu = 0.3 for both; mu = 0.3; E_n = 3e4 = 10 E / h_master. Both steps
NLGEOM. Step 1: pressure p on the upper block's top, whose nodes (set TOP) are held in x and y.
Step 2: the TOP nodes are moved by u_x = U (ramped), still held in y, free in z. Output every
increment: *NODE PRINT, NSET=BASE, TOTALS=ONLY of RF, the reactions of the lower block's fixed
base, where no load is applied: T = -RF_x and N = RF_z of BASE (the push and the normal load the
upper block passes on; at TOP, loaded by the pressure, RF is the reaction of the supports
without that load).

--variant partial: p = 10, E_t = E_n, U = 0.1. The stick slope E_t is so stiff that the
  shear first slips at the block edges (partial slip) and the curve bends over gradually into
  gross sliding. Checks: in the slip phase (u >= U/2, many times the stick displacement
  mu p / E_t = 1e-4 plus the elastic shear of the blocks) |T/N - mu| <= tolerance mu at every
  output; nowhere T/N > (1 + tolerance) mu; T(u) non-decreasing while T/N < 0.99 mu, to
  1e-3 mu N (the equilibrium error the static-explicit scheme carries between increments);
  the slip-phase spread of T within 2 tolerance mu N. N equals p A to 1e-3.
--variant soft ("block on a plane", method notes section 4): p = 0.1 applied as a
  prescribed displacement of TOP (5.43e-5 down, so that the slider cannot rock; N is
  measured), E_t = 1 (3e4 times softer than E_n), U = 0.08, matching interface meshes and the
  lower block 100 times stiffer (E = 1e5). The contact's stick spring dominates the
  compliance: the independent estimate of the stick slope is k = 1 / (1 / (E_t A) +
  c_blocks), A = 1 the slave area, c_blocks the shear compliance of the blocks, estimated as
  h / (kappa G A) for the slider (kappa = 5/6: 1.6e-3) plus the same for a 1 x 1 column of
  the lower block (3e-5; an upper bound, the block is wider): 0.16 % of 1 / (E_t A).
  Checks: the slope of T(u) while T < mu N / 4 (before any node slips) is E_t A within 1 %
  (the tolerance covers the block compliance); gross slip (T/N >= 0.999 mu) is reached where
  the most loaded node's stick spring reaches its cone, u = mu max(p_s) / E_t (p_s from the
  *CONTACT PRINT at the end; the push at the top tilts the pressure distribution) within
  3 %; afterwards T/N = mu within tolerance.

Increments: the default R-minimum limits let an increment of gross sliding be as long as the
strain limit allows (the slider barely strains): 0.2 of the step, 0.02 of slide; the friction
direction of every slipping node turns by up to 90 degrees within such an increment, which
the explicit predictor cannot follow (measured overshoot of T/N: 5.8 %, see
doc/validation/contact.md and tests/pending/contact_sliding_default_increments.sh).
--max-increment F caps the increment at F of the step (the *STATIC maximum increment).
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
NORMAL_STIFFNESS = 3.0e4
VARIANTS = {
    'partial': dict(pressure=10.0, stick=NORMAL_STIFFNESS, push=0.1, lower_young=YOUNG,
                    lower_x=np.linspace(-0.5, 1.5, 7)),
    'soft': dict(pressure=0.1, stick=1.0, push=0.08, lower_young=100.0 * YOUNG,
                 lower_x=np.linspace(-0.6, 1.6, 12), press=5.43e-5),
}
SLAVE_AREA = 1.0
SHEAR_MODULUS = YOUNG / (2.0 * (1.0 + POISSON))
# Slider h / (kappa G A) plus a 1 x 1 column of the (100 times stiffer) lower block.
BLOCK_COMPLIANCE = 0.5 / (5.0 / 6.0 * SHEAR_MODULUS) + 1.0 / (5.0 / 6.0 * 100.0 * SHEAR_MODULUS)


def make_deck(path, variant, max_increment, push, small_strain=False):
    v = VARIANTS[variant]
    push = v['push'] if push is None else push
    lower = cc.Box(v['lower_x'], v['lower_x'], np.linspace(0.0, 1.0, 4),
                   first_node=1, first_element=1)
    upper = cc.Box(np.linspace(0.0, 1.0, 6), np.linspace(0.0, 1.0, 6), np.linspace(1.0, 1.5, 3),
                   first_node=1001, first_element=1001)
    lines = ['*HEADING', 'Block on a block pushed sideways, variant %s '
             '(tests/integration/contact/block_sliding.py)' % variant]
    lines += lower.mesh_cards('LOWER') + upper.mesh_cards('UPPER')
    lines += cc.nset_cards('BASE', lower.face_nodes(2, 0))
    lines += cc.nset_cards('TOP', upper.face_nodes(2, 1))
    lines += cc.face_surface_cards('MASTER', lower, 2, 1)
    lines += cc.face_surface_cards('SLAVE', upper, 2, 0)
    lines += cc.face_surface_cards('LOADED', upper, 2, 1)
    lines += cc.material_cards('LOWER_MAT', 'LOWER', v['lower_young'], POISSON)
    lines += cc.material_cards('UPPER_MAT', 'UPPER', YOUNG, POISSON)
    lines += cc.interaction_cards('ROUGH', NORMAL_STIFFNESS, MU, v['stick'])
    lines += ['*CONTACT PAIR, INTERACTION=ROUGH, TYPE=NODE TO SURFACE', 'SLAVE, MASTER']
    step = '*STEP' if small_strain else '*STEP, NLGEOM'
    lines += [step, '*STATIC', '0.25, 1.', '*BOUNDARY', 'BASE, 1, 3', 'TOP, 1, 2']
    if 'press' in v:
        lines += ['TOP, 3, 3, %.12g' % -v['press']]
    else:
        lines += ['*DSLOAD', 'LOADED, P, %.12g' % v['pressure']]
    lines += ['*NODE PRINT, NSET=BASE, TOTALS=ONLY', 'RF', '*END STEP']
    static = '0.01, 1.' if max_increment is None else \
        '%.12g, 1., 1e-6, %.12g' % (min(0.01, max_increment), max_increment)
    lines += [step, '*STATIC', static, '*BOUNDARY', 'TOP, 1, 1, %.12g' % push,
              '*NODE PRINT, NSET=BASE, TOTALS=ONLY, FREQUENCY=1', 'RF',
              '*CONTACT PRINT', 'CSTR', '*END STEP']
    cc.write_deck(path, lines)


def curve(job, push):
    """u, T, N of every output of step 2 (t in (1, 2]) and of the end of step 1 (u = 0)."""
    times, forces = cc.totals(cc.read_dat(job + '.dat'), 'BASE')
    keep = times >= 1.0 - 1e-9
    times, forces = times[keep], forces[keep]
    u = push * (times - 1.0)
    return u, -forces[:, 0], forces[:, 2]


def check(job, variant, tolerance, push, csv, png, min_slip_outputs=5):
    v = VARIANTS[variant]
    push = v['push'] if push is None else push
    checker = cc.Checker()
    u, t, n = curve(job, push)
    ratio = t / n
    checker.check(len(u) >= 10, '%d outputs of the push (expected >= 10)' % len(u))
    normal = v['pressure'] * SLAVE_AREA
    if 'press' in v:
        normal = n[-1]
        checker.check(abs(n.max() / n.min() - 1) <= 0.02, 'N = RF_z of BASE (normal load by '
                      'the prescribed top displacement): %.6g .. %.6g' % (n.min(), n.max()))
    else:
        checker.relative('N = RF_z of BASE at the end', n[-1], normal, 1e-3)
    reached = np.nonzero(ratio >= 0.99 * MU)[0]
    if len(reached) == 0:
        checker.check(False, 'T/N never reaches 0.99 mu (max %.5f)' % ratio.max())
        checker.finish()
    onset = reached[0]
    steps = np.diff(t[:onset + 1])
    checker.check(np.all(steps >= -1e-3 * MU * normal), 'T(u) non-decreasing (to 1e-3 mu N, the '
                  'equilibrium error carried by the explicit scheme) until T/N first reaches '
                  '0.99 mu (at u = %.5g; largest decrease %.3g mu N)'
                  % (u[onset], max(0.0, -steps.min()) / (MU * normal) if len(steps) else 0))
    checker.check(ratio.max() <= MU * (1.0 + tolerance), 'max T/N = %.6f <= mu (1 + %g) = %.6f '
                  '(overshoot %.3f %%)' % (ratio.max(), tolerance, MU * (1 + tolerance),
                                           100 * (ratio.max() / MU - 1)))
    if variant == 'partial':
        slip = u >= 0.5 * push
    else:
        stiffness = v['stick'] * SLAVE_AREA
        k_estimate = 1.0 / (1.0 / stiffness + BLOCK_COMPLIANCE)
        early = (t < 0.25 * MU * normal) & (u > 0)
        slope = np.polyfit(u[early], t[early], 1)[0]
        checker.check(early.sum() >= 3, '%d outputs with T < mu N / 4 for the stick slope'
                      % early.sum())
        checker.relative('stick slope dT/du vs E_t A = %g' % stiffness, slope, stiffness, 0.01)
        print('     (independent estimate with the block shear compliance: %.6g; slope / '
              'estimate - 1 = %.2e)' % (k_estimate, slope / k_estimate - 1))
        # Each node's stick spring E_t A_s u reaches mu p_s A_s at u = mu p_s / E_t: gross slip
        # when the most loaded node slips (the push at height h tilts the pressure).
        stress = cc.contact_tables(cc.read_dat(job + '.dat'))[-1][1]
        p_max = max(values[0] for values in stress.values())
        u_gross = MU * p_max / v['stick'] + (normal * MU) * BLOCK_COMPLIANCE
        gross = np.nonzero(ratio >= MU * (1 - 1e-3))[0]
        if len(gross) == 0:
            checker.check(False, 'T/N never reaches 0.999 mu (max %.6f)' % ratio.max())
            checker.finish()
        first = gross[0]
        checker.relative('gross slip (T/N >= 0.999 mu) at u = %.5g vs mu max(p_s) / E_t'
                         % u[first], u[first], u_gross, 0.03)
        slip = u >= u[first]
    errors = np.abs(ratio[slip] / MU - 1.0)
    checker.check(slip.sum() >= min_slip_outputs and errors.max() <= tolerance,
                  'slip phase (%d outputs, u >= %.4g): |T/N - mu| / mu max %.3e, mean %.3e '
                  '(tolerance %g)' % (slip.sum(), u[slip][0], errors.max(), errors.mean(),
                                      tolerance))
    flat = (t[slip].max() - t[slip].min()) / (MU * normal)
    checker.check(flat <= 2 * tolerance, 'slip phase flat: (max T - min T) / (mu N) = %.3e '
                  '(tolerance %g)' % (flat, 2 * tolerance))
    print('summary %s: outputs %d, onset u %.5g, slip-phase T/N mean %.6f min %.6f max %.6f, '
          'overall max %.6f' % (variant, len(u), u[onset], ratio[slip].mean(), ratio[slip].min(),
                                ratio[slip].max(), ratio.max()))
    if csv:
        cc.save_csv(csv, ['u', 'T', 'N', 'T_over_N'], [u, t, n, ratio])
    if png:
        plot(png, [(variant, u, ratio)], MU)
    checker.finish()


def plot(png, curves, mu, title='Block on a block: tangential / normal force vs push'):
    import matplotlib
    matplotlib.use('Agg')
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6.4, 4.0))
    for label, u, ratio in curves:
        ax.plot(u, ratio, '.-', markersize=3, label=label)
    ax.axhline(mu, color='k', linestyle='--', linewidth=0.8, label='mu = %g' % mu)
    ax.set_xlabel('prescribed displacement of the top u')
    ax.set_ylabel('T / N')
    ax.set_title(title, fontsize=10)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(png, dpi=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    sub = parser.add_subparsers(dest='command', required=True)
    d = sub.add_parser('deck')
    d.add_argument('path')
    d.add_argument('--variant', choices=sorted(VARIANTS), required=True)
    d.add_argument('--max-increment', type=float)
    d.add_argument('--push', type=float)
    d.add_argument('--small-strain', action='store_true', help='steps without NLGEOM')
    c = sub.add_parser('check')
    c.add_argument('job')
    c.add_argument('--variant', choices=sorted(VARIANTS), required=True)
    c.add_argument('--tolerance', type=float, default=0.01)
    c.add_argument('--push', type=float)
    c.add_argument('--csv')
    c.add_argument('--png')
    c.add_argument('--min-slip-outputs', type=int, default=5,
                   help='outputs (increments) required in the slip phase (default 5; with the '
                   'default increments the gross-slip phase takes 2 or 3)')
    args = parser.parse_args()
    if args.command == 'deck':
        make_deck(args.path, args.variant, args.max_increment, args.push, args.small_strain)
    else:
        check(args.job, args.variant, args.tolerance, args.push, args.csv, args.png,
              args.min_slip_outputs)


if __name__ == '__main__':
    main()
