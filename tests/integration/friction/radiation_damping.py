"""Steady sliding of the block-slider with radiation damping (issue 19, item 3).

    radiation_damping.py deck JOB.inp --damping ETA|MATERIAL
    radiation_damping.py check JOB --damping ETA|MATERIAL [--tolerance 1e-6]

Model: friction_common.py (a one-element slider on a rigid base, pushed at its top, sigma_n =
10 MPa), *FRICTION, LAW=RATE STATE with the parameters of steady_state.py and STATE LAW=SLIP,
and RADIATION DAMPING=ETA (a number, MPa s/mm) or MATERIAL (every material then gets a
*DENSITY RHO = 1e-3: eta = Z_s Z_b / (Z_s + Z_b), Z = sqrt(G rho), with the slider's G =
2e4 MPa and the base's 1e6/2.6 MPa: eta = 3.6417 MPa s/mm). The top is driven at V = 1e-3,
1e-2, 1e-1 mm/s (steps 2-4), 25 DC of slip each.

Closed form (quasi-dynamic approximation, Rice 1993): a node sliding steadily at V resists
with tau = sigma_n mu_ss(V) + eta V, so the contact's shear over its pressure is
mu_ss(V) + eta V / sigma_n (0.6, 0.588487, 0.576974 plus 5e-4, 5e-3, 5e-2 with eta = 5). The
slider is stiff, the slip rate equals the load rate, and after 20 DC the state is within 2e-9
of steady state (steady_state.py): the tolerance 1e-6 is that test's. The echo must state the
pair's eta (MATERIAL: the value above, within 1e-5 relative: printed digits).
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import friction_common as fc  # noqa: E402

RATES = [1.0e-3, 1.0e-2, 1.0e-1]
SLIP_PER_STEP = 25.0   # in DC
STEADY_AFTER = 20.0    # in DC
STICK_SLOPE = 1.0e5
DENSITY = 1.0e-3


def material_damping():
    """eta of RADIATION DAMPING=MATERIAL for the block-slider with density DENSITY."""
    z_slider = math.sqrt(fc.SLIDER_SHEAR * DENSITY)
    z_base = math.sqrt(fc.BASE_YOUNG / (2.0 * 1.3) * DENSITY)
    return z_slider * z_base / (z_slider + z_base)


def damping_value(damping):
    return material_damping() if damping == 'MATERIAL' else float(damping)


def make_deck(path, damping):
    p = fc.RS
    friction = fc.friction_card('RATE STATE', STICK_SLOPE, MU0=p['MU0'], A=p['A'], B=p['B'],
                                DC=p['DC'], V0=p['V0'], VC=p['VC'], STATE_LAW='SLIP',
                                VINIT=RATES[0], RADIATION_DAMPING=damping)
    steps = []
    for v in RATES:
        period = SLIP_PER_STEP * p['DC'] / v
        steps.append(dict(velocity=v, period=period, initial=1e-3 * period, max=period / 100))
    fc.slider_deck(path, friction, steps, title='steady sliding with radiation damping %s' % damping)
    if damping == 'MATERIAL':
        with open(path) as f:
            lines = f.read().splitlines()
        out = []
        for k, line in enumerate(lines):
            out.append(line)
            if k > 0 and lines[k - 1].upper() == '*ELASTIC':
                out += ['*DENSITY', '%.17g' % DENSITY]
        with open(path, 'w') as f:
            f.write('\n'.join(out) + '\n')


def check(job, damping, tolerance):
    checker = fc.Checker()
    eta = damping_value(damping)
    with open(job + '.echo') as f:
        echo = f.read()
    marker = 'radiation damping eta = '
    if marker not in echo:
        checker.check(False, 'the echo states the pair\'s radiation damping')
    else:
        printed = float(echo.split(marker)[1].split()[0])
        checker.check(abs(printed / eta - 1) <= 1e-5, 'echo: eta = %.6g (expected %.6g)' % (printed, eta))
    h = fc.History(job)
    start = fc.STEP1_PERIOD
    p = fc.RS
    for v in RATES:
        end = start + SLIP_PER_STEP * p['DC'] / v
        in_step = (h.t > start * (1 + 1e-12)) & (h.t <= end * (1 + 1e-12))
        start = end
        if not in_step.any():
            checker.check(False, 'V = %g: no samples' % v)
            continue
        first = np.nonzero(in_step)[0][0]
        window = in_step & (h.slip - h.slip[first - 1] >= STEADY_AFTER * p['DC'])
        last = np.nonzero(in_step)[0][-1]
        window[last] = False
        if window.sum() < 5:
            checker.check(False, 'V = %g: only %d samples after %g DC' % (v, window.sum(), STEADY_AFTER))
            continue
        expected = fc.mu_steady(v) + eta * v / fc.SIGMA_N
        err = np.abs(h.mu[window] - expected)
        checker.check(err.max() <= tolerance, 'V = %g mm/s: shear / pressure = mu_ss + eta V / '
                      'sigma_n = %.7f (damping %.2e): max error %.2e over %d samples (tolerance %.0e)'
                      % (v, expected, eta * v / fc.SIGMA_N, err.max(), window.sum(), tolerance))
        rate_err = np.abs(h.rate[window] / v - 1)
        checker.check(rate_err.max() <= tolerance, 'V = %g mm/s: slip rate / V - 1 max %.2e'
                      % (v, rate_err.max()))
    checker.finish()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    sub = parser.add_subparsers(dest='command', required=True)
    d = sub.add_parser('deck')
    d.add_argument('path')
    d.add_argument('--damping', required=True)
    c = sub.add_parser('check')
    c.add_argument('job')
    c.add_argument('--damping', required=True)
    c.add_argument('--tolerance', type=float, default=1e-6)
    args = parser.parse_args()
    if args.command == 'deck':
        make_deck(args.path, args.damping)
    else:
        check(args.job, args.damping, args.tolerance)


if __name__ == '__main__':
    main()
