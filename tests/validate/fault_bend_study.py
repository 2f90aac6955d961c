"""The fault-bend study of doc/validation/fault_bend.md (issue 7): the default model of
`make run` and variants that change one thing each (mesh, penalties, R-minimum limits, the
low-velocity regularisation of the friction law, the flat fault, matching fault nodes). For
each run it records, from the run's own outputs (history CSV, event catalog, log):

  first_slip   the first time in stage 2 that a node of the D-F fault slips (DF_SLIP > 0 in
               the per-increment history);
  first_event  onset of the first catalogued slip event;
  big_events   onsets of the events that involve at least half of the fault's slave nodes
               ("system-size" events: the stress drops of the paper's narrative);
  events       number of catalogued events, and the mean stress drop of the big ones;
  increments, wall time (the log's "done:" line).

and writes a Markdown table and a CSV. The paper's first stick-to-slip time is 228.7 s (with
our assumed 10 s stage 1). Checks (exit 1 if any fails): every run completes; the default
run's first slip is within 25 % of 228.7 s; the two meshes agree on the first slip and on the
first big event within 10 %.

Usage: fault_bend_study.py --fcs3d BIN --work DIR [--out DIR] [--only name,name] [--jobs N]
Each run meshes with gmsh and runs through tools/run_default.sh.
"""
import argparse
import concurrent.futures
import csv
import os
import re
import subprocess
import sys
import time

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..'))
DECK = os.path.join(ROOT, 'input', 'fault_bend', 'fault_bend.inp')
PAPER_FIRST_SLIP = 228.7
DEFAULT_EN = None  # read from the default run's echo


def friction_line(text, extra):
    return re.sub(r'^(\*FRICTION, LAW=RATE DEPENDENT[^\n]*)$', lambda m: m.group(1) + extra,
                  text, count=1, flags=re.M)


def with_penalties(text, normal, stick):
    """Explicit E_n (and E_t as the stick slope) on the fault pair's interaction."""
    text = text.replace('*SURFACE INTERACTION, NAME=FAULT\n',
                        '*SURFACE INTERACTION, NAME=FAULT\n*SURFACE BEHAVIOR, '
                        'PRESSURE-OVERCLOSURE=LINEAR\n%.6g\n' % normal, 1)
    return friction_line(text, ', STICK SLOPE=%.6g' % stick)


def with_rmin(text, card):
    return re.sub(r'^(\*STATIC\n[^\n]*\n)', lambda m: m.group(1) + card + '\n', text, flags=re.M)


def stage2_min_increment(text, value):
    return re.sub(r'^1\., 390\., , 5\.$', '1., 390., %g, 5.' % value, text, count=1, flags=re.M)


FINE = '-setnumber h_fault 5 -setnumber h_far 12 -setnumber layers 5'
# name: (description, gmsh options, deck edit taking (text, E_n default))
VARIANTS = {
    'default': ('the deck of make run (default mesh, E_n = E_t = 10 E/h, FLOOR below '
                'VC = 1e-6 mm/s)', '', lambda t, en: t),
    'fine_mesh': ('finer mesh: h_fault 5, h_far 12, 5 layers', FINE, lambda t, en: t),
    'fine_mesh_same_penalty': ('finer mesh with the default mesh\'s E_n = E_t', FINE,
                               lambda t, en: with_penalties(t, en, en)),
    'en_x2': ('E_n x 2 (E_t unchanged)', '', lambda t, en: with_penalties(t, 2 * en, en)),
    'et_x0.5': ('E_t x 0.5', '', lambda t, en: with_penalties(t, en, 0.5 * en)),
    'strain_1e-3': ('*RMIN MAX STRAIN INCREMENT = 1e-3 (default 2e-3)', '',
                    lambda t, en: with_rmin(t, '*RMIN, MAX STRAIN INCREMENT=1e-3')),
    'friction_change_1e-3': ('*RMIN MAX FRICTION CHANGE = 1e-3 (default 5e-3)', '',
                             lambda t, en: with_rmin(t, '*RMIN, MAX FRICTION CHANGE=1e-3')),
    'min_increment_x0.1': ('stage-2 minimum increment 3.9e-4 s (default 3.9e-3 s)', '',
                           lambda t, en: stage2_min_increment(t, 3.9e-4)),
    'vc_1e-5': ('VC = 1e-5 mm/s (static mu 0.6691 instead of 0.7036)', '',
                lambda t, en: t.replace('VC=1e-6', 'VC=1e-5')),
    'linear': ('REGULARISATION = LINEAR (static mu 0.7186)', '',
               lambda t, en: t.replace('REGULARISATION=FLOOR', 'REGULARISATION=LINEAR')),
    'flat': ('flat fault (bend 0), same E_n = E_t as the default run', '-setnumber bend_angle 0',
             lambda t, en: with_penalties(t.replace('bend 5.6 deg', 'flat fault (bend 0)'),
                                          en, en)),
    'matching_nodes': ('matching fault nodes (lower_fault_factor 1), same E_n = E_t as the '
                       'default run', '-setnumber lower_fault_factor 1',
                       lambda t, en: with_penalties(t, en, en)),
}


