"""event_catalog.sh: the slip-event catalog against the slip-rate history of the same run.

The rule of src/io/fcs_event_catalog.f90 (catalog_update, called after every increment with
the slip rates of the pair's slave nodes at its end): an event starts in the first increment
in which some node's slip rate exceeds the threshold (strictly); its onset is the time at the
START of that increment (time - dt). It ends in the first later increment in which no node
exceeds the threshold; its end is the time at the START of that increment (= the end of the
last increment above the threshold). The peak slip rate is the largest node slip rate over
the increments of the event. An event still under way when the run ends is not catalogued;
events whose largest slip is below MIN SLIP are dropped.

With *HISTORY, FREQUENCY=1 the history has a row after every increment (and one at time 0),
and its column UPPERBOTTOM-LOWERTOP_RATE_MAX is the largest node slip rate at the end of the
increment, so with rows (t_i, R_i), increment i spanning [t_{i-1}, t_i]: event k starts at
the k-th up-crossing i (R_{i-1} <= thr < R_i, or the first row above thr after the previous
event ended): onset = t_{i-1}; ends at the first j > i with R_j <= thr: end = t_{j-1};
peak = max(R_i..R_{j-1}). Checked:
  - the history has one row per increment plus the initial one;
  - the events derived from the history equal the catalog (/events/catalog/values of job.h5):
    same count (the number of up-crossings that end before the run does), onset and end
    within 4 ulp (the code computes the start of an increment as time - dt, the history
    stores the time of the previous increment: they differ by rounding), duration = end -
    onset, peak slip rate exactly; plausible nodes (1..16), slips, hypocentre (a slave node,
    on the upper block's bottom face);
  - job_events.csv equals /events/catalog/values: the same header as its `columns` attribute,
    the integer columns exactly, the others to the CSV's 10 significant digits (1e-9);
  - job.log has one "slip event" line per event;
  - a second run with MIN SLIP halfway between two events' largest slips catalogues exactly
    the first run's events with max_slip >= MIN SLIP, values bit for bit.
usage: event_catalog.py WORKDIR
"""
import csv
import os
import re
import sys

import numpy as np

import restart_common as rc

JOB = 'job'
RATE = rc.PAIR + '_RATE_MAX'
SLIP_MAX = rc.PAIR + '_SLIP_MAX'
INTEGER_COLUMNS = ['event', 'pair', 'nodes', 'hypocentre_node']


def text(value):
    return value.decode() if isinstance(value, bytes) else str(value)


def read_run(directory):
    import h5py
    with h5py.File(os.path.join(directory, JOB + '.h5'), 'r') as f:
        history = f['history/%s/values' % rc.HISTORY]
        columns = text(history.attrs['columns']).split(',')
        rows = history[()]
        catalog = f['events/catalog/values']
        event_columns = text(catalog.attrs['columns']).split(',')
        events = catalog[()].reshape(-1, len(event_columns))
    return columns, rows, event_columns, events


def derive_events(t, rate, threshold):
    """The catalog's rule applied to the history rows; also whether an event is under way
    at the end."""
    events, active = [], False
    for i in range(1, len(t)):
        if not active and rate[i] > threshold:
            active, onset, peak, first = True, t[i - 1], rate[i], i
        if active:
            peak = max(peak, rate[i])
            if rate[i] <= threshold:
                events.append((onset, t[i - 1], peak, first, i))
                active = False
    return events, active


