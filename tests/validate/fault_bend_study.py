"""The fault-bend study of doc/validation/fault_bend_paper_law.md (issue 7): the default model of
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
# The one-change study of section 8 varies the paper's law (the default deck before issue 19)
# on the mesh of that time (non-matching fault nodes, lower_fault_factor 1.25): its variants
# edit that deck's text.
STUDY_DECK = os.path.join(ROOT, 'input', 'fault_bend', 'fault_bend_paper_law.inp')
STUDY_MESH = '-setnumber lower_fault_factor 1.25'
GEO = os.path.join(ROOT, 'input', 'fault_bend', 'fault_bend.geo')
sys.path.insert(0, os.path.join(ROOT, 'post'))
import fault_profile  # noqa: E402  (post/: the trace of the .geo, numpy only)
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
    'default': ('the paper\'s-law deck (fault_bend_paper_law.inp; non-matching fault nodes, '
                'E_n = E_t = 10 E/h, FLOOR below VC = 1e-6 mm/s)', '', lambda t, en: t),
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


# ---------------------------------------------------------------- runs (shared with
# fault_bend_convergence.py and fault_bend_ensemble.py)


def mesh_options(values):
    """gmsh options "-setnumber NAME VALUE ..." of a {name: value} dict (in its order)."""
    return ' '.join('-setnumber %s %s' % (k, ('%.6g' % v) if isinstance(v, float) else v)
                    for k, v in values.items())


def scaled_mesh(factor, geo=GEO):
    """The -setnumber values of the .geo's default mesh refined by `factor`: h_fault and h_far
    divided by it, the number of layers through the thickness multiplied by it (rounded)."""
    d = fault_profile.geo_defaults(geo)
    return {'h_fault': d['h_fault'] / factor, 'h_far': d['h_far'] / factor,
            'layers': max(1, int(round(d['layers'] * factor)))}


def static_lines(text):
    """[(start, end) of the data line] of every *STATIC card of a deck, in order."""
    return [(m.start(1), m.end(1)) for m in
            re.finditer(r'^\*STATIC[^\n]*\n(?:\*\*[^\n]*\n)*([^\n*][^\n]*)$', text, re.M)]


def with_end_time(text, end):
    """The deck with its last step shortened (or lengthened) to end at total time `end`: the
    period of the last *STATIC line becomes `end` minus the earlier steps' periods."""
    lines = static_lines(text)
    if not lines:
        raise ValueError('the deck has no *STATIC data line')
    periods = [float(text[a:b].split(',')[1]) for a, b in lines]
    period = end - sum(periods[:-1])
    if period <= 0:
        raise ValueError('end time %g is before the last step starts' % end)
    a, b = lines[-1]
    fields = [f.strip() for f in text[a:b].split(',')]
    fields[1] = '%g.' % period if period == int(period) else '%g' % period
    return text[:a] + ', '.join(fields) + text[b:]


def end_time(text):
    """Total time at the end of the deck's last step (the sum of the *STATIC periods)."""
    return sum(float(text[a:b].split(',')[1]) for a, b in static_lines(text))


#: Node sets whose mean displacement the segment history records (the .geo's groups).
SEGMENT_SETS = ('DE_UPPER', 'DE_LOWER', 'EF_UPPER', 'EF_LOWER')


def with_segment_history(text):
    """The deck with a *HISTORY of the mean displacement of the two sides of D-E and of E-F at
    every increment (<job>_segments.csv): output only, the solution is unchanged. It gives
    each event's mean slip on D-E and on E-F (segment_slip)."""
    card = ('** added by tests/validate/fault_bend_study.py: mean displacement of the sides of '
            'D-E and E-F\n*HISTORY, NAME=SEGMENTS, FREQUENCY=1\n' +
            ''.join('NSET, %s, U\n' % name for name in SEGMENT_SETS))
    k = re.search(r'^\*STEP', text, re.M)
    if k is None:
        raise ValueError('the deck has no *STEP')
    return text[:k.start()] + card + text[k.start():]