def run_variant(name, fcs3d, work):
    description, gmsh, edit = VARIANTS[name]
    directory = os.path.join(work, name)
    os.makedirs(directory, exist_ok=True)
    deck = os.path.join(directory, 'study.inp')
    with open(deck, 'w') as f:
        f.write(edit(open(DECK).read(), DEFAULT_EN))
    env = dict(os.environ, FAULT_BEND_DIR=directory, FAULT_BEND_DECK=deck,
               FAULT_BEND_GMSH=gmsh, FCS3D_OPTIONS='-q')
    started = time.time()
    with open(os.path.join(directory, 'study.out'), 'w') as out:
        status = subprocess.call(['sh', os.path.join(ROOT, 'tools', 'run_default.sh'), fcs3d],
                                 env=env, stdout=out, stderr=subprocess.STDOUT)
    return name, status, time.time() - started


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def summarise(name, status, work):
    directory = os.path.join(work, name)
    row = {'name': name, 'description': VARIANTS[name][0], 'status': status}
    log = open(os.path.join(directory, 'fault_bend.log')).read() \
        if os.path.exists(os.path.join(directory, 'fault_bend.log')) else ''
    m = re.search(r'^done: (\d+) increment\(s\), time ([\d.]+), wall (.*?), peak memory ([\d.]+) MiB',
                  log, re.M)
    row['increments'] = int(m.group(1)) if m else None
    row['end_time'] = float(m.group(2)) if m else None
    row['wall'] = m.group(3) if m else None
    m = re.search(r'E_n = ([\d.eE+-]+), E_t = ([\d.eE+-]+)', open(
        os.path.join(directory, 'fault_bend.echo')).read()) if os.path.exists(
        os.path.join(directory, 'fault_bend.echo')) else None
    row['E_n'] = float(m.group(1)) if m else None
    row['E_t'] = float(m.group(2)) if m else None
    history = os.path.join(directory, 'fault_bend_fault.csv')
    row['first_slip'] = None
    n_slaves = None
    if os.path.exists(history):
        rows = read_csv(history)
        for r in rows:
            n_slaves = float(r['DF_STICK']) + float(r['DF_SLIP']) + float(r['DF_OPEN'])
            if float(r['time']) > 10.0 and float(r['DF_SLIP']) > 0:
                row['first_slip'] = float(r['time'])
                break
    events_path = os.path.join(directory, 'fault_bend_events.csv')
    events = read_csv(events_path) if os.path.exists(events_path) else []
    events = [e for e in events if e['pair'].strip() == '1']
    row['events'] = len(events)
    row['first_event'] = float(events[0]['onset']) if events else None
    big = [e for e in events if n_slaves and int(e['nodes']) >= 0.5 * n_slaves]
    row['big_events'] = [float(e['onset']) for e in big]
    row['big_drop'] = (sum(float(e['stress_drop']) for e in big) / len(big)) if big else None
    row['slaves'] = int(n_slaves) if n_slaves else None
    return row


def fmt(value, digits=2):
    if value is None:
        return '-'
    if isinstance(value, float):
        return '%.*f' % (digits, value)
    return str(value)