def main():
    rc.require_h5py()
    work = sys.argv[1]
    failures = []
    directory = rc.fresh_dir(os.path.join(work, 'run'))
    rc.write_deck(os.path.join(directory, JOB + '.inp'), restart=False)
    rc.run(directory, JOB)
    columns, rows, event_columns, events = read_run(directory)
    col = {name: k for k, name in enumerate(event_columns)}
    t, rate = rows[:, 0], rows[:, columns.index(RATE)]
    with open(os.path.join(directory, JOB + '.log')) as f:
        log = f.read()
    increments = int(re.search(r'done: (\d+) increment\(s\)', log).group(1))
    if len(t) != increments + 1:
        failures.append('the history has %d rows for %d increments (expected one per increment '
                        'and the initial row)' % (len(t), increments))
    derived, running = derive_events(t, rate, rc.THRESHOLD)
    upcrossings = int(np.sum((rate[1:] > rc.THRESHOLD) & (rate[:-1] <= rc.THRESHOLD)))
    print('%d increments, %d history rows; %d up-crossings of %s over %g%s; %d events '
          'catalogued' % (increments, len(t), upcrossings, RATE, rc.THRESHOLD,
                          ' (the last one still under way at the end)' if running else '',
                          len(events)))
    if len(derived) != len(events) or len(derived) != upcrossings - running:
        failures.append('%d events catalogued, %d derived from the history, %d up-crossings'
                        % (len(events), len(derived), upcrossings))
    if len(events) < 3:
        failures.append('the test problem should have several events, it has %d' % len(events))
    worst = 0.0
    slave_ids = set(range(10001, 10017))
    for k, (e, d) in enumerate(zip(events, derived)):
        onset, end, peak, first, closing = d
        tol = 4 * np.finfo(float).eps * max(1.0, abs(end))
        worst = max(worst, abs(e[col['onset']] - onset), abs(e[col['end']] - end))
        problems = []
        if int(e[col['event']]) != k + 1 or int(e[col['pair']]) != 1:
            problems.append('event number %g, pair %g' % (e[col['event']], e[col['pair']]))
        if abs(e[col['onset']] - onset) > tol:
            problems.append('onset %.17g, the history says %.17g' % (e[col['onset']], onset))
        if abs(e[col['end']] - end) > tol:
            problems.append('end %.17g, the history says %.17g' % (e[col['end']], end))
        if e[col['duration']] != e[col['end']] - e[col['onset']]:
            problems.append('duration %.17g is not end - onset' % e[col['duration']])
        if e[col['peak_slip_rate']] != peak:
            problems.append('peak slip rate %.17g, the history says %.17g' % (
                e[col['peak_slip_rate']], peak))
        if not 1 <= e[col['nodes']] <= 16:
            problems.append('%g nodes' % e[col['nodes']])
        if not 0 <= e[col['mean_slip']] <= e[col['max_slip']] <= \
                rows[closing, columns.index(SLIP_MAX)] + 1e-15:
            problems.append('slips: mean %g, max %g, largest accumulated %g' % (
                e[col['mean_slip']], e[col['max_slip']], rows[closing, columns.index(SLIP_MAX)]))
        x, y, z = e[col['x']], e[col['y']], e[col['z']]
        if int(e[col['hypocentre_node']]) not in slave_ids or not (
                1.0 < x < 3.2 and 1.0 < y < 3.2 and abs(z) < 0.05):
            problems.append('hypocentre node %g at (%g, %g, %g)' % (e[col['hypocentre_node']],
                                                                   x, y, z))
        if problems:
            failures.append('event %d: %s' % (k + 1, '; '.join(problems)))
    print('onsets, ends, peak slip rates as the history says (largest time difference %.2g)'
          % worst)

    with open(os.path.join(directory, JOB + '_events.csv')) as f:
        table = list(csv.reader(f))
    if table[0] != event_columns:
        failures.append('CSV header %s, HDF5 columns %s' % (table[0], event_columns))
    values = np.array([[float(v) for v in row] for row in table[1:]]).reshape(-1, len(table[0]))
    if values.shape != events.shape:
        failures.append('CSV %s, HDF5 %s' % (values.shape, events.shape))
    else:
        integer = [col[name] for name in INTEGER_COLUMNS]
        real = [k for k in range(len(event_columns)) if k not in integer]
        if not np.array_equal(values[:, integer], events[:, integer]) or not np.allclose(
                values[:, real], events[:, real], rtol=1e-9, atol=1e-300):
            failures.append('job_events.csv differs from /events/catalog/values')
        else:
            print('job_events.csv = /events/catalog/values (%d x %d; integers exactly, reals '
                  'to 1e-9)' % events.shape)
    logged = re.findall(r'slip event (\d+) on ' + re.escape(rc.PAIR) + r': onset', log)
    if logged != [str(k + 1) for k in range(len(events))]:
        failures.append('job.log lists events %s' % logged)

    largest = np.sort(events[:, col['max_slip']])
    middle = len(largest) // 2
    min_slip = 0.5 * (largest[middle - 1] + largest[middle])
    kept = events[events[:, col['max_slip']] >= min_slip]
    second = rc.fresh_dir(os.path.join(work, 'min_slip'))
    rc.write_deck(os.path.join(second, JOB + '.inp'), restart=False, min_slip=float(min_slip))
    rc.run(second, JOB)
    _, _, _, filtered = read_run(second)
    others = [k for k in range(len(event_columns)) if k != col['event']]
    if filtered.shape != kept.shape or not np.array_equal(filtered[:, others], kept[:, others]) \
            or not np.array_equal(filtered[:, col['event']], np.arange(1, len(kept) + 1)):
        failures.append('with MIN SLIP=%r: %d events, expected the %d of the first run with '
                        'max_slip >= MIN SLIP' % (min_slip, len(filtered), len(kept)))
    else:
        print('MIN SLIP=%.6g: the %d of %d events with max_slip >= MIN SLIP, renumbered, '
              'values identical' % (min_slip, len(kept), len(events)))
    for failure in failures:
        print('FAIL ' + failure)
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