def run_case(directory, fcs3d, deck_text, gmsh='', options='-q', env=None):
    """Mesh and run one case in `directory` through tools/run_default.sh (the deck written
    there as case.inp). Returns (exit status, wall seconds, CPU seconds of the run and its
    children)."""
    os.makedirs(directory, exist_ok=True)
    deck = os.path.join(directory, 'case.inp')
    with open(deck, 'w') as f:
        f.write(deck_text)
    environment = dict(os.environ, FAULT_BEND_DIR=directory, FAULT_BEND_DECK=deck,
                       FAULT_BEND_GMSH=gmsh, FCS3D_OPTIONS=options)
    environment.update(env or {})
    started = time.time()
    with open(os.path.join(directory, 'case.out'), 'w') as out:
        process = subprocess.Popen(['nice', '-n', '10', 'sh',
                                    os.path.join(ROOT, 'tools', 'run_default.sh'), fcs3d],
                                   env=environment, stdout=out, stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(process.pid, 0)
        process.returncode = os.waitstatus_to_exitcode(status)
    seconds = time.time() - started
    cpu = usage.ru_utime + usage.ru_stime
    with open(os.path.join(directory, 'case.time'), 'w') as f:
        f.write('wall %.1f cpu %.1f status %d\n' % (seconds, cpu, process.returncode))
    return process.returncode, seconds, cpu


def run_variant(name, fcs3d, work):
    description, gmsh, edit = VARIANTS[name]
    if 'lower_fault_factor' not in gmsh:
        gmsh = (STUDY_MESH + ' ' + gmsh).strip()
    directory = os.path.join(work, name)
    status, seconds, _ = run_case(directory, fcs3d, edit(open(STUDY_DECK).read(), DEFAULT_EN),
                                  gmsh)
    return name, status, seconds


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


LOG_DONE = re.compile(r'^done: (\d+) increment\(s\), time ([\d.eE+-]+), wall (.*?), peak memory '
                      r'([\d.]+) MiB', re.M)
LOG_STEP_END = re.compile(r'^end of step (\d+) .*? at time ([\d.eE+-]+) after', re.M)
LOG_STICK_SLIP = re.compile(r'^inc \d+ step (\d+) time (\S+) .*? limit stick->slip(?: node '
                            r'(\d+))?', re.M)
LOG_STEP_START = re.compile(r'^step (\d+) \(', re.M)
LOG_MESH = re.compile(r'^model: (\d+) nodes, (\d+) elements .*?, (\d+) degrees of freedom', re.M)


def segment_slip(rows, t0, t1):
    """{'DE': mean slip, 'EF': mean slip} [mm] between the last sample at or before t0 and the
    first at or after t1 of the segment history (with_segment_history): the norm of the
    change of the mean upper-minus-lower displacement of each segment's nodes."""
    before = [r for r in rows if r['time'] <= t0 + 1e-12]
    after = [r for r in rows if r['time'] >= t1 - 1e-12]
    if not before or not after:
        return None
    a, b = before[-1], after[0]
    out = {}
    for seg in ('DE', 'EF'):
        d = [(b[seg + '_UPPER_U%d' % k] - b[seg + '_LOWER_U%d' % k]) -
             (a[seg + '_UPPER_U%d' % k] - a[seg + '_LOWER_U%d' % k]) for k in (1, 2, 3)]
        out[seg] = sum(x * x for x in d) ** 0.5
    return out


def measure(directory, job='fault_bend'):
    """What the run in `directory` shows, from its own outputs (log, history CSVs, event
    catalog, mesh_options.txt). Times are total times. Keys:
      status          0 when the log has its "done:" line
      increments, end_time, wall, nodes, elements, dof, E_n, E_t, stage_1_end
      first_slip      first history row after stage 1 with a slipping node of a frictional
                      pair; first_slip_log, first_slip_node: the first increment of the last
                      step limited by stick->slip in the log
      slaves          slave nodes of the frictional pairs (stick + slip + open)
      half_slip_time  first history row with at least half of them slipping at once
      events          [{onset, end, nodes, stress_drop, peak_rate, segment, position,
                      slip_DE, slip_EF}] (segment: of the hypocentre, along the trace;
                      slip_*: mean slip of each segment during the event, when the run has the
                      segment history)
      big             the events on at least half of the slave nodes ("system-size")
      nucleation      onset of the first system-size event minus first_slip
    """
    path = lambda name: os.path.join(directory, name)  # noqa: E731
    row = {'directory': directory}
    log = open(path(job + '.log')).read() if os.path.exists(path(job + '.log')) else ''
    m = LOG_DONE.search(log)
    row['status'] = 0 if m else 1
    row['increments'] = int(m.group(1)) if m else None
    row['end_time'] = float(m.group(2)) if m else None
    row['wall'] = m.group(3) if m else None
    m = LOG_MESH.search(log)
    row['nodes'], row['elements'], row['dof'] = (int(m.group(k)) for k in (1, 2, 3)) if m \
        else (None, None, None)
    ends = {int(k): float(t) for k, t in LOG_STEP_END.findall(log)}
    steps = {int(k) for k in LOG_STEP_START.findall(log)}
    # Stage 1 (pressure) ends with step 1 of a deck of two or more steps.
    row['stage_1_end'] = ends.get(1, 0.0) if len(steps) > 1 else 0.0
    row['first_slip_log'] = row['first_slip_node'] = None
    for step, t, node in LOG_STICK_SLIP.findall(log):
        if int(step) > 1 and float(t) > row['stage_1_end']:
            row['first_slip_log'], row['first_slip_node'] = float(t), node or None
            break
    echo = open(path(job + '.echo')).read() if os.path.exists(path(job + '.echo')) else ''
    m = re.search(r'E_n = ([\d.eE+-]+), E_t = ([\d.eE+-]+)', echo)
    row['E_n'], row['E_t'] = (float(m.group(1)), float(m.group(2))) if m else (None, None)
    history = read_csv(path(job + '_fault.csv')) if os.path.exists(path(job + '_fault.csv')) \
        else []
    pairs = sorted({c[:-len('_STICK')] for c in (history[0] if history else {})
                    if c.endswith('_STICK')})
    counts = {p: max(float(r[p + '_STICK']) + float(r[p + '_SLIP']) + float(r[p + '_OPEN'])
                     for r in history) for p in pairs}
    # The *CONTACT PAIR names of the deck (a *TIE's nodes count as stick in the history).
    deck = open(path(job + '.inp')).read() if os.path.exists(path(job + '.inp')) else ''
    declared = {n.upper() for n in re.findall(r'^\*CONTACT PAIR\b[^\n]*\bNAME\s*=\s*([^,\s]+)',
                                              deck, re.M | re.I)}
    frictional = [p for p in pairs if counts[p] > 0 and (not declared or p.upper() in declared)]
    row['slaves'] = int(sum(counts[p] for p in frictional)) if frictional else None
    row['first_slip'] = row['half_slip_time'] = None
    for r in history:
        t = float(r['time'])
        if t <= row['stage_1_end'] + 1e-9:
            continue
        slipping = sum(float(r[p + '_SLIP']) for p in frictional)
        if slipping > 0 and row['first_slip'] is None:
            row['first_slip'] = t
        if row['slaves'] and slipping >= 0.5 * row['slaves']:
            row['half_slip_time'] = t
            break
    trace = None
    if os.path.exists(path('fault_bend.geo')):
        options = []
        if os.path.exists(path('mesh_options.txt')):
            words = open(path('mesh_options.txt')).read().split()
            options = [(words[i + 1], words[i + 2]) for i in range(len(words) - 2)
                       if words[i] == '-setnumber']
        trace = fault_profile.FaultTrace.from_parameters(
            fault_profile.parameters(path('fault_bend.geo'), options))
    segments = []
    if os.path.exists(path(job + '_segments.csv')):
        segments = [{k: float(v) for k, v in r.items()} for r in read_csv(path(job + '_segments.csv'))]
    events = []
    catalog = read_csv(path(job + '_events.csv')) if os.path.exists(path(job + '_events.csv')) \
        else []
    for e in catalog:
        event = {'onset': float(e['onset']), 'end': float(e['end']), 'nodes': int(e['nodes']),
                 'stress_drop': float(e['stress_drop']), 'peak_rate': float(e['peak_slip_rate']),
                 'segment': None, 'position': None, 'slip_DE': None, 'slip_EF': None}
        if trace is not None:
            position, segment, _ = trace.along([[float(e['x']), float(e['y'])]])
            event['segment'], event['position'] = str(segment[0]), float(position[0])
        slip = segment_slip(segments, event['onset'], event['end']) if segments else None
        if slip:
            event['slip_DE'], event['slip_EF'] = slip['DE'], slip['EF']
        events.append(event)
    row['events'] = events
    row['segment_nodes'] = None
    if trace is not None and row['slaves']:
        de, ef = trace.lengths['DE'], trace.lengths['EF']
        row['segment_nodes'] = {'DE': row['slaves'] * de / (de + ef),
                                'EF': row['slaves'] * ef / (de + ef)}
    row['big'] = [e for e in events if row['slaves'] and e['nodes'] >= 0.5 * row['slaves']]
    row['nucleation'] = (row['big'][0]['onset'] - row['first_slip']) \
        if row['big'] and row['first_slip'] is not None else None
    return row


def summarise(name, status, work):
    m = measure(os.path.join(work, name))
    row = {'name': name, 'description': VARIANTS[name][0], 'status': status}
    for key in ('increments', 'end_time', 'wall', 'E_n', 'E_t', 'first_slip'):
        row[key] = m[key]
    row['events'] = len(m['events'])
    row['first_event'] = m['events'][0]['onset'] if m['events'] else None
    row['big_events'] = [e['onset'] for e in m['big']]
    row['big_drop'] = (sum(e['stress_drop'] for e in m['big']) / len(m['big'])) if m['big'] \
        else None
    row['slaves'] = m['slaves']
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
