"""Spring-slider stability study: how sharp the FE stability boundary is, how the scheme damps,
and what sets the size of a quasi-static event.

    stability_sweep.py DIRECTORY [--markdown FILE] [--png FILE]

The spring-slider of stability.py (RATE STATE ageing law, slave nodes driven, k = E_t =
R k_c, k_c = 50 MPa/mm, V_lp = 1e-3 mm/s, *EVENT CATALOG, SLIP RATE=1e-2 mm/s):

1. R = 0.8, 0.9, 0.95, 1.05, 1.1, 1.2, 600 s, increments up to 0.1 s: events after 300 s,
   peak-to-peak of mu over the last 100 s, the last event. Checks (the issue's +-20 %): R = 0.8
   has events after 300 s and R = 1.2 has none. The +-5 % boundary is
   tests/pending/friction_stability_boundary.sh.
2. R = 1.2, 260 s, increments up to 0.1, 0.03, 0.01 s: the decay per cycle of mu - mu_ss after
   the last event, FE against the quasi-static ODE from the same state (stability.decay_ratios):
   the implicit return mapping damps, first order in the increment.
3. R = 0.8, 300 s, *STATIC minimum increment 1e-5, 1e-7, 1e-9 s: the first events' slip,
   stress drop and peak slip rate. The quasi-static event has no bounded solution; the
   friction-rate limits (*RMIN) cut the increments as the slip rate grows, down to the
   minimum increment, and the event then completes in increments of that length.
--png: mu (spring force / sigma_n) and slip rate against time for R = 0.8 and 1.2 (the runs
of part 1), the figure of doc/validation/friction.md.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import friction_common as fc  # noqa: E402
import stability  # noqa: E402


def run(directory, name, ratio, period, max_increment=0.1, min_increment=1e-9):
    job = os.path.join(directory, name)
    stability.make_deck(job + '.inp', ratio, 'AGEING', period, max_increment, min_increment)
    fc.run(job + '.inp')
    return job


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('directory')
    parser.add_argument('--markdown')
    parser.add_argument('--png')
    args = parser.parse_args()
    os.makedirs(args.directory, exist_ok=True)
    checker = fc.Checker()
    out = []
    mu_ss = fc.mu_steady(stability.LOAD_RATE)

    out += ['Part 1: k / k_c against the outcome (600 s, increments up to 0.1 s).', '',
            '| k / k_c | events (after 300 s) | last event [s] | mu peak-to-peak, last 100 s | '
            'abs(mu - mu_ss) at the end | increments |', '|---|---|---|---|---|---|']
    jobs = {}
    for ratio in (0.8, 0.9, 0.95, 1.05, 1.1, 1.2):
        job = run(args.directory, 'ratio_%g' % ratio, ratio, 600.0)
        jobs[ratio] = job
        h = fc.History(job)
        e = fc.read_events(job)
        late = h.t >= h.t[-1] - 100.0
        after = int(np.sum(e['onset'] > 300.0))
        out.append('| %g | %d (%d) | %.1f | %.2e | %.2e | %d |' % (
            ratio, len(e['onset']), after, e['onset'][-1] if len(e['onset']) else 0,
            np.ptp(h.mu[late]), abs(h.mu[-1] - mu_ss), len(h.t) - 1))
        if ratio == 0.8:
            checker.check(after >= 8, 'k = 0.8 k_c: %d events after 300 s (stick-slip)' % after)
        if ratio == 1.2:
            checker.check(after == 0, 'k = 1.2 k_c: no event after 300 s (steady sliding)')

    out += ['', 'Part 2: k = 1.2 k_c, decay of mu - mu_ss per cycle after the last event.', '',
            '| max increment [s] | FE ratio per cycle | quasi-static ODE | FE period [s] | '
            'ODE period [s] | increments |', '|---|---|---|---|---|---|']
    for dt in (0.1, 0.03, 0.01):
        job = run(args.directory, 'decay_%g' % dt, 1.2, 260.0, max_increment=dt)
        fe, ode, t0, pf, po = stability.decay_ratios(job, 1.2, 'AGEING')
        out.append('| %g | %s | %s | %.2f | %.2f | %d |' % (
            dt, ', '.join('%.3f' % r for r in fe[:3]), ', '.join('%.3f' % r for r in ode[:3]),
            pf[1][0] - pf[0][0], po[1][0] - po[0][0], len(fc.History(job).t) - 1))

    out += ['', 'Part 3: k = 0.8 k_c, the first three events against the minimum increment '
            '(300 s).', '',
            '| min increment [s] | onsets [s] | slip [DC] | stress drop [MPa] | peak slip rate '
            '[mm/s] | increments |', '|---|---|---|---|---|---|']
    for dt_min in (1e-5, 1e-7, 1e-9):
        job = run(args.directory, 'event_%g' % dt_min, 0.8, 300.0, min_increment=dt_min)
        e = fc.read_events(job)
        n = min(3, len(e['onset']))
        out.append('| %g | %s | %s | %s | %s | %d |' % (
            dt_min, ', '.join('%.2f' % x for x in e['onset'][:n]),
            ', '.join('%.1f' % (x / fc.RS['DC']) for x in e['max_slip'][:n]),
            ', '.join('%.3f' % x for x in e['stress_drop'][:n]),
            ', '.join('%.2g' % x for x in e['peak_slip_rate'][:n]), len(fc.History(job).t) - 1))
    text = '\n'.join(out) + '\n'
    print(text)
    if args.markdown:
        with open(args.markdown, 'w') as f:
            f.write(text)
    if args.png:
        stability.plot(args.png, [jobs[0.8], jobs[1.2]], [0.8, 1.2])
    checker.finish()


if __name__ == '__main__':
    main()