def write_outputs(rows, out):
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, 'fault_bend_study.csv'), 'w', newline='') as f:
        w = csv.writer(f)
        w.writerow(['name', 'status', 'increments', 'wall', 'E_n', 'E_t', 'first_slip',
                    'first_event', 'events', 'big_events', 'big_mean_stress_drop'])
        for r in rows:
            w.writerow([r['name'], r['status'], r['increments'], r['wall'], r['E_n'], r['E_t'],
                        r['first_slip'], r['first_event'], r['events'],
                        ' '.join('%.2f' % t for t in r['big_events']), r['big_drop']])
    lines = ['| run | what changes | first slip [s] | vs paper 228.7 s | events | onsets of '
             'system-size events [s] | their mean stress drop [MPa] | increments | wall |',
             '|---|---|---|---|---|---|---|---|---|']
    for r in rows:
        rel = ('%+.1f %%' % (100 * (r['first_slip'] / PAPER_FIRST_SLIP - 1))
               if r['first_slip'] else '-')
        lines.append('| %s | %s | %s | %s | %s | %s | %s | %s | %s |' % (
            r['name'], r['description'], fmt(r['first_slip']), rel, fmt(r['events']),
            ', '.join('%.1f' % t for t in r['big_events']) or '-', fmt(r['big_drop']),
            fmt(r['increments']), r['wall'] or ('failed (%s)' % r['status'])))
    with open(os.path.join(out, 'fault_bend_study.md'), 'w') as f:
        f.write('\n'.join(lines) + '\n')
    print('\n'.join(lines))


def checks(rows):
    by = {r['name']: r for r in rows}
    failures = []
    for r in rows:
        if r['status'] != 0 or r['end_time'] is None or abs(r['end_time'] - 400.0) > 1e-6:
            failures.append('%s: the run did not complete (status %s)' % (r['name'], r['status']))
    d = by.get('default')
    if d and d['first_slip']:
        rel = d['first_slip'] / PAPER_FIRST_SLIP - 1
        ok = abs(rel) <= 0.25
        print('%s default first slip %.2f s vs paper 228.7 s: %+.1f %% (tolerance 25 %%)'
              % ('ok  ' if ok else 'FAIL', d['first_slip'], 100 * rel))
        if not ok:
            failures.append('default first slip outside 25 % of the paper')
    f = by.get('fine_mesh')
    if d and f and d['first_slip'] and f['first_slip']:
        for key, label in (('first_slip', 'first slip'), ):
            rel = f[key] / d[key] - 1
            ok = abs(rel) <= 0.10
            print('%s mesh convergence, %s: default %.2f s, fine %.2f s: %+.1f %% (tolerance 10 %%)'
                  % ('ok  ' if ok else 'FAIL', label, d[key], f[key], 100 * rel))
            if not ok:
                failures.append('mesh convergence of the %s' % label)
        if d['big_events'] and f['big_events']:
            rel = f['big_events'][0] / d['big_events'][0] - 1
            ok = abs(rel) <= 0.10
            print('%s mesh convergence, first system-size event: default %.2f s, fine %.2f s: '
                  '%+.1f %% (tolerance 10 %%)' % ('ok  ' if ok else 'FAIL', d['big_events'][0],
                                                 f['big_events'][0], 100 * rel))
            if not ok:
                failures.append('mesh convergence of the first system-size event')
    return failures


def main():
    global DEFAULT_EN
    parser = argparse.ArgumentParser()
    parser.add_argument('--fcs3d', required=True)
    parser.add_argument('--work', required=True)
    parser.add_argument('--out', default=None)
    parser.add_argument('--only', default=None)
    parser.add_argument('--jobs', type=int, default=1)
    parser.add_argument('--summarise-only', action='store_true')
    args = parser.parse_args()
    names = args.only.split(',') if args.only else list(VARIANTS)
    work = os.path.abspath(args.work)
    fcs3d = os.path.abspath(args.fcs3d)
    if not args.summarise_only:
        if 'default' in names or not os.path.exists(os.path.join(work, 'default', 'fault_bend.echo')):
            run_variant('default', fcs3d, work)
        echo = open(os.path.join(work, 'default', 'fault_bend.echo')).read()
        DEFAULT_EN = float(re.search(r'contact pair DF\s*: E_n = ([\d.eE+-]+)', echo).group(1))
        rest = [n for n in names if n != 'default']
        with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
            for name, status, seconds in pool.map(lambda n: run_variant(n, fcs3d, work), rest):
                print('%s: status %d, %.0f s' % (name, status, seconds), flush=True)
    rows = []
    for name in names:
        log = os.path.join(work, name, 'fault_bend.log')
        status = 0 if os.path.exists(log) and 'done:' in open(log).read() else 1
        rows.append(summarise(name, status, work))
    if args.out:
        write_outputs(rows, args.out)
    failures = checks(rows)
    for f in failures:
        print('FAIL ' + f)
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
