"""The paper's friction law under a constant load rate: stick-slip events, their recurrence and
stress drop against the regularisation (FLOOR, LINEAR), its cut-off rate VC, and the numerical
treatment of the rate (RATE UPDATE, increment limits).

    regularisation.py DIRECTORY [--markdown FILE] [--schemes NAME ...] [--period 1000]

Model: friction_common.py with the slave nodes driven (drive SLAVE): each of the four slave
nodes is a spring-slider with the stick slope E_t = k = 40 MPa/mm (per unit area) as its spring,
sigma_n = 10 MPa, load point at V_lp = 1e-3 mm/s (the paper's loading rate) for --period s.
*FRICTION, LAW=RATE DEPENDENT, MU0=0.60, A=0.010, B=0.025, V0=0.001 mm/s (Xing, Mora &
Makinouchi 2003), REGULARISATION=FLOOR or LINEAR, VC = 1e-6, 1e-5, 1e-4 mm/s; *EVENT CATALOG,
SLIP RATE=1e-2 mm/s (10 V_lp); history of RF of each slave node every increment (its x
component, less its value at the end of the pressing step, is the node's friction force).
Schemes (--schemes, SCHEMES below): "explicit" (the law's default RATE UPDATE=EXPLICIT,
increments 0.1 s down to 1e-9 s), "explicit-min1e-7" (the same with a minimum increment of
1e-7 s), "implicit" (RATE UPDATE=IMPLICIT, 0.1 s down to 1e-9 s), "implicit-max1"
(RATE UPDATE=IMPLICIT, increments up to 1 s).

The law has no state: mu = mu_ss(V) falls with V everywhere above VC, so a sliding node is
unstable for any spring (quasi-static: k (V_lp - V) = sigma_n dmu/dV dV/dt, with dmu/dV < 0
V runs away from V_lp either way). Below VC the regularisation sets the static friction:
FLOOR mu_s = mu_ss(VC); LINEAR mu(0) = mu_ss(VC) - (A - B) = mu_ss(VC) + 0.015 (doc/friction.md).
A node sticks until its stick spring carries mu_s sigma_n, at t_1 = t_press + mu_s sigma_n /
(k V_lp), then slips and runs away. How far the event goes is not physics in this model: the
quasi-static slider has no arrest (no inertia, no state). It is numerical:

  * IMPLICIT: the event happens within one increment, whose return mapping
    f^tr - k_t l = f_n mu(l/dt) has its largest root at a slip l set by the increment dt: the
    stress drop is that of one increment of the maximum length (one_increment_drop);
  * EXPLICIT: each increment's cone is mu at the previous increment's slip rate; the friction-
    rate limits (*RMIN) cut the increments as the rate grows, down to the minimum, where the
    event runs to slip rates of order (slip)/(minimum increment): the friction after the event is
    mu_ss at the event's peak slip rate, and the stress drop grows by (B - A) sigma_n ln 100 =
    0.69 MPa for each factor 100 of smaller minimum increment.

Measured per slave node (the four nodes are identical spring-sliders; when they fall out of
step - with LINEAR, whether a node whose trial force equals the cone to round-off slips in this
increment or the next is decided by round-off - the catalog lists their events separately):
events = drops of the node's friction force by more than 1 % of mu_s f_n between samples;
recurrence = median interval between a node's events after the first; stress drop = median
drop of the node's shear traction; peak = largest shear / sigma_n before an event. From the
catalog: the number of events and the medians of its (mean-over-nodes) stress drops and peak
slip rates.

Checks: every run has at least 4 events per node; the peak friction before the events is mu_s
(up to the load of one increment, k V_lp dt / sigma_n); the first drop comes within three
maximum increments after t_1 (explicit: the node slips first at mu_s and the friction falls over
a few increments); the recurrence equals stress drop / (k V_lp) within 2 % plus one maximum
increment (the reload time; the rest is the event's own increments); the stress drop equals
one_increment_drop within 1 % (implicit), or sigma_n (mu_s - mu_ss(V_peak)) with the catalog's
median peak slip rate within 2 % (explicit: the catalog's peak rate and stress drop are means
over an event's nodes, the measured drop a median over nodes and events).
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import friction_common as fc  # noqa: E402

PAPER = dict(MU0=0.60, A=0.010, B=0.025, V0=0.001)
#: name: (RATE UPDATE, maximum increment, minimum increment)
SCHEMES = {'explicit': ('EXPLICIT', 0.1, 1e-9), 'explicit-min1e-7': ('EXPLICIT', 0.1, 1e-7),
           'implicit': ('IMPLICIT', 0.1, 1e-9), 'implicit-max1': ('IMPLICIT', 1.0, 1e-9)}
K = 40.0            # MPa/mm, the stick slope = loading spring per unit area
LOAD_RATE = 1.0e-3
NODE_AREA = 0.25
NODES = [11, 12, 13, 14]


def mu_ss(v):
    return PAPER['MU0'] + (PAPER['A'] - PAPER['B']) * math.log(v / PAPER['V0'])


def static_friction(regularisation, vc):
    """mu at rest: FLOOR mu_ss(VC), LINEAR mu_ss(VC) - (A - B)."""
    mu = mu_ss(vc)
    if regularisation == 'LINEAR':
        mu -= PAPER['A'] - PAPER['B']
    return mu


def make_deck(path, regularisation, vc, scheme, period):
    update, max_increment, min_increment = SCHEMES[scheme]
    friction = fc.friction_card('RATE DEPENDENT', K, MU0=PAPER['MU0'], A=PAPER['A'], B=PAPER['B'],
                                V0=PAPER['V0'], VC=vc, REGULARISATION=regularisation,
                                RATE_UPDATE=update)
    fc.slider_deck(path, friction, [dict(velocity=LOAD_RATE, period=period, initial=0.01,
                                         max=max_increment, min=min_increment)],
                   title='paper law, %s VC = %g' % (regularisation, vc),
                   catalog='SLIP RATE=1e-2', drive='SLAVE', node_histories=True)


def one_increment_drop(mu_s, dt):
    """Stress drop [MPa] of an event completed in one increment dt that starts on the cone:
    the largest root l of tau_tr - k l = sigma_n mu_ss(l/dt), tau_tr = mu_s sigma_n + k V_lp dt
    (the return mapping's equation per unit area), drop = tau_tr - k l - ... measured from
    mu_s sigma_n: sigma_n (mu_s - mu_ss(l/dt)). Bisection on [tau_tr/(2k), tau_tr/k]."""
    trial = mu_s * fc.SIGMA_N + K * LOAD_RATE * dt

    def g(l):
        return trial - K * l - fc.SIGMA_N * mu_ss(l / dt)
    lo, hi = 0.5 * trial / K, trial / K
    while g(lo) < 0.0:
        lo *= 0.5
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if g(mid) > 0.0:
            lo = mid
        else:
            hi = mid
    return fc.SIGMA_N * (mu_s - mu_ss(lo / dt))


def median(values):
    return float(np.median(values)) if len(values) else np.nan


def node_events(t, force, mu_s):
    """(times, drops [MPa], peaks [-]) of the drops of one node's friction force."""
    fn = fc.SIGMA_N * NODE_AREA
    drops = force[:-1] - force[1:]
    where = np.nonzero(drops > 0.01 * mu_s * fn)[0]
    # a drop may take more than one increment: merge consecutive samples
    events = []
    for i in where:
        if events and i == events[-1][1]:
            events[-1][1] = i + 1
        else:
            events.append([i, i + 1])
    times = np.array([t[a + 1] for a, b in events])
    size = np.array([(force[a] - force[b]) / NODE_AREA for a, b in events])
    peaks = np.array([force[a] / fn for a, b in events])
    return times, size, peaks


def study(directory, schemes, period):
    rows = []
    checker = fc.Checker()
    for scheme in schemes:
        update, max_increment, min_increment = SCHEMES[scheme]
        for regularisation in ('FLOOR', 'LINEAR'):
            for vc in (1e-6, 1e-5, 1e-4):
                name = '%s_vc%g_%s' % (regularisation.lower(), vc, scheme)
                job = os.path.join(directory, name)
                make_deck(job + '.inp', regularisation, vc, scheme, period)
                fc.run(job + '.inp')
                h = fc.read_csv(job + '_' + fc.HISTORY + '.csv')
                mu_s = static_friction(regularisation, vc)
                t = h['time']
                times, drops, peaks, recur = [], [], [], []
                pressed = int(np.argmin(np.abs(t - fc.STEP1_PERIOD)))
                for n in NODES:
                    # RF_x of a driven slave node is its friction force plus a constant: the
                    # x-share of the slider's radial stress from the pressing (held in x, y).
                    force = h['N%d_RF1' % n][pressed:] - h['N%d_RF1' % n][pressed]
                    a, b, c = node_events(t[pressed:], force, mu_s)
                    times.append(a)
                    drops += list(b)
                    peaks += list(c)
                    recur += list(np.diff(a))
                events = fc.read_events(job)
                firsts = [x[0] for x in times if len(x)]
                t1 = fc.STEP1_PERIOD + mu_s * fc.SIGMA_N / (K * LOAD_RATE)
                n_events = min(len(x) for x in times)
                row = dict(reg=regularisation, vc=vc, scheme=scheme, mu_s=mu_s,
                           t1=min(firsts) if firsts else np.nan, t1_expected=t1,
                           n_node=n_events, recurrence=median(recur), drop=median(drops),
                           drop_min=min(drops, default=np.nan), drop_max=max(drops, default=np.nan),
                           peak=max(peaks, default=np.nan),
                           after=mu_s - median(drops) / fc.SIGMA_N,
                           predicted=(one_increment_drop(mu_s, max_increment)
                                      if update == 'IMPLICIT' else fc.SIGMA_N * (mu_s - mu_ss(
                                          median(events['peak_slip_rate'])))),
                           n_catalog=len(events['onset']),
                           catalog_drop=median(events['stress_drop']),
                           catalog_rate=median(events['peak_slip_rate']),
                           catalog_nodes=median(events['nodes']), increments=len(t) - 1)
                first = row['t1']
                rows.append(row)
                label = '%s VC = %g, %s' % (regularisation, vc, scheme)
                checker.check(n_events >= 4, '%s: %d events per node (>= 4)' % (label, n_events))
                checker.check(-1e-9 <= first - t1 <= 3 * max_increment + 1e-9,
                              '%s: first drop at %.3f s, closed form t_press + mu_s sigma_n / '
                              '(k V_lp) = %.3f s (within three increments of %g s after it)'
                              % (label, first, t1, max_increment))
                load = K * LOAD_RATE * max_increment / fc.SIGMA_N
                checker.check(mu_s - 1e-9 <= row['peak'] <= mu_s + load + 1e-9,
                              '%s: peak friction before events %.6f, mu_s = %.6f (+ at most one '
                              'increment\'s load %.1e)' % (label, row['peak'], mu_s, load))
                reload = row['drop'] / (K * LOAD_RATE)
                checker.check(abs(row['recurrence'] - reload) <= 0.02 * reload + max_increment,
                              '%s: recurrence %.3f s vs stress drop / (k V_lp) = %.3f s (within '
                              '2 %% and one increment)' % (label, row['recurrence'], reload))
                implicit = update == 'IMPLICIT'
                checker.relative('%s: stress drop vs %s' % (label, 'one-increment prediction'
                                                            if implicit else
                                                            'sigma_n (mu_s - mu_ss(V_peak))'),
                                 row['drop'], row['predicted'], 0.01 if implicit else 0.02)
    return rows, checker


def markdown(rows, command):
    lines = ['Measured with `%s` (block-slider, k = %g MPa/mm per unit area, sigma_n = %g MPa, '
             'V_lp = %g mm/s; per slave node; medians over the events after the first; '
             'prediction: one_increment_drop (implicit) or sigma_n (mu_s - mu_ss(V_peak)) '
             '(explicit)).' % (command, K, fc.SIGMA_N, LOAD_RATE), '',
             '| scheme | regularisation | VC [mm/s] | mu_s (closed form) | '
             'first drop [s] (closed form) | recurrence [s] | stress drop [MPa] (min-max) | '
             'prediction [MPa] | mu after event | catalog: events, median drop '
             '[MPa], median peak V [mm/s], nodes/event | increments |',
             '|---|---|---|---|---|---|---|---|---|---|---|']
    for r in rows:
        lines.append('| %s | %s | %g | %.4f | %.2f (%.2f) | %.2f | %.3f (%.3f-%.3f) | %.3f | '
                     '%.4f | %d, %.3f, %.3g, %g | %d |'
                     % (r['scheme'], r['reg'], r['vc'], r['mu_s'], r['t1'], r['t1_expected'],
                        r['recurrence'], r['drop'], r['drop_min'], r['drop_max'], r['predicted'],
                        r['after'], r['n_catalog'], r['catalog_drop'], r['catalog_rate'],
                        r['catalog_nodes'], r['increments']))
    return '\n'.join(lines) + '\n'


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('directory')
    parser.add_argument('--markdown')
    parser.add_argument('--schemes', nargs='+', choices=sorted(SCHEMES),
                        default=['explicit', 'explicit-min1e-7', 'implicit', 'implicit-max1'])
    parser.add_argument('--period', type=float, default=1000.0)
    args = parser.parse_args()
    os.makedirs(args.directory, exist_ok=True)
    rows, checker = study(args.directory, args.schemes, args.period)
    command = 'regularisation.py DIR --schemes %s --period %g' % (' '.join(args.schemes),
                                                                  args.period)
    text = markdown(rows, command)
    print(text)
    if args.markdown:
        with open(args.markdown, 'w') as f:
            f.write(text)
    checker.finish()


if __name__ == '__main__':
    main()
